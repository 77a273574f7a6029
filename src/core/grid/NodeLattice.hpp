// NodeLattice: the unbounded lattice lower + i h on which the kernels are weighed
// (docs/model.md sec. 4, eqs. 23-24): the grid's nodes and the ghost nodes up to one grid
// length beyond each face, whose weights fold onto their mirror images across the face
// (folded kernels, GridSpec::mirrorIndex; docs/model.md sec. 4, edge nodes). Geometry
// only: the lattice's coordinates and spacings, the box of lattice nodes within reach of a
// path, and the folding of a box onto the grid's nodes.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/ParcelPath.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

// The mirror image (a grid index) of each lattice index of a box, per direction.
using MirrorImages = std::array<std::vector<int>, 3>;

class NodeLattice
{
public:
    explicit NodeLattice(const GridSpec& spec); // spec validated by the caller

    const GridSpec& spec() const { return spec_; }
    const std::array<int, 3>& nodes() const { return spec_.nodes; }
    // Coordinates of the lattice nodes in direction d, indexed by lattice index (node 0
    // at 0; ghost nodes from -(nodes - 1) to 2 (nodes - 1); flat directions: node 0 only).
    const double* coordinates(int d) const
    {
        return coordinates_[static_cast<std::size_t>(d)].data() + ghostLayers_[static_cast<std::size_t>(d)];
    }
    // Node spacing per direction, 0 in flat directions (cloud-in-cell's axisCell).
    const std::array<double, 3>& spacings() const { return spacing_; }
    // Over the active directions: the smallest spacing (cloud-in-cell path points), the
    // largest (KernelSettings::cloudInCellBelow, the widths in the deposit report) and the
    // half cell diagonal (the negligible-weight cut, P10).
    double smallestSpacing() const { return smallestSpacing_; }
    double largestSpacing() const { return largestSpacing_; }
    double halfCellDiagonal() const { return halfCellDiagonal_; }

    // The lattice nodes within `reach` of the path (may be empty), ghost nodes beyond the
    // faces included (at most one grid length beyond each face).
    IndexBox nodeBox(const ClippedPath& path, double reach) const;
    // True when the box holds no ghost node (the kernel stays inside the grid).
    bool withinGrid(const IndexBox& box) const;
    // True when the box holds a node on a face of the grid box (active directions).
    bool touchesFace(const IndexBox& box) const;
    // The nodes the lattice box's nodes fold onto (mirror images; the box itself when it
    // holds no ghost node), without listing them.
    IndexBox foldedBox(const IndexBox& box) const;
    // The mirror images of the box's lattice indices per direction (into images), and the
    // box of the nodes they name.
    IndexBox mirror(const IndexBox& box, MirrorImages& images) const;

private:
    GridSpec spec_;
    std::array<std::vector<double>, 3> coordinates_; // per direction, from the first ghost node
    std::array<int, 3> ghostLayers_{};               // ghost nodes beyond each face: nodes - 1 (flat: 0)
    std::array<double, 3> inverseSpacing_{};         // 0 in flat directions
    std::array<double, 3> spacing_{};
    double smallestSpacing_ = 0.0;
    double largestSpacing_ = 0.0;
    double halfCellDiagonal_ = 0.0;
};

} // namespace dropletFiber
