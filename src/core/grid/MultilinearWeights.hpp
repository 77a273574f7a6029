// MultilinearWeights: bilinear (2D) / trilinear (3D) interpolation weights of a point on
// the grid (docs/model.md sec. 4, between nodes), also used as the mass-conserving fallback
// for a parcel whose kernel reaches no node (cloud-in-cell weights).
//
// Flat directions do not count: a 2D grid interpolates in its plane and ignores the
// point's coordinate across the layer. Points outside the box in an active direction are
// clamped to it (callers decide beforehand what outside means, see insideActiveBox).
#pragma once

#include "grid/GridSpec.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace dropletFiber
{

struct CornerWeights
{
    int count = 0;                     // 1, 2, 4 or 8 corners (2^active dimensions)
    std::array<std::size_t, 8> node{}; // flat node indices
    std::array<double, 8> weight{};    // sum to 1, all >= 0
    std::array<int, 3> lowerCorner{};  // index of the lowest corner per direction
};

CornerWeights multilinearWeights(const GridSpec& spec, const Eigen::Vector3d& point);

// Where a coordinate lies along one active direction of `nodes` nodes: the lower node of
// its cell and the fraction towards the next node, clamped to the box (the upper bound
// belongs to the last cell). Inline because the cloud-in-cell deposit calls it for every
// point of every path; multilinearWeights uses the same arithmetic, so both give the same
// weights to the bit. The cell is a non-decreasing function of the coordinate (every
// floating-point step here is), which DensityGrid relies on to bound a path's corners.
struct AxisCell
{
    int cell = 0;
    double fraction = 0.0;
};

inline AxisCell axisCell(double coordinate, double lower, double spacing, int nodes)
{
    const double t = (coordinate - lower) / spacing;
    const double clamped = std::min(std::max(t, 0.0), static_cast<double>(nodes - 1));
    const int cell = std::min(static_cast<int>(std::floor(clamped)), nodes - 2);
    return {cell, clamped - cell};
}

// Inside the box in every active direction, with a tolerance of `relativeTolerance` times
// the box size (so that points on the boundary that carry round-off still count).
bool insideActiveBox(const GridSpec& spec, const Eigen::Vector3d& point, double relativeTolerance = 1e-12);

} // namespace dropletFiber
