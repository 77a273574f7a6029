#include "Table.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace dropletFiber
{
namespace validation
{

void Table::add(const std::string& label, const std::vector<double>& values)
{
    if (values.size() != columns.size())
    {
        throw std::invalid_argument("Table " + name + ": row has " + std::to_string(values.size())
                                    + " values, table has " + std::to_string(columns.size()) + " columns");
    }
    rows.push_back(TableRow{label, values});
}

int Table::column(const std::string& columnName) const
{
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
        if (columns[c] == columnName)
        {
            return static_cast<int>(c);
        }
    }
    throw std::invalid_argument("Table " + name + ": no column " + columnName);
}

double Table::value(std::size_t row, const std::string& columnName) const
{
    return rows.at(row).values[static_cast<std::size_t>(column(columnName))];
}

void Table::write(const std::string& directory) const
{
    const std::string path = directory + "/" + name + ".csv";
    std::ofstream out(path);
    if (!out)
    {
        throw std::runtime_error("cannot write " + path);
    }
    out << "label";
    for (const std::string& c : columns)
    {
        out << ',' << c;
    }
    out << '\n';
    char buffer[64];
    for (const TableRow& row : rows)
    {
        // The label is quoted (it may hold commas); a quote inside is doubled (RFC 4180).
        out << '"';
        for (char c : row.label)
        {
            out << (c == '"' ? "\"\"" : std::string(1, c));
        }
        out << '"';
        for (double v : row.values)
        {
            std::snprintf(buffer, sizeof buffer, "%.17g", v);
            out << ',' << buffer;
        }
        out << '\n';
    }
}

} // namespace validation
} // namespace dropletFiber
