// SpreadLevel: a coarser lattice of the coupling grid's box, spacing H = r h, on which the
// population of a weighted fiber is spread (docs/model.md sec. 12, P53): a fiber whose
// physical fibers spread over sigma = H / sqrt(3) is, on its level, a fiber on a grid of its
// own width, with 2^d multilinear weights instead of the (6 sigma / h + 2)^d nodes its
// kernel would reach on the grid.
//
// The level's nodes sit at lower + C H per active direction, C = 0 .. ceil((n - 1) / r):
// where r does not divide the grid's n - 1 cells the last node lies beyond the upper face,
// and its hat is cut at the box (only the grid's nodes count, below). A flat direction of
// the grid (one node) is flat on every level. Ratio 1 is the grid itself.
//
// The hat of level node C, read at the grid's node n: per active direction
// max(0, 1 - |i_n - r C| / r). Over the level's nodes the hats sum to 1 at every grid node
// (a partition of unity), so that
//   restrict(q)_C = sum_n hat_C(g_n) q_n   (an extensive field: masses, volumes)
// conserves the total, and
//   prolong(x)_n = sum_C hat_C(g_n) x_C    (a field of the level read on the grid)
// is its adjoint: sum_C restrict(q)_C x_C = sum_n q_n prolong(x)_n, the identity by which
// P51's grants on a level add up to what the parcels lost. The level's node volume is
// V_C = restrict(V)_C, the grid's dual volumes restricted (they sum to the box's volume).
//
// A point's multilinear weights on the level (weightsAt) are its grid weights restricted,
// to round-off: the level's hats are linear between the grid's nodes, which the level's
// nodes are among, so interpolating them on the grid is exact (P53: a cloud-in-cell
// parcel's level weights are its own multilinear weights on the level). Halving h maps
// level (h, r) onto level (h / 2, 2 r): the same lattice, the same weights.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/MultilinearWeights.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

// The level ratios r = 1, 2, 3, 4, 6, 8, 12, 16, ... (2^j and 3 2^j: steps of 2, then 1.5
// and 4/3) up to maxRatio. Throws std::invalid_argument for maxRatio < 1.
std::vector<int> spreadLevelRatios(int maxRatio);

class SpreadLevel
{
public:
    // Level of ratio r >= 1 of the grid `grid` (validated); throws std::invalid_argument.
    SpreadLevel(const GridSpec& grid, int ratio);

    int ratio() const { return ratio_; }
    // The level as a lattice: its nodes per direction, lower the grid's, upper at its last
    // node (beyond the grid's box where r does not divide it); flat directions the grid's.
    const GridSpec& spec() const { return level_; }
    const GridSpec& grid() const { return grid_; }

    // The hat of the level's node `coarse` at the grid's node `fine` along direction d
    // (1 in a flat direction).
    double hat(int d, int coarse, int fine) const;

    // V_C: the grid's dual volumes restricted, one per level node (flat index of spec()).
    std::vector<double> volumes() const;
    // V_C of one level node (flat index of spec()): separable, a product of the directions'
    // restricted dual widths (no grid-sized array is held).
    double volume(std::size_t levelNode) const;

    // The grid nodes (grid indices) that the hat of level node `levelNode` reaches.
    IndexBox hatBox(std::size_t levelNode) const;
    // Calls f(index in `region`'s flat order, hat) for the nodes of the hat of level node
    // `levelNode` inside `region` (grid indices), row by row: the hats per direction are
    // evaluated once (separable), the region's values touched in memory order.
    template <class F>
    void forEachFineNodeIn(std::size_t levelNode, const IndexBox& region, F&& f) const;

    // restrict(q)_C = sum_n hat_C(g_n) q_n of a field on the grid's nodes (flat indices of
    // grid()): the total is kept.
    std::vector<double> restrict(const std::vector<double>& fine) const;

    // prolong(x)_n = sum_C hat_C(g_n) x_C of a field on the level's nodes: its multilinear
    // interpolant on the grid's nodes (restrict's adjoint).
    std::vector<double> prolong(const std::vector<double>& coarse) const;

    // The multilinear weights of a point on the level (the corners of its level cell).
    CornerWeights weightsAt(const Eigen::Vector3d& point) const;

private:
    // The level nodes whose hats reach grid index `fine` along d (1 or 2) and their hats.
    struct AxisShare
    {
        int count = 1;
        std::array<int, 2> coarse{{0, 0}};
        std::array<double, 2> hat{{1.0, 0.0}};
    };
    AxisShare share(int d, int fine) const;

    // Calls f(fine node flat index, level node flat index, hat) for every pair with a
    // non-zero hat, the grid's nodes in flat order.
    template <class F>
    void forEachPair(F&& f) const;

    GridSpec grid_;
    GridSpec level_;
    int ratio_ = 1;
    // Per direction and level index: the grid's dual widths restricted (the thickness in a
    // flat direction)
    std::array<std::vector<double>, 3> axisVolume_;
};

template <class F>
void SpreadLevel::forEachFineNodeIn(std::size_t levelNode, const IndexBox& region, F&& f) const
{
    const IndexBox box = hatBox(levelNode).intersected(region);
    if (box.empty())
    {
        return;
    }
    const std::array<int, 3> coarse = nodeIndicesOfFlat(level_.nodes, levelNode);
    std::array<std::vector<double>, 3> hats;
    for (int d = 0; d < 3; ++d)
    {
        const auto u = static_cast<std::size_t>(d);
        for (int i = box.lo[u]; i <= box.hi[u]; ++i)
        {
            hats[u].push_back(hat(d, coarse[u], i));
        }
    }
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    {
        const double hk = hats[2][static_cast<std::size_t>(k - box.lo[2])];
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
        {
            const double hjk = hats[1][static_cast<std::size_t>(j - box.lo[1])] * hk;
            std::size_t at = flatIndexInBox(region, box.lo[0], j, k);
            for (std::size_t i = 0; i < hats[0].size(); ++i, ++at)
            {
                f(at, hats[0][i] * hjk);
            }
        }
    }
}

} // namespace dropletFiber
