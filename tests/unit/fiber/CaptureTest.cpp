// Droplet capture (f_contact, docs/model.md sec. 1 and eq. 7): captured mass joins the
// segment and its momentum is added inelastically, so the momentum of fiber plus
// captured droplets is conserved, and sigma (mass per length) grows.
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

TEST(Capture, MomentumOfFiberAndDropletsConserved)
{
    const int segments = 50;
    Fiber fiber(straightPoints(segments, Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 0.3, 0.0), 0.01),
                glassFiber());
    // Start translating and spinning.
    Eigen::Matrix3Xd v(3, segments + 1);
    for (int i = 0; i <= segments; ++i)
    {
        v.col(i)
            = Eigen::Vector3d(0.1, -0.05, 0.02) + Eigen::Vector3d(0, 0, 5.0).cross(fiber.positions().col(i));
    }
    fiber.setVelocities(v);
    std::vector<Fiber> fibers{fiber};

    FiberSolverSettings settings;
    settings.gravity.setZero();
    FiberSolver solver(settings);
    const Eigen::Vector3d p0 = fibers[0].momentum();
    const double m0 = fibers[0].totalMass();
    Eigen::Vector3d injected = Eigen::Vector3d::Zero();
    double injectedMass = 0.0, scale = p0.norm();
    double worstSegmentError = 0.0;
    for (int step = 0; step < 100; ++step)
    {
        CaptureSources capture(1, std::vector<SegmentSource>(segments));
        for (int j = 0; j < segments; ++j)
        {
            if ((j + step) % 5 != 0)
                continue;
            SegmentSource& source = capture[0][static_cast<std::size_t>(j)];
            source.mass = 1e-3 * fibers[0].segmentMass(j);
            source.momentum = source.mass * Eigen::Vector3d(1.0 + 0.1 * j, -2.0, 0.5 * std::sin(step + j));
            injected += source.momentum;
            injectedMass += source.mass;
            scale += source.momentum.norm();
        }
        const StepReport report = solver.step(fibers, 1e-4, AirSample(), &capture);
        worstSegmentError = std::max(worstSegmentError, report.maxSegmentLengthError);
    }
    const double momentumError = (fibers[0].momentum() - p0 - injected).norm() / scale;
    const double massError = std::abs(fibers[0].totalMass() - m0 - injectedMass) / m0;
    const Eigen::VectorXd sigma = fibers[0].lineDensityAtPoints();
    std::printf(
        "capture: momentum error %.3e (relative to total |p|), mass error %.3e, sigma %.4e..%.4e kg/m "
        "(base %.4e), segment error %.1e\n",
        momentumError, massError, sigma.minCoeff(), sigma.maxCoeff(), glassFiber().baseLineDensity(),
        worstSegmentError);
    EXPECT_LT(momentumError, 1e-10);
    EXPECT_LT(massError, 1e-14);
    EXPECT_NEAR(fibers[0].totalCapturedMass(), injectedMass, 1e-14 * m0);
    EXPECT_GT(sigma.minCoeff(), glassFiber().baseLineDensity());
    EXPECT_LT(worstSegmentError, 1e-8);
}

TEST(Capture, ImmobileFiberCollectsMassOnly)
{
    std::vector<Fiber> fibers{Fiber::immobileFiber(
        straightPoints(10, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.01), glassFiber())};
    CaptureSources capture(
        1, std::vector<SegmentSource>(10, SegmentSource{1e-12, Eigen::Vector3d(0, 0, -1e-12)}));
    FiberSolver solver{FiberSolverSettings()};
    const Eigen::Matrix3Xd before = fibers[0].positions();
    const StepReport report = solver.step(fibers, 1e-3, AirSample(), &capture);
    EXPECT_EQ(report.fibersAdvanced, 0);
    EXPECT_NEAR(fibers[0].totalCapturedMass(), 1e-11, 1e-24);
    EXPECT_EQ(fibers[0].positions(), before);
    EXPECT_EQ(fibers[0].velocities().norm(), 0.0);
}
