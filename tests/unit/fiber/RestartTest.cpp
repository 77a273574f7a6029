// Restart: stepping N times, copying every fiber's state out and into fresh fibers
// and a fresh solver, then stepping M more, is bit-for-bit identical to N+M steps.
#include "FiberTestSupport.hpp"

using namespace dropletFiber;
using namespace dropletFiber::test;

namespace
{

std::vector<Fiber> makeFibers()
{
    std::vector<Fiber> fibers;
    fibers.emplace_back(straightPoints(29, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0.2), 0.01),
                        glassFiber(), EndCondition::pinnedEnd(), EndCondition::freeEnd());
    fibers.emplace_back(straightPoints(44, Eigen::Vector3d(0, 0.01, 0), Eigen::Vector3d(0, 1, 1), 0.02),
                        glassFiber(), EndCondition::clampedEnd(Eigen::Vector3d(0.01, 0, 0)),
                        EndCondition::freeEnd());
    fibers.push_back(Fiber::immobileFiber(
        straightPoints(5, Eigen::Vector3d(0, 0, -0.01), Eigen::Vector3d::UnitY(), 0.01), glassFiber()));
    return fibers;
}

CaptureSources captureAt(int step, const std::vector<Fiber>& fibers)
{
    CaptureSources capture;
    for (const Fiber& fiber : fibers)
    {
        std::vector<SegmentSource> sources(static_cast<std::size_t>(fiber.segmentCount()));
        for (std::size_t j = 0; j < sources.size(); ++j)
        {
            if ((j + static_cast<std::size_t>(step)) % 3 == 0)
            {
                sources[j].mass = 1e-13 * (1 + j % 4);
                sources[j].momentum = sources[j].mass * Eigen::Vector3d(0.3, 0.0, -1.0);
            }
        }
        capture.push_back(sources);
    }
    return capture;
}

FiberSolverSettings settings()
{
    FiberSolverSettings s;
    s.drag.model = DragModelType::slenderBodyOseen;
    return s;
}

void advance(std::vector<Fiber>& fibers, int from, int to)
{
    FiberSolver solver(settings());
    const AirSample air = uniformAir(fibers, Eigen::Vector3d(0.5, 0.1, 0.0), 1.2, 1.8e-5);
    for (int step = from; step < to; ++step)
    {
        const CaptureSources capture = captureAt(step, fibers);
        solver.step(fibers, 1e-3, air, &capture);
    }
}

} // namespace

TEST(Restart, StateRoundTripIsBitIdentical)
{
    std::vector<Fiber> continuous = makeFibers();
    advance(continuous, 0, 30);

    std::vector<Fiber> first = makeFibers();
    advance(first, 0, 15);
    std::vector<FiberState> saved;
    for (const Fiber& fiber : first)
        saved.push_back(fiber.state());
    std::vector<Fiber> restarted;
    for (const FiberState& state : saved)
        restarted.emplace_back(state);
    advance(restarted, 15, 30);

    ASSERT_EQ(restarted.size(), continuous.size());
    for (std::size_t f = 0; f < continuous.size(); ++f)
    {
        EXPECT_TRUE(restarted[f].positions() == continuous[f].positions()) << "fiber " << f;
        EXPECT_TRUE(restarted[f].velocities() == continuous[f].velocities()) << "fiber " << f;
        EXPECT_TRUE(restarted[f].tension() == continuous[f].tension()) << "fiber " << f;
        EXPECT_TRUE(restarted[f].capturedMassPerSegment() == continuous[f].capturedMassPerSegment());
    }
    // and the run did move the fibers
    EXPECT_GT((continuous[1].positions() - makeFibers()[1].positions()).norm(), 1e-4);
}

TEST(Restart, RejectsInconsistentState)
{
    FiberState state = makeFibers()[0].state();
    state.tension.resize(3);
    EXPECT_THROW(Fiber{state}, std::invalid_argument);
}
