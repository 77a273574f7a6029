// Newton's method on the implicit step converges quadratically only with the exact
// Jacobian: from the first iterate x_n + h v_n, whose relative error is about
// theta h^2 |a| / l (1e-3 to 1e-2 here, the bent fibers' bending release being the
// largest), the errors go 1e-2, 1e-4, 1e-8, 1e-16: at most three updates to the
// 1e-13 constraint tolerance and a fourth only when round-off blurs the last one.
// A wrong Jacobian term (drag tangent, tension, constraint rows, their scaling)
// makes the convergence linear and shows up as more iterations long before it
// shows up in the physics tests. Fibers as in the channelSpray tutorial (r = 3 um,
// 1 cm, 21 points, dt = 5e-4 s, slenderBodyOseen drag) in sheared air, free, pinned
// and clamped (held rows), bent and tilted so that all Jacobian blocks are non-zero.
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

AirSample shearedAir(const Eigen::Matrix3Xd& points)
{
    const Eigen::Index n = points.cols();
    AirSample air;
    air.velocity.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        // 2 m/s down, shear 200 1/s across, a weak swirl along the flow
        air.velocity.col(i)
            = Eigen::Vector3d(0.1 * std::sin(300.0 * points(1, i)), -2.0 + 200.0 * points(0, i), 0.05);
    }
    air.density = Eigen::VectorXd::Constant(n, 1.2);
    air.viscosity = Eigen::VectorXd::Constant(n, 1.8e-5);
    return air;
}

} // namespace

TEST(NewtonConvergence, AtMostThreeIterationsPerStepForTutorialFibers)
{
    const FiberMaterial glass{3e-6, 2500.0, 7e10};
    const auto bent = [](double s) { return 3e-4 * std::sin(300.0 * s); };
    std::vector<Fiber> fibers;
    fibers.emplace_back(offsetPoints(20, Eigen::Vector3d(0.0, 0.0, 0.0),
                                     Eigen::Vector3d(1.0, 0.2, 0.1).normalized(), Eigen::Vector3d::UnitY(),
                                     0.01, bent),
                        glass);
    fibers.emplace_back(offsetPoints(20, Eigen::Vector3d(0.0, 0.01, 0.0),
                                     Eigen::Vector3d(1.0, -0.3, 0.0).normalized(), Eigen::Vector3d::UnitZ(),
                                     0.01, bent),
                        glass, EndCondition::pinnedEnd(Eigen::Vector3d(0.0, -2.0, 0.0)));
    fibers.emplace_back(
        straightPoints(20, Eigen::Vector3d(0.0, 0.02, 0.0), Eigen::Vector3d(1.0, 0.3, 0.0), 0.01), glass,
        EndCondition::clampedEnd(Eigen::Vector3d(0.0, -2.0, 0.0)));
    for (Fiber& fiber : fibers)
        fiber.setVelocities(Eigen::Vector3d(0.0, -2.0, 0.0).replicate(1, 21));

    FiberSolverSettings settings;
    settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    settings.drag.model = DragModelType::slenderBodyOseen;
    FiberSolver solver(settings);
    int worst = 0, loose = 0, rejected = 0;
    const RunSummary summary = run(solver, fibers, 5e-4, 100, shearedAir,
                                   [&](int, const StepReport& report)
                                   {
                                       worst = std::max(worst, report.maxNewtonIterations);
                                       loose += report.looseConvergences;
                                       rejected += report.rejectedSubSteps;
                                   });
    EXPECT_EQ(summary.subSteps, 300); // one sub-step per fiber and step
    EXPECT_EQ(loose, 0);
    EXPECT_EQ(rejected, 0);
    EXPECT_LE(worst, 4);
    EXPECT_LE(static_cast<double>(summary.newtonIterations) / summary.subSteps, 3.5);
    EXPECT_LT(summary.worstSegmentError, 1e-12);
}
