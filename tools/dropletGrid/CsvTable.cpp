#include "CsvTable.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace dropletFiber
{
namespace cli
{

namespace
{

std::string trim(const std::string& s)
{
    const char* blanks = " \t\r\n";
    const std::size_t first = s.find_first_not_of(blanks);
    if (first == std::string::npos)
    {
        return "";
    }
    const std::size_t last = s.find_last_not_of(blanks);
    return s.substr(first, last - first + 1);
}

std::vector<std::string> split(const std::string& line)
{
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true)
    {
        const std::size_t comma = line.find(',', start);
        fields.push_back(
            trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos)
        {
            return fields;
        }
        start = comma + 1;
    }
}

std::string where(const std::string& path, int line)
{
    return path + ":" + std::to_string(line) + ": ";
}

} // namespace

std::vector<CsvRow> readCsv(const std::string& path, const std::vector<std::string>& columns)
{
    std::ifstream in(path);
    if (!in)
    {
        throw InputError(path + ": cannot open file");
    }
    std::vector<CsvRow> rows;
    std::vector<std::size_t> position; // column index in the file of each requested column
    std::size_t fieldCount = 0;
    std::string text;
    int line = 0;
    bool haveHeader = false;
    while (std::getline(in, text))
    {
        ++line;
        const std::string trimmed = trim(text);
        if (trimmed.empty() || trimmed[0] == '#')
        {
            continue;
        }
        const std::vector<std::string> fields = split(trimmed);
        if (!haveHeader)
        {
            haveHeader = true;
            fieldCount = fields.size();
            for (const std::string& column : columns)
            {
                std::size_t found = fields.size();
                for (std::size_t f = 0; f < fields.size(); ++f)
                {
                    if (fields[f] == column)
                    {
                        found = f;
                        break;
                    }
                }
                if (found == fields.size())
                {
                    throw InputError(where(path, line) + "header: missing column '" + column
                                     + "' (header is '" + trimmed + "')");
                }
                position.push_back(found);
            }
            continue;
        }
        if (fields.size() != fieldCount)
        {
            std::string message = where(path, line) + "line has " + std::to_string(fields.size())
                + " fields, the header has " + std::to_string(fieldCount);
            if (fields.size() < fieldCount)
            {
                // Name the first requested field that is missing.
                for (std::size_t c = 0; c < columns.size(); ++c)
                {
                    if (position[c] >= fields.size())
                    {
                        message = where(path, line) + "field '" + columns[c] + "': missing (line has "
                            + std::to_string(fields.size()) + " fields, the header has "
                            + std::to_string(fieldCount) + ")";
                        break;
                    }
                }
            }
            throw InputError(message);
        }
        CsvRow row;
        row.line = line;
        row.values.reserve(columns.size());
        for (std::size_t c = 0; c < columns.size(); ++c)
        {
            const std::string& token = fields[position[c]];
            if (token.empty())
            {
                throw InputError(where(path, line) + "field '" + columns[c] + "': empty value");
            }
            char* end = nullptr;
            const double value = std::strtod(token.c_str(), &end);
            if (end != token.c_str() + token.size())
            {
                throw InputError(where(path, line) + "field '" + columns[c] + "': not a number: '" + token
                                 + "'");
            }
            if (!std::isfinite(value))
            {
                throw InputError(where(path, line) + "field '" + columns[c] + "': not a finite number: '"
                                 + token + "'");
            }
            row.values.push_back(value);
        }
        rows.push_back(std::move(row));
    }
    if (!haveHeader)
    {
        throw InputError(path + ": empty file (a header line is required)");
    }
    return rows;
}

} // namespace cli
} // namespace dropletFiber
