// DensityGrid: mass conservation (eqs. 24-25), the edge cases (outside, partly outside,
// no node reached, n = 1, zero velocity), node weights following phi, mean radii
// (eq. 10 and the mass-weighted one), the averaging window (eq. 26), cost scaling,
// restart and the MPI-style reduction. Expected values come from the physics (parcel
// masses n rho 4/3 pi r^3, time fractions, bilinear weights, eq. 12 written out here),
// never from the grid's own output.
#include "grid/DensityGrid.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <random>

using namespace dropletFiber;
using test::grid2D;
using test::grid3D;
using test::randomParcels;

namespace
{

constexpr double pi = 3.14159265358979323846;

double massOf(double n, double diameter, double rho)
{
    const double r = 0.5 * diameter;
    return n * rho * 4.0 / 3.0 * pi * r * r * r;
}

double stepMass(const DensityGrid& grid)
{
    double m = 0.0;
    const NodeValueArray& v = grid.stepValues();
    for (std::size_t n = 0; n < grid.spec().nodeCount(); ++n)
    {
        m += v[n * nQuantities + quantityMass];
    }
    return m;
}

Parcel makeParcel(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double diameter, double n,
                  double rho = 1000.0)
{
    Parcel p;
    p.position = position;
    p.velocity = velocity;
    p.diameter = diameter;
    p.nParticle = n;
    p.rhoDroplet = rho;
    return p;
}

// Squared distance from g to the segment [a, b] (the test's own geometry).
double segmentDistanceSquared(const Eigen::Vector3d& g, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    double t = ab.squaredNorm() > 0.0 ? (g - a).dot(ab) / ab.squaredNorm() : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    return (a + t * ab - g).squaredNorm();
}

} // namespace

TEST(DensityGrid, MassConservedForRandomClouds)
{
    for (const GridSpec& spec : {grid2D(), grid3D()})
    {
        for (double cap : {0.0, 4e-3})
        {
            KernelSettings settings;
            settings.rMaxCap = cap;
            DensityGrid grid(spec, settings);
            std::mt19937_64 rng(42);
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            const double dt = 1e-4;
            int fullyInside = 0;
            StepStatistics s;
            double nodeMassTotal = 0.0;
            for (int n = 0; n < 1500; ++n)
            {
                // Positions in a box 20 % larger than the grid: inside, near edges and
                // corners, outside, crossing the boundary.
                Eigen::Vector3d pos;
                for (int d = 0; d < 3; ++d)
                {
                    const double size = spec.upper[d] - spec.lower[d];
                    pos[d] = spec.lower[d] - 0.1 * size + 1.2 * size * unit(rng);
                    if (spec.flat(d))
                    {
                        pos[d] = spec.lower[d] + size * unit(rng);
                    }
                }
                Eigen::Vector3d vel(40.0 * (unit(rng) - 0.5), 40.0 * (unit(rng) - 0.5),
                                    spec.flat(2) ? 0.0 : 40.0 * (unit(rng) - 0.5));
                if (n % 10 == 0)
                {
                    vel.setZero();
                }
                // Droplet counts 1..3000 (n = 1 with 5 um droplets reaches no node: fallback).
                const double count = n % 7 == 0 ? 1.0 : std::floor(std::exp(unit(rng) * std::log(3000.0)));
                const double diameter = n % 7 == 0 ? 1e-5 : 1e-5 + 1e-4 * unit(rng);
                const Parcel p = makeParcel(pos, vel, diameter, count);
                // One parcel per step, so that the step accumulator holds this parcel only
                // (differences of large sums would hide its round-off).
                grid.deposit(p, dt);
                const double given = stepMass(grid);
                const double reported = grid.stepStatistics().massDeposited;
                const double mass = massOf(count, diameter, 1000.0);
                // What the nodes received is what the statistics report...
                EXPECT_NEAR(given, reported, 1e-12 * mass) << "parcel " << n;
                // ...and for a path that lies inside the box (start and end inside, box
                // convex) it is the whole parcel mass.
                if (spec.contains(p.position) && spec.contains(p.position - p.velocity * dt))
                {
                    ++fullyInside;
                    EXPECT_NEAR(given, mass, 1e-12 * mass) << "parcel " << n;
                }
                for (std::size_t node = 0; node < spec.nodeCount(); ++node)
                {
                    for (int q : {quantityMass, quantityCount, quantityCountRadius, quantityMassRadius})
                    {
                        ASSERT_GE(grid.stepValues()[node * nQuantities + static_cast<std::size_t>(q)], 0.0);
                    }
                }
                nodeMassTotal += given;
                grid.commitStep();
                s += grid.lastStepStatistics();
            }
            EXPECT_NEAR(s.massDeposited + s.massOutside, s.massIn, 1e-12 * s.massIn);
            EXPECT_NEAR(nodeMassTotal, s.massDeposited, 1e-12 * s.massIn);
            // All edge cases were exercised.
            EXPECT_GT(fullyInside, 500);
            EXPECT_GT(s.parcelsOutside, 10);
            EXPECT_GT(s.parcelsPartlyOutside, 10);
            EXPECT_GT(s.parcelsFallback, 10);
            EXPECT_EQ(s.parcelsCapped > 0, cap > 0.0);
        }
    }
}

TEST(DensityGrid, ParcelCrossingTheBoundaryGivesItsTimeFraction)
{
    DensityGrid grid(grid2D());
    // Path from x = -2 mm to x = +3 mm: 3/5 of the step inside the box.
    const Parcel p
        = makeParcel(Eigen::Vector3d(3e-3, 5e-3, 5e-4), Eigen::Vector3d(50.0, 0.0, 0.0), 5e-5, 200.0);
    grid.deposit(p, 1e-4);
    const double mass = massOf(200.0, 5e-5, 1000.0);
    EXPECT_NEAR(stepMass(grid), 0.6 * mass, 1e-12 * mass);
    EXPECT_NEAR(grid.stepStatistics().massOutside, 0.4 * mass, 1e-12 * mass);
    EXPECT_EQ(grid.stepStatistics().parcelsPartlyOutside, 1);
}

TEST(DensityGrid, ParcelOutsideGivesNothingEvenWhenItsKernelReachesNodes)
{
    DensityGrid grid(grid2D());
    // 0.1 mm left of the box; reach r_max = 1 cm would cover many nodes.
    grid.deposit(makeParcel(Eigen::Vector3d(-1e-4, 1e-2, 5e-4), Eigen::Vector3d::Zero(), 2e-5, 1000.0), 1e-4);
    // Outside the slab of the 2D grid (z beyond the depth).
    grid.deposit(makeParcel(Eigen::Vector3d(1e-2, 1e-2, 2e-3), Eigen::Vector3d::Zero(), 2e-5, 1000.0), 1e-4);
    EXPECT_EQ(stepMass(grid), 0.0);
    EXPECT_EQ(grid.stepStatistics().parcelsOutside, 2);
    EXPECT_NEAR(grid.stepStatistics().massOutside, 2.0 * massOf(1000.0, 2e-5, 1000.0), 1e-25);
    EXPECT_TRUE(grid.stepBox().empty());
}

TEST(DensityGrid, ParcelReachingNoNodeFallsBackToBilinearWeights)
{
    const GridSpec spec = grid2D(); // spacing 1 mm
    DensityGrid grid(spec);
    // n = 1, r = 1 um: reach 1 um, no node within reach. At (x, y) = (10.3, 7.6) mm.
    const Eigen::Vector3d p(10.3e-3, 7.6e-3, 5e-4);
    grid.deposit(makeParcel(p, Eigen::Vector3d::Zero(), 2e-6, 1.0), 1e-4);
    EXPECT_EQ(grid.stepStatistics().parcelsFallback, 1);
    const double mass = massOf(1.0, 2e-6, 1000.0);
    const double fx = 0.3, fy = 0.6; // position within the cell (10..11, 7..8) mm
    const NodeValueArray& v = grid.stepValues();
    auto nodeMass = [&](int i, int j) { return v[spec.flatIndex(i, j, 0) * nQuantities + quantityMass]; };
    EXPECT_NEAR(nodeMass(10, 7), mass * (1 - fx) * (1 - fy), 1e-9 * mass);
    EXPECT_NEAR(nodeMass(11, 7), mass * fx * (1 - fy), 1e-9 * mass);
    EXPECT_NEAR(nodeMass(10, 8), mass * (1 - fx) * fy, 1e-9 * mass);
    EXPECT_NEAR(nodeMass(11, 8), mass * fx * fy, 1e-9 * mass);
    EXPECT_NEAR(stepMass(grid), mass, 1e-14 * mass);

    // A moving n = 1 parcel crossing several cells: mass conserved, spread along the path.
    DensityGrid moving(spec);
    moving.deposit(
        makeParcel(Eigen::Vector3d(15.2e-3, 7.6e-3, 5e-4), Eigen::Vector3d(50.0, 0.0, 0.0), 2e-6, 1.0), 1e-4);
    EXPECT_EQ(moving.stepStatistics().parcelsFallback, 1);
    EXPECT_NEAR(stepMass(moving), mass, 1e-14 * mass);
    EXPECT_LE(moving.stepBox().lo[0], 10);
    EXPECT_GE(moving.stepBox().hi[0], 15); // path from x = 10.2 to 15.2 mm
}

TEST(DensityGrid, StationaryParcelWeightsFollowPhi)
{
    // Zero velocity: omega_g = phi(|p - g|) (eq. 23 for L = 0), so node masses are
    // proportional to eq. 12 with alpha of eq. 18 (written out here independently).
    // Exact tails (negligibleWeight 0): the far nodes are compared to 1e-30 of the mass.
    const GridSpec spec = grid2D();
    KernelSettings exactTails;
    exactTails.negligibleWeight = 0.0;
    DensityGrid grid(spec, exactTails);
    const double rp = 1e-5, n = 1000.0;
    const Eigen::Vector3d p(12.25e-3, 9.5e-3, 5e-4);
    grid.deposit(makeParcel(p, Eigen::Vector3d::Zero(), 2.0 * rp, n), 1e-4);
    const double rMax = rp * n;
    const double rMin = rp * std::sqrt(2.0 * std::sqrt(3.0) * n / pi);
    const double alpha = rMax * rMax / (2.0 * std::pow(0.025 * rMax + 0.975 * rMin, 2));
    auto phi = [&](double d)
    { return d < rMax ? std::exp(-alpha * d * d / (rMax * rMax)) - std::exp(-alpha) : 0.0; };
    double phiSum = 0.0;
    for (int j = 0; j < spec.nodes[1]; ++j)
        for (int i = 0; i < spec.nodes[0]; ++i)
            phiSum += phi((spec.nodePosition(i, j, 0) - p).head<2>().norm());
    const double mass = massOf(n, 2.0 * rp, 1000.0);
    for (int j = 0; j < spec.nodes[1]; ++j)
        for (int i = 0; i < spec.nodes[0]; ++i)
        {
            const double expected = mass * phi((spec.nodePosition(i, j, 0) - p).head<2>().norm()) / phiSum;
            EXPECT_NEAR(grid.stepValues()[spec.flatIndex(i, j, 0) * nQuantities + quantityMass], expected,
                        1e-10 * expected + 1e-30 * mass)
                << i << " " << j;
        }
}

TEST(DensityGrid, NegligibleWeightsLeftOutAreBelowTheBound)
{
    // KernelSettings::negligibleWeight promises: every node left out would have held less
    // than negligibleWeight times the parcel's largest node weight, and the mass stays on
    // the grid: the kept nodes hold the exact values times total / (total - left out).
    // The left-out share of the mass is the Gaussian tail beyond the cut (docs/model.md
    // sec. 4): at most 2 sqrt(ln(1/epsilon) / pi) epsilon (3D; epsilon in 2D). Checked
    // against the exact deposit (negligibleWeight 0), parcel by parcel, for kernels where
    // the cut binds (many droplets per parcel: alpha 40-150), moving and stationary, in 2D
    // and 3D, for the default and for 1e-17.
    KernelSettings exactTails;
    exactTails.negligibleWeight = 0.0;
    exactTails.method = DepositMethod::Exact;
    for (const double epsilon : {KernelSettings{}.negligibleWeight, 1e-17})
    {
        std::mt19937_64 rng(17);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        KernelSettings cutTails;
        cutTails.negligibleWeight = epsilon;
        cutTails.method = DepositMethod::Exact; // the exact code's cut (SeparableWeightTest: the other)
        const double tailBound = 2.0 * std::sqrt(std::log(1.0 / epsilon) / M_PI) * epsilon;
        int cutNodes = 0;
        for (const bool threeD : {false, true})
        {
            GridSpec spec = grid2D();
            if (threeD)
            {
                spec.nodes[2] = 21;
                spec.upper.z() = spec.lower.z() + 20 * spec.spacing(0);
            }
            for (int p = 0; p < 40; ++p)
            {
                DensityGrid cut(spec, cutTails);
                DensityGrid exact(spec, exactTails);
                const double n = 150.0 + 850.0 * unit(rng); // r_max 1.5-10 mm
                const double rp = 1e-5;
                const Eigen::Vector3d centre = 0.5 * (spec.lower + spec.upper);
                const Eigen::Vector3d position = centre
                    + 2e-3
                        * Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, threeD ? unit(rng) - 0.5 : 0.0);
                const Eigen::Vector3d velocity = (p % 4 == 0)
                    ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                    : Eigen::Vector3d(20.0 * (unit(rng) - 0.5), 20.0 * (unit(rng) - 0.5), 0.0);
                const Parcel parcel = makeParcel(position, velocity, 2.0 * rp, n);
                cut.deposit(parcel, 1e-4);
                exact.deposit(parcel, 1e-4);
                double largest = 0.0, exactTotal = 0.0, leftOut = 0.0, cutTotal = 0.0;
                for (std::size_t node = 0; node < spec.nodeCount(); ++node)
                {
                    const double c = cut.stepValues()[node * nQuantities + quantityMass];
                    const double e = exact.stepValues()[node * nQuantities + quantityMass];
                    largest = std::max(largest, e);
                    exactTotal += e;
                    leftOut += c == 0.0 ? e : 0.0;
                }
                EXPECT_LE(leftOut, tailBound * exactTotal)
                    << "parcel " << p << ", negligibleWeight " << epsilon;
                const double scale = exactTotal / (exactTotal - leftOut);
                for (std::size_t node = 0; node < spec.nodeCount(); ++node)
                {
                    const double c = cut.stepValues()[node * nQuantities + quantityMass];
                    const double e = exact.stepValues()[node * nQuantities + quantityMass];
                    cutTotal += c;
                    if (c == 0.0 && e > 0.0)
                    {
                        ++cutNodes;
                        ASSERT_LT(e, epsilon * largest) << "node " << node << " parcel " << p;
                        continue;
                    }
                    ASSERT_FALSE(c > 0.0 && e == 0.0);
                    // Kept nodes: renormalised over the kept nodes (eq. 24).
                    ASSERT_NEAR(c, e * scale, 1e-14 * largest) << "node " << node << " parcel " << p;
                }
                const double mass = massOf(n, 2.0 * rp, 1000.0);
                EXPECT_NEAR(cutTotal, mass, 1e-12 * mass);
                EXPECT_NEAR(exactTotal, mass, 1e-12 * mass);
            }
        }
        EXPECT_GT(cutNodes, 1000) << "negligibleWeight " << epsilon; // the cut really binds
    }
}

TEST(DensityGrid, MeanRadiiNumberAndMassWeighted)
{
    // Tiny kernels centred exactly on node (10, 5): all droplets land on that node, so its
    // sums are the plain sums over the parcels.
    const GridSpec spec = grid2D();
    DensityGrid grid(spec);
    const Eigen::Vector3d node = spec.nodePosition(10, 5, 0);
    struct Drops
    {
        double n, r;
        Eigen::Vector3d u;
    };
    const Drops drops[] = {{3.0, 2e-6, Eigen::Vector3d(1, 0, 0)},
                           {1.0, 5e-6, Eigen::Vector3d(0, 2, 0)},
                           {2.0, 1e-6, Eigen::Vector3d(0, 0, 3)}};
    double sn = 0, snr = 0, sm = 0, smr = 0;
    Eigen::Vector3d smu = Eigen::Vector3d::Zero();
    for (const Drops& d : drops)
    {
        // Stationary path (u = 0 during the step) but a droplet velocity: use dt = 0.
        grid.deposit(makeParcel(node, d.u, 2.0 * d.r, d.n), 0.0);
        const double m = massOf(d.n, 2.0 * d.r, 1000.0);
        sn += d.n;
        snr += d.n * d.r;
        sm += m;
        smr += m * d.r;
        smu += m * d.u;
    }
    grid.commitStep();
    const DropletFieldValue f = grid.nodeValue(10, 5, 0);
    const double volume = 1e-3 * 1e-3 * 1e-3;
    EXPECT_NEAR(f.rho, sm / volume, 1e-12 * sm / volume);
    EXPECT_NEAR(f.numberDensity, sn / volume, 1e-12 * sn / volume);
    EXPECT_NEAR(f.rMeanNumber, snr / sn, 1e-12 * snr / sn); // eq. 10
    EXPECT_NEAR(f.rMeanMass, smr / sm, 1e-12 * smr / sm);   // sum n m r / sum n m
    EXPECT_LT((f.velocity - smu / sm).norm(), 1e-12);
    EXPECT_GT(f.rMeanMass, f.rMeanNumber); // polydisperse: mass favours big drops
    // The neighbours got nothing.
    EXPECT_EQ(grid.nodeValue(11, 5, 0).rho, 0.0);
    EXPECT_EQ(grid.nodeValue(11, 5, 0).rMeanNumber, 0.0);
}

TEST(DensityGrid, WindowAveragesTheLastWSteps)
{
    // W = 3. Step s puts mass M_s on node (4, 4) only (tiny stationary kernel on the node);
    // rho there = mean of the M_s in the window / V, with s = min(committed, W) steps.
    const GridSpec spec = grid2D();
    DensityGrid grid(spec, KernelSettings{}, 3);
    const Eigen::Vector3d node = spec.nodePosition(4, 4, 0);
    const double counts[] = {1.0, 2.0, 4.0, 8.0, 16.0, 0.0, 0.0, 0.0};
    const double volume = spec.nodeVolume();
    std::vector<double> masses;
    for (double c : counts)
    {
        if (c > 0.0)
        {
            grid.deposit(makeParcel(node, Eigen::Vector3d::Zero(), 2e-6, c), 1e-4);
        }
        grid.commitStep();
        masses.push_back(massOf(c, 2e-6, 1000.0));
        const std::size_t s = std::min<std::size_t>(masses.size(), 3);
        double sum = 0.0;
        for (std::size_t k = masses.size() - s; k < masses.size(); ++k)
        {
            sum += masses[k];
        }
        const double expected = sum / (volume * static_cast<double>(s));
        EXPECT_NEAR(grid.nodeValue(4, 4, 0).rho, expected, 1e-12 * (expected + 1e-30))
            << "step " << masses.size();
        EXPECT_EQ(grid.stepsInWindow(), static_cast<int>(s));
    }
    // After three empty steps the window is exactly empty (no add/subtract residue).
    EXPECT_EQ(grid.nodeValue(4, 4, 0).rho, 0.0);
    EXPECT_EQ(grid.windowMassPerStep(), 0.0);
}

TEST(DensityGrid, CostScalesWithReachNotGridSize)
{
    // The same parcel, at the same place relative to the lower corner, on grids of
    // 41^2, 401^2 and 1001^2 nodes with the same spacing (0.5 mm); every node within
    // r_max evaluated (negligibleWeight 0), so that a brute-force count can check them.
    const double h = 5e-4;
    const Eigen::Vector3d end(7.3e-3, 8.1e-3, 5e-4);
    const Eigen::Vector3d velocity(12.0, -7.0, 0.0);
    const double dt = 1e-4, rp = 1e-5, n = 150.0; // reach r_max = 1.5 mm = 3 spacings
    const double reach = rp * n;
    std::vector<std::int64_t> visited, weighted;
    for (int nodes : {41, 401, 1001})
    {
        GridSpec spec;
        spec.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
        spec.upper = Eigen::Vector3d((nodes - 1) * h, (nodes - 1) * h, 1e-3);
        spec.nodes = {{nodes, nodes, 1}};
        KernelSettings exactTails;
        exactTails.negligibleWeight = 0.0;
        DensityGrid grid(spec, exactTails);
        grid.deposit(makeParcel(end, velocity, 2.0 * rp, n), dt);
        visited.push_back(grid.stepStatistics().nodesVisited);
        weighted.push_back(grid.stepStatistics().nodesWeighted);
        if (nodes == 41)
        {
            // Nodes within reach of the path, counted by brute force over the whole grid.
            const Eigen::Vector3d a = end - velocity * dt;
            std::int64_t within = 0;
            for (int j = 0; j < nodes; ++j)
                for (int i = 0; i < nodes; ++i)
                {
                    Eigen::Vector3d g = spec.nodePosition(i, j, 0);
                    g.z() = end.z();
                    within += segmentDistanceSquared(g, a, end) < reach * reach ? 1 : 0;
                }
            EXPECT_EQ(grid.stepStatistics().nodesWeighted, within);
            // Visited = the nodes of the capsule's bounding box, no more.
            std::int64_t box = 1;
            for (int d = 0; d < 2; ++d)
            {
                const double lo = std::min(a[d], end[d]) - reach, hi = std::max(a[d], end[d]) + reach;
                box *= static_cast<std::int64_t>(std::floor(hi / h) - std::ceil(lo / h) + 1);
            }
            EXPECT_EQ(grid.stepStatistics().nodesVisited, box);
            EXPECT_LT(box, 100);
        }
    }
    EXPECT_EQ(visited[0], visited[1]);
    EXPECT_EQ(visited[0], visited[2]);
    EXPECT_EQ(weighted[0], weighted[2]);
}

TEST(DensityGrid, RestartReproducesContinuousRunBitForBit)
{
    const GridSpec spec = grid2D();
    auto parcelsOfStep = [&](int step)
    {
        std::mt19937_64 rng(static_cast<std::uint64_t>(100 + step));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<Parcel> parcels;
        for (int n = 0; n < 200; ++n)
        {
            parcels.push_back(makeParcel(Eigen::Vector3d(0.03 * unit(rng), 0.02 * unit(rng), 5e-4),
                                         Eigen::Vector3d(10.0 * unit(rng), -10.0 * unit(rng), 0.0),
                                         1e-5 + 5e-5 * unit(rng), 1.0 + 500.0 * unit(rng)));
        }
        return parcels;
    };
    auto runStep = [&](DensityGrid& grid, int step)
    {
        for (const Parcel& p : parcelsOfStep(step))
        {
            grid.deposit(p, 1e-4);
        }
        grid.commitStep();
    };
    DensityGrid continuous(spec, KernelSettings{}, 4);
    DensityGrid continuousShort(spec, KernelSettings{}, 2);
    DensityGrid first(spec, KernelSettings{}, 4);
    for (int step = 0; step < 6; ++step)
    {
        runStep(continuous, step);
        runStep(continuousShort, step);
        runStep(first, step);
    }
    const WindowState state = first.saveWindow(DensityGrid::WindowStateFormat::DepositLog);
    DensityGrid restored(spec, KernelSettings{}, 4);
    restored.restoreWindow(state);
    DensityGrid restoredShort(spec, KernelSettings{}, 2); // window length changed on restart
    restoredShort.restoreWindow(state);
    EXPECT_EQ(restored.committedSteps(), 6);
    for (int step = 6; step < 11; ++step)
    {
        ASSERT_TRUE(restored.windowTotals() == continuous.windowTotals()) << "step " << step;
        ASSERT_TRUE(restoredShort.windowTotals() == continuousShort.windowTotals()) << "step " << step;
        runStep(continuous, step);
        runStep(continuousShort, step);
        runStep(restored, step);
        runStep(restoredShort, step);
    }
    EXPECT_TRUE(restored.windowTotals() == continuous.windowTotals());
    const Eigen::Vector3d point(0.0123, 0.0077, 0.0);
    EXPECT_EQ(restored.sample(point).rho, continuous.sample(point).rho);
    EXPECT_EQ(restored.sample(point).rMeanMass, continuous.sample(point).rMeanMass);

    // A state for another grid is refused with a message.
    DensityGrid other(grid2D(32, 21));
    EXPECT_THROW(other.restoreWindow(state), std::invalid_argument);
}

TEST(DensityGrid, SumOverRanksEqualsSerial)
{
    // Two "ranks" deposit half of the parcels each; the caller sums the step accumulators
    // over the union of the touched boxes (as MPI_Allreduce would) and commits on both.
    const GridSpec spec = grid2D();
    DensityGrid serial(spec), rank0(spec), rank1(spec);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 400; ++n)
    {
        const Parcel p = makeParcel(Eigen::Vector3d(0.01 + 0.01 * unit(rng), 0.005 + 0.01 * unit(rng), 5e-4),
                                    Eigen::Vector3d(5.0 * unit(rng), 5.0 * unit(rng), 0.0), 3e-5, 100.0);
        serial.deposit(p, 1e-4);
        (n % 2 == 0 ? rank0 : rank1).deposit(p, 1e-4);
    }
    const IndexBox box = rank0.stepBox().united(rank1.stepBox());
    std::vector<double> a = rank0.packStep(box);
    const std::vector<double> b = rank1.packStep(box);
    for (std::size_t k = 0; k < a.size(); ++k)
    {
        a[k] += b[k];
    }
    rank0.unpackStep(box, a);
    rank1.unpackStep(box, a);
    serial.commitStep();
    rank0.commitStep();
    rank1.commitStep();
    EXPECT_TRUE(rank0.windowTotals() == rank1.windowTotals());
    for (std::size_t k = 0; k < serial.windowTotals().size(); ++k)
    {
        EXPECT_NEAR(rank0.windowTotals()[k], serial.windowTotals()[k],
                    1e-13 * std::abs(serial.windowTotals()[k]));
    }
}

TEST(DensityGrid, KernelDimensionFollowsGridUnlessSet)
{
    EXPECT_EQ(DensityGrid(grid2D()).kernelDimension(), 2);
    EXPECT_EQ(DensityGrid(grid3D()).kernelDimension(), 3);
    KernelSettings s;
    s.dimension = KernelDimension::TwoD;
    EXPECT_EQ(DensityGrid(grid3D(), s).kernelDimension(), 2);
}

TEST(DensityGrid, RejectsInvalidInput)
{
    DensityGrid grid(grid2D());
    const Eigen::Vector3d p(0.01, 0.01, 5e-4);
    EXPECT_THROW(grid.deposit(makeParcel(p, Eigen::Vector3d::Zero(), -1e-5, 10.0), 1e-4),
                 std::invalid_argument);
    EXPECT_THROW(
        grid.deposit(makeParcel(Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d::Zero(), 1e-5, 10.0), 1e-4),
        std::invalid_argument);
    EXPECT_THROW(grid.deposit(makeParcel(p, Eigen::Vector3d::Zero(), 1e-5, -1.0), 1e-4),
                 std::invalid_argument);
    EXPECT_THROW(grid.deposit(makeParcel(p, Eigen::Vector3d::Zero(), 1e-5, 1.0), -1e-4),
                 std::invalid_argument);
    grid.deposit(makeParcel(p, Eigen::Vector3d::Zero(), 1e-5, 0.0), 1e-4); // empty parcel: skipped
    EXPECT_EQ(grid.stepStatistics().parcelsEmpty, 1);
    GridSpec bad = grid2D();
    bad.nodes = {{0, 10, 1}};
    EXPECT_THROW(DensityGrid{bad}, std::invalid_argument);
    bad = grid2D();
    bad.nodes = {{1, 1, 1}};
    EXPECT_THROW(DensityGrid{bad}, std::invalid_argument);
    EXPECT_THROW(DensityGrid(grid2D(), KernelSettings{}, 0), std::invalid_argument);
}

TEST(DensityGrid, CommittedStepsAreTheLastWStepArraysBitForBit)
{
    // commitStep hands the step array to the window (it becomes the newest slot, and the
    // evicted slot, cleared, the next step array). Reference: a copy of stepValues()
    // taken before each commit, the last W of them summed oldest to newest. Steps of
    // parcels in different parts of the grid (touched boxes of different sizes and
    // places), more than W of them; a restart midway goes on committing the same way.
    const GridSpec spec = grid3D();
    const int length = 3;
    auto parcelsOfStep = [&](int step)
    {
        // Parcels in a box that moves and changes size from step to step (empty at step 4).
        std::mt19937_64 rng(static_cast<std::uint64_t>(300 + step));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const double x0 = 0.002 * (step % 5), width = 0.004 + 0.003 * (step % 3);
        std::vector<Parcel> parcels;
        for (int n = 0; n < (step == 4 ? 0 : 30); ++n)
        {
            parcels.push_back(makeParcel(
                Eigen::Vector3d(x0 + width * unit(rng), 0.015 * unit(rng), 0.002 + 0.004 * unit(rng)),
                Eigen::Vector3d(2.0 * unit(rng), -2.0 * unit(rng), 0.5), 1e-5 + 5e-5 * unit(rng),
                1.0 + 500.0 * unit(rng)));
        }
        return parcels;
    };
    DensityGrid grid(spec, KernelSettings{}, length);
    std::unique_ptr<DensityGrid> restored;
    std::deque<NodeValueArray> history; // the last W step arrays, oldest first
    for (int step = 0; step < 10; ++step)
    {
        for (DensityGrid* g : {&grid, restored.get()})
        {
            if (g == nullptr)
                continue;
            for (const Parcel& p : parcelsOfStep(step))
                g->deposit(p, 1e-3);
        }
        history.push_back(grid.stepValues());
        if (static_cast<int>(history.size()) > length)
            history.pop_front();
        grid.commitStep();
        if (restored)
            restored->commitStep();
        if (step == 5)
        {
            restored = std::make_unique<DensityGrid>(spec, KernelSettings{}, length);
            restored->restoreWindow(grid.saveWindow());
        }
        NodeValueArray expected(history.back().size(), 0.0);
        for (const auto& s : history)
            for (std::size_t v = 0; v < expected.size(); ++v)
                expected[v] += s[v];
        for (const DensityGrid* g : std::array<const DensityGrid*, 2>{&grid, restored.get()})
        {
            if (g == nullptr)
                continue;
            // Node by node (what sampling reads every step), then the whole array
            for (std::size_t node = 0; node < spec.nodeCount(); ++node)
            {
                double sums[nQuantities];
                g->windowTotal(node, sums);
                for (std::size_t q = 0; q < nQuantities; ++q)
                {
                    ASSERT_EQ(sums[q], expected[node * nQuantities + q])
                        << "step " << step << " node " << node;
                    ASSERT_EQ(g->lastStepValue(node, static_cast<int>(q)),
                              history.back()[node * nQuantities + q]);
                }
            }
            ASSERT_TRUE(g->windowTotals() == expected) << "step " << step;
            // The next step's array is zero everywhere
            ASSERT_TRUE(std::all_of(g->stepValues().begin(), g->stepValues().end(),
                                    [](double v) { return v == 0.0; }))
                << "step " << step;
        }
    }
}

TEST(DensityGrid, BlockStoringMoreThanItOwnsCommitsItsOwnedNodes)
{
    // A block whose storage box is larger than its owned box (the step array is not laid
    // out as the window: commitStep copies its owned part): its window totals at the owned
    // nodes are the whole grid's, bit for bit (each stored node gets the whole grid's
    // deposit, in the same parcel order), over more steps than the window holds.
    const GridSpec spec = grid3D();
    GridBlock block;
    block.owned.lo = {{4, 3, 2}};
    block.owned.hi = {{13, 10, 7}};
    block.storage.lo = {{2, 1, 0}};
    block.storage.hi = {{16, 14, 9}};
    DensityGrid whole(spec, KernelSettings{}, 2);
    DensityGrid part(spec, KernelSettings{}, 2, block);
    for (int step = 0; step < 5; ++step)
    {
        for (const Parcel& p : randomParcels(spec, 40, 70u + static_cast<unsigned>(step)))
        {
            whole.deposit(p, 1e-3);
            part.deposit(p, 1e-3);
        }
        whole.commitStep();
        part.commitStep();
        ASSERT_TRUE(std::all_of(part.stepValues().begin(), part.stepValues().end(),
                                [](double v) { return v == 0.0; }));
        for (int k = block.owned.lo[2]; k <= block.owned.hi[2]; ++k)
            for (int j = block.owned.lo[1]; j <= block.owned.hi[1]; ++j)
                for (int i = block.owned.lo[0]; i <= block.owned.hi[0]; ++i)
                {
                    const std::size_t node = spec.flatIndex(i, j, k);
                    double sums[nQuantities];
                    part.windowTotal(node, sums);
                    for (std::size_t q = 0; q < nQuantities; ++q)
                        ASSERT_EQ(sums[q], whole.windowTotals()[node * nQuantities + q])
                            << "step " << step << " node " << node;
                }
    }
}
