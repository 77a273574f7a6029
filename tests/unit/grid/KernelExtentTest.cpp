// KernelExtent: the widest-kernel figures DensityGrid::deposit records in its step
// statistics (docs/model.md sec. 4, cost of wide kernels). The width is checked against the
// paper's figure-4 kernel; the reach against its defining property (P10: the weight bound at
// the cut is negligibleWeight times the parcel's least largest weight) and against the nodes
// the deposit visits.
#include "grid/DensityGrid.hpp"
#include "grid/KernelExtent.hpp"
#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dropletFiber;

namespace
{
KernelSettings settings2D(double negligibleWeight)
{
    KernelSettings s;
    s.dimension = KernelDimension::TwoD;
    s.negligibleWeight = negligibleWeight;
    return s;
}

Parcel wideParcel(const Eigen::Vector3d& velocity)
{
    // r_max = 12.5 mm, width ~0.89 mm: the 1e-17 cut binds (alpha ~100 > 39)
    Parcel p;
    p.position = Eigen::Vector3d(0.0153, 0.0103, 0.0005);
    p.velocity = velocity;
    p.diameter = 5e-5;
    p.nParticle = 500.0;
    p.rhoDroplet = 1000.0;
    return p;
}

// Lattice nodes in [x - R, x + R] along one direction (spacing 1 mm, lower 0): the box
// DensityGrid::deposit visits for a path from a to b reaching R.
long nodesAlong(double a, double b, double reach)
{
    const double h = 1e-3;
    return static_cast<long>(std::floor((std::max(a, b) + reach) / h)
                             - std::ceil((std::min(a, b) - reach) / h))
        + 1;
}
} // namespace

TEST(KernelExtent, WidthOfFigure4KernelInSpacings)
{
    // n = 1000, r_p = 1e-5 m, 2D: r_max = 1e-2 m, alpha = 151.9 (the paper's figure 4), so
    // the width r_max / sqrt(2 alpha) is 5.737e-4 m: 0.5737 spacings of 1 mm.
    DensityGrid grid(test::grid2D(), settings2D(0.0));
    Parcel p;
    p.position = Eigen::Vector3d(0.015, 0.01, 0.0005);
    p.diameter = 2e-5;
    p.nParticle = 1000.0;
    p.rhoDroplet = 1000.0;
    grid.deposit(p, 1e-3);
    const StepStatistics& stats = grid.stepStatistics();
    EXPECT_NEAR(stats.widestKernelWidth, 1e-2 / std::sqrt(2.0 * 151.9) / 1e-3, 2e-4);
    // negligibleWeight 0: every node within r_max = 10 spacings
    EXPECT_NEAR(stats.widestKernelReach, 10.0, 1e-12);
    EXPECT_EQ(stats.parcelsCloudInCell, 0);
}

TEST(KernelExtent, ReachIsWhereTheBoundFallsToNegligibleWeight)
{
    for (const double epsilon : {1e-17, 1e-12, 1e-8, 1e-6})
    {
        const ParcelKernel kernel(2.5e-5, 500.0, settings2D(epsilon), 2);
        const double c = std::sqrt(0.5) * 1e-3; // half the diagonal of a 1 mm square cell
        const double pathLength = 2e-3;
        const double d = negligibleReach(kernel, pathLength, c, epsilon);
        ASSERT_LT(d, kernel.reach());
        // exp(-gamma d^2) = epsilon * phi(c + L/2), with phi from eq. 12
        const double largestBound
            = std::exp(-kernel.alpha() * std::pow(c + 0.5 * pathLength, 2) / std::pow(kernel.rMax(), 2))
            - std::exp(-kernel.alpha());
        EXPECT_NEAR(std::exp(-kernel.alpha() * d * d / std::pow(kernel.rMax(), 2)) / largestBound, epsilon,
                    1e-9 * epsilon);
    }
}

TEST(KernelExtent, ReachGivesTheNodesTheDepositVisits)
{
    // Stationary and moving (2 mm along x during the step), interior of the grid.
    for (const double speed : {0.0, 2.0})
    {
        for (const double epsilon : {1e-17, 1e-8})
        {
            const KernelSettings settings = settings2D(epsilon);
            DensityGrid grid(test::grid2D(), settings);
            const Parcel p = wideParcel(Eigen::Vector3d(speed, 0.0, 0.0));
            const double dt = 1e-3;
            grid.deposit(p, dt);
            const double reach = grid.stepStatistics().widestKernelReach * 1e-3;
            const double startX = p.position.x() - speed * dt;
            const long expected = nodesAlong(startX, p.position.x(), reach)
                * nodesAlong(p.position.y(), p.position.y(), reach);
            EXPECT_EQ(grid.stepStatistics().nodesVisited, expected)
                << "speed " << speed << ", negligibleWeight " << epsilon;
        }
    }
}

TEST(KernelExtent, RecordKeepsTheWidestAndSumsTakeTheLarger)
{
    Parcel narrow = wideParcel(Eigen::Vector3d::Zero());
    narrow.nParticle = 50.0;
    const Parcel wide = wideParcel(Eigen::Vector3d::Zero());
    DensityGrid wideAlone(test::grid2D(), settings2D(1e-17));
    wideAlone.deposit(wide, 1e-3);
    DensityGrid both(test::grid2D(), settings2D(1e-17));
    both.deposit(wide, 1e-3);
    both.deposit(narrow, 1e-3);
    const StepStatistics& a = both.stepStatistics();
    EXPECT_DOUBLE_EQ(a.widestKernelWidth, wideAlone.stepStatistics().widestKernelWidth);
    EXPECT_DOUBLE_EQ(a.widestKernelReach, wideAlone.stepStatistics().widestKernelReach);
    DensityGrid narrowAlone(test::grid2D(), settings2D(1e-17));
    narrowAlone.deposit(narrow, 1e-3);
    StepStatistics b = narrowAlone.stepStatistics();
    EXPECT_LT(b.widestKernelWidth, a.widestKernelWidth);
    b += a;
    EXPECT_DOUBLE_EQ(b.widestKernelWidth, a.widestKernelWidth);
    EXPECT_DOUBLE_EQ(b.widestKernelReach, a.widestKernelReach);
}
