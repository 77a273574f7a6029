// CsvTable: a numeric CSV file with a header line, read with messages that name the file,
// line and field of every error (the dropletGrid tool's input check).
//
// Format: the first non-empty line names the columns (comma-separated, surrounding
// blanks ignored, any order, extra columns allowed and ignored); every following
// non-empty line has exactly as many fields; each required field is a finite decimal
// number. Lines starting with '#' are comments.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace dropletFiber
{
namespace cli
{

// Bad user input: the message is meant for the user; the tool exits with code 2.
struct InputError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct CsvRow
{
    int line = 0;               // 1-based line number in the file
    std::vector<double> values; // in the order of the requested columns
};

// Reads `path` and returns, for every data line, the values of `columns` (in that order).
// Throws InputError: file unreadable, empty, a column missing from the header, a line
// with the wrong number of fields, a value that is empty, not a number or not finite.
std::vector<CsvRow> readCsv(const std::string& path, const std::vector<std::string>& columns);

} // namespace cli
} // namespace dropletFiber
