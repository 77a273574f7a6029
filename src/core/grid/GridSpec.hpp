// GridSpec: geometry of the regular density grid of MODEL.md sec. 4 (nodes, spacing,
// node volume), and IndexBox, an inclusive box of node indices.
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
// Every node gets the full volume h_x h_y [h_z] of eq. 26, also nodes on the edge of
// the box (see DensityGrid.hpp on what that means for edge nodes).
//
// Flat node index: i + nx * (j + ny * k) (i fastest).
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>

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
    bool operator==(const IndexBox& other) const { return lo == other.lo && hi == other.hi; }
    bool operator!=(const IndexBox& other) const { return !(*this == other); }
};

struct GridSpec
{
    Eigen::Vector3d lower{0.0, 0.0, 0.0};
    Eigen::Vector3d upper{1.0, 1.0, 1.0};
    std::array<int, 3> nodes{{2, 2, 2}};

    // Throws std::invalid_argument naming the offending entry: nodes < 1, all directions
    // flat, upper <= lower (a flat direction needs a positive thickness too), non-finite.
    void validate() const;

    bool flat(int d) const { return nodes[d] == 1; }
    // Number of directions with more than one node (2 for a 2D grid).
    int activeDimensions() const;
    // Node spacing; for a flat direction the thickness upper - lower.
    double spacing(int d) const;
    // h_x h_y h_z with the thickness for flat directions: the volume of eq. 26.
    double nodeVolume() const;
    std::size_t nodeCount() const;
    IndexBox fullBox() const;

    double nodeCoordinate(int d, int index) const;
    Eigen::Vector3d nodePosition(int i, int j, int k) const;
    std::size_t flatIndex(int i, int j, int k) const
    {
        return static_cast<std::size_t>(i)
            + static_cast<std::size_t>(nodes[0])
                * (static_cast<std::size_t>(j) + static_cast<std::size_t>(nodes[1]) * static_cast<std::size_t>(k));
    }
    // Closed box test; flat directions included (the slab of the 2D case).
    bool contains(const Eigen::Vector3d& point) const;
};

} // namespace dropletFiber
