// VtkWriter: ParaView-readable output of the fibers and the density grid, as VTK XML
// files, plus the ".series" index that makes ParaView load a set of files as one time
// series. The fibers' arrays are ASCII; the grid's (most of the bytes) are VTK's inline
// binary form on little-endian hosts (base64 of a UInt64 byte count and the doubles, as
// VTK writes uncompressed arrays; ASCII elsewhere): still XML, exact, and about ten times
// faster to write than decimals.
//
//   writePolylines - fibers: one polyline per fiber (.vtp, PolyData), with point and
//                    cell (= segment) data;
//   writeParallelPolylines - the index (.pvtp, PPolyData) of polylines written in
//                    pieces (one .vtp per processor), which ParaView reads as one;
//   writeImageData - the regular density grid (.vti, ImageData), with point data, or
//                    one piece of it (a processor's block);
//   writePImageData - the index of the pieces of a grid written in parallel (.pvti,
//                    ParaView's parallel ImageData): whole extent, fields, pieces.
//   SeriesFile     - the JSON "<file>.series" index (file name and time per entry),
//                    re-read on restart so that later times replace, never duplicate.
//
// ASCII values are the shortest decimals that read back as the same doubles, binary ones
// the doubles themselves: the files are also what a user compares against, so they must
// not round away what the solver computed.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace dropletFiber
{

// A named data array: `components` values per point (or cell), point after point.
struct VtkField
{
    std::string name;
    int components = 1;
    std::vector<double> values;
};

// Fibers as polylines. lineOffsets[f] is the index of the first point of line f in
// `points`; the lines are consecutive, the last one ends at the last point.
void writePolylines(const std::string& path, double time, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<std::size_t>& lineOffsets, const std::vector<VtkField>& pointData,
                    const std::vector<VtkField>& cellData);

// The index of polylines written as pieces (writePolylines, one file each): the piece
// files (paths relative to the index's folder), and the arrays every piece holds
// (their names and components; the values are not used).
void writeParallelPolylines(const std::string& path, double time, const std::vector<std::string>& pieces,
                            const std::vector<VtkField>& pointData, const std::vector<VtkField>& cellData);

// A regular grid: origin, spacing and number of nodes per direction, point data in
// VTK order (x fastest, then y, then z).
void writeImageData(const std::string& path, double time, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& spacing, const std::array<int, 3>& nodes,
                    const std::vector<VtkField>& pointData);

// Node index extent: x from, x to, y from, y to, z from, z to (inclusive).
using VtkExtent = std::array<int, 6>;

// One piece of a regular grid: the nodes of `extent` (of the grid whose node 0 sits at
// origin), point data in VTK order over the piece.
void writeImageDataPiece(const std::string& path, double time, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& spacing, const VtkExtent& extent,
                         const std::vector<VtkField>& pointData);

// A piece listed in a .pvti: its extent and its file (relative to the .pvti).
struct VtkPiece
{
    VtkExtent extent;
    std::string source;
};

// The parallel index of a grid written as pieces: fields named as pointFields (their
// values are not used), pieces that together cover wholeExtent.
void writePImageData(const std::string& path, double time, const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& spacing, const VtkExtent& wholeExtent,
                     const std::vector<VtkField>& pointFields, const std::vector<VtkPiece>& pieces);

// The ".series" index of one output stream.
class SeriesFile
{
public:
    explicit SeriesFile(std::string path) : path_(std::move(path)) {}

    // Read the entries of an existing index (a restarted run), keeping those with a
    // time before `restartTime`.
    void load(double restartTime);

    // Add (or replace, for the same time) an entry and rewrite the index.
    void add(const std::string& fileName, double time);

    std::size_t size() const { return entries_.size(); }

private:
    struct Entry
    {
        std::string name;
        double time;
    };
    void write() const;

    std::string path_;
    std::vector<Entry> entries_;
};

} // namespace dropletFiber
