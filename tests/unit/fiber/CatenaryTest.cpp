// A limp fiber (S_b = 0) hanging between two pins 0.8 L apart settles into a
// catenary: L = 2 c sinh(a/c) with a = 0.4 L gives c; sag = c (cosh(a/c) - 1) and
// support tension = sigma g c cosh(a/c) (= 0.265 L and 0.604 sigma g L).
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

TEST(Catenary, SagAndSupportTension)
{
    const int segments = 50;
    const double length = 0.1;
    const double halfSpan = 0.4 * length;
    // Catenary parameter by bisection on f(c) = 2 c sinh(a/c) - L (decreasing in c).
    double lo = 0.01 * length, hi = 10.0 * length;
    for (int k = 0; k < 200; ++k)
    {
        const double c = 0.5 * (lo + hi);
        (2.0 * c * std::sinh(halfSpan / c) > length ? lo : hi) = c;
    }
    const double c = 0.5 * (lo + hi);
    const double expectedSag = c * (std::cosh(halfSpan / c) - 1.0);
    FiberMaterial limp = glassFiber();
    limp.youngsModulus = 0.0;
    const double sigma = limp.baseLineDensity();
    const double g = 9.81;
    const double expectedTension = sigma * g * c * std::cosh(halfSpan / c);

    // Start from a V: every segment has horizontal part 0.8 l and vertical part 0.6 l,
    // so the ends are exactly 0.8 L apart.
    Eigen::Matrix3Xd points(3, segments + 1);
    const double l = length / segments;
    points.col(0).setZero();
    for (int i = 1; i <= segments; ++i)
    {
        const double down = i <= segments / 2 ? -0.6 : 0.6;
        points.col(i) = points.col(i - 1) + l * Eigen::Vector3d(0.8, 0.0, down);
    }
    std::vector<Fiber> fibers{Fiber(points, limp, EndCondition::pinnedEnd(), EndCondition::pinnedEnd())};

    // Backward Euler with steps ~10x the swing period damps each swing ~100x per step.
    FiberSolverSettings settings;
    settings.theta = 1.0;
    FiberSolver solver(settings);
    const RunSummary summary = run(solver, fibers, 10.0 * std::sqrt(length / g), 40);

    const Fiber& chain = fibers[0];
    const double sag = -chain.positions().row(2).minCoeff();
    // Support reaction at the first pin (static): balances segment 0's tension and the
    // weight of the half segment lumped on the pin.
    const Eigen::Vector3d e0 = (chain.positions().col(1) - chain.positions().col(0)).normalized();
    const double pinMass = chain.pointMasses()(0);
    const Eigen::Vector3d reaction = -(chain.tension()(0) * e0 + pinMass * settings.gravity);
    std::printf("catenary: sag/L %.5f (theory %.5f, error %.2e), support tension/(sigma g L) %.5f "
                "(theory %.5f, error %.2e), sub-steps %d, segment error %.1e\n",
                sag / length, expectedSag / length, sag / expectedSag - 1.0,
                reaction.norm() / (sigma * g * length), expectedTension / (sigma * g * length),
                reaction.norm() / expectedTension - 1.0, summary.subSteps, summary.worstSegmentError);
    EXPECT_NEAR(sag / expectedSag, 1.0, 0.005);
    EXPECT_NEAR(reaction.norm() / expectedTension, 1.0, 0.005);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
    EXPECT_LT(chain.velocities().norm(), 1e-8);
}
