#include "output/VtkWriter.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace dropletFiber
{

namespace
{

std::ofstream openOrThrow(const std::string& path)
{
    std::ofstream os(path);
    if (!os)
    {
        throw std::runtime_error("cannot open '" + path + "' for writing");
    }
    os << std::setprecision(17);
    return os;
}

// The shortest decimal that reads back as the same double (std::to_chars): as exact as
// the stream at precision 17, about ten times faster (formatting the grid's ~50k values
// was nearly all of a write in the tutorial) and shorter. Non-finite values are written
// as 0: VTK has no notation for them that every reader accepts.
void appendNumber(std::string& out, double v)
{
    char buffer[32];
    const std::to_chars_result written
        = std::to_chars(buffer, buffer + sizeof buffer, std::isfinite(v) ? v : 0.0);
    out.append(buffer, written.ptr);
}

// The time as the shortest decimal that reads back as it: a time given as its folder's
// name (0.3) is written as that, not as 0.29999999999999999
void writeTimeFieldData(std::ostream& os, double time)
{
    std::string text;
    appendNumber(text, time);
    os << "    <FieldData>\n"
       << "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\""
          " format=\"ascii\">"
       << text << "</DataArray>\n"
       << "    </FieldData>\n";
}

void checkFieldSize(const VtkField& field, std::size_t tuples)
{
    if (field.values.size() != tuples * static_cast<std::size_t>(field.components))
    {
        throw std::invalid_argument("VTK field '" + field.name + "' has "
                                    + std::to_string(field.values.size()) + " values, expected "
                                    + std::to_string(tuples * field.components));
    }
}

void writeDataArray(std::ostream& os, const VtkField& field, std::size_t tuples)
{
    checkFieldSize(field, tuples);
    os << "        <DataArray type=\"Float64\" Name=\"" << field.name << "\" NumberOfComponents=\""
       << field.components << "\" format=\"ascii\">\n";
    std::string text;
    text.reserve(field.values.size() * 24);
    for (std::size_t i = 0; i < field.values.size(); ++i)
    {
        text += i % 6 == 0 ? "          " : " ";
        appendNumber(text, field.values[i]);
        if (i % 6 == 5 || i + 1 == field.values.size())
        {
            text += '\n';
        }
    }
    os << text << "        </DataArray>\n";
}

// Base64 (RFC 4648 alphabet, '=' padding) of `count` bytes, appended to `out`.
void appendBase64(std::string& out, const unsigned char* bytes, std::size_t count)
{
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::size_t i = 0;
    for (; i + 3 <= count; i += 3)
    {
        const unsigned triple = (unsigned(bytes[i]) << 16) | (unsigned(bytes[i + 1]) << 8) | bytes[i + 2];
        const char quad[4] = {alphabet[(triple >> 18) & 63], alphabet[(triple >> 12) & 63],
                              alphabet[(triple >> 6) & 63], alphabet[triple & 63]};
        out.append(quad, 4);
    }
    if (i < count)
    {
        const bool two = i + 1 < count;
        const unsigned triple = (unsigned(bytes[i]) << 16) | (two ? unsigned(bytes[i + 1]) << 8 : 0u);
        const char quad[4] = {alphabet[(triple >> 18) & 63], alphabet[(triple >> 12) & 63],
                              two ? alphabet[(triple >> 6) & 63] : '=', '='};
        out.append(quad, 4);
    }
}

bool littleEndianHost()
{
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 1;
}

// VTK's inline binary form (format="binary", header_type="UInt64" in the VTKFile element):
// one base64 stream of the array's byte count (UInt64) followed by its values, as VTK's own
// writer encodes uncompressed arrays. Exact doubles, ~10x faster to write than decimals
// and ~2x smaller; non-finite values are written as 0, as in the ASCII form.
void writeBinaryDataArray(std::ostream& os, const VtkField& field)
{
    os << "        <DataArray type=\"Float64\" Name=\"" << field.name << "\" NumberOfComponents=\""
       << field.components << "\" format=\"binary\">\n          ";
    const std::uint64_t byteCount = field.values.size() * sizeof(double);
    std::vector<unsigned char> bytes(sizeof byteCount + byteCount);
    std::memcpy(bytes.data(), &byteCount, sizeof byteCount);
    for (std::size_t i = 0; i < field.values.size(); ++i)
    {
        const double v = std::isfinite(field.values[i]) ? field.values[i] : 0.0;
        std::memcpy(bytes.data() + sizeof byteCount + i * sizeof(double), &v, sizeof v);
    }
    std::string text;
    text.reserve(4 * (bytes.size() / 3 + 1));
    appendBase64(text, bytes.data(), bytes.size());
    os << text << "\n        </DataArray>\n";
}

void writeFieldBlock(std::ostream& os, const char* tag, const std::vector<VtkField>& fields,
                     std::size_t tuples, bool binary = false)
{
    os << "      <" << tag << ">\n";
    for (const VtkField& field : fields)
    {
        if (binary)
        {
            checkFieldSize(field, tuples);
            writeBinaryDataArray(os, field);
            continue;
        }
        writeDataArray(os, field, tuples);
    }
    os << "      </" << tag << ">\n";
}

void writeArrayDeclarations(std::ostream& os, const char* tag, const std::vector<VtkField>& fields)
{
    os << "    <" << tag << ">\n";
    for (const VtkField& field : fields)
    {
        os << "      <PDataArray type=\"Float64\" Name=\"" << field.name << "\" NumberOfComponents=\""
           << field.components << "\"/>\n";
    }
    os << "    </" << tag << ">\n";
}

} // namespace

void writePolylines(const std::string& path, double time, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<std::size_t>& lineOffsets, const std::vector<VtkField>& pointData,
                    const std::vector<VtkField>& cellData)
{
    std::size_t nSegments = 0;
    for (std::size_t f = 0; f < lineOffsets.size(); ++f)
    {
        const std::size_t end = f + 1 < lineOffsets.size() ? lineOffsets[f + 1] : points.size();
        nSegments += end - lineOffsets[f] - 1;
    }

    std::ofstream os = openOrThrow(path);
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
       << "  <PolyData>\n";
    writeTimeFieldData(os, time);
    // One VTK line cell per segment, so that cell data (tension) is per segment
    os << "    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfLines=\"" << nSegments << "\">\n"
       << "      <Points>\n"
       << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    std::string text;
    for (const Eigen::Vector3d& p : points)
    {
        text += "         ";
        for (int d = 0; d < 3; ++d)
        {
            text += ' ';
            appendNumber(text, p[d]);
        }
        text += '\n';
    }
    os << text << "        </DataArray>\n"
       << "      </Points>\n"
       << "      <Lines>\n"
       << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t f = 0; f < lineOffsets.size(); ++f)
    {
        const std::size_t end = f + 1 < lineOffsets.size() ? lineOffsets[f + 1] : points.size();
        for (std::size_t i = lineOffsets[f]; i + 1 < end; ++i)
        {
            os << "          " << i << ' ' << i + 1 << '\n';
        }
    }
    os << "        </DataArray>\n"
       << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t s = 1; s <= nSegments; ++s)
    {
        os << "          " << 2 * s << '\n';
    }
    os << "        </DataArray>\n"
       << "      </Lines>\n";
    writeFieldBlock(os, "PointData", pointData, points.size());
    writeFieldBlock(os, "CellData", cellData, nSegments);
    os << "    </Piece>\n"
       << "  </PolyData>\n"
       << "</VTKFile>\n";
    if (!os)
    {
        throw std::runtime_error("error writing '" + path + "'");
    }
}

void writeParallelPolylines(const std::string& path, double time, const std::vector<std::string>& pieces,
                            const std::vector<VtkField>& pointData, const std::vector<VtkField>& cellData)
{
    std::ofstream os = openOrThrow(path);
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
       << "  <PPolyData GhostLevel=\"0\">\n";
    writeTimeFieldData(os, time);
    os << "    <PPoints>\n"
       << "      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n"
       << "    </PPoints>\n";
    writeArrayDeclarations(os, "PPointData", pointData);
    writeArrayDeclarations(os, "PCellData", cellData);
    for (const std::string& piece : pieces)
    {
        os << "    <Piece Source=\"" << piece << "\"/>\n";
    }
    os << "  </PPolyData>\n"
       << "</VTKFile>\n";
    if (!os)
    {
        throw std::runtime_error("error writing '" + path + "'");
    }
}

void writeImageData(const std::string& path, double time, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& spacing, const std::array<int, 3>& nodes,
                    const std::vector<VtkField>& pointData)
{
    writeImageDataPiece(path, time, origin, spacing, {{0, nodes[0] - 1, 0, nodes[1] - 1, 0, nodes[2] - 1}},
                        pointData);
}

namespace
{
std::string extentText(const VtkExtent& e)
{
    std::ostringstream text;
    text << e[0] << ' ' << e[1] << ' ' << e[2] << ' ' << e[3] << ' ' << e[4] << ' ' << e[5];
    return text.str();
}

std::size_t extentPoints(const VtkExtent& e)
{
    std::size_t n = 1;
    for (int d = 0; d < 3; ++d)
    {
        n *= static_cast<std::size_t>(
            std::max(0, e[static_cast<std::size_t>(2 * d + 1)] - e[static_cast<std::size_t>(2 * d)] + 1));
    }
    return n;
}
} // namespace

void writeImageDataPiece(const std::string& path, double time, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& spacing, const VtkExtent& extent,
                         const std::vector<VtkField>& pointData)
{
    std::ofstream os = openOrThrow(path);
    const std::string text = extentText(extent);
    // The grid's values in binary (base64) on little-endian hosts: most of a write's time
    // was their decimal formatting (docs/performance.md, output)
    const bool binary = littleEndianHost();
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\""
       << (binary ? " header_type=\"UInt64\"" : "") << ">\n"
       << "  <ImageData WholeExtent=\"" << text << "\" Origin=\"" << origin.x() << ' ' << origin.y() << ' '
       << origin.z() << "\" Spacing=\"" << spacing.x() << ' ' << spacing.y() << ' ' << spacing.z() << "\">\n";
    writeTimeFieldData(os, time);
    os << "    <Piece Extent=\"" << text << "\">\n";
    writeFieldBlock(os, "PointData", pointData, extentPoints(extent), binary);
    os << "      <CellData>\n      </CellData>\n"
       << "    </Piece>\n"
       << "  </ImageData>\n"
       << "</VTKFile>\n";
    if (!os)
    {
        throw std::runtime_error("error writing '" + path + "'");
    }
}

void writePImageData(const std::string& path, double time, const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& spacing, const VtkExtent& wholeExtent,
                     const std::vector<VtkField>& pointFields, const std::vector<VtkPiece>& pieces)
{
    std::ofstream os = openOrThrow(path);
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"PImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
       << "  <PImageData WholeExtent=\"" << extentText(wholeExtent) << "\" GhostLevel=\"0\" Origin=\""
       << origin.x() << ' ' << origin.y() << ' ' << origin.z() << "\" Spacing=\"" << spacing.x() << ' '
       << spacing.y() << ' ' << spacing.z() << "\">\n";
    writeTimeFieldData(os, time);
    os << "    <PPointData>\n";
    for (const VtkField& field : pointFields)
    {
        os << "      <PDataArray type=\"Float64\" Name=\"" << field.name << "\" NumberOfComponents=\""
           << field.components << "\"/>\n";
    }
    os << "    </PPointData>\n";
    for (const VtkPiece& piece : pieces)
    {
        os << "    <Piece Extent=\"" << extentText(piece.extent) << "\" Source=\"" << piece.source
           << "\"/>\n";
    }
    os << "  </PImageData>\n"
       << "</VTKFile>\n";
    if (!os)
    {
        throw std::runtime_error("error writing '" + path + "'");
    }
}

void SeriesFile::load(double restartTime)
{
    entries_.clear();
    std::ifstream is(path_);
    if (!is)
    {
        return;
    }
    // Entries are written one per line by write(); read them back the same way
    const std::regex entry("\"name\"\\s*:\\s*\"([^\"]*)\"\\s*,\\s*\"time\"\\s*:\\s*([-+0-9.eE]+)");
    std::string line;
    while (std::getline(is, line))
    {
        std::smatch m;
        if (std::regex_search(line, m, entry))
        {
            const double t = std::stod(m[2].str());
            if (t < restartTime)
            {
                entries_.push_back({m[1].str(), t});
            }
        }
    }
}

void SeriesFile::add(const std::string& fileName, double time)
{
    entries_.erase(
        std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.time == time; }),
        entries_.end());
    entries_.push_back({fileName, time});
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return a.time < b.time; });
    write();
}

void SeriesFile::write() const
{
    std::ofstream os = openOrThrow(path_);
    os << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
    for (std::size_t i = 0; i < entries_.size(); ++i)
    {
        std::string time;
        appendNumber(time, entries_[i].time);
        os << "    { \"name\" : \"" << entries_[i].name << "\", \"time\" : " << time << " }"
           << (i + 1 < entries_.size() ? "," : "") << '\n';
    }
    os << "  ]\n}\n";
}

} // namespace dropletFiber
