// The drag as the air feels it (DragReaction): over a step, the impulse recorded per
// point is what changed the fibers' momentum (a free fiber without gravity: its
// momentum change; with gravity: less m g dt), and an immobile fiber across a uniform
// air stream feels l c_n u per point with c_n of slender-body theory, 4 pi mu / ln(L/r).
#include "FiberTestSupport.hpp"

#include "fiber/DragModel.hpp"
#include "fiber/DragReaction.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{
constexpr double airDensity = 1.2;
constexpr double airViscosity = 1.8e-5;

Eigen::Vector3d sum(const Eigen::Matrix3Xd& columns)
{
    return columns.rowwise().sum();
}
} // namespace

TEST(DragReaction, ImpulseIsTheFibersMomentumChange)
{
    // A bent fiber in a sheared, fast air: many sub-steps, tension, bending
    std::vector<Fiber> fibers;
    fibers.emplace_back(offsetPoints(10, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                     Eigen::Vector3d::UnitY(), 0.01,
                                     [](double s) { return 2e-3 * std::sin(300.0 * s); }),
                        glassFiber());
    fibers.emplace_back(straightPoints(6, Eigen::Vector3d(0, 0.01, 0), Eigen::Vector3d(1, 1, 0), 0.005),
                        glassFiber());
    const std::vector<Eigen::Vector3d> gravities{Eigen::Vector3d::Zero(), Eigen::Vector3d(0, -9.81, 0)};
    for (const Eigen::Vector3d& gravity : gravities)
    {
        FiberSolverSettings settings;
        settings.drag.model = DragModelType::slenderBodyOseen;
        settings.gravity = gravity;
        FiberSolver solver(settings);
        for (int step = 0; step < 5; ++step)
        {
            const Eigen::Matrix3Xd points = airSamplePoints(fibers);
            AirSample air = uniformAir(fibers, Eigen::Vector3d::Zero(), airDensity, airViscosity);
            for (Eigen::Index i = 0; i < points.cols(); ++i)
                air.velocity.col(i) = Eigen::Vector3d(2.0 + 300.0 * points(1, i), -1.0, 0.5);
            Eigen::Vector3d before = Eigen::Vector3d::Zero();
            double mass = 0.0;
            for (const Fiber& f : fibers)
            {
                before += f.momentum();
                mass += f.totalMass();
            }
            const double dt = 2e-3;
            DragReaction reaction;
            solver.step(fibers, dt, air, nullptr, nullptr, &reaction);
            ASSERT_EQ(reaction.pointCount(), points.cols());
            Eigen::Vector3d after = Eigen::Vector3d::Zero();
            for (const Fiber& f : fibers)
                after += f.momentum();
            const Eigen::Vector3d expected = after - before - mass * gravity * dt;
            const Eigen::Vector3d recorded = sum(reaction.impulse);
            EXPECT_GT(recorded.norm(), 1e-12);
            EXPECT_LT((recorded - expected).norm(), 1e-8 * recorded.norm())
                << recorded.transpose() << " vs " << expected.transpose();
            EXPECT_TRUE((reaction.coefficientTime.array() > 0.0).all());
        }
    }
}

TEST(DragReaction, ImmobileFiberAcrossAStreamFeelsTheSlenderBodyDrag)
{
    const double length = 0.02, radius = 5e-6, speed = 0.4, dt = 1e-3;
    const Fiber fiber = Fiber::immobileFiber(
        straightPoints(8, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), length), glassFiber());
    DragSettings drag;
    drag.model = DragModelType::slenderBodyStokes;
    AirSample air;
    air.velocity = Eigen::Vector3d(speed, 0, 0).replicate(1, 9);
    air.density = Eigen::VectorXd::Constant(9, airDensity);
    air.viscosity = Eigen::VectorXd::Constant(9, airViscosity);
    DragReaction reaction;
    reaction.reset(11); // two points before and after: the fiber's columns start at 1
    addImmobileFiberReaction(fiber, air, 0, drag, dt, reaction, 1);

    const double cn = 4.0 * M_PI * airViscosity / std::log(length / radius);
    const double ct = cn / 2.0;
    const Eigen::Vector3d total = sum(reaction.impulse);
    EXPECT_NEAR(total.x(), dt * length * cn * speed, 1e-12 * dt * length * cn * speed);
    EXPECT_NEAR(total.y(), 0.0, 1e-25);
    EXPECT_NEAR(total.z(), 0.0, 1e-25);
    // End points stand for half a segment
    EXPECT_NEAR(reaction.impulse(0, 1), dt * length / 16 * cn * speed, 1e-12 * dt * cn * speed * length);
    EXPECT_EQ(reaction.impulse.col(0).norm(), 0.0);
    EXPECT_EQ(reaction.impulse.col(10).norm(), 0.0);
    EXPECT_NEAR(reaction.coefficientTime.sum(), dt * length * (2.0 * cn + ct) / 3.0,
                1e-12 * dt * length * cn);
}

TEST(DragReaction, NoDragModelNoReaction)
{
    std::vector<Fiber> fibers;
    fibers.emplace_back(straightPoints(4, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.01),
                        glassFiber());
    FiberSolver solver;
    DragReaction reaction;
    solver.step(fibers, 1e-3, AirSample(), nullptr, nullptr, &reaction);
    EXPECT_EQ(reaction.impulse.norm(), 0.0);
}
