// fiberStepBench: cost of FiberSolver::step per fiber point per CFD step, for 1 to
// 1000 fibers of 20 to 200 points, to show the cost grows linearly with the number
// of points (banded Newton solve: O(points)). Prints a table and ratios; it is a
// measurement, not a test (timings depend on the machine and its load).
//
// Case: flexible glass fibers (r = 5 um, 1 cm) in a uniform cross-wind with gravity
// and the slenderBodyOseen drag, every third fiber pinned at one end, dt = 1 ms.
// Then the turbulent air (docs/model.md sec. 8): the cost per point per step of
// advancing u' (TurbulentAir) against the fiber step without it, and of the step with it
// (which moves the fibers otherwise: its Newton iterations differ, so the ratio of the
// two steps is not the cost of u' alone).
// Then the drag handed to the air (two-way coupling, docs/model.md sec. 10): the step
// with its DragReaction recorded against the same step without (the same fibers, the
// same motion: the difference is the recording alone), interleaved.
#include "BenchFibers.hpp"
#include "fiber/DragReaction.hpp"
#include "fiber/FiberSolver.hpp"
#include "fiber/TurbulentAir.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace dropletFiber;

namespace
{

// Seconds per step of u' alone, of the fiber step without and with u' (k = 0.01,
// epsilon = 0.1: u' of 0.08 m/s on a 0.5 m/s cross-wind).
void turbulenceCost(int fibersN, int pointsN, const FiberSolverSettings& settings, double dt)
{
    std::vector<Fiber> plain = bench::makeFibers(fibersN, pointsN), turbulent = plain;
    const AirSample air = uniformAir(plain, Eigen::Vector3d(0.5, 0.2, 0.0), 1.2, 1.8e-5);
    const Eigen::Index n = air.pointCount();
    const TurbulenceSample k{Eigen::VectorXd::Constant(n, 0.01), Eigen::VectorXd::Constant(n, 0.1)};
    TurbulenceSettings model;
    model.model = TurbulenceModelType::ornsteinUhlenbeck;
    std::vector<std::uint64_t> ids(plain.size());
    for (std::size_t f = 0; f < ids.size(); ++f)
        ids[f] = f;
    FiberSolver solver(settings);
    const int steps = static_cast<int>(std::max(3L, 200000L / n));
    double fluctuation = 0.0, withoutU = 0.0, withU = 0.0;
    for (int step = 0; step <= steps; ++step) // step 0: warm-up, not timed
    {
        const auto t0 = std::chrono::steady_clock::now();
        solver.step(plain, dt, air);
        const auto t1 = std::chrono::steady_clock::now();
        advanceTurbulentVelocities(turbulent, ids, k, model, std::uint64_t(step), dt);
        const auto t2 = std::chrono::steady_clock::now();
        solver.step(turbulent, dt, air);
        const auto t3 = std::chrono::steady_clock::now();
        if (step == 0)
            continue;
        withoutU += std::chrono::duration<double>(t1 - t0).count();
        fluctuation += std::chrono::duration<double>(t2 - t1).count();
        withU += std::chrono::duration<double>(t3 - t1).count();
    }
    const double scale = 1e9 / steps / static_cast<double>(n);
    std::printf("%7d %7d %14.1f %14.1f %14.1f %9.3f\n", fibersN, pointsN, scale * fluctuation,
                scale * withoutU, scale * withU, withU / withoutU);
}

// Seconds per point per step of the fiber step without and with its drag recorded.
void reactionCost(int fibersN, int pointsN, const FiberSolverSettings& settings, double dt)
{
    std::vector<Fiber> plain = bench::makeFibers(fibersN, pointsN), recorded = plain;
    const AirSample air = uniformAir(plain, Eigen::Vector3d(0.5, 0.2, 0.0), 1.2, 1.8e-5);
    const Eigen::Index n = air.pointCount();
    FiberSolver solver(settings);
    DragReaction reaction;
    const int steps = static_cast<int>(std::max(3L, 200000L / n));
    double without = 0.0, with = 0.0;
    for (int step = 0; step <= steps; ++step) // step 0: warm-up, not timed
    {
        const auto t0 = std::chrono::steady_clock::now();
        solver.step(plain, dt, air);
        const auto t1 = std::chrono::steady_clock::now();
        solver.step(recorded, dt, air, nullptr, nullptr, &reaction);
        const auto t2 = std::chrono::steady_clock::now();
        if (step == 0)
            continue;
        without += std::chrono::duration<double>(t1 - t0).count();
        with += std::chrono::duration<double>(t2 - t1).count();
    }
    const double scale = 1e9 / steps / static_cast<double>(n);
    std::printf("%7d %7d %14.1f %14.1f %14.1f %9.3f\n", fibersN, pointsN, scale * without, scale * with,
                scale * (with - without), with / without);
}

} // namespace

int main()
{
    FiberSolverSettings settings;
    settings.drag.model = DragModelType::slenderBodyOseen;
    const double dt = 1e-3;
    const std::vector<int> fiberCounts{1, 10, 100, 1000};
    const std::vector<int> pointCounts{20, 50, 100, 200};

    std::printf("fiberStepBench: FiberSolver::step cost per point per step (dt = %g s)\n", dt);
    std::printf("%7s %7s %9s %6s %11s %13s %10s %11s %8s\n", "fibers", "points", "total pts", "steps",
                "ms/step", "ns/point/step", "sub/fiber", "Newton/sub", "loose");
    std::vector<std::vector<double>> costs(fiberCounts.size(), std::vector<double>(pointCounts.size(), 0.0));
    for (std::size_t a = 0; a < fiberCounts.size(); ++a)
    {
        for (std::size_t b = 0; b < pointCounts.size(); ++b)
        {
            const int fibersN = fiberCounts[a], pointsN = pointCounts[b];
            const long totalPoints = static_cast<long>(fibersN) * pointsN;
            std::vector<Fiber> fibers = bench::makeFibers(fibersN, pointsN);
            const AirSample air = uniformAir(fibers, Eigen::Vector3d(0.5, 0.2, 0.0), 1.2, 1.8e-5);
            FiberSolver solver(settings);
            solver.step(fibers, dt, air); // warm-up (first-touch allocations)
            // about 4e5 point-steps per configuration, at least 3 steps
            const int steps = static_cast<int>(std::max(3L, 400000L / totalPoints));
            long subSteps = 0, newton = 0, loose = 0;
            const auto t0 = std::chrono::steady_clock::now();
            for (int k = 0; k < steps; ++k)
            {
                const StepReport report = solver.step(fibers, dt, air);
                subSteps += report.subSteps;
                newton += report.newtonIterations;
                loose += report.looseConvergences;
            }
            const double seconds
                = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const double perPoint = seconds / steps / static_cast<double>(totalPoints) * 1e9;
            costs[a][b] = perPoint;
            std::printf("%7d %7d %9ld %6d %11.3f %13.1f %10.2f %11.2f %8ld\n", fibersN, pointsN, totalPoints,
                        steps, 1e3 * seconds / steps, perPoint,
                        static_cast<double>(subSteps) / steps / fibersN,
                        static_cast<double>(newton) / static_cast<double>(subSteps), loose);
        }
    }
    std::printf("\nlinearity: cost per point per step relative to 1 fiber x 20 points (1.00 = linear)\n");
    std::printf("%7s", "fibers");
    for (int p : pointCounts)
        std::printf(" %8d pts", p);
    std::printf("\n");
    for (std::size_t a = 0; a < fiberCounts.size(); ++a)
    {
        std::printf("%7d", fiberCounts[a]);
        for (std::size_t b = 0; b < pointCounts.size(); ++b)
            std::printf(" %12.2f", costs[a][b] / costs[0][0]);
        std::printf("\n");
    }
    std::printf("\ntotal-cost ratios: 10x the points -> cost x (linear = 10)\n");
    std::printf("  20 -> 200 points, 1000 fibers: x %.1f\n", 10.0 * costs[3][3] / costs[3][0]);
    std::printf("  1 -> 10 fibers of 200 points: x %.1f;  100 -> 1000 fibers of 200 points: x %.1f\n",
                10.0 * costs[1][3] / costs[0][3], 10.0 * costs[3][3] / costs[2][3]);

    std::printf("\nturbulent air: ns per point per step of u' alone, of the step without u', of u' + "
                "the step with it, and the ratio of the last two\n");
    std::printf("%7s %7s %14s %14s %14s %9s\n", "fibers", "points", "u' alone", "step", "u' + step", "ratio");
    for (const int fibersN : {10, 100})
        for (const int pointsN : {20, 200})
            turbulenceCost(fibersN, pointsN, settings, dt);

    std::printf("\ndrag handed to the air: ns per point per step of the step without and with its "
                "DragReaction, the difference and the ratio\n");
    std::printf("%7s %7s %14s %14s %14s %9s\n", "fibers", "points", "step", "with reaction", "reaction",
                "ratio");
    for (const int fibersN : {10, 100})
        for (const int pointsN : {20, 200})
            reactionCost(fibersN, pointsN, settings, dt);
    return 0;
}
