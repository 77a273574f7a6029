// fiberScalingBench: FiberSolver::step in point-steps per second for 1 to 10,000 fibers of
// 20 to 200 points, to show the cost is linear in the total number of fiber points. It
// extends fiberStepBench (same fiber case, built by the same recipe, 1-1000 fibers) to
// 10,000 fibers and reports the best of several timed steps with their spread.
//
// Usage: fiberScalingBench [--max-fibers N] [--repeats N]
//   --max-fibers  largest fiber count (default 10000; 1000 for a quick run)
//   --repeats     timed steps per configuration at most (default 3; fewer for the
//                 largest configurations so that each takes < ~1 min)
//
// Case (as fiberStepBench): glass fibers r = 5 um, 1 cm long, slightly bent, in a uniform
// cross-wind of 0.5 m/s with gravity, slenderBodyOseen drag, every third fiber pinned at
// one end, dt = 1 ms. One warm-up step per configuration is not timed.
#include "BenchCommon.hpp"

#include "BenchFibers.hpp"
#include "fiber/FiberSolver.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace dropletFiber;

int main(int argc, char** argv)
{
    int maxFibers = 10000;
    int repeats = 3;
    for (int a = 1; a < argc; ++a)
    {
        if (!std::strcmp(argv[a], "--max-fibers") && a + 1 < argc)
        {
            maxFibers = std::atoi(argv[++a]);
        }
        else if (!std::strcmp(argv[a], "--repeats") && a + 1 < argc)
        {
            repeats = std::max(1, std::atoi(argv[++a]));
        }
    }
    FiberSolverSettings settings;
    settings.drag.model = DragModelType::slenderBodyOseen;
    const double dt = 1e-3;

    std::printf("== fiberScalingBench: FiberSolver::step, dt = %g s ==\n", dt);
    std::printf("%7s %7s %9s | %9s %13s %12s %6s | %9s %8s | %6s %5s\n", "fibers", "points", "total pts",
                "s/step", "Mpoint-step/s", "ns/pt-step", "lin", "sub/fiber", "Newton", "spread", "reps");
    std::vector<int> fiberCounts;
    for (int f = 1; f <= maxFibers; f *= 10)
    {
        fiberCounts.push_back(f);
    }
    const std::vector<int> pointCounts{20, 50, 100, 200};
    double baseline = 0.0;
    for (int fibersN : fiberCounts)
    {
        for (int pointsN : pointCounts)
        {
            const double totalPoints = static_cast<double>(fibersN) * pointsN;
            std::vector<Fiber> fibers = bench::makeFibers(fibersN, pointsN);
            const AirSample air = uniformAir(fibers, Eigen::Vector3d(0.5, 0.2, 0.0), 1.2, 1.8e-5);
            FiberSolver solver(settings);
            const auto warm = bench::Clock::now();
            solver.step(fibers, dt, air); // warm-up
            const double warmSeconds = bench::secondsSince(warm);
            // steps per timing sample: about 0.2 s of work; samples: `repeats`, fewer when slow
            const int inner = static_cast<int>(std::max(1.0, std::ceil(0.2 / std::max(warmSeconds, 1e-6))));
            const int reps = warmSeconds * repeats > 40.0 ? 2 : repeats;
            long subSteps = 0, newton = 0, steps = 0;
            const bench::Timing t = bench::timeRepeated(reps,
                                                        [&]
                                                        {
                                                            for (int k = 0; k < inner; ++k)
                                                            {
                                                                const StepReport report
                                                                    = solver.step(fibers, dt, air);
                                                                subSteps += report.subSteps;
                                                                newton += report.newtonIterations;
                                                                ++steps;
                                                            }
                                                        });
            const double perStep = t.best / inner;
            const double ns = perStep / totalPoints * 1e9;
            if (baseline == 0.0)
            {
                baseline = ns;
            }
            std::printf("%7d %7d %9.0f | %9.4f %13.3f %12.1f %6.2f | %9.2f %8.2f | %5.1f%% %5d\n", fibersN,
                        pointsN, totalPoints, perStep, totalPoints / perStep / 1e6, ns, ns / baseline,
                        static_cast<double>(subSteps) / steps / fibersN,
                        static_cast<double>(newton) / static_cast<double>(std::max(1L, subSteps)),
                        t.spreadPercent(), t.repeats);
            std::fflush(stdout);
        }
    }
    std::printf("lin = ns per point-step relative to 1 fiber x 20 points (1.00 = linear in points);\n"
                "Newton = Newton iterations per sub-step.\n");
    return 0;
}
