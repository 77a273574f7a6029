// SeparableWeight: the path-integrated weights omega_g (eq. 23) of all nodes of a parcel's
// lattice box at a few operations per node, for wide kernels (reach of several node
// spacings: parcels of hundreds to thousands of droplets; docs/model.md sec. 4, P12).
//
// Method: the Gaussian of eq. 12 / P9 factorises per axis,
//     exp(-gamma |g - c|^2) = prod_d exp(-gamma (g_d - c_d)^2),
// so for a point c one table of exponentials per axis gives every node's value with two
// multiplications. The path average of eq. 23 is taken with the Q-point Gauss-Legendre
// rule in the path parameter tau (points c_q = start + tau_q displacement, weights W_q):
//     omega_g ~ sum_q W_q prod_d exp(-gamma (g_d - c_q,d)^2) - exp(-gamma reach^2),
// Q tables per axis, per node Q multiply-adds, a stationary parcel Q = 1 at the path's
// midpoint (as PathWeight takes it). The nodes kept are PathWeight's: distance from the path
// line (stationary: from the point) below PathWeight::cutoffSquared(); the rest get 0.
//
// Error per node against eq. 23, in units of the kernel's peak (phi <= 1):
//  - quadrature: with k = sqrt(gamma) L (L the path length),
//        B(Q, k) = 1.0865 k^(2Q) sqrt(4^Q (2Q)!) (Q!)^4 / ((2Q + 1) ((2Q)!)^3),
//    from the Gauss-Legendre remainder L^(2Q) (Q!)^4 / ((2Q + 1) ((2Q)!)^3) max |f^(2Q)|
//    for the path average, and |d^m/dx^m exp(-x^2)| <= 1.0865 sqrt(2^m m!) (Cramer's bound on
//    the Hermite functions), x = sqrt(gamma) lambda;
//  - truncation: the exact integrand is 0 where the path leaves the reach, this one
//    exp(-gamma d^2) - exp(-gamma reach^2), which lies in [-exp(-gamma reach^2), 0] there:
//    at most E = exp(-gamma reach^2);
//  - rounding: relative, below relativeRounding of (omega + E).
// chooseQuadrature turns these into a bound on the normalised weights (eq. 24) and picks Q.
#pragma once

#include "grid/PathWeight.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

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

    // B(Q, k): the quadrature's error per node (above) for Q points and k = sqrt(gamma) L.
    static double quadratureBound(int points, double k);

    // The fewest Gauss-Legendre points Q for which the normalised weights of a parcel agree
    // with eqs. 23-24 to `tolerance` of its largest weight; 0 when no Q <= maximumPoints
    // does (the caller uses the exact code). k = sqrt(gamma) L; edgeValue = E;
    // largestWeightBound: a lower bound of the parcel's largest omega (DensityGrid:
    // phi(c + L/2)); boxNodes: the lattice nodes evaluated (N). With per-node errors at most
    // a = B + E and rounding rho (omega + E), the weights w = omega / sum omega differ by
    // at most ((N + 1) (a + rho E) / P + 2 rho) times the largest (docs/model.md, P12).
    static int chooseQuadrature(double k, double edgeValue, double largestWeightBound, std::size_t boxNodes);

    // omega of every lattice node of the box [lo, hi] (i fastest) of a grid with node
    // coordinates x[i], y[j], z[k], for the parcel of `path` that moves from `start` by
    // `displacement` (the same as path's), with `points` Gauss-Legendre points (>= 1;
    // chooseQuadrature). Values >= 0; valid until the next call.
    const double* boxOmegas(const PathWeight& path, const Eigen::Vector3d& start,
                            const Eigen::Vector3d& displacement, int points, const double* x, const double* y,
                            const double* z, const std::array<int, 3>& lo, const std::array<int, 3>& hi);

private:
    // Per axis: node offsets p(i) from the path's start (stationary: from its midpoint)
    // and the Gaussian factors exp(-gamma (x_i - c_q)^2), q-major.
    void axisTables(int d, const double* coordinate, int lo, int hi, const PathWeight& path,
                    const Eigen::Vector3d& start, const Eigen::Vector3d& displacement, int points);
    // One row (j, k) of the box: omegas of its nodes.
    void rowOmegas(int j, int k, int points, const PathWeight& path, double* omega);

    std::array<std::vector<double>, 3> offset_;
    std::array<std::vector<double>, 3> factor_;
    std::array<double, maximumPoints> tau_{};    // Gauss-Legendre points in [0, 1]
    std::array<double, maximumPoints> weight_{}; // their weights, summing to 1
    std::array<double, maximumPoints> rowFactor_{};
    Eigen::Vector3d direction_{0.0, 0.0, 0.0}; // unit vector along the path (0: stationary)
    std::vector<double> rowSum_;
    std::vector<double> omega_;
};

} // namespace dropletFiber
