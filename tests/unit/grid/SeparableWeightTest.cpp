// SeparableWeight (wide kernels, docs/model.md P16) against the exact deposit
// (KernelSettings::method Exact: PathWeight's closed form of eq. 23):
//  - the quadrature bound B(Q, k) holds for the path average of a Gaussian, computed here
//    with erf (an independent closed form);
//  - single parcels and whole clouds, 2D and 3D, stationary and moving, in the middle of the
//    grid and at its faces, edges and corners (folded kernels), and a grid block smaller than
//    the grid (storage and overflow): every quantity at every node within 1e-7 (single
//    parcels: the proven bound) or 1e-6 (clouds: the requirement) of the largest
//    node value; the separable path was taken; mass conserved to 1e-12;
//  - narrow kernels, method Exact, and kernels whose bound cannot be met keep the exact code;
//  - the normalising sum from the per-axis sums (P17) against the node-by-node sum from the
//    definition, before and after folding; blocks tiling the grid, each weighing only its
//    stored rows, hold the whole grid's deposit to the bit, with the AVX2 + FMA loops
//    (SeparableLanes) and with the portable ones, which agree to 1e-14; depositedShare
//    (depletion) gives the weights deposit() put on the nodes.
#include "grid/DensityGrid.hpp"
#include "grid/GaussLegendre.hpp"
#include "grid/SeparableWeight.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <cmath>
#include <random>
#include <vector>

using namespace dropletFiber;
using dropletFiber::test::grid2D;
using dropletFiber::test::grid3D;

namespace
{

constexpr double dt = 1e-4;

Parcel makeParcel(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double radius, double n)
{
    Parcel p;
    p.position = position;
    p.velocity = velocity;
    p.diameter = 2.0 * radius;
    p.nParticle = n;
    p.rhoDroplet = 1000.0;
    return p;
}

// At negligibleWeight 1e-17 the exact code's own cut error is ~1e-16 of the largest node
// value, so the comparisons below measure the separable weights' error alone (the default
// cut, 1e-8, adds up to 5e-8: RandomClouds uses the default).
KernelSettings settingsWith(DepositMethod method, double negligibleWeight = 1e-17)
{
    KernelSettings s;
    s.method = method;
    s.negligibleWeight = negligibleWeight;
    return s;
}

// Largest |fast - exact| over the stored nodes per quantity, relative to the largest
// |exact| of that quantity.
double worstRelativeDifference(const DensityGrid& fast, const DensityGrid& exact)
{
    double worst = 0.0;
    for (int q = 0; q < nQuantities; ++q)
    {
        double largest = 0.0, difference = 0.0;
        for (std::size_t n = 0; n * nQuantities < exact.stepValues().size(); ++n)
        {
            const double e = exact.stepValues()[n * nQuantities + q];
            largest = std::max(largest, std::abs(e));
            difference = std::max(difference, std::abs(fast.stepValues()[n * nQuantities + q] - e));
        }
        if (largest > 0.0)
        {
            worst = std::max(worst, difference / largest);
        }
    }
    return worst;
}

double depositedMass(const DensityGrid& grid)
{
    double mass = 0.0;
    for (std::size_t n = 0; n * nQuantities < grid.stepValues().size(); ++n)
    {
        mass += grid.stepValues()[n * nQuantities + quantityMass];
    }
    return mass;
}

// A random parcel of a wide kernel (r_p 10-50 um, 300-3000 droplets: reach after the
// negligible-weight cut 3 to ~30 spacings of 1 mm) anywhere in the box, moving up to
// `speed` m/s in a random direction (0: stationary).
Parcel randomWideParcel(std::mt19937_64& random, const GridSpec& spec, double speed)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Eigen::Vector3d position;
    for (int d = 0; d < 3; ++d)
    {
        position[d] = spec.lower[d] + unit(random) * (spec.upper[d] - spec.lower[d]);
    }
    const Eigen::Vector3d velocity
        = speed * Eigen::Vector3d(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
    return makeParcel(position, velocity, 1e-5 + 4e-5 * unit(random), 300.0 + 2700.0 * unit(random));
}

} // namespace

TEST(SeparableWeight, QuadratureBoundHoldsForTheGaussianPathAverage)
{
    // Path average of exp(-x^2) over [x0, x0 + k] (x = sqrt(gamma) lambda, k = sqrt(gamma) L):
    // exactly sqrt(pi) / 2 (erf(x0 + k) - erf(x0)) / k; the Q-point rule within B(Q, k).
    const double halfSqrtPi = 0.5 * std::sqrt(3.14159265358979323846);
    int checked = 0;
    for (int points = 1; points <= SeparableWeight::maximumPoints; ++points)
    {
        std::vector<double> node(static_cast<std::size_t>(points)), weight(static_cast<std::size_t>(points));
        gaussLegendreRule(points, node.data(), weight.data());
        for (double k : {0.05, 0.2, 0.5, 1.0, 2.0})
        {
            const double bound = SeparableWeight::quadratureBound(points, k);
            for (double x0 = -4.0; x0 <= 3.0; x0 += 0.125)
            {
                // erfc differences on the side away from 0: no cancellation in the tails.
                const double x1 = x0 + k;
                const double difference = x0 >= 0.0 ? std::erfc(x0) - std::erfc(x1)
                    : x1 <= 0.0                     ? std::erfc(-x1) - std::erfc(-x0)
                                                    : std::erf(x1) - std::erf(x0);
                const double exact = halfSqrtPi * difference / k;
                double rule = 0.0;
                for (int q = 0; q < points; ++q)
                {
                    const double x = x0 + 0.5 * k * (1.0 + node[static_cast<std::size_t>(q)]);
                    rule += 0.5 * weight[static_cast<std::size_t>(q)] * std::exp(-x * x);
                }
                ASSERT_LE(std::abs(rule - exact), bound + 1e-14 * exact + 1e-300)
                    << "Q " << points << " k " << k << " x0 " << x0;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 1000);
    // Not vacuous: the midpoint rule's error k^2/12 at x0 = -k/2 is within a factor 2 of B.
    const double k = 0.1;
    const double midpointError = std::abs(std::exp(0.0) - halfSqrtPi * 2.0 * std::erf(0.5 * k) / k);
    EXPECT_GT(midpointError, 0.5 * SeparableWeight::quadratureBound(1, k));
}

TEST(SeparableWeight, SingleParcelsAgreeWithTheExactDepositAtEveryPlace)
{
    // 2D and 3D; middle, face, edge and corner of the box (folded kernels); stationary and
    // moving (paths up to ~2 kernel widths: several Gauss-Legendre points).
    int separable = 0;
    double worst = 0.0;
    for (const GridSpec& spec : {grid2D(), grid3D()})
    {
        const Eigen::Vector3d size = spec.upper - spec.lower;
        const std::vector<Eigen::Vector3d> places{
            spec.lower + 0.5 * size, spec.lower + Eigen::Vector3d(0.5 * size.x(), 1e-4, 0.5 * size.z()),
            spec.lower + Eigen::Vector3d(2e-4, 1e-4, 0.5 * size.z()),
            spec.lower + Eigen::Vector3d(1e-4, 2e-4, 1e-4), spec.upper - Eigen::Vector3d(1e-4, 3e-4, 2e-4)};
        for (const Eigen::Vector3d& place : places)
        {
            for (double speed : {0.0, 1.0, 5.0, 20.0})
            {
                for (double n : {400.0, 1500.0, 5000.0})
                {
                    DensityGrid fast(spec, settingsWith(DepositMethod::Automatic));
                    DensityGrid exact(spec, settingsWith(DepositMethod::Exact));
                    const Parcel parcel = makeParcel(place, speed * Eigen::Vector3d(0.6, -0.8, 0.3), 2e-5, n);
                    fast.deposit(parcel, dt);
                    exact.deposit(parcel, dt);
                    ASSERT_EQ(exact.stepStatistics().parcelsSeparable, 0);
                    separable += static_cast<int>(fast.stepStatistics().parcelsSeparable);
                    const double difference = worstRelativeDifference(fast, exact);
                    worst = std::max(worst, difference);
                    ASSERT_LE(difference, SeparableWeight::tolerance) << "n " << n << " speed " << speed;
                    const double massOnGrid = fast.stepStatistics().massDeposited;
                    ASSERT_NEAR(depositedMass(fast), massOnGrid, 1e-12 * massOnGrid);
                }
            }
        }
    }
    // 2 grids x 5 places x 4 speeds x 3 counts; the fast path taken for nearly all.
    EXPECT_GE(separable, 100);
    std::printf("single parcels: %d separable, worst difference %.3g of the largest node value\n", separable,
                worst);
}

TEST(SeparableWeight, RandomCloudsAgreeWithTheExactDeposit)
{
    std::mt19937_64 random(19);
    for (const GridSpec& spec : {grid2D(), grid3D()})
    {
        for (double speed : {0.0, 10.0, 40.0})
        {
            DensityGrid fast(spec, settingsWith(DepositMethod::Automatic, KernelSettings{}.negligibleWeight));
            DensityGrid exact(spec, settingsWith(DepositMethod::Exact, KernelSettings{}.negligibleWeight));
            for (int p = 0; p < 40; ++p)
            {
                const Parcel parcel = randomWideParcel(random, spec, speed);
                fast.deposit(parcel, dt);
                exact.deposit(parcel, dt);
            }
            EXPECT_GE(fast.stepStatistics().parcelsSeparable, 30);
            EXPECT_LE(worstRelativeDifference(fast, exact), 1e-6) << "speed " << speed;
            const double massOnGrid = fast.stepStatistics().massDeposited;
            EXPECT_NEAR(depositedMass(fast), massOnGrid, 1e-12 * massOnGrid);
            EXPECT_NEAR(fast.stepStatistics().massDeposited, exact.stepStatistics().massDeposited,
                        1e-15 * massOnGrid);
        }
    }
}

TEST(SeparableWeight, GridBlockStoresWhatTheWholeGridGets)
{
    // A block storing part of the grid: its stored nodes and its overflow list hold the
    // exact whole-grid deposit at those nodes.
    const GridSpec spec = grid3D();
    GridBlock block;
    block.owned.lo = {{5, 4, 3}};
    block.owned.hi = {{12, 10, 7}};
    block.storage.lo = {{3, 2, 1}};
    block.storage.hi = {{14, 12, 9}};
    std::mt19937_64 random(7);
    DensityGrid fast(spec, settingsWith(DepositMethod::Automatic), 1, block);
    DensityGrid exact(spec, settingsWith(DepositMethod::Exact));
    for (int p = 0; p < 20; ++p)
    {
        const Parcel parcel = randomWideParcel(random, spec, 10.0);
        fast.deposit(parcel, dt);
        exact.deposit(parcel, dt);
    }
    EXPECT_GE(fast.stepStatistics().parcelsSeparable, 15);
    // The block's stored nodes hold the whole grid's values there; the nodes beyond are left
    // to the blocks that store them
    double largest = 0.0, difference = 0.0, storedMass = 0.0, wholeMass = 0.0;
    for (std::size_t n = 0; n < spec.nodeCount(); ++n)
    {
        const double e = exact.stepValues()[n * nQuantities + quantityMass];
        largest = std::max(largest, e);
        wholeMass += e;
    }
    for (int k = block.storage.lo[2]; k <= block.storage.hi[2]; ++k)
    {
        for (int j = block.storage.lo[1]; j <= block.storage.hi[1]; ++j)
        {
            for (int i = block.storage.lo[0]; i <= block.storage.hi[0]; ++i)
            {
                const double stored
                    = fast.stepValues()[flatIndexInBox(block.storage, i, j, k) * nQuantities + quantityMass];
                const double e = exact.stepValues()[spec.flatIndex(i, j, k) * nQuantities + quantityMass];
                difference = std::max(difference, std::abs(stored - e));
                storedMass += stored;
            }
        }
    }
    EXPECT_LE(difference, 1e-6 * largest);
    EXPECT_LT(storedMass, 0.99 * wholeMass); // kernels reach beyond the block
}

TEST(SeparableWeight, ExactCodeWhereChosenOrWhereTheBoundFails)
{
    const GridSpec spec = grid3D();
    const Eigen::Vector3d centre = 0.5 * (spec.lower + spec.upper);
    // Narrow kernel (reach ~1.5 spacings), wide kernel with method Exact: the exact code, to the bit.
    for (const auto& [n, method] :
         {std::pair{150.0, DepositMethod::Automatic}, std::pair{2000.0, DepositMethod::Exact}})
    {
        DensityGrid chosen(spec, settingsWith(method));
        KernelSettings exactSettings = settingsWith(DepositMethod::Exact);
        DensityGrid exact(spec, exactSettings);
        const Parcel parcel = makeParcel(centre, Eigen::Vector3d(3.0, 1.0, 0.0), 1e-5, n);
        chosen.deposit(parcel, dt);
        exact.deposit(parcel, dt);
        EXPECT_EQ(chosen.stepStatistics().parcelsSeparable, 0);
        EXPECT_EQ(chosen.stepValues(), exact.stepValues());
    }
    // A capped kernel cut inside its Gaussian (r_max 6 cm, cap 5 mm: E = exp(-gamma cap^2)
    // ~ 0.1): the left-out constant would be visible, so the exact code deposits it.
    KernelSettings capped = settingsWith(DepositMethod::Automatic);
    capped.rMaxCap = 5e-3;
    DensityGrid cappedGrid(spec, capped);
    cappedGrid.deposit(makeParcel(centre, Eigen::Vector3d(3.0, 1.0, 0.0), 3e-5, 2000.0), dt);
    EXPECT_EQ(cappedGrid.stepStatistics().parcelsCapped, 1);
    EXPECT_EQ(cappedGrid.stepStatistics().parcelsSeparable, 0);
    // The truncation term E = exp(-gamma reach^2) alone breaks the bound: no quadrature.
    EXPECT_EQ(SeparableWeight::chooseQuadrature(0.0, 1e-9, 0.0, 1.0, 1000), 0);
    EXPECT_EQ(SeparableWeight::chooseQuadrature(0.0, 1e-20, 1e-17, 1.0, 1000), 1);
    // A path much longer than the kernel's width: more than maximumPoints points needed.
    EXPECT_EQ(SeparableWeight::chooseQuadrature(20.0, 0.0, 0.0, 1.0, 1000), 0);
    // Q grows with the path length.
    EXPECT_LT(SeparableWeight::chooseQuadrature(0.1, 0.0, 0.0, 1.0, 1000),
              SeparableWeight::chooseQuadrature(1.0, 0.0, 0.0, 1.0, 1000));
}

TEST(SeparableWeight, CappedTwoDimensionalSprayAgreesWithTheExactDeposit)
{
    // The tutorial's setting (channelSpray): 2D grid 5 x 15 cm, 1 mm spacing, 1 cm thick,
    // rMaxCap 6 mm, cloudInCellBelow 0.5, dt 5e-4 s; parcels of 1-3000 droplets of 5-60 um
    // moving up to 10 m/s (paths up to 5 spacings), some leaving the grid.
    GridSpec spec;
    spec.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    spec.upper = Eigen::Vector3d(0.05, 0.15, 0.01);
    spec.nodes = {{51, 151, 1}};
    KernelSettings fastSettings = settingsWith(DepositMethod::Automatic);
    fastSettings.rMaxCap = 6e-3;
    fastSettings.cloudInCellBelow = 0.5;
    KernelSettings exactSettings = fastSettings;
    exactSettings.method = DepositMethod::Exact;
    DensityGrid fast(spec, fastSettings);
    DensityGrid exact(spec, exactSettings);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int p = 0; p < 400; ++p)
    {
        const Eigen::Vector3d position(0.052 * unit(random), 0.152 * unit(random), 0.01 * unit(random));
        const Eigen::Vector3d velocity
            = 10.0 * unit(random) * Eigen::Vector3d(unit(random) - 0.5, unit(random) - 0.5, 0.0);
        const double n = std::exp(std::log(3000.0) * unit(random));
        const Parcel parcel = makeParcel(position, velocity, 5e-6 + 55e-6 * unit(random), n);
        fast.deposit(parcel, 5e-4);
        exact.deposit(parcel, 5e-4);
    }
    EXPECT_GE(fast.stepStatistics().parcelsSeparable, 20);
    EXPECT_LE(worstRelativeDifference(fast, exact), 1e-6);
    std::printf("capped 2D spray: %lld of 400 separable, worst difference %.3g\n",
                static_cast<long long>(fast.stepStatistics().parcelsSeparable),
                worstRelativeDifference(fast, exact));
}

TEST(SeparableWeight, NormalisingSumFromTheAxisSumsIsTheSumOfTheNodeWeights)
{
    // A moving 3D parcel's tables on a lattice box (Q = 4), the box's omegas summed node by
    // node here from their definition, sum_q W_q exp(-gamma |g - c_q|^2); SeparableWeight::sum
    // (per-axis sums) must agree to round-off, before and after folding (folding moves
    // weight between nodes, the sum stays), and a part of a row must be that part of the row.
    const double h = 1e-3;
    const int lowest = -30;
    const test::TestLattice grid = test::testLattice(lowest, 60, h);
    const std::array<const double*, 3>& lattice = grid.atIndexZero;
    const KernelSettings settings;
    const ParcelKernel kernel(2e-5, 2000.0, settings, 3);
    const Eigen::Vector3d start(3.3e-3, 1.2e-3, 0.4e-3), displacement(2e-3, -1e-3, 0.5e-3);
    const PathWeight path(kernel, start, displacement);
    const int points = 4;
    const std::array<int, 3> lo{{-12, -14, -15}}, hi{{18, 16, 15}};
    SeparableWeight separable;
    separable.prepare(path, start, displacement, points, lattice, lo, hi);

    std::array<double, points> node{}, weight{};
    gaussLegendreRule(points, node.data(), weight.data());
    double direct = 0.0;
    double worstRow = 0.0;
    for (int k = lo[2]; k <= hi[2]; ++k)
    {
        for (int j = lo[1]; j <= hi[1]; ++j)
        {
            const double* row = separable.row(j - lo[1], k - lo[2]);
            for (int i = lo[0]; i <= hi[0]; ++i)
            {
                double omega = 0.0;
                for (int q = 0; q < points; ++q)
                {
                    const double tau = 0.5 * (1.0 + node[static_cast<std::size_t>(q)]);
                    const Eigen::Vector3d g(i * h, j * h, k * h);
                    omega += 0.5 * weight[static_cast<std::size_t>(q)]
                        * std::exp(-kernel.gamma() * (g - start - tau * displacement).squaredNorm());
                }
                direct += omega;
                worstRow = std::max(worstRow, std::abs(row[i - lo[0]] - omega));
            }
        }
    }
    EXPECT_NEAR(separable.sum(), direct, 1e-14 * direct);
    EXPECT_LE(worstRow, 1e-14);
    // Part of a row: the same values to the bit.
    const std::vector<double> whole(separable.row(20, 9), separable.row(20, 9) + (hi[0] - lo[0] + 1));
    const double* part = separable.row(20, 9, 7, 11);
    for (std::size_t i = 0; i < 11; ++i)
    {
        EXPECT_EQ(part[i], whole[7 + i]);
    }
    EXPECT_THROW(separable.row(20, 9, 25, 11), std::out_of_range);

    // Folded onto a grid of nodes 0..9 per axis (mirror images at 0 and 9): the same sum,
    // now that of the folded rows.
    const GridSpec spec = []
    {
        GridSpec s;
        s.upper = Eigen::Vector3d(9e-3, 9e-3, 9e-3);
        s.nodes = {{10, 10, 10}};
        return s;
    }();
    std::array<std::vector<int>, 3> image;
    for (int d = 0; d < 3; ++d)
    {
        for (int i = lo[static_cast<std::size_t>(d)]; i <= hi[static_cast<std::size_t>(d)]; ++i)
        {
            image[static_cast<std::size_t>(d)].push_back(spec.mirrorIndex(d, i));
        }
    }
    separable.fold(image, {{0, 0, 0}}, {{9, 9, 9}});
    double folded = 0.0;
    for (int k = 0; k < 10; ++k)
    {
        for (int j = 0; j < 10; ++j)
        {
            const double* row = separable.row(j, k);
            for (int i = 0; i < 10; ++i)
            {
                folded += row[i];
            }
        }
    }
    EXPECT_NEAR(separable.sum(), direct, 1e-14 * direct);
    EXPECT_NEAR(folded, direct, 1e-14 * direct);
}

namespace
{

// Four blocks tiling the 3D grid, each depositing every parcel on its stored nodes (the
// first by deposit, the others as copies): each stored node holds the whole grid's value to
// the bit (the same weights, added in the same order), and the blocks' masses add up to the
// whole grid's. vectorised: the AVX2 + FMA loops (SeparableLanes) where the CPU has them, or
// the portable ones.
void blocksHoldTheWholeGridsDeposit(bool vectorised)
{
    KernelSettings settings = settingsWith(DepositMethod::Automatic, KernelSettings{}.negligibleWeight);
    settings.vectorised = vectorised;
    const GridSpec spec = grid3D();
    const int splitI = 8, splitK = 4;
    std::vector<GridBlock> blocks;
    for (const auto& [iLo, iHi] : {std::pair{0, splitI}, std::pair{splitI + 1, spec.nodes[0] - 1}})
    {
        for (const auto& [kLo, kHi] : {std::pair{0, splitK}, std::pair{splitK + 1, spec.nodes[2] - 1}})
        {
            GridBlock block;
            block.owned.lo = {{iLo, 0, kLo}};
            block.owned.hi = {{iHi, spec.nodes[1] - 1, kHi}};
            block.storage = block.owned;
            blocks.push_back(block);
        }
    }
    DensityGrid whole(spec, settings);
    std::vector<DensityGrid> parts;
    for (const GridBlock& block : blocks)
    {
        parts.emplace_back(spec, settings, 1, block);
    }
    std::mt19937_64 random(23);
    for (int p = 0; p < 30; ++p)
    {
        const Parcel parcel = randomWideParcel(random, spec, p % 3 == 0 ? 0.0 : 20.0);
        whole.deposit(parcel, dt);
        for (std::size_t b = 0; b < parts.size(); ++b)
        {
            b == 0 ? parts[b].deposit(parcel, dt) : parts[b].depositCopy(parcel, dt);
        }
    }
    EXPECT_GE(whole.stepStatistics().parcelsSeparable, 20);
    double partsMass = 0.0;
    for (std::size_t b = 0; b < parts.size(); ++b)
    {
        const IndexBox& storage = blocks[b].storage;
        EXPECT_EQ(parts[b].stepBox(), whole.stepBox().intersected(storage));
        for (int k = storage.lo[2]; k <= storage.hi[2]; ++k)
        {
            for (int j = storage.lo[1]; j <= storage.hi[1]; ++j)
            {
                for (int i = storage.lo[0]; i <= storage.hi[0]; ++i)
                {
                    for (int q = 0; q < nQuantities; ++q)
                    {
                        ASSERT_EQ(parts[b].stepValues()[flatIndexInBox(storage, i, j, k) * nQuantities + q],
                                  whole.stepValues()[spec.flatIndex(i, j, k) * nQuantities + q])
                            << "block " << b << " node " << i << " " << j << " " << k << " q " << q;
                    }
                }
            }
        }
        partsMass += depositedMass(parts[b]);
    }
    const double massOnGrid = whole.stepStatistics().massDeposited;
    EXPECT_NEAR(partsMass, massOnGrid, 1e-12 * massOnGrid);
}

} // namespace

TEST(SeparableWeight, BlocksTilingTheGridStoreTheWholeGridsDepositToTheBit)
{
    blocksHoldTheWholeGridsDeposit(true);
    blocksHoldTheWholeGridsDeposit(false);
}

TEST(SeparableWeight, PortableAndAvx2LoopsAgreeToRoundOff)
{
    // The same wide parcels with the AVX2 + FMA loops (where the CPU has them) and the
    // portable ones: the same nodes, values within 1e-14 of each quantity's largest (FMA
    // and the inline exp: ~1e-16 per weight), the same mass to 1e-14.
    const GridSpec spec = grid3D();
    KernelSettings lanes = settingsWith(DepositMethod::Automatic, KernelSettings{}.negligibleWeight);
    KernelSettings portable = lanes;
    portable.vectorised = false;
    DensityGrid a(spec, lanes), b(spec, portable);
    EXPECT_FALSE(b.batchedKernel());
    std::mt19937_64 random(29);
    for (int p = 0; p < 30; ++p)
    {
        const Parcel parcel = randomWideParcel(random, spec, p % 3 == 0 ? 0.0 : 20.0);
        a.deposit(parcel, dt);
        b.deposit(parcel, dt);
    }
    EXPECT_GE(a.stepStatistics().parcelsSeparable, 20);
    EXPECT_EQ(a.stepStatistics().parcelsSeparable, b.stepStatistics().parcelsSeparable);
    EXPECT_LE(worstRelativeDifference(a, b), 1e-14);
    EXPECT_NEAR(depositedMass(a), depositedMass(b), 1e-14 * depositedMass(b));
    std::printf("AVX2 (%s) against portable loops: worst difference %.3g of the largest value\n",
                a.batchedKernel() ? "in use" : "not on this CPU", worstRelativeDifference(a, b));
}

TEST(SeparableWeight, DepositedShareGivesTheDepositsWeights)
{
    // depositedShare (depletion) re-weighs a wide parcel without accumulating: per parcel it
    // must give sum over the nodes of (the mass deposit() put there / the parcel's mass)
    // times a random fraction per node, and 1 with the fraction 1 (parcels inside the box).
    const GridSpec spec = grid3D();
    DensityGrid grid(spec, settingsWith(DepositMethod::Automatic, KernelSettings{}.negligibleWeight));
    std::mt19937_64 random(29);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> fraction(spec.nodeCount());
    for (double& f : fraction)
    {
        f = unit(random);
    }
    const DensityGrid::NodeFraction fractionAt = [&](std::size_t node) { return fraction[node]; };
    const DensityGrid::NodeFraction one = [](std::size_t) { return 1.0; };
    const DensityGrid::NodeBoxTest askAll = [](const IndexBox&) { return true; };
    std::int64_t separable = 0;
    IndexBox region; // a corner of the grid
    region.lo = {{3, 2, 1}};
    region.hi = {{9, 8, 5}};
    double regionShare = 0.0;
    for (int p = 0; p < 20; ++p)
    {
        const Parcel parcel = randomWideParcel(random, spec, p % 2 == 0 ? 0.0 : 20.0);
        grid.deposit(parcel, dt);
        grid.commitStep();
        separable += grid.lastStepStatistics().parcelsSeparable;
        double expected = 0.0;
        for (std::size_t node = 0; node < spec.nodeCount(); ++node)
        {
            expected += grid.lastStepValue(node, quantityMass) * fraction[node];
        }
        const double mass = grid.lastStepStatistics().massDeposited;
        EXPECT_NEAR(grid.depositedShare(parcel, dt, askAll, fractionAt, spec.fullBox()),
                    expected / parcelMass(parcel), 1e-13);
        EXPECT_NEAR(grid.depositedShare(parcel, dt, askAll, one, spec.fullBox()), mass / parcelMass(parcel),
                    1e-13);
        // A region holding every node with a fraction: the same sum, to the bit
        const DensityGrid::NodeFraction inRegion = [&](std::size_t node)
        {
            const auto nx = static_cast<std::size_t>(spec.nodes[0]);
            const auto ny = static_cast<std::size_t>(spec.nodes[1]);
            const bool inside = region.holds(static_cast<int>(node % nx), static_cast<int>((node / nx) % ny),
                                             static_cast<int>(node / (nx * ny)));
            return inside ? fraction[node] : 0.0;
        };
        EXPECT_EQ(grid.depositedShare(parcel, dt, askAll, inRegion, region),
                  grid.depositedShare(parcel, dt, askAll, inRegion, spec.fullBox()));
        regionShare += grid.depositedShare(parcel, dt, askAll, inRegion, region);
    }
    EXPECT_GT(regionShare, 0.0);
    EXPECT_GE(separable, 15);
}
