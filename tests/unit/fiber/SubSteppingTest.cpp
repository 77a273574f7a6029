// Sub-stepping only where accuracy needs it: stiff bending at steps far beyond its
// period needs none (unconditionally stable), a fast large swing does.
#include "FiberTestSupport.hpp"

#include "fiber/FiberDiagnostics.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

TEST(SubStepping, StiffBendingNeedsNoSubSteps)
{
    // Cantilever vibrating in its first mode, stepped at 5 periods per step.
    const int segments = 50;
    const double length = 0.01;
    const FiberMaterial material = glassFiber();
    const double omega1
        = 3.516 * std::sqrt(material.bendingStiffness() / (material.baseLineDensity() * std::pow(length, 4)));
    EndCondition clamp = EndCondition::clampedEnd();
    clamp.clampDirection = Eigen::Vector3d::UnitX();
    std::vector<Fiber> fibers{
        Fiber(offsetPoints(segments, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                           Eigen::Vector3d::UnitY(), length, [&](double s) { return 1e-4 * s * s / length; }),
              material, clamp, EndCondition::freeEnd())};
    FiberSolverSettings settings;
    settings.gravity.setZero();
    FiberSolver solver(settings);
    const double e0 = diagnose(fibers[0], settings.gravity).totalEnergy();
    const int steps = 200;
    const RunSummary summary = run(solver, fibers, 5.0 * 2.0 * M_PI / omega1, steps);
    const double e1 = diagnose(fibers[0], settings.gravity).totalEnergy();
    std::printf("stiff bending at 5 periods/step: sub-steps %d for %d steps, energy change %.2e, Newton "
                "its/step %.2f\n",
                summary.subSteps, steps, (e1 - e0) / e0,
                static_cast<double>(summary.newtonIterations) / steps);
    EXPECT_EQ(summary.subSteps, steps);
    EXPECT_LT(std::abs(e1 - e0) / e0, 1e-8);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
}

TEST(SubStepping, LargeFastSwingIsSubStepped)
{
    // A stiff rod pinned at one end, released horizontally, stepped at a quarter of
    // its small-swing period: segments turn ~1.5 rad per step, so steps are split.
    // (A limp chain released like this whips - its free end turns ever faster - and
    // needs far more sub-steps; that is the physics, not the scheme.)
    const double length = 0.1;
    std::vector<Fiber> fibers{
        Fiber(straightPoints(50, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), length),
              FiberMaterial{1e-3, 2500.0, 7e10}, EndCondition::pinnedEnd(), EndCondition::freeEnd())};
    FiberSolverSettings settings;
    FiberSolver solver(settings);
    const double dt = 0.25 * 2.0 * M_PI * std::sqrt(2.0 * length / (3.0 * 9.81));
    const double e0 = diagnose(fibers[0], settings.gravity).totalEnergy();
    const RunSummary summary = run(solver, fibers, dt, 8);
    const double e1 = diagnose(fibers[0], settings.gravity).totalEnergy();
    const double scale = fibers[0].totalMass() * 9.81 * length;
    std::printf(
        "large swing at T/4 per step: %d sub-steps in 8 steps (max %d in one), energy change %.2e of m g L\n",
        summary.subSteps, summary.maxSubStepsOfAFiber, (e1 - e0) / scale);
    EXPECT_GT(summary.subSteps, 8);
    EXPECT_LT(std::abs(e1 - e0) / scale, 1e-10);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
}

TEST(SubStepping, ManyFibersOfDifferentSizesAndOneBatchedAirSample)
{
    std::vector<Fiber> fibers;
    for (int k = 0; k < 5; ++k)
    {
        fibers.emplace_back(
            straightPoints(3 + 7 * k, Eigen::Vector3d(0.01 * k, 0, 0), Eigen::Vector3d(1, k, 1), 0.005),
            glassFiber());
    }
    fibers.push_back(Fiber::immobileFiber(
        straightPoints(4, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), 0.01), glassFiber()));
    Eigen::Index expectedPoints = 0;
    for (int k = 0; k < 5; ++k)
        expectedPoints += fibers[static_cast<std::size_t>(k)].pointCount();
    // The caller samples the points the core lays out (the movable fibers only), once per
    // step: the solver takes the sample, it cannot ask again.
    const Eigen::Index sampledPoints = airSamplePoints(fibers).cols();
    FiberSolverSettings settings;
    settings.drag.model = DragModelType::slenderBodyStokes;
    FiberSolver solver(settings);
    const StepReport report
        = solver.step(fibers, 1e-3, uniformAir(fibers, Eigen::Vector3d::Zero(), 1.2, 1.8e-5));
    EXPECT_EQ(sampledPoints, expectedPoints);
    EXPECT_EQ(report.fibersAdvanced, 5);
    EXPECT_LT(report.maxSegmentLengthError, 1e-8);
}

TEST(SubStepping, MovingClampCarriesFiber)
{
    // A fiber spun from a nozzle moving along the fiber axis: all of it follows.
    const Eigen::Vector3d nozzle(0.2, 0.0, 0.0);
    std::vector<Fiber> fibers{
        Fiber(straightPoints(30, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.01), glassFiber(),
              EndCondition::clampedEnd(nozzle), EndCondition::freeEnd())};
    const Eigen::Matrix3Xd start = fibers[0].positions();
    FiberSolverSettings settings;
    settings.gravity.setZero();
    FiberSolver solver(settings);
    const RunSummary summary = run(solver, fibers, 1e-3, 20);
    const Eigen::Matrix3Xd expected = start.colwise() + nozzle * 0.02;
    EXPECT_LT((fibers[0].positions() - expected).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((fibers[0].velocities().colwise() - nozzle).cwiseAbs().maxCoeff(), 1e-10);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
}
