#include "laydown/FormingLine.hpp"

#include <stdexcept>
#include <string>

namespace dropletFiber
{

long evenShift(long rows, int hoods)
{
    return hoods > 0 ? std::max(1L, rows / hoods) : 1L;
}

MatMap formingLine(const MatMap& hood, long rowFrom, long rowTo, int hoods, long shift)
{
    const long rows = rowTo - rowFrom + 1;
    if (hoods < 1 || shift < 1)
        throw std::invalid_argument("formingLine: the hoods and the shift must be >= 1");
    if ((hoods - 1) * shift >= rows)
    {
        throw std::invalid_argument("formingLine: " + std::to_string(hoods) + " hoods "
                                    + std::to_string(shift) + " rows apart need more than the "
                                    + std::to_string(rows) + " complete rows of the hood's mat");
    }
    MatMap line(hood.cell(), hood.acrossMin(), hood.acrossMax());
    for (const auto& [key, cell] : hood.cells())
    {
        const auto [column, row] = key;
        if (row < rowFrom || row > rowTo)
            continue;
        // Hood j lays on the line's row r what the hood laid on row r + j shift (wrapped)
        for (int j = 0; j < hoods; ++j)
        {
            const long lineRow = rowFrom + ((row - rowFrom - j * shift) % rows + rows) % rows;
            auto sums = cell.sums();
            const auto it = line.cells().find({column, lineRow});
            if (it != line.cells().end())
            {
                const auto have = it->second.sums();
                for (std::size_t k = 0; k < sums.size(); ++k)
                    sums[k] += have[k];
            }
            MatCell sum;
            sum.setSums(sums);
            line.setCell(column, lineRow, sum);
        }
    }
    return line;
}

} // namespace dropletFiber
