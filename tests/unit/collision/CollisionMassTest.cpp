// Eq. 9 and its use with the density grid: the formula against eqs. 4-5 written out
// (normal vector, collision volume), a uniform spray (constant density: exact result for
// a segment normal to the flow, zero parallel to it), and a geometric Monte-Carlo count
// of droplets hitting a fiber in a polydisperse spray, which decides between the
// number- and mass-weighted mean radius.
#include "collision/CollisionMass.hpp"

#include "../grid/UniformStream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dropletFiber;

namespace
{
constexpr double pi = 3.14159265358979323846;

// Eqs. 4-5 as printed: n = ((l x v) x l) / |(l x v) x l|, V = |v dt . n| |l| 2 (r_F + r).
double collisionVolumeEq5(const Eigen::Vector3d& l, const Eigen::Vector3d& v, double dt, double rF, double r)
{
    const Eigen::Vector3d m = (l.cross(v)).cross(l);
    if (m.norm() == 0.0)
    {
        return 0.0;
    }
    const Eigen::Vector3d n = m / m.norm();
    return std::abs((v * dt).dot(n)) * l.norm() * 2.0 * (rF + r);
}
} // namespace

TEST(CollisionMass, FormulaEqualsEquationsFourAndFive)
{
    std::mt19937_64 rng(9);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int i = 0; i < 1000; ++i)
    {
        const Eigen::Vector3d l(g(rng) * 1e-3, g(rng) * 1e-3, g(rng) * 1e-3);
        const Eigen::Vector3d v(g(rng) * 5.0, g(rng) * 5.0, g(rng) * 5.0);
        const double rho = 0.1 + std::abs(g(rng)), r = 1e-5 * (1.0 + std::abs(g(rng))), rF = 1e-4, dt = 1e-4;
        const double expected = rho * collisionVolumeEq5(l, v, dt, rF, r); // eq. 6-9 for one radius
        EXPECT_NEAR(collisionMass(rho, r, rF, l, v, dt), expected, 1e-12 * expected);
    }
    // Parallel: zero (eq. 4 would divide by zero).
    EXPECT_EQ(collisionMass(1.0, 1e-5, 1e-4, Eigen::Vector3d(1e-3, 0, 0), Eigen::Vector3d(-3.0, 0, 0), 1e-4),
              0.0);
}

TEST(CollisionMass, UniformSprayGivesExactResultNormalAndZeroParallel)
{
    const test::UniformStream stream;
    KernelSettings settings;
    settings.rMaxCap = 3e-3;
    DensityGrid grid(stream.grid(), settings, 2);
    const std::vector<Parcel> parcels = stream.parcels();
    for (int step = 0; step < 2; ++step)
    {
        for (const Parcel& p : parcels)
        {
            grid.deposit(p, stream.dt);
        }
        grid.commitStep();
    }
    const double rF = 1e-4, dt = stream.dt, length = 4e-3;
    // Segment normal to the flow (along x), fiber at rest, in the middle of the box.
    const Eigen::Vector3d a(0.008, 0.015, 5e-4), b(0.012, 0.015, 5e-4);
    const SegmentCollision normal = collisionMass(grid, a, b, rF, Eigen::Vector3d::Zero(), dt);
    const double rhoGrid = grid.sample(0.5 * (a + b)).rho;
    EXPECT_NEAR(rhoGrid, stream.rhoAnalytic(), 0.005 * stream.rhoAnalytic());
    // Eq. 9 with the grid's rho: 2 rho (r_F + r) |v| dt l, exactly (r and v are the parcels').
    const double expected = 2.0 * rhoGrid * (rF + stream.dropletRadius) * stream.speed * dt * length;
    EXPECT_NEAR(normal.mass, expected, 1e-12 * expected);
    EXPECT_NEAR(normal.momentum.y(), -stream.speed * expected, 1e-12 * stream.speed * expected);
    EXPECT_EQ(normal.momentum.x(), 0.0);
    EXPECT_EQ(normal.samples, 1);
    EXPECT_EQ(normal.samplesOutside, 0);
    // ...and within 0.5 % of the analytic density's value.
    const double analytic
        = 2.0 * stream.rhoAnalytic() * (rF + stream.dropletRadius) * stream.speed * dt * length;
    EXPECT_NEAR(normal.mass, analytic, 0.005 * analytic);

    // Parallel to the flow: exactly zero.
    const SegmentCollision parallel
        = collisionMass(grid, Eigen::Vector3d(0.01, 0.012, 5e-4), Eigen::Vector3d(0.01, 0.016, 5e-4), rF,
                        Eigen::Vector3d::Zero(), dt);
    EXPECT_EQ(parallel.mass, 0.0);

    // Several sample points along the segment: same result in a uniform field.
    CollisionOptions several;
    several.samples = 0; // automatic: one per node spacing spanned (4 mm / 0.5 mm = 8)
    const SegmentCollision sampled = collisionMass(grid, a, b, rF, Eigen::Vector3d::Zero(), dt, several);
    EXPECT_EQ(sampled.samples, 8);
    EXPECT_NEAR(sampled.mass, expected, 1e-4 * expected);

    // A fiber moving with the droplets' direction at 1 m/s: v_rel = 4 m/s.
    const SegmentCollision moving = collisionMass(grid, a, b, rF, Eigen::Vector3d(0.0, -1.0, 0.0), dt);
    EXPECT_NEAR(moving.mass, expected * 4.0 / 5.0, 1e-12 * expected);
    // Number- and mass-weighted radius agree for a monodisperse spray.
    CollisionOptions number;
    number.radiusAverage = RadiusAverage::Number;
    EXPECT_NEAR(collisionMass(grid, a, b, rF, Eigen::Vector3d::Zero(), dt, number).mass, normal.mass,
                1e-12 * normal.mass);

    // Outside the grid: nothing, and counted.
    const SegmentCollision outside
        = collisionMass(grid, Eigen::Vector3d(0.03, 0.04, 5e-4), Eigen::Vector3d(0.031, 0.04, 5e-4), rF,
                        Eigen::Vector3d::Zero(), dt);
    EXPECT_EQ(outside.mass, 0.0);
    EXPECT_EQ(outside.samplesOutside, 1);
}

TEST(CollisionMass, MonteCarloCountOfPolydisperseSprayFollowsMassWeightedRadius)
{
    // Geometric count: droplets of two sizes, uniformly at random, move by U dt in -y past a
    // fiber segment along x (axis y = z = 0, length l, radius r_F). A droplet hits when its
    // centre enters the disc of radius r_F + r around the axis during the step (|z| < r_F + r,
    // starts outside, ends inside or beyond) with 0 <= x <= l. Compared with eq. 9 for
    // rho = droplet mass / volume and either mean radius.
    const double l = 1e-3, rF = 2e-5, U = 2.0, dt = 1e-4;
    const double radii[2] = {1e-5, 1e-4};
    const double fractionSmall = 0.8;
    const double rMaxAll = rF + radii[1];
    const double ySize = U * dt + rMaxAll, zSize = 2.0 * rMaxAll;
    const double volume = l * ySize * zSize;
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int droplets = 200000;
    double hitMass = 0.0, totalMass = 0.0, sumN = 0.0, sumNr = 0.0, sumM = 0.0, sumMr = 0.0;
    for (int i = 0; i < droplets; ++i)
    {
        const double r = unit(rng) < fractionSmall ? radii[0] : radii[1];
        const double m = 1000.0 * 4.0 / 3.0 * pi * r * r * r;
        const double y0 = ySize * unit(rng);
        const double z = zSize * (unit(rng) - 0.5);
        totalMass += m;
        sumN += 1.0;
        sumNr += r;
        sumM += m;
        sumMr += m * r;
        const double R = rF + r;
        if (std::abs(z) >= R)
        {
            continue;
        }
        const double c = std::sqrt(R * R - z * z); // entry height of the disc at this z
        if (y0 >= c && y0 - U * dt < c)
        {
            hitMass += m;
        }
    }
    const double rho = totalMass / volume;
    const Eigen::Vector3d segment(l, 0.0, 0.0), vRel(0.0, -U, 0.0);
    const double massWeighted = collisionMass(rho, sumMr / sumM, rF, segment, vRel, dt);
    const double numberWeighted = collisionMass(rho, sumNr / sumN, rF, segment, vRel, dt);
    RecordProperty("countOverMassWeighted", std::to_string(hitMass / massWeighted));
    RecordProperty("countOverNumberWeighted", std::to_string(hitMass / numberWeighted));
    // ~25000 hits of large droplets: statistical error ~0.6 %; 3 % is > 4 sigma.
    EXPECT_NEAR(hitMass / massWeighted, 1.0, 0.03);
    EXPECT_GT(std::abs(hitMass / numberWeighted - 1.0), 0.5);
    // The default is the one the count supports.
    EXPECT_EQ(CollisionOptions{}.radiusAverage, RadiusAverage::Mass);
}

TEST(CollisionMass, AutomaticSampleCountFollowsGridSpacing)
{
    GridSpec spec;
    spec.lower = Eigen::Vector3d(0, 0, 0);
    spec.upper = Eigen::Vector3d(0.01, 0.01, 0.001);
    spec.nodes = {{11, 11, 1}}; // 1 mm spacing
    const DensityGrid grid(spec);
    CollisionOptions automatic;
    automatic.samples = 0;
    EXPECT_EQ(collisionSamples(grid, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.5e-3, 0, 0), automatic), 3);
    EXPECT_EQ(collisionSamples(grid, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e-4, 0, 0), automatic), 1);
    // Across the flat direction nothing is resolved: one sample.
    EXPECT_EQ(collisionSamples(grid, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1e-3), automatic), 1);
    CollisionOptions fixed;
    fixed.samples = 5;
    EXPECT_EQ(collisionSamples(grid, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.5e-3, 0, 0), fixed), 5);
    // An empty grid collects nothing.
    EXPECT_EQ(collisionMass(grid, Eigen::Vector3d(1e-3, 1e-3, 0), Eigen::Vector3d(2e-3, 1e-3, 0), 1e-4,
                            Eigen::Vector3d::Zero(), 1e-4)
                  .mass,
              0.0);
}
