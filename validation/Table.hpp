// Table: the result of one experiment, a label and numeric columns per row, written as CSV
// for plot.py and report.py.
#pragma once

#include <string>
#include <vector>

namespace dropletFiber
{
namespace validation
{

struct TableRow
{
    std::string label;
    std::vector<double> values;
};

struct Table
{
    std::string name;                 // file stem, e.g. "figure7"
    std::vector<std::string> columns; // numeric columns (the label column comes first)
    std::vector<TableRow> rows;

    void add(const std::string& label, const std::vector<double>& values);
    int column(const std::string& columnName) const; // throws if absent
    double value(std::size_t row, const std::string& columnName) const;
    // Writes <directory>/<name>.csv: header "label,<columns>", the label quoted, values with
    // 17 significant digits.
    void write(const std::string& directory) const;
};

} // namespace validation
} // namespace dropletFiber
