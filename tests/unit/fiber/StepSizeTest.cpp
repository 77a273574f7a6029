// The same uniform-flow case at two CFD step sizes: a fiber pinned at one end,
// started horizontal in a cross-wind with gravity, swings and bends; positions after
// 0.1 s at dt = 2 ms and dt = 0.5 ms agree within 1 % of the displacement.
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

Eigen::Matrix3Xd positionsAfter(double dt, double endTime, double* segmentError, int* subSteps)
{
    std::vector<Fiber> fibers{
        Fiber(straightPoints(50, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.01), glassFiber(),
              EndCondition::pinnedEnd(), EndCondition::freeEnd())};
    FiberSolverSettings settings;
    settings.drag.model = DragModelType::slenderBodyStokes;
    FiberSolver solver(settings);
    const int steps = static_cast<int>(std::lround(endTime / dt));
    const RunSummary summary
        = run(solver, fibers, dt, steps, uniformAir(fibers, Eigen::Vector3d(0.0, 0.3, 0.1), 1.2, 1.8e-5));
    *segmentError = summary.worstSegmentError;
    *subSteps = summary.subSteps;
    return fibers[0].positions();
}

} // namespace

TEST(StepSize, TwoCfdStepSizesAgree)
{
    const Eigen::Matrix3Xd start
        = straightPoints(50, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.01);
    double errorCoarse = 0.0, errorFine = 0.0;
    int subCoarse = 0, subFine = 0;
    const Eigen::Matrix3Xd coarse = positionsAfter(2e-3, 0.1, &errorCoarse, &subCoarse);
    const Eigen::Matrix3Xd fine = positionsAfter(5e-4, 0.1, &errorFine, &subFine);
    const double displacement = (fine - start).colwise().norm().maxCoeff();
    const double difference = (coarse - fine).colwise().norm().maxCoeff();
    std::printf(
        "step size: max point displacement %.3e m, dt=2ms vs 0.5ms max difference %.3e (%.3e relative), "
        "sub-steps %d / %d for %d / %d steps\n",
        displacement, difference, difference / displacement, subCoarse, subFine, 50, 200);
    EXPECT_LT(difference / displacement, 0.01);
    EXPECT_LT(errorCoarse, 1e-8);
    EXPECT_LT(errorFine, 1e-8);
}
