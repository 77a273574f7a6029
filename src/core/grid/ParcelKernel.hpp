// ParcelKernel: the truncated Gaussian by which one parcel spreads over the density grid
// (docs/model.md sec. 4, eqs. 11-18): range of influence r_max (eq. 13), packing radius r_min
// (eqs. 14-15, 2D or 3D), shape alpha (eq. 18) and phi(d) (eq. 12).
//
// Optional cap on the influence radius (KernelSettings::rMaxCap): r_max = r_p n grows
// linearly with the droplet count, so a parcel of 1e5 droplets would touch the whole
// grid. The cap only truncates the support at reach = min(r_max, cap) and keeps the
// Gaussian itself (its inflection point, eq. 17) unchanged:
//     phi(d) = exp(-gamma d^2) - exp(-gamma reach^2)   for d < reach,   gamma = alpha / r_max^2,
// which is eq. 12 when the cap does not bind. (Recomputing alpha from the capped radius
// would instead shrink the kernel's width and change the physics of eq. 17.)
#pragma once

namespace dropletFiber
{

// Which packing formula gives r_min (eq. 14 for 2D, eq. 15's 3D analogue).
enum class KernelDimension
{
    Automatic, // 3D on a grid with three non-flat directions, otherwise 2D
    TwoD,
    ThreeD
};

// How DensityGrid::deposit evaluates the node weights of eq. 23.
enum class DepositMethod
{
    Automatic, // wide kernels separably (SeparableWeight) where its error bound holds, else exact
    Exact      // always the per-node path integral (PathWeight, PathWeightBatch)
};

struct KernelSettings
{
    double beta = 0.025;  // eq. 17/18: inflection point between r_min (0) and r_max (1)
    double rMaxCap = 0.0; // cap on the influence radius in metres; <= 0: no cap
    KernelDimension dimension = KernelDimension::Automatic;
    // Parcels the grid cannot resolve: a parcel whose kernel width (the inflection point
    // of eq. 16, r_max / sqrt(2 alpha)) is below cloudInCellBelow times the largest node
    // spacing is deposited with cloud-in-cell (multilinear) weights along its path
    // instead of the kernel. 0: always the kernel (the paper). Why: eq. 24 normalises a
    // kernel much narrower than the spacing onto the one or two nearest nodes, which
    // moves the parcel's mass by up to half a cell (-6 % at 10 droplets per parcel in
    // the paper's setting); multilinear weights keep its centre of mass. 0.5 brings the
    // paper's constant-density experiments below 1 % at 100x100 (docs/validation.md).
    double cloudInCellBelow = 0.0;
    // Nodes whose weight from a parcel would be below negligibleWeight times the parcel's
    // largest node weight are left out (DensityGrid::deposit). Why: alpha grows with the
    // droplets per parcel (100 at n = 500 in 2D), and most of the support then holds
    // weights far below the peak that cost full price; leaving them out is several times
    // faster for such kernels. The mass stays on the grid (the weights are normalised over
    // the kept nodes). The error it allows (docs/model.md sec. 4): the tail mass beyond the
    // cut moves to the kept nodes, epsilon of the largest node value in 2D and about
    // 2 sqrt(ln(1/epsilon) / pi) epsilon in 3D: 5e-8 at 1e-8, the default (reach 6.1 kernel
    // widths; 1e-17, reach 8.9 widths, visits 3x more nodes in 3D for 7e-17).
    // 0: exact tails (every node within reach).
    double negligibleWeight = 1e-8;
    // Moving parcels' node weights with the batched AVX2 + FMA node loop when the CPU has
    // it (KernelBuild.hpp; ~1.6x faster deposit for resolved kernels), else node by node.
    // false: always node by node. Why a choice: the two agree to ~1 ulp of exp/erfc (node
    // values to ~1e-14 of the largest), not to the bit, so runs on a mix of CPUs, or
    // bitwise comparisons across machines, may want the portable per-node results.
    bool vectorised = true;
    // Automatic: a parcel whose kernel (after the negligible-weight cut) reaches at least
    // ParcelWeights::separableFromSpacings node spacings gets its weights from per-axis
    // tables of the Gaussian (SeparableWeight; docs/model.md P16) when the proven bound
    // keeps them within 1e-7 of its largest weight of eqs. 23-24, else the exact code.
    // Why: the exact code costs one erf-type evaluation per node, (reach / h)^D nodes per
    // parcel; the tables cost a few multiplications per node. Exact: always the exact code
    // (the reference; tests and benchmarks compare the two).
    DepositMethod method = DepositMethod::Automatic;

    // Throws std::invalid_argument: beta outside (0, 1], rMaxCap not finite,
    // cloudInCellBelow negative or not finite, negligibleWeight not in [0, 1e-6].
    void validate() const;
};

// Eq. 13: r_max = r_p n.
double influenceRadiusMax(double dropletRadius, double nParticle);
// Eqs. 14-15: 2D r_min = r_p sqrt(2 sqrt(3) n / pi); 3D r_min = r_p (sqrt(18) n / pi)^(1/3).
double influenceRadiusMin(double dropletRadius, double nParticle, int dimension);
// Eq. 18: alpha = r_max^2 / (2 (beta r_max + (1 - beta) r_min)^2).
double kernelAlpha(double rMax, double rMin, double beta);

class ParcelKernel
{
public:
    // dimension: 2 or 3 (the packing formula for r_min). Requires radius > 0, n > 0.
    ParcelKernel(double dropletRadius, double nParticle, const KernelSettings& settings, int dimension);

    // Direct construction from the Gaussian and its support (tests, other kernels):
    // phi(d) = exp(-gamma d^2) - exp(-gamma reach^2), d < reach.
    static ParcelKernel fromShape(double gamma, double reach);

    double rMax() const { return rMax_; }
    double rMin() const { return rMin_; }
    double alpha() const { return alpha_; }
    double reach() const { return reach_; }               // support radius, min(r_max, cap)
    double gamma() const { return gamma_; }               // alpha / r_max^2, 1/m^2
    double width() const;                                 // r_max / sqrt(2 alpha), eq. 16
    double edgeExponent() const { return edgeExponent_; } // gamma reach^2 (= alpha uncapped)
    double edgeValue() const { return edgeValue_; }       // exp(-edgeExponent)
    bool capped() const { return capped_; }

    // Eq. 12, accurate also near the edge of the support (no cancellation, see .cpp).
    double phi(double distance) const;
    // The same from the squared distance (what the grid loop has).
    double phiOfSquaredDistance(double distanceSquared) const;

private:
    ParcelKernel() = default;
    void setShape(double gamma, double reach);

    double rMax_ = 0.0;
    double rMin_ = 0.0;
    double alpha_ = 0.0;
    double reach_ = 0.0;
    double gamma_ = 0.0;
    double edgeExponent_ = 0.0;
    double edgeValue_ = 0.0;
    bool capped_ = false;
};

} // namespace dropletFiber
