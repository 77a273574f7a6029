// The belt and the mat's map: where a fiber is laid (its centre's foot, the belt's
// frame by hand), what it carries, and the map's area weights, LOI and across profile
// for fibers placed by hand.
#include "laydown/Belt.hpp"
#include "laydown/MatMap.hpp"
#include "laydown/MatUncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dropletFiber;

namespace
{
// A straight fiber of `segments` segments from start along direction, glass r = 5 um.
Fiber straightFiber(const Eigen::Vector3d& start, const Eigen::Vector3d& direction, double length,
                    int segments)
{
    Eigen::Matrix3Xd x(3, segments + 1);
    for (int i = 0; i <= segments; ++i)
        x.col(i) = start + direction.normalized() * (length * i / segments);
    return Fiber(x, FiberMaterial{5e-6, 2500.0, 7e10});
}

// The belt at y = 0, air above (normal -y), moving along +x at 0.5 m/s.
Belt floorBelt()
{
    Belt b;
    b.point = Eigen::Vector3d(0, 0, 0);
    b.normal = Eigen::Vector3d(0, -1, 0);
    b.velocity = Eigen::Vector3d(0.5, 0, 0);
    return b;
}
} // namespace

TEST(Belt, FrameAndCrossing)
{
    const Belt belt = floorBelt();
    EXPECT_NO_THROW(belt.validate());
    // e_a = +x, e_c = n x e_a = (0,-1,0) x (1,0,0) = (0,0,1)
    EXPECT_LT((belt.acrossDirection() - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
    const Fiber above = straightFiber(Eigen::Vector3d(0.1, 0.001, 0.2), Eigen::Vector3d::UnitZ(), 0.01, 4);
    const Fiber below = straightFiber(Eigen::Vector3d(0.1, -0.001, 0.2), Eigen::Vector3d::UnitZ(), 0.01, 4);
    EXPECT_FALSE(reachesBelt(above, belt));
    EXPECT_TRUE(reachesBelt(below, belt));

    const LaidFiber laid = layFiber(below, belt, 2.0, 7);
    // centre (0.1, -0.001, 0.205): foot (0.1, 0, 0.205); across 0.205, along 0.5*2 - 0.1
    EXPECT_NEAR(laid.across, 0.205, 1e-15);
    EXPECT_NEAR(laid.along, 0.9, 1e-15);
    EXPECT_NEAR(laid.orientation.x(), 1.0, 1e-15); // along z = across the belt
    EXPECT_NEAR(laid.length, 0.01, 1e-15);
    EXPECT_NEAR(laid.glassMass, 2500.0 * M_PI * 25e-12 * 0.01, 1e-20);
    EXPECT_EQ(laid.binderMass, 0.0);
    EXPECT_EQ(laid.bareFraction, 1.0);
    EXPECT_EQ(laid.id, 7);

    Belt tilted = belt;
    tilted.velocity = Eigen::Vector3d(0.5, 0.1, 0);
    EXPECT_THROW(tilted.validate(), std::invalid_argument);
}

TEST(MatMap, AreaWeightsLoiAndProfile)
{
    // Belt 0.3 m wide (across 0 to 0.3), cells of 0.1 m: three columns.
    MatMap map(0.1, 0.0, 0.3);
    EXPECT_EQ(map.lattice().columns(), 3);
    LaidFiber f;
    f.glassMass = 2e-9;
    f.binderMass = 1e-10;
    f.represents = 1000.0;
    f.orientation = Eigen::Vector3d(0, 1, 0); // along the belt: cos 2 theta = 1
    // Two fibers in column 0, one in column 2, all in row 0; one in column 1, row 1
    for (double across : {0.05, 0.07, 0.25})
    {
        f.across = across;
        f.along = 0.05;
        map.add(f);
    }
    f.across = 0.15;
    f.along = 0.15;
    f.orientation = Eigen::Vector3d(1, 0, 0); // across: -1
    map.add(f);

    const MatCell total = map.total();
    EXPECT_NEAR(total.glass, 4 * 1000 * 2e-9, 1e-20);
    EXPECT_NEAR(total.binder, 4 * 1000 * 1e-10, 1e-20);
    EXPECT_NEAR(total.fibers, 4000.0, 1e-12);
    EXPECT_NEAR(total.orientationSum, (3 - 1) * 1000 * 2e-9, 1e-20);

    // Over rows 0 and 1 (area 0.1 x 0.2 per column): 4e-6, 2e-6, 2e-6 kg over 0.02 m^2
    const AcrossProfile profile = acrossProfileWithErrors(map, 0, 1);
    ASSERT_EQ(profile.areaWeight.size(), 3u);
    EXPECT_NEAR(profile.areaWeight[0].value, 4e-6 / 0.02, 1e-15);
    EXPECT_NEAR(profile.areaWeight[1].value, 2e-6 / 0.02, 1e-15);
    EXPECT_NEAR(profile.areaWeight[2].value, 2e-6 / 0.02, 1e-15);
    // mean 4/3 1e-4, deviations (2/3, -1/3, -1/3) 1e-4: population sd sqrt(2/9) 1e-4,
    // CoV sqrt(2)/3 / (4/3) = sqrt(2)/4
    EXPECT_NEAR(nonUniformity(profile).observed, std::sqrt(2.0) / 4.0, 1e-12);
    EXPECT_THROW(MatMap(0.0, 0.0, 1.0), std::invalid_argument);
}

TEST(MatMap, OrientationOrder)
{
    EXPECT_NEAR(orientationOrder(Eigen::Vector3d(0, 1, 0)), 1.0, 1e-15);
    EXPECT_NEAR(orientationOrder(Eigen::Vector3d(1, 0, 0)), -1.0, 1e-15);
    EXPECT_NEAR(orientationOrder(Eigen::Vector3d(std::sqrt(0.5), std::sqrt(0.5), 0)), 0.0, 1e-15);
    EXPECT_EQ(orientationOrder(Eigen::Vector3d(0, 0, 1)), 0.0);
}
