// GridSpec: geometry of the regular density grid of docs/model.md sec. 4 (nodes, spacing,
// node volume), IndexBox, an inclusive box of node indices, and forEachRow, the one loop
// over a box's nodes row by row.
//
// Nodes sit on the bounds: direction d has nodes[d] nodes at
//     lower[d] + i * h[d],   h[d] = (upper[d] - lower[d]) / (nodes[d] - 1),
// so that bilinear/trilinear interpolation covers the whole box [lower, upper].
// A direction with a single node is "flat" (2D grid: one node layer). Its node sits at
// the middle of [lower, upper], and upper - lower is the thickness (the case's depth)
// that enters the node volume (eq. 26: h_x h_y * thickness). The kernel ignores the
// flat coordinate (the 2D model has all parcels in one plane), but the box still
// decides which parcels are inside.
//
// Node volumes are those of the dual cells (docs/model.md sec. 4, edge nodes): the cell
// h_x h_y [h_z] around an interior node, half of it on a face of the box, a quarter on an
// edge, an eighth at a corner, counting the active directions only (a flat direction's
// thickness is the slab, not a face). mirrorIndex folds the unbounded lattice
// lower + i h onto the nodes (the folded kernels of DensityGrid.hpp).
//
// Flat node index: i + nx * (j + ny * k) (i fastest).
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <string>
#include <utility>

namespace dropletFiber
{

// Inclusive box of node indices; empty when lo > hi in any direction.
struct IndexBox
{
    std::array<int, 3> lo{{0, 0, 0}};
    std::array<int, 3> hi{{-1, -1, -1}};

    bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
    std::size_t nodeCount() const;
    // Smallest box holding both (an empty box is neutral).
    IndexBox united(const IndexBox& other) const;
    // The nodes in both (empty when they do not overlap).
    IndexBox intersected(const IndexBox& other) const;
    bool holds(int i, int j, int k) const
    {
        return i >= lo[0] && i <= hi[0] && j >= lo[1] && j <= hi[1] && k >= lo[2] && k <= hi[2];
    }
    // Node counts per direction (0 for an empty box).
    std::array<int, 3> extents() const;
    bool operator==(const IndexBox& other) const { return lo == other.lo && hi == other.hi; }
    bool operator!=(const IndexBox& other) const { return !(*this == other); }
};

// Every index of a lattice of counts[d] points per direction (a grid's nodes, or its tiles).
inline IndexBox wholeBox(const std::array<int, 3>& counts)
{
    return IndexBox{{{0, 0, 0}}, {{counts[0] - 1, counts[1] - 1, counts[2] - 1}}};
}

// "(lo x y z) to (hi x y z)", for messages.
std::string boxText(const IndexBox& box);

// Flat index i + nx * (j + ny * k) of node (i, j, k) in a grid of `nodes` nodes per direction.
inline std::size_t flatNodeIndex(const std::array<int, 3>& nodes, int i, int j, int k)
{
    return static_cast<std::size_t>(i)
        + static_cast<std::size_t>(nodes[0])
        * (static_cast<std::size_t>(j) + static_cast<std::size_t>(nodes[1]) * static_cast<std::size_t>(k));
}

// Its inverse: the grid indices (i, j, k) of flat node index `node`.
inline std::array<int, 3> nodeIndicesOfFlat(const std::array<int, 3>& nodes, std::size_t node)
{
    const auto nx = static_cast<std::size_t>(nodes[0]);
    const auto ny = static_cast<std::size_t>(nodes[1]);
    return {{static_cast<int>(node % nx), static_cast<int>((node / nx) % ny),
             static_cast<int>(node / (nx * ny))}};
}

// Flat index of node (i, j, k) among the nodes of `region` (i fastest): the storage of a
// block of the grid (DensityGrid's storage box, AveragingWindow's region).
inline std::size_t flatIndexInBox(const IndexBox& region, int i, int j, int k)
{
    return static_cast<std::size_t>(i - region.lo[0])
        + static_cast<std::size_t>(region.hi[0] - region.lo[0] + 1)
        * (static_cast<std::size_t>(j - region.lo[1])
           + static_cast<std::size_t>(region.hi[1] - region.lo[1] + 1)
               * static_cast<std::size_t>(k - region.lo[2]));
}

// One row of an IndexBox: its nodes lo[0]..hi[0] at fixed (j, k), consecutive in the grid.
struct IndexRow
{
    int j = 0;
    int k = 0;
    std::size_t first = 0;       // flat index of node (lo[0], j, k)
    std::size_t length = 0;      // hi[0] - lo[0] + 1 nodes
    std::size_t offsetInBox = 0; // position of its first node in the box, i fastest
};

// Calls f(row) for every row of the box, k outermost, then j: the nodes in flat order (i
// fastest), so loops that sum over the box always add in the same order. Nothing for an
// empty box. nodes: the grid's node counts per direction (GridSpec::nodes).
template <class F>
void forEachRow(const IndexBox& box, const std::array<int, 3>& nodes, F&& f)
{
    if (box.empty())
    {
        return;
    }
    IndexRow row;
    row.length = static_cast<std::size_t>(box.hi[0] - box.lo[0] + 1);
    for (row.k = box.lo[2]; row.k <= box.hi[2]; ++row.k)
    {
        for (row.j = box.lo[1]; row.j <= box.hi[1]; ++row.j)
        {
            row.first = flatNodeIndex(nodes, box.lo[0], row.j, row.k);
            f(static_cast<const IndexRow&>(row));
            row.offsetInBox += row.length;
        }
    }
}

// forEachRow over the rows of `box` (inside `region`), with row.first the flat index of
// the row's first node among the nodes of region (flatIndexInBox) and row.j, row.k
// relative to region.lo: loops over a block of the grid stored on its own.
template <class F>
void forEachRowIn(const IndexBox& box, const IndexBox& region, F&& f)
{
    if (box.empty())
    {
        return;
    }
    IndexBox local;
    for (int d = 0; d < 3; ++d)
    {
        local.lo[d] = box.lo[d] - region.lo[d];
        local.hi[d] = box.hi[d] - region.lo[d];
    }
    forEachRow(local, region.extents(), std::forward<F>(f));
}

struct GridSpec
{
    // Largest node count validate() accepts (flat indices are std::size_t; beyond this
    // a grid is a configuration error, e.g. a spacing typo).
    static constexpr double maxNodes = 1e10;

    Eigen::Vector3d lower{0.0, 0.0, 0.0};
    Eigen::Vector3d upper{1.0, 1.0, 1.0};
    std::array<int, 3> nodes{{2, 2, 2}};

    // Throws std::invalid_argument naming the offending entry: nodes < 1, all directions
    // flat, upper <= lower (a flat direction needs a positive thickness too), non-finite,
    // more than maxNodes nodes.
    void validate() const;

    bool flat(int d) const { return nodes[d] == 1; }
    // Number of directions with more than one node (2 for a 2D grid).
    int activeDimensions() const;
    // Node spacing; for a flat direction the thickness upper - lower.
    double spacing(int d) const;
    // h_x h_y h_z with the thickness for flat directions: the volume of eq. 26 of an
    // interior node (a whole cell).
    double nodeVolume() const;
    // Active directions in which node (i, j, k) lies on a face of the box (index 0 or
    // nodes - 1): 0 interior, 1 face, 2 edge, 3 corner.
    int boundaryDirections(int i, int j, int k) const;
    // The node's dual-cell volume: nodeVolume() / 2^boundaryDirections(i, j, k).
    double dualVolume(int i, int j, int k) const;
    // The node that lattice index `index` (any integer; the lattice lower[d] + index h[d]
    // extends beyond the box) maps to when the lattice is folded onto the box by mirroring
    // at its faces, repeatedly (period 2 (nodes - 1)): -1 -> 1, nodes -> nodes - 2, ...
    // Flat directions: 0. Inline: called per lattice index of every folded kernel box.
    int mirrorIndex(int d, int index) const
    {
        if (flat(d))
        {
            return 0;
        }
        const int last = nodes[d] - 1;
        const int period = 2 * last;
        int folded = index % period;
        folded += folded < 0 ? period : 0;
        return folded > last ? period - folded : folded;
    }
    std::size_t nodeCount() const;
    IndexBox fullBox() const;

    double nodeCoordinate(int d, int index) const;
    Eigen::Vector3d nodePosition(int i, int j, int k) const;
    std::size_t flatIndex(int i, int j, int k) const { return flatNodeIndex(nodes, i, j, k); }
    // Closed box test; flat directions included (the slab of the 2D case).
    bool contains(const Eigen::Vector3d& point) const;
};

// Whether two grids are the same lattice (box and node counts), e.g. to rebuild what was
// derived from one when a run's grid changes.
bool sameLattice(const GridSpec& a, const GridSpec& b);

} // namespace dropletFiber
