// SpreadPopulations: the N - 1 physical fibers a weighted computed fiber stands for, spread
// around it and acting on the spray as what they are (docs/model.md sec. 12, P49-P54).
//
// Per step, on the levels of the coupling grid (SpreadLevel: spacing H = r h):
//  1. Count (P52). Every computed fiber's length and number at its centre, on every level's
//     nodes with multilinear weights (addLength): the computed fibers' length and number
//     per volume, lambda_C and n_C, each computed fiber once whatever its weight.
//  2. Level (P52, P53). A weighted fiber's population takes the finest level on which it
//     is thin, (N - 1) c / (4 H) <= maxClustering (P55), or on which pi sigma^2 lambda^ +
//     4/3 pi sigma^3 n^ >= k (`neighbours`; sigma = H / sqrt(3); the second term in 3D
//     only), lambda^ and n^ the counts interpolated at the fiber's centre less the fiber's
//     own (choose): its kernel reaches k other computed fibers (the fibers a ball of radius
//     sigma meets). Neither: the coarsest level, marked capped.
//  3. Demand (P50, P53, P54). A collision sample s of swept volume kappa_s (eq. 9's mass
//     over the density it read) stands for N - 1 spread fibers: on its level's nodes C,
//     share_C += (N - 1) kappa_s w_sC and depth_C += that times (1 + sigma~_sC), sigma~ the
//     self-shadow of a strip (N + 1) q_d on the level (P54; SelfShadow.hpp). A grid node n
//     then holds the populations' swept fraction and depth
//         P_n = sum_C hat_C(g_n) share_C / V_C,   P'_n = sum_C hat_C(g_n) depth_C / V_C
//     (prolongOnto): its demand grows by s_n P_n and its depth by P'_n (CaptureLimit::addSpread)
//     and the parcels cross the grid's depths as before (P14).
//  4. Grant (P51). With the grid's grants g_n, a level node's grant G_C = sum_n hat_C(g_n)
//     s_n g_n (restrictFrom over CaptureLimit::grantedSupplies) and the sample's
//     population captures (N - 1) kappa_s sum_C w_sC G_C / V_C (readLevel): over all
//     samples, sum_n g_n s_n P_n, the populations' part of sum_n g_n d_n = sum_n R_n.
//
// Every table is keyed by level node (LevelTable), so that in a parallel run the parts of
// a level node from several processors add up at one owner; each step here is local to
// the keys and grid nodes it is given.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/LevelTable.hpp"
#include "grid/MultilinearWeights.hpp"
#include "grid/SpreadLevel.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace dropletFiber
{

// The level a population takes (choose), and why there.
struct LevelChoice
{
    enum class Why
    {
        thin,    // its clustering eps is small enough on this level (P55)
        reached, // its kernel reaches `neighbours` other computed fibers (P52)
        capped   // neither on any level: the coarsest allowed
    };
    int level = 0;
    double reach = 0.0; // the other computed fibers its kernel reaches (reachOn)
    double eps = 0.0;   // its clustering on the level, (N - 1) c / (4 H)
    Why why = Why::thin;
};

class SpreadPopulations
{
public:
    // Levels of ratio 1, 2, 3, 4, 6, ... up to maxRatio (defaultMaxRatio when 0); neighbours
    // k > 0; maxClustering >= 0, the clustering eps a population may keep on its level.
    // Throws std::invalid_argument.
    SpreadPopulations(const GridSpec& grid, double neighbours, int maxRatio = 0, double maxClustering = 0.05);

    // The ratio whose spacing first reaches half the box's largest active extent.
    static int defaultMaxRatio(const GridSpec& grid);
    // The grid's largest spacing over its active directions.
    static double largestSpacing(const GridSpec& grid);
    // H of level l: its largest spacing over the active directions (the kernel's scale).
    double levelSpacing(int l) const { return level(l).ratio() * largestSpacing(grid_); }

    int levelCount() const { return static_cast<int>(levels_.size()); }
    const SpreadLevel& level(int l) const { return levels_[static_cast<std::size_t>(l)]; }
    double neighbours() const { return neighbours_; }
    const GridSpec& grid() const { return grid_; }

    // --- 1. count -------------------------------------------------------------------------
    // A computed fiber of `length` with its centre at `centre`, on every level (width 2:
    // length, number).
    void addLength(const Eigen::Vector3d& centre, double length, LevelTerms& count) const;

    // --- 2. level -------------------------------------------------------------------------
    // The finest level on which the population is thin, (N - 1) c / (4 H) <= maxClustering
    // (its clustering loss P55 is small: no need to spread it wider and blur the veil), or
    // its kernel reaches k other computed fibers at the fiber's centre (no holes between
    // populations); opacity = (N - 1) c / 4 [m], c the fiber's strip 2 (r_F + <r>). count:
    // the summed table of every computed fiber's addLength, its own included.
    LevelChoice choose(const Eigen::Vector3d& centre, double ownLength, const LevelTable& count,
                       double opacity) const;
    // The other computed fibers the kernel of level l reaches at the centre: pi sigma^2
    // lambda^ + 4/3 pi sigma^3 n^ (ownLength 0: a point that is no fiber, nothing taken out).
    double reachOn(int l, const Eigen::Vector3d& centre, double ownLength, const LevelTable& count) const;

    // --- 3. demand ------------------------------------------------------------------------
    // A sample of N = fibers physical fibers on `level`: volume = (N - 1) kappa_s (m^3),
    // strip = the computed fiber's q_d (stripAcrossFlow; zero: no shadow). Terms of width 2
    // (share, depth).
    void addDemand(const Eigen::Vector3d& point, int level, double volume, const Eigen::Vector3d& strip,
                   double fibers, LevelTerms& demand) const;
    // amount w_C on the level's nodes at the point (width 1): e.g. the realised hits'
    // r_s (N - 1) kappa_s of a sample.
    void addAtLevel(const Eigen::Vector3d& point, int level, double amount, LevelTerms& terms) const;
    // The grid nodes the table's level nodes reach (grid indices; empty: none).
    IndexBox reach(const LevelTable& table) const;
    // P_n (and P'_n for a table of width 2) of the nodes of `region` (grid indices), dense
    // over it in flatIndexInBox order (resized and zeroed; depth left empty for width 1).
    void prolongOnto(const LevelTable& table, const IndexBox& region, std::vector<double>& share,
                     std::vector<double>& depth) const;

    // --- 4. grant -------------------------------------------------------------------------
    // Per key of `keys`: sum over the nodes of `region` (grid indices) of its hat x values
    // (dense over the region, flatIndexInBox order; width 1).
    LevelTable restrictFrom(const LevelTable& keys, const IndexBox& region,
                            const std::vector<double>& values) const;
    // sum_C w_C table_C[column] / V_C at the point on `level`: a level field read per volume.
    double readLevel(const Eigen::Vector3d& point, int level, const LevelTable& table, int column = 0) const;

private:
    GridSpec grid_;
    double neighbours_;
    double maxClustering_;
    std::vector<SpreadLevel> levels_;
};

} // namespace dropletFiber
