// SeparableWeight: the path-integrated weights omega_g (eq. 23) of all nodes of a parcel's
// lattice box at a few operations per node, for wide kernels (reach of several node
// spacings: parcels of hundreds to thousands of droplets; docs/model.md sec. 4, P16).
//
// Method: the Gaussian of eq. 12 / P9 factorises per axis,
//     exp(-gamma |g - c|^2) = prod_d exp(-gamma (g_d - c_d)^2),
// so for a point c one table of exponentials per axis gives every node's value with two
// multiplications. The path average of eq. 23 is taken with the Q-point Gauss-Legendre
// rule in the path parameter tau (points c_q = start + tau_q displacement, weights W_q):
//     omega_g ~ sum_q W_q X_q(i) Y_q(j) Z_q(k),   X_q(i) = exp(-gamma (x_i - c_q,x)^2), ...
// Q tables per axis, per node Q multiply-adds (a stationary parcel: Q = 1 at the path's
// midpoint, as PathWeight takes it); the normalising sum of eq. 24 from the per-axis sums
// of the tables (sum()), so a caller can weigh any part of the box, row by row, without
// visiting the rest. The constant exp(-gamma reach^2) of eq. 12 and the
// truncation at the reach are left out (bounded below), so omega is a sum of products of
// per-axis factors, and so is its folded form: ghost nodes beyond the faces fold onto their
// mirror images axis by axis (GridSpec::mirrorIndex), i.e. the tables are folded, and the
// folded box (at most the grid) is evaluated instead of the lattice box (up to 3^D times
// the grid for kernels wider than it).
//
// Error per lattice node against eq. 23, in units of the kernel's peak (phi <= 1):
//  - quadrature: with k = sqrt(gamma) L (L the path length),
//        B(Q, k) = 1.0865 k^(2Q) sqrt(4^Q (2Q)!) (Q!)^4 / ((2Q + 1) ((2Q)!)^3),
//    the Gauss-Legendre remainder L^(2Q) (Q!)^4 / ((2Q + 1) ((2Q)!)^3) max |f^(2Q)| of the
//    path average, with |d^m/dx^m exp(-x^2)| <= 1.0865 sqrt(2^m m!) (Cramer's bound on the
//    Hermite functions), x = sqrt(gamma) lambda;
//  - truncation and constant: |exp(-gamma d^2) - phi(d)| <= E = exp(-gamma reach^2) for
//    every d (inside the reach phi = exp(-gamma d^2) - E; beyond it exp(-gamma d^2) < E);
//  - nodes left out: the caller keeps nodes with omega above a threshold t (the
//    negligible-weight cut: t = negligibleWeight times a lower bound of the largest weight,
//    the weight at the cut distance of P10), and the exact code drops nodes farther than
//    the cut from the path, whose weights are below that too: at most t;
//  - rounding: relative, below relativeRounding of (omega + E); besides, the exponents'
//    arguments gamma (x - c)^2, rounded to ~3 ulp, add up to 3 u X exp(-X) <= 1.2e-16 of the
//    peak per node (X = gamma (x - c)^2; docs/model.md P16), counted as argumentRounding.
// chooseQuadrature turns these into a bound on the normalised weights (eq. 24) and picks Q.
//
// On CPUs with AVX2 + FMA (vectorised, the default) the tables' exponentials and the rows'
// multiply-adds run four nodes per instruction (SeparableLanes): the same formulas with FMA
// and the inline exp of BranchFreeExp.hpp (within 1.01 ulp), values within ~1e-16 relative
// of the portable loops', inside the rounding allowance relativeRounding (docs/model.md P16).
#pragma once

#include "grid/PathWeight.hpp"
#include "grid/SeparableLanes.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

// The tables omega() reads, wherever they are held: SeparableWeight's own, or a compact
// copy of them (KeptTables: the deposit's tables kept for the removal). factor[d] holds
// length[d] values per point q, q-major; weight the points' W_q; lanes: fused multiply-adds
// as SeparableWeight::vectorised().
struct SeparableTables
{
    int points = 0;
    bool lanes = false;
    std::array<std::size_t, 3> length{};
    const double* weight = nullptr;
    std::array<const double*, 3> factor{};

    // omega of the node (i, j, k) of the (folded) box: SeparableWeight::omega's arithmetic.
    double omega(int i, int j, int k) const;
    // The tables of a compact copy (SeparableWeight::copyTables) at `values`, with the points,
    // lanes and lengths of the tables() it was copied from.
    static SeparableTables inCompactCopy(const double* values, int points, bool lanes,
                                         const std::array<std::size_t, 3>& length);
};

class SeparableWeight
{
public:
    // Most Gauss-Legendre points tried; a parcel that needs more goes to the exact code.
    static constexpr int maximumPoints = 12;
    // Bound on |w_fast - w_exact| per node, relative to the parcel's largest node weight
    // (after eq. 24), that chooseQuadrature guarantees.
    static constexpr double tolerance = 1e-7;
    // Rounding of the per-node products and sums, relative to omega + E (a few ulp of up to
    // Q + 3 operations, with margin).
    static constexpr double relativeRounding = 1e-14;
    // The exponents' arguments X = gamma (x - c)^2, rounded to ~3 ulp, change a node's omega
    // by at most 3 u X exp(-X) <= 3 u / e = 1.23e-16 of the kernel's peak (absolute, not
    // covered by relativeRounding where X > ~30): rounded up, per node.
    static constexpr double argumentRounding = 1.3e-16;

    // vectorised: the per-node loops in AVX2 + FMA (SeparableLanes) where the build and CPU
    // have them (KernelSettings::vectorised, as DensityGrid::batchedKernel); false: the
    // portable loops, the same results on every CPU.
    explicit SeparableWeight(bool vectorised = true);
    // True when the AVX2 + FMA loops are in use.
    bool vectorised() const { return lanes_; }

    // B(Q, k): the quadrature's error per node (above) for Q points and k = sqrt(gamma) L.
    static double quadratureBound(int points, double k);

    // The fewest Gauss-Legendre points Q for which the normalised weights of a parcel agree
    // with eqs. 23-24 to `tolerance` of its largest weight; 0 when no Q <= maximumPoints
    // does (the caller uses the exact code). k = sqrt(gamma) L; edgeValue = E; threshold: t
    // (above); largestWeightBound P: a lower bound of the parcel's largest omega
    // (DensityGrid: phi(c + L/2)); boxNodes N: the lattice nodes evaluated. With per-node
    // errors at most a = B + E + argumentRounding + t and rounding rho (omega + E), a folded node collecting m
    // <= N lattice nodes, the weights w = omega / sum omega differ by at most
    // ((2 N + 1) (a + rho E) / P + 2 rho) times the largest (docs/model.md, P16).
    static int chooseQuadrature(double k, double edgeValue, double threshold, double largestWeightBound,
                                std::size_t boxNodes);

    // Per-axis tables for the lattice box [lo, hi] of a grid with lattice coordinates
    // coordinates[d][i], for the parcel of `path` that moves from `start` by `displacement`
    // (the same as path's), with `points` Gauss-Legendre points (>= 1; chooseQuadrature).
    void prepare(const PathWeight& path, const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
                 int points, const std::array<const double*, 3>& coordinates, const std::array<int, 3>& lo,
                 const std::array<int, 3>& hi);
    // Folds the tables onto the nodes: image[d][i - lo[d]] is the node index of lattice
    // index i (GridSpec::mirrorIndex), folded.lo/hi the range of those (DensityGrid::mirrorBox).
    void fold(const std::array<std::vector<int>, 3>& image, const std::array<int, 3>& foldedLo,
              const std::array<int, 3>& foldedHi);
    // omega of the nodes of row (j, k) of the (folded) box, positions relative to its lower
    // corner, i fastest: the row's length values, valid until the next call.
    const double* row(int j, int k);
    // The same for the `count` nodes from position `first` of the row on (a block's stored
    // part of it): the same values, to the bit, as those positions of row(j, k).
    const double* row(int j, int k, std::size_t first, std::size_t count);
    // For every row of the part [lo, hi] of the (folded) box (positions relative to its
    // lower corner), in one call (SeparableLanes::addRows): omega inverseSum totals[q] added
    // to the 7 values of each node, the same to the bit as row() then
    // SeparableLanes::addWeightedRow give, omega never stored. `to`: where the rows' values
    // lie (values, strides, prefetch; the tables' fields are set here). Only where
    // vectorised() (std::logic_error otherwise); std::out_of_range beyond the box.
    void addRowsInLanes(const std::array<int, 3>& lo, const std::array<int, 3>& hi, double inverseSum,
                        const double* totals, SeparableLanes::BoxRows to);
    // omega of the one node (i, j, k) of the (folded) box, positions relative to its lower
    // corner: row()'s arithmetic in row()'s order, so the same value to the bit, at Q
    // multiply-adds (depletion's sums over a few nodes, DensityGrid::depositedShare).
    double omega(int i, int j, int k) const { return tables().omega(i, j, k); }
    // The present tables (valid until the next prepare() or fold()).
    SeparableTables tables() const;
    // Doubles a compact copy of the tables takes: W_q and every axis's factors.
    std::size_t tableValues() const;
    // Copies them to `to` (tableValues() doubles): W_q, then the x, y and z factors, q-major.
    void copyTables(double* to) const;
    // sum omega over the nodes of the (folded) box, eq. 24's normalising sum, itself
    // separable: sum_q W_q (sum_i X_q(i)) (sum_j Y_q(j)) (sum_k Z_q(k)), O(Q (nx + ny + nz))
    // instead of one addition per node. The per-axis sums are compensated (Neumaier), so the
    // result is within (Q + 8) ulp, relative, of the exact sum of the table products; the
    // rows' omegas are within (Q + 2) ulp of theirs (all terms positive): the weights
    // omega / sum sum to 1 within (2 Q + 12) ulp (docs/model.md P16).
    double sum() const;

private:
    // The Gaussian factors of one axis, q-major: exp(-gamma (x_i - c_q,d)^2).
    void axisTable(int d, const double* coordinate, int lo, int hi, double gamma,
                   const Eigen::Vector3d& start, const Eigen::Vector3d& displacement);
    // The row's working memory and pointMajor_ for the present tables, once per prepare() (or
    // fold()), at the first row(): not twice for a folded kernel.
    void prepareRows();
    // sum() from the per-axis sums in lanes (SeparableLanes::compensatedSums): the same value.
    double sumInLanes() const;
    // rowFactor_ of row (j, k) (std::out_of_range beyond the box), the rows prepared.
    void setRowFactors(int j, int k, std::size_t first, std::size_t count);

    bool lanes_; // vectorised()
    int points_ = 0;
    std::array<std::size_t, 3> length_{};        // table length per axis
    std::array<std::vector<double>, 3> factor_;  // per axis, q-major
    std::array<std::vector<double>, 3> folded_;  // folding's working copy
    std::array<double, maximumPoints> tau_{};    // Gauss-Legendre points in [0, 1]
    std::array<double, maximumPoints> weight_{}; // their weights, summing to 1
    // The y and z tables point-major (index i of axis d at [i Q + q]), so that a row's Q
    // factors W_q Y_q(j) Z_q(k) are read contiguously (per row, not per node); y times W_q.
    std::array<std::vector<double>, 2> pointMajor_;
    bool rowsPrepared_ = false;
    std::array<double, maximumPoints> rowFactor_{};
    std::vector<double> rowOmega_;
};

} // namespace dropletFiber
