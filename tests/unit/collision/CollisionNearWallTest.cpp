// Eq. 9 along a fiber one node spacing from a wall of the grid box, in a uniform spray
// filling the box (../grid/FillingSpray.hpp): the grid's density near the wall is the true
// one (docs/model.md sec. 4, edge nodes), so the captured mass is 2 rho (r_F + r)
// |l x v| dt with the true rho, within 1 %.
#include "collision/CollisionMass.hpp"
#include "../grid/FillingSpray.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace dropletFiber;
using namespace dropletFiber::test;

TEST(CollisionNearWall, FiberOneSpacingFromAWallCapturesTheFormulasMass)
{
    // Eq. 9 along a fiber lying one node spacing above the wall y = lower, running wall to
    // wall in x, in a spray moving towards the wall: 2 rho (r_F + r) |l x v| dt with the
    // true rho.
    for (const Deposit& deposit : deposits)
    {
        Spray spray;
        spray.nParticle = deposit.nParticle;
        spray.perCell = 8;
        spray.steps = Eigen::Vector3d(2, -6, 0); // (0.25, -0.75) h per step
        const DensityGrid grid
            = depositSpray(spray, kernelWithReach(deposit.reach, deposit.cloudInCellBelow));
        const GridSpec& spec = grid.spec();
        const double y = spec.lower.y() + spacing;
        const Eigen::Vector3d a(spec.lower.x(), y, 0.5 * depth), b(spec.upper.x(), y, 0.5 * depth);
        const double fiberRadius = 1e-4;
        CollisionOptions options;
        options.samples = 0; // one per spacing
        const SegmentCollision hit
            = collisionMass(grid, a, b, fiberRadius, Eigen::Vector3d::Zero(), dt, options);
        const Eigen::Vector3d l = b - a;
        const double expected = 2.0 * spray.trueDensity() * (fiberRadius + dropletRadius)
            * l.cross(spray.velocity()).norm() * dt;
        EXPECT_NEAR(hit.mass, expected, 0.01 * expected) << deposit.name;
        EXPECT_EQ(hit.samplesOutside, 0);
        std::printf("%-40s fiber at the wall: %.4f of eq. 9\n", deposit.name, hit.mass / expected);
    }
}
