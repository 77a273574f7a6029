// KernelSettings::cloudInCellBelow: parcels whose kernel the grid cannot resolve go to
// the cell corners with multilinear weights, which keep the parcel's centre of mass;
// parcels with a wide kernel are untouched. Expected values: the parcel's own position
// and mass (centre of mass of the node masses), and the grid without the option.
#include "grid/DensityGrid.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dropletFiber;
using test::grid2D;

namespace
{

Parcel stationary(double x, double y, double nParticle)
{
    Parcel p;
    p.position = Eigen::Vector3d(x, y, 5e-4);
    p.velocity = Eigen::Vector3d::Zero();
    p.diameter = 20e-6;
    p.nParticle = nParticle;
    p.rhoDroplet = 1000.0;
    return p;
}

// Centre of mass of the node masses of the committed step.
Eigen::Vector2d centreOfMass(const DensityGrid& grid)
{
    const GridSpec& s = grid.spec();
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    double mass = 0.0;
    for (int j = 0; j < s.nodes[1]; ++j)
    {
        for (int i = 0; i < s.nodes[0]; ++i)
        {
            const double m = grid.windowTotals()[s.flatIndex(i, j, 0) * nQuantities + quantityMass];
            sum += m * Eigen::Vector2d(s.nodeCoordinate(0, i), s.nodeCoordinate(1, j));
            mass += m;
        }
    }
    return sum / mass;
}

} // namespace

TEST(CloudInCell, narrowKernelKeepsTheCentreOfMass)
{
    // 10 droplets of 10 um: r_max = 0.1 mm, far below the 1 mm spacing; the parcel
    // sits 0.05 / 0.03 mm from node (10, 7), so the kernel reaches that node only
    const Parcel p = stationary(0.01005, 0.00703, 10.0);
    KernelSettings paper, resolved;
    resolved.cloudInCellBelow = 0.5;
    DensityGrid a(grid2D(), paper), b(grid2D(), resolved);
    a.deposit(p, 1e-3);
    b.deposit(p, 1e-3);
    EXPECT_EQ(b.stepStatistics().parcelsCloudInCell, 1);
    EXPECT_EQ(a.stepStatistics().parcelsCloudInCell, 0);
    a.commitStep();
    b.commitStep();
    const Eigen::Vector2d exact(0.01005, 0.00703);
    // the paper's kernel hands the whole parcel to node (10, 7): 0.058 mm off
    EXPECT_NEAR((centreOfMass(a) - exact).norm(), std::hypot(5e-5, 3e-5), 1e-12);
    EXPECT_NEAR(centreOfMass(b).x(), exact.x(), 1e-12);
    EXPECT_NEAR(centreOfMass(b).y(), exact.y(), 1e-12);
}

TEST(CloudInCell, wideKernelIsUntouched)
{
    // 1000 droplets of 10 um: r_max = 10 mm, kernel width about 0.5 mm
    Parcel p = stationary(0.0154, 0.0101, 1000.0);
    p.velocity = Eigen::Vector3d(0.3, -0.2, 0.0);
    KernelSettings paper, resolved;
    resolved.cloudInCellBelow = 0.2; // width 0.5 mm > 0.2 * 1 mm: the kernel is used
    DensityGrid a(grid2D(), paper), b(grid2D(), resolved);
    a.deposit(p, 1e-3);
    b.deposit(p, 1e-3);
    EXPECT_EQ(b.stepStatistics().parcelsCloudInCell, 0);
    EXPECT_EQ(a.stepValues(), b.stepValues());
}

TEST(CloudInCell, negativeRatioIsRejected)
{
    KernelSettings bad;
    bad.cloudInCellBelow = -1.0;
    EXPECT_THROW(DensityGrid(grid2D(), bad), std::invalid_argument);
}

TEST(CloudInCell, stepBoxIsTheSmallestBoxHoldingTheTouchedNodes)
{
    // A fast parcel crossing several cells diagonally (path 0.5 mm + 4.2 mm in x, -2.7 mm
    // in y). The step box must hold every node that received mass (the cross-rank sum
    // moves only the box) and be no larger than the nodes' own bounding box.
    KernelSettings settings;
    settings.cloudInCellBelow = 0.5;
    DensityGrid grid(grid2D(), settings, 1);
    Parcel p = stationary(0.0053, 0.0121, 10.0);
    const double dt = 1e-3;
    p.velocity = Eigen::Vector3d(4.2, -2.7, 0.0); // m/s: the path starts at position - v dt
    grid.deposit(p, dt);
    ASSERT_EQ(grid.stepStatistics().parcelsCloudInCell, 1);

    const GridSpec& s = grid.spec();
    IndexBox touched;
    for (int j = 0; j < s.nodes[1]; ++j)
    {
        for (int i = 0; i < s.nodes[0]; ++i)
        {
            if (grid.stepValues()[s.flatIndex(i, j, 0) * nQuantities + quantityMass] != 0.0)
            {
                IndexBox node;
                node.lo = {{i, j, 0}};
                node.hi = {{i, j, 0}};
                touched = touched.united(node);
            }
        }
    }
    ASSERT_FALSE(touched.empty());
    // Multilinear weights of interior points are all non-zero, so the box of the nodes
    // with mass and the box of the corners coincide here.
    EXPECT_EQ(grid.stepBox(), touched);
    // And it spans the path: x from 0.0011 to 0.0053 m, y from 0.0148 to 0.0121 m.
    EXPECT_EQ(touched.lo[0], 1);
    EXPECT_EQ(touched.hi[0], 6);
    EXPECT_EQ(touched.lo[1], 12);
    EXPECT_EQ(touched.hi[1], 15);
}
