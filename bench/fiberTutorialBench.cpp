// fiberTutorialBench: FiberSolver::step on the fibers of the channelSpray tutorial, the
// workload whose cost issue 7 is about: 10 free glass fibers of 21 points (r = 3 um,
// rho = 2500 kg/m^3, E = 7e10 Pa, 1 cm long), slenderBodyOseen drag in air (1.2 kg/m^3,
// mu = 1.8e-5 Pa s) coming down at about 2 m/s with a shear across the channel,
// gravity (0, -9.81, 0), dt = 5e-4 s (the tutorial's CFD step). The fibers start as
// the tutorial injects them (straight, across the flow in the three stream directions,
// moving with the air at (0, -2, 0)), staggered in age, and are stepped `steps` times.
// Prints microseconds per point-step (best of `repeats` runs of the whole sequence, thread
// CPU time, see BenchCommon.hpp), Newton iterations per sub-step and per fiber-step,
// sub-steps per fiber-step, and a checksum of the final state (to compare two builds).
//
// Usage: fiberTutorialBench [--steps N] [--repeats N] [--dump FILE]
//   --dump  writes the final positions, velocities and tensions (%.17g, one value a
//           line) for a value-by-value comparison of two builds.
#include "BenchCommon.hpp"

#include "fiber/FiberSolver.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace dropletFiber;

namespace
{

// The tutorial's three injectors (left, middle, right), each fiber 0-3 steps of age
// further down so that they are not all alike.
std::vector<Fiber> tutorialFibers()
{
    const FiberMaterial glass{3e-6, 2500.0, 7e10};
    const int points = 21;
    const double length = 0.01;
    const Eigen::Vector3d injector[3] = {{0.003, 0.147, 0.005}, {0.010, 0.147, 0.005}, {0.018, 0.147, 0.005}};
    const Eigen::Vector3d direction[3]
        = {Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(1.0, -0.3, 0.0).normalized(),
           Eigen::Vector3d(1.0, 0.3, 0.0).normalized()};
    const Eigen::Vector3d velocity(0.0, -2.0, 0.0);
    std::vector<Fiber> fibers;
    for (int f = 0; f < 10; ++f)
    {
        const int stream = f % 3;
        const double age = 0.02 * f; // the streams' rate is 50 per second
        const Eigen::Vector3d start = injector[stream] + velocity * age;
        Eigen::Matrix3Xd x(3, points);
        for (int i = 0; i < points; ++i)
        {
            x.col(i) = start + direction[stream] * (length * i / (points - 1));
        }
        Fiber fiber(x, glass);
        fiber.setVelocities(velocity.replicate(1, points));
        fibers.push_back(fiber);
    }
    return fibers;
}

// Air at 2 m/s down with a shear of 40 1/s across the channel (the tutorial's flow near
// its left wall, where the fibers are injected), plus a weak cross-flow varying along y.
AirSample tutorialAir(const Eigen::Matrix3Xd& points)
{
    const Eigen::Index n = points.cols();
    AirSample air;
    air.velocity.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        const double x = points(0, i), y = points(1, i);
        air.velocity.col(i) = Eigen::Vector3d(0.05 * std::sin(100.0 * y), -2.0 + 40.0 * (x - 0.015), 0.0);
    }
    air.density = Eigen::VectorXd::Constant(n, 1.2);
    air.viscosity = Eigen::VectorXd::Constant(n, 1.8e-5);
    return air;
}

} // namespace

int main(int argc, char** argv)
{
    int steps = 200;
    int repeats = 7;
    const char* dump = nullptr;
    for (int a = 1; a < argc; ++a)
    {
        if (!std::strcmp(argv[a], "--steps") && a + 1 < argc)
            steps = std::max(1, std::atoi(argv[++a]));
        else if (!std::strcmp(argv[a], "--repeats") && a + 1 < argc)
            repeats = std::max(1, std::atoi(argv[++a]));
        else if (!std::strcmp(argv[a], "--dump") && a + 1 < argc)
            dump = argv[++a];
    }
    FiberSolverSettings settings;
    settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    settings.drag.model = DragModelType::slenderBodyOseen;
    const double dt = 5e-4;

    const std::vector<Fiber> initial = tutorialFibers();
    long pointCount = 0;
    for (const Fiber& fiber : initial)
        pointCount += fiber.pointCount();

    std::vector<Fiber> fibers;
    long subSteps = 0, newton = 0, fiberSteps = 0, loose = 0, rejected = 0;
    FiberSolver solver(settings);
    const bench::Timing t = bench::timeRepeated(
        repeats,
        [&]
        {
            fibers = initial;
            subSteps = newton = fiberSteps = loose = rejected = 0;
        },
        [&]
        {
            for (int k = 0; k < steps; ++k)
            {
                const StepReport report = solver.step(fibers, dt, tutorialAir(airSamplePoints(fibers)));
                subSteps += report.subSteps;
                newton += report.newtonIterations;
                fiberSteps += report.fibersAdvanced;
                loose += report.looseConvergences;
                rejected += report.rejectedSubSteps;
            }
        });

    double checksum = 0.0, tension = 0.0;
    for (const Fiber& fiber : fibers)
    {
        checksum += fiber.positions().sum() + 1e-3 * fiber.velocities().sum();
        tension += fiber.tension().sum();
    }
    const double perPointStep = t.best / steps / static_cast<double>(pointCount) * 1e6;
    std::printf("fiberTutorialBench: %zu fibers, %ld points, dt = %g s, %d steps, best of %d (%s)\n",
                fibers.size(), pointCount, dt, steps, repeats, bench::Clock::name());
    std::printf("  us/point-step %.3f  (ms/step %.4f, spread %.1f%%)\n", perPointStep, 1e3 * t.best / steps,
                t.spreadPercent());
    std::printf("  Newton/sub-step %.3f  Newton/fiber-step %.3f  sub-steps/fiber-step %.3f  loose %ld  "
                "rejected %ld\n",
                static_cast<double>(newton) / subSteps, static_cast<double>(newton) / fiberSteps,
                static_cast<double>(subSteps) / fiberSteps, loose, rejected);
    std::printf("  checksum %.17g  tension sum %.17g\n", checksum, tension);
    if (dump != nullptr)
    {
        std::FILE* out = std::fopen(dump, "w");
        if (out == nullptr)
            return 1;
        for (const Fiber& fiber : fibers)
        {
            for (Eigen::Index i = 0; i < fiber.pointCount(); ++i)
            {
                for (int a = 0; a < 3; ++a)
                    std::fprintf(out, "%.17g\n", fiber.positions()(a, i));
                for (int a = 0; a < 3; ++a)
                    std::fprintf(out, "%.17g\n", fiber.velocities()(a, i));
            }
            for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
                std::fprintf(out, "%.17g\n", fiber.tension()(j));
        }
        std::fclose(out);
    }
    return 0;
}
