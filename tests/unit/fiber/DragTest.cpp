// Air drag: coefficients of the documented models, terminal velocity of a fiber
// falling broadside, and the sideways drift of an inclined fiber under anisotropic
// Stokes-regime drag (c_n = 2 c_t): at 54.7 deg to the vertical it drifts at
// atan(sqrt(2)/4) = 19.47 deg.
#include "FiberTestSupport.hpp"

#include "fiber/DragModel.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{
constexpr double airDensity = 1.2;
constexpr double airViscosity = 1.8e-5;
} // namespace

TEST(DragModel, SlenderBodyCoefficients)
{
    DragSettings stokes;
    stokes.model = DragModelType::slenderBodyStokes;
    const double lambda = std::log(0.01 / 5e-6);
    const DragCoefficients c = dragCoefficients(stokes, airDensity, airViscosity, 5e-6, 0.01, 0.3);
    EXPECT_NEAR(c.normal, 4.0 * M_PI * airViscosity / lambda, 1e-15);
    EXPECT_NEAR(c.tangential, 2.0 * M_PI * airViscosity / lambda, 1e-15);

    // Oseen: Re_n = 1.2 * 1e-5 * 0.3 / 1.8e-5 = 0.2; Lamb: ln(8/0.2) + 1/2 - gamma.
    DragSettings oseen;
    oseen.model = DragModelType::slenderBodyOseen;
    const double lamb = std::log(40.0) + 0.5 - 0.5772156649015329;
    EXPECT_NEAR(
        slenderBodyLogarithm(DragModelType::slenderBodyOseen, airDensity, airViscosity, 5e-6, 0.01, 0.3),
        lamb, 1e-12);
    // Slow: the fiber length is the cut-off again.
    EXPECT_NEAR(
        slenderBodyLogarithm(DragModelType::slenderBodyOseen, airDensity, airViscosity, 5e-6, 0.01, 1e-6),
        lambda, 1e-12);
    EXPECT_EQ(dragModelFromName("slenderBodyOseen"), DragModelType::slenderBodyOseen);
    EXPECT_THROW(dragModelFromName("stokes"), std::invalid_argument);
}

TEST(DragModel, FiberLogarithmOncePerFiberGivesTheSameCoefficients)
{
    EXPECT_DOUBLE_EQ(fiberLogarithm(5e-6, 0.01), std::log(2000.0));
    EXPECT_EQ(fiberLogarithm(1e-3, 2e-3), 1.0); // ln 2 < 1: held at 1 (not slender)
    for (DragModelType model : {DragModelType::slenderBodyStokes, DragModelType::slenderBodyOseen})
    {
        DragSettings settings;
        settings.model = model;
        for (double speed : {0.0, 1e-4, 0.3, 50.0})
        { // Re_n = 0, < 1, > 1
            const DragCoefficients direct
                = dragCoefficients(settings, airDensity, airViscosity, 3e-6, 0.01, speed);
            const DragCoefficients split = dragCoefficientsOfFiber(settings, airDensity, airViscosity, 3e-6,
                                                                   fiberLogarithm(3e-6, 0.01), speed);
            EXPECT_EQ(direct.normal, split.normal);
            EXPECT_EQ(direct.tangential, split.tangential);
        }
    }
    // Fast air (Re_n = 1.2 * 6e-6 * 50 / 1.8e-5 = 20 > 1): Lamb's logarithm held at
    // its Re_n = 1 value, ln 8 + 1/2 - gamma.
    DragSettings oseen;
    oseen.model = DragModelType::slenderBodyOseen;
    const DragCoefficients fast
        = dragCoefficientsOfFiber(oseen, airDensity, airViscosity, 3e-6, fiberLogarithm(3e-6, 0.01), 50.0);
    EXPECT_NEAR(fast.normal, 4.0 * M_PI * airViscosity / (std::log(8.0) + 0.5 - 0.5772156649015329), 1e-15);
    DragSettings linear;
    linear.model = DragModelType::linear;
    linear.normalCoefficient = 2.0;
    linear.tangentialCoefficient = 1.0;
    const DragCoefficients c = dragCoefficientsOfFiber(linear, airDensity, airViscosity, 3e-6, 7.0, 0.3);
    EXPECT_EQ(c.normal, 2.0);
    EXPECT_EQ(c.tangential, 1.0);
}

namespace
{

// Vertical velocity of the centre of mass of a horizontal fiber falling in still air.
double terminalSpeed(DragModelType model, double* segmentError, int* subSteps)
{
    const int segments = 50;
    Fiber fiber(straightPoints(segments, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.01),
                glassFiber());
    FiberSolverSettings settings;
    settings.drag.model = model;
    FiberSolver solver(settings);
    std::vector<Fiber> fibers{fiber};
    const RunSummary summary = run(solver, fibers, 1e-3, 200,
                                   uniformAir(fibers, Eigen::Vector3d::Zero(), airDensity, airViscosity));
    *segmentError = summary.worstSegmentError;
    *subSteps = summary.subSteps;
    const Eigen::Vector3d v = fibers[0].momentum() / fibers[0].totalMass();
    return -v.z();
}

} // namespace

TEST(Drag, BroadsideTerminalVelocityStokes)
{
    const double sigmaG = glassFiber().baseLineDensity() * 9.81;
    const double expected = sigmaG * std::log(0.01 / 5e-6) / (4.0 * M_PI * airViscosity);
    double segmentError = 0.0;
    int subSteps = 0;
    const double measured = terminalSpeed(DragModelType::slenderBodyStokes, &segmentError, &subSteps);
    std::printf("terminal velocity (slenderBodyStokes): %.6e m/s, analytic %.6e, relative error %.2e\n",
                measured, expected, measured / expected - 1.0);
    EXPECT_NEAR(measured / expected, 1.0, 0.01);
    EXPECT_LT(segmentError, 1e-8);
}

TEST(Drag, BroadsideTerminalVelocityOseen)
{
    // Analytic: sigma g = 4 pi mu U / Lambda(U), Lambda = min(ln(L/r), ln(8/Re) + 1/2 - gamma).
    const double sigmaG = glassFiber().baseLineDensity() * 9.81;
    const double gammaEuler = 0.5772156649015329;
    double u = 0.05;
    for (int k = 0; k < 100; ++k)
    {
        const double reynolds = airDensity * 1e-5 * u / airViscosity;
        const double lambda = std::min(std::log(0.01 / 5e-6), std::log(8.0 / reynolds) + 0.5 - gammaEuler);
        u = sigmaG * lambda / (4.0 * M_PI * airViscosity);
    }
    double segmentError = 0.0;
    int subSteps = 0;
    const double measured = terminalSpeed(DragModelType::slenderBodyOseen, &segmentError, &subSteps);
    std::printf("terminal velocity (slenderBodyOseen): %.6e m/s, analytic %.6e, relative error %.2e\n",
                measured, u, measured / u - 1.0);
    EXPECT_NEAR(measured / u, 1.0, 0.01);
    EXPECT_LT(segmentError, 1e-8);
}

TEST(Drag, InclinedFiberDriftsAtNineteenPointFiveDegrees)
{
    const int segments = 50;
    const double tilt = std::acos(1.0 / std::sqrt(3.0)); // 54.7356 deg from the vertical
    const Eigen::Vector3d axis(std::sin(tilt), 0.0, -std::cos(tilt));
    Fiber fiber(straightPoints(segments, Eigen::Vector3d::Zero(), axis, 0.01), glassFiber());
    FiberSolverSettings settings;
    settings.drag.model = DragModelType::linear;
    settings.drag.normalCoefficient = 3e-5;
    settings.drag.tangentialCoefficient = 1.5e-5;
    FiberSolver solver(settings);
    std::vector<Fiber> fibers{fiber};
    const RunSummary summary
        = run(solver, fibers, 1e-3, 300, uniformAir(fibers, Eigen::Vector3d::Zero(), 1.2, 1.8e-5));
    const Eigen::Vector3d v = fibers[0].momentum() / fibers[0].totalMass();
    const double drift = std::atan2(std::hypot(v.x(), v.y()), -v.z()) * 180.0 / M_PI;
    const double expected = std::atan(std::sqrt(2.0) / 4.0) * 180.0 / M_PI;
    const Eigen::Vector3d axisNow
        = (fibers[0].positions().col(segments) - fibers[0].positions().col(0)).normalized();
    std::printf("inclined fiber: drift %.4f deg (theory %.4f), axis turned %.2e rad\n", drift, expected,
                (axisNow - axis).norm());
    EXPECT_NEAR(drift, expected, 0.1);
    EXPECT_LT((axisNow - axis).norm(), 1e-6);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
}
