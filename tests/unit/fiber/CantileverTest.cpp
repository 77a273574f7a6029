// Clamped-free fiber (cantilever): static deflection under its own weight, buckling
// under an axial tip load, and the first two bending frequencies, against
// Euler-Bernoulli beam theory.
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

// Static tip deflection: backward Euler with a step far beyond every time scale of
// the fiber is a Newton solve of the static equilibrium.
double staticTipDeflection(int segments, double length, double* segmentError)
{
    Fiber fiber(straightPoints(segments, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), length),
                glassFiber(), EndCondition::clampedEnd(), EndCondition::freeEnd());
    FiberSolverSettings settings;
    settings.theta = 1.0;
    FiberSolver solver(settings);
    std::vector<Fiber> fibers{fiber};
    const RunSummary summary = run(solver, fibers, 1e3, 3);
    *segmentError = summary.worstSegmentError;
    return -fibers[0].positions()(2, segments);
}

} // namespace

TEST(Cantilever, OwnWeightDeflectionConvergesSecondOrder)
{
    const FiberMaterial material = glassFiber();
    const double q = material.baseLineDensity() * 9.81;
    const double EI = material.bendingStiffness();
    // Length such that the beam-theory tip deflection is 1e-3 L (small deflection, so
    // the geometric nonlinearity, ~ (tip/L)^2, stays far below the discretisation error).
    const double ratio = 1e-3;
    const double length = std::cbrt(8.0 * EI * ratio / q);
    const double expected = q * std::pow(length, 4) / (8.0 * EI);

    std::vector<double> errors;
    for (int segments : {25, 50, 100})
    {
        double segmentError = 0.0;
        const double tip = staticTipDeflection(segments, length, &segmentError);
        errors.push_back(std::abs(tip - expected) / expected);
        std::printf("cantilever N=%3d: tip %.6e expected %.6e relative error %.3e (segment error %.1e)\n",
                    segments, tip, expected, errors.back(), segmentError);
        EXPECT_LT(segmentError, 1e-8);
    }
    EXPECT_LT(errors[1], 0.01);
    const double order1 = std::log2(errors[0] / errors[1]);
    const double order2 = std::log2(errors[1] / errors[2]);
    std::printf("cantilever observed order %.2f, %.2f\n", order1, order2);
    EXPECT_GT(order1, 1.7);
    EXPECT_GT(order2, 1.7);
}

TEST(Cantilever, LargerDeflectionWithinOnePercent)
{
    const FiberMaterial material = glassFiber();
    const double q = material.baseLineDensity() * 9.81;
    const double EI = material.bendingStiffness();
    const double length = std::cbrt(8.0 * EI * 0.02 / q); // tip/L = 0.02
    const double expected = q * std::pow(length, 4) / (8.0 * EI);
    double segmentError = 0.0;
    const double tip = staticTipDeflection(50, length, &segmentError);
    std::printf("cantilever tip/L=0.02, N=50: relative error %.3e\n", std::abs(tip - expected) / expected);
    EXPECT_LT(std::abs(tip - expected) / expected, 0.01);
    EXPECT_LT(segmentError, 1e-8);
}

namespace
{

// Largest lateral tip excursion / L under a compressive dead tip load of
// loadFactor * pi^2 EI / (4 L^2), starting straight with a tiny lateral velocity.
double bucklingExcursion(double loadFactor, double* segmentError)
{
    const int segments = 50;
    const double length = 0.01;
    const FiberMaterial material = glassFiber();
    const double EI = material.bendingStiffness();
    const double sigma = material.baseLineDensity();
    const double omega1 = 3.516 * std::sqrt(EI / (sigma * std::pow(length, 4)));
    const double period1 = 2.0 * M_PI / omega1;

    Fiber fiber(straightPoints(segments, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), length), material,
                EndCondition::clampedEnd(), EndCondition::freeEnd());
    Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, segments + 1);
    force(0, segments) = -loadFactor * M_PI * M_PI * EI / (4.0 * length * length);
    fiber.setExternalForce(force);
    Eigen::Matrix3Xd velocity = Eigen::Matrix3Xd::Zero(3, segments + 1);
    for (int i = 0; i <= segments; ++i)
    {
        const double s = static_cast<double>(i) / segments;
        velocity(1, i) = 1e-6 * length * omega1 * s * s;
    }
    fiber.setVelocities(velocity);

    FiberSolverSettings settings;
    settings.gravity.setZero();
    FiberSolver solver(settings);
    std::vector<Fiber> fibers{fiber};
    double excursion = 0.0;
    const RunSummary summary
        = run(solver, fibers, period1 / 40.0, 40 * 25, AirSample(),
              [&](int, const StepReport&)
              { excursion = std::max(excursion, std::abs(fibers[0].positions()(1, segments))); });
    *segmentError = summary.worstSegmentError;
    return excursion / length;
}

} // namespace

TEST(Cantilever, BucklesAboveEulerLoadOnly)
{
    double segmentError = 0.0;
    const double below = bucklingExcursion(0.95, &segmentError);
    EXPECT_LT(segmentError, 1e-8);
    const double above = bucklingExcursion(1.05, &segmentError);
    EXPECT_LT(segmentError, 1e-8);
    std::printf("buckling: max tip excursion / L at 0.95 P_cr %.3e, at 1.05 P_cr %.3e\n", below, above);
    EXPECT_LT(below, 1e-4); // stays straight (perturbation ~1e-6 L)
    EXPECT_GT(above, 0.1);  // buckles
}

namespace
{

// Cantilever mode shape (beam theory), beta L = root of 1 + cos cosh = 0.
double modeShape(double betaL, double s)
{
    const double sigma = (std::cosh(betaL) + std::cos(betaL)) / (std::sinh(betaL) + std::sin(betaL));
    const double x = betaL * s;
    return std::cosh(x) - std::cos(x) - sigma * (std::sinh(x) - std::sin(x));
}

double measuredFrequencyRatio(double betaL, double expectedSquare, int segments)
{
    const double length = 0.01;
    const FiberMaterial material = glassFiber();
    const double EI = material.bendingStiffness();
    const double sigma = material.baseLineDensity();
    const double omega = expectedSquare * std::sqrt(EI / (sigma * std::pow(length, 4)));
    const double period = 2.0 * M_PI / omega;
    const double amplitude = 1e-5 * length;

    auto shape = [&](double s) { return amplitude * modeShape(betaL, s / length) / 2.0; };
    EndCondition clamp = EndCondition::clampedEnd();
    clamp.clampDirection = Eigen::Vector3d::UnitX();
    Fiber fiber(offsetPoints(segments, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                             Eigen::Vector3d::UnitY(), length, shape),
                material, clamp, EndCondition::freeEnd());
    Eigen::VectorXd reference = fiber.positions().row(1).transpose();
    const Eigen::VectorXd m = fiber.pointMasses();

    FiberSolverSettings settings;
    settings.gravity.setZero();
    FiberSolver solver(settings);
    std::vector<Fiber> fibers{fiber};
    std::vector<double> times{0.0}, signal{reference.dot(m.cwiseProduct(reference))};
    const double dt = period / 200.0;
    const RunSummary summary = run(solver, fibers, dt, 200 * 6, AirSample(),
                                   [&](int k, const StepReport&)
                                   {
                                       times.push_back((k + 1) * dt);
                                       const Eigen::VectorXd lateral
                                           = fibers[0].positions().row(1).transpose();
                                       signal.push_back(lateral.dot(m.cwiseProduct(reference)));
                                   });
    EXPECT_LT(summary.worstSegmentError, 1e-8);
    return period / meanPeriod(times, signal); // omega_measured / omega_expected
}

} // namespace

TEST(Cantilever, FirstTwoBendingFrequencies)
{
    const double ratio1 = measuredFrequencyRatio(1.87510407, 3.516, 50);
    const double ratio2 = measuredFrequencyRatio(4.69409113, 22.03, 50);
    std::printf("cantilever frequencies: omega1/theory - 1 = %.3e, omega2/theory - 1 = %.3e\n", ratio1 - 1.0,
                ratio2 - 1.0);
    EXPECT_NEAR(ratio1, 1.0, 0.01);
    EXPECT_NEAR(ratio2, 1.0, 0.02);
}
