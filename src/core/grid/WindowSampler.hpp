// WindowSampler: the droplet fields read from the averaging window (docs/model.md sec. 4,
// eq. 26, between nodes; sec. 5, what the collision reads): at a node, interpolated at a
// point, and the parts of a point's interpolation that the blocks owning its cell corners
// each hold (parallel runs).
//
// At a node with window sums S_q over s steps (s = min(committed, W)) and node volume V
// (the dual cell, GridSpec::dualVolume):
//     rho = S_mass / (V s),  number density = S_count / (V s),
//     rMeanNumber = S_countRadius / S_count (eq. 10),  rMeanMass = S_massRadius / S_mass,
//     velocity = S_momentum / S_mass (mass-weighted mean droplet velocity).
// Empty nodes give zeros. sample(point) interpolates the densities S_q / V multilinearly
// and then forms the same ratios: rho and the momentum density are exactly
// bilinear/trilinear between nodes, and the means are not dragged to zero by empty
// neighbours. Points outside the box (in active directions) give inside = false and zeros.
// Node volumes are those of the dual cells (half a cell on a face of the box, a quarter on
// an edge, an eighth at a corner; active directions only): with the folded kernels a
// uniform spray filling the box reads its density at every node (EdgeNodesTest).
//
// A block owns part of the nodes (the window's region): windowTotal() answers for an
// owned node, addOwnedCornerSums() gives a block's share of sample()'s sums at a point,
// and the shares of the blocks owning its corners add up to them.
#pragma once

#include "grid/AveragingWindow.hpp"
#include "grid/GridQuantities.hpp"
#include "grid/GridSpec.hpp"
#include "grid/MultilinearWeights.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace dropletFiber
{

// Droplet field at a node or interpolated at a point.
struct DropletFieldValue
{
    bool inside = true;                      // false: point outside the grid box, all zeros
    double rho = 0.0;                        // droplet mass per volume of space, kg/m^3
    double numberDensity = 0.0;              // droplets per volume, 1/m^3
    double rMeanNumber = 0.0;                // number-weighted mean droplet radius (eq. 10), m
    double rMeanMass = 0.0;                  // mass-weighted mean droplet radius, m
    Eigen::Vector3d velocity{0.0, 0.0, 0.0}; // mass-weighted mean droplet velocity, m/s
};

// Window sums of the seven quantities (GridQuantities.hpp).
using QuantitySums = std::array<double, nQuantities>;

class WindowSampler
{
public:
    // owned: the nodes whose window the block holds (grid indices).
    WindowSampler(const GridSpec& spec, const IndexBox& owned);

    bool owns(std::size_t node) const;
    // The window sums S_q of an owned node (global flat index), nQuantities values;
    // throws std::out_of_range for a node owned elsewhere.
    void windowTotal(const AveragingWindow& window, std::size_t node, double* sums) const;
    // Quantity q of the newest committed step at an owned node.
    double lastStepValue(const AveragingWindow& window, std::size_t node, int q) const;
    // Fields at an owned node, from the window or from the node's window sums.
    DropletFieldValue nodeValue(const AveragingWindow& window, std::size_t node) const;
    DropletFieldValue nodeValueFromTotals(const AveragingWindow& window, std::size_t node,
                                          const double* sums) const;
    // The field at a point whose cell corners are owned here.
    DropletFieldValue sample(const AveragingWindow& window, const Eigen::Vector3d& point) const;
    // Per owned corner: weight x window sums per whole cell, added to sums in corner order.
    void addOwnedCornerSums(const AveragingWindow& window, const CornerWeights& corners,
                            QuantitySums& sums) const;
    // Requests the memory addOwnedCornerSums will read (AveragingWindow::prefetchNodeTotal).
    void prefetchOwnedCornerSums(const AveragingWindow& window, const CornerWeights& corners) const;
    // Window sums per whole cell volume (any weights) -> field values.
    DropletFieldValue fieldFromSums(const AveragingWindow& window, const QuantitySums& sums) const;
    // sample()'s value from the corners' window sums (corner c's at cornerTotals + c nQuantities).
    DropletFieldValue interpolated(const AveragingWindow& window, const CornerWeights& corners,
                                   const double* cornerTotals) const;
    // Each corner's part of the interpolated mass sum (into parts[c]); returns their sum.
    double densityParts(const CornerWeights& corners, const double* cornerTotals, double* parts) const;
    // Window mass per step on the owned nodes (kg).
    double windowMassPerStep(const AveragingWindow& window) const;

private:
    // Whole cells per dual-cell volume of the node: 1 inside, 2 on a face, 4 on an edge,
    // 8 at a corner (GridSpec::dualVolume).
    double cellsPerNodeVolume(std::size_t node) const;
    // Corner c's share of sample()'s sums: weight x window sums per whole cell.
    void addCornerSum(const CornerWeights& corners, int c, const double* total, QuantitySums& sums) const;
    // The window's index of an owned node; throws std::out_of_range otherwise.
    std::size_t windowIndex(std::size_t node) const;

    GridSpec spec_;
    IndexBox owned_;
    bool ownsWholeGrid_; // flat node index = window index
    double nodeVolume_;  // of an interior node (whole cell)
};

} // namespace dropletFiber
