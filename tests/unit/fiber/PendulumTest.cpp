// Fibers swinging under gravity from a pinned top end: a stiff fiber is a uniform
// rod pendulum (T = 2 pi sqrt(2L/3g)); a limp one is a hanging chain whose first mode
// is omega_1 = (j_01 / 2) sqrt(g/L) = 1.2024 sqrt(g/L). Also the energy behaviour of
// the midpoint scheme over 100 periods.
#include "FiberTestSupport.hpp"

#include "fiber/FiberDiagnostics.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

// Stiff rod: r = 1 mm glass, L = 0.1 m: S_b / (sigma g L^3) ~ 700, so bending is
// negligible for the swing.
Fiber stiffPendulum(int segments, double length, double angle)
{
    const Eigen::Vector3d direction(std::sin(angle), 0.0, -std::cos(angle));
    return Fiber(straightPoints(segments, Eigen::Vector3d::Zero(), direction, length),
                 FiberMaterial{1e-3, 2500.0, 7e10}, EndCondition::pinnedEnd(), EndCondition::freeEnd());
}

} // namespace

TEST(Pendulum, StiffRodPeriod)
{
    const double length = 0.1;
    const double g = 9.81;
    const double period = 2.0 * M_PI * std::sqrt(2.0 * length / (3.0 * g));
    std::vector<Fiber> fibers{stiffPendulum(50, length, 0.05)};
    FiberSolver solver{FiberSolverSettings()};
    const double dt = period / 200.0;
    std::vector<double> times{0.0}, signal{fibers[0].positions()(0, 50)};
    const RunSummary summary = run(solver, fibers, dt, 200 * 5, AirSample(),
                                   [&](int k, const StepReport&)
                                   {
                                       times.push_back((k + 1) * dt);
                                       signal.push_back(fibers[0].positions()(0, 50));
                                   });
    const double measured = meanPeriod(times, signal);
    std::printf("rod pendulum: period %.6f s, theory %.6f s, relative error %.3e, segment error %.1e\n",
                measured, period, measured / period - 1.0, summary.worstSegmentError);
    EXPECT_NEAR(measured / period, 1.0, 0.01);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
}

TEST(Pendulum, LimpChainFirstMode)
{
    const int segments = 50;
    const double length = 0.1;
    const double g = 9.81;
    const double j01 = 2.404825557695773;
    const double omega = 0.5 * j01 * std::sqrt(g / length); // = 1.2024 sqrt(g/L)
    // First mode: lateral offset J0(j01 sqrt(z/L)), z measured up from the free end.
    auto shape = [&](double s)
    { return 1e-4 * length * std::cyl_bessel_j(0.0, j01 * std::sqrt((length - s) / length)); };
    FiberMaterial limp = glassFiber();
    limp.youngsModulus = 0.0;
    Fiber chain(offsetPoints(segments, Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitZ(),
                             Eigen::Vector3d::UnitX(), length, shape),
                limp, EndCondition::pinnedEnd(), EndCondition::freeEnd());
    const Eigen::VectorXd reference = chain.positions().row(0).transpose();
    const Eigen::VectorXd m = chain.pointMasses();
    std::vector<Fiber> fibers{chain};
    FiberSolver solver{FiberSolverSettings()};
    const double period = 2.0 * M_PI / omega;
    const double dt = period / 200.0;
    std::vector<double> times{0.0}, signal{reference.dot(m.cwiseProduct(reference))};
    const RunSummary summary
        = run(solver, fibers, dt, 200 * 6, AirSample(),
              [&](int k, const StepReport&)
              {
                  times.push_back((k + 1) * dt);
                  signal.push_back(fibers[0].positions().row(0).dot(m.cwiseProduct(reference)));
              });
    const double measuredOmega = 2.0 * M_PI / meanPeriod(times, signal);
    std::printf("hanging chain: omega_1 sqrt(L/g) = %.5f (theory 1.20241), relative error %.3e\n",
                measuredOmega * std::sqrt(length / g), measuredOmega / omega - 1.0);
    EXPECT_NEAR(measuredOmega / omega, 1.0, 0.01);
    EXPECT_LT(summary.worstSegmentError, 1e-8);
}

TEST(Pendulum, EnergyOverHundredPeriods)
{
    const double length = 0.1;
    const double g = 9.81;
    const double period = 2.0 * M_PI * std::sqrt(2.0 * length / (3.0 * g));
    const double amplitude = 0.5; // rad: a real swing, not the linear limit
    struct Variant
    {
        double theta;
        bool projectEachSubStep;
    };
    for (const Variant variant : {Variant{0.5, false}, Variant{0.5, true}, Variant{1.0, false}})
    {
        const double theta = variant.theta;
        FiberSolverSettings settings;
        settings.theta = theta;
        settings.projectVelocitiesAfterSubStep = variant.projectEachSubStep;
        FiberSolver solver(settings);
        std::vector<Fiber> fibers{stiffPendulum(50, length, amplitude)};
        // Energy relative to the rest state (hanging straight down).
        const double restEnergy = fibers[0].totalMass() * g * (-0.5 * length); // m g z_com
        auto swingEnergy = [&]() { return diagnose(fibers[0], settings.gravity).totalEnergy() - restEnergy; };
        const double e0 = swingEnergy();
        const int periods = 100;
        const int perPeriod = 100;
        double worstDrift = 0.0;
        double afterOnePeriod = 0.0;
        double firstPeriodSegmentError = 0.0, lastPeriodSegmentError = 0.0;
        const RunSummary summary
            = run(solver, fibers, period / perPeriod, periods * perPeriod, AirSample(),
                  [&](int k, const StepReport& report)
                  {
                      const double e = swingEnergy();
                      worstDrift = std::max(worstDrift, std::abs(e - e0) / e0);
                      if (k + 1 == perPeriod)
                          afterOnePeriod = e / e0;
                      double& bucket = k < perPeriod ? firstPeriodSegmentError : lastPeriodSegmentError;
                      if (k < perPeriod || k >= (periods - 1) * perPeriod)
                      {
                          bucket = std::max(bucket, report.maxSegmentLengthError);
                      }
                  });
        const double finalRatio = swingEnergy() / e0;
        if (theta == 0.5 && variant.projectEachSubStep)
        {
            std::printf("midpoint + velocity projection every sub-step, 100 periods at T/100: final E/E0 - 1 "
                        "= %.3e\n",
                        finalRatio - 1.0);
            EXPECT_LT(finalRatio, 1.0 + 1e-9); // the projection only removes energy
        }
        else if (theta == 0.5)
        {
            std::printf(
                "midpoint (theta=0.5), 100 periods at T/100: max |dE|/E = %.3e, final E/E0 - 1 = %.3e, "
                "segment error %.1e, Newton iterations/step %.2f\n",
                worstDrift, finalRatio - 1.0, summary.worstSegmentError,
                static_cast<double>(summary.newtonIterations) / (periods * perPeriod));
            EXPECT_LT(worstDrift, 1e-3);
        }
        else
        {
            std::printf("backward Euler (theta=1) at T/100: energy decay in the first period %.3e "
                        "(E/E0 after 1 period %.3e, after 100 periods %.3e)\n",
                        1.0 - afterOnePeriod, afterOnePeriod, finalRatio);
            EXPECT_LT(afterOnePeriod, 1.0);
        }
        std::printf("  segment-length error: first period %.2e, last period %.2e\n", firstPeriodSegmentError,
                    lastPeriodSegmentError);
        EXPECT_LT(summary.worstSegmentError, 1e-8);
        EXPECT_LT(lastPeriodSegmentError, 1e-11); // round-off level, not growing
    }
}
