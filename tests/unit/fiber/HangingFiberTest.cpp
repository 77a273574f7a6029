// A fiber pinned at its top hangs at rest: the multiplier of each segment is its
// tension, which must equal g times the mass below it (docs/model.md eq. 2, T as the
// Lagrange multiplier of eq. 3). With lumped masses the mass below segment j is that
// of points j+1..n-1, i.e. sigma (L - s_mid), the continuum tension at mid-segment.
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

TEST(HangingFiber, TensionEqualsWeightBelow)
{
    const int segments = 60;
    const double length = 0.05;
    Fiber fiber(straightPoints(segments, Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitZ(), length),
                glassFiber(), EndCondition::pinnedEnd(), EndCondition::freeEnd());
    // Non-uniform captured mass, so the check is not just a linear profile.
    for (int j = 0; j < segments; ++j)
    {
        fiber.mutableState().segmentCapturedMass(j) = 1e-12 * (1.0 + (j % 7));
    }
    std::vector<Fiber> fibers{fiber};
    FiberSolverSettings settings;
    FiberSolver solver(settings);
    const RunSummary summary = run(solver, fibers, 1e-3, 50);

    const Fiber& hung = fibers[0];
    const Eigen::VectorXd m = hung.pointMasses();
    const double g = settings.gravity.norm();
    double worst = 0.0;
    for (int j = 0; j < segments; ++j)
    {
        const double below = m.tail(segments - j).sum();
        worst = std::max(worst, std::abs(hung.tension()(j) - g * below) / (g * below));
    }
    std::printf("hanging fiber: max relative tension error %.3e, segment error %.3e\n", worst,
                summary.worstSegmentError);
    EXPECT_LT(worst, 1e-8);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
    EXPECT_LT(hung.velocities().norm(), 1e-12);
}
