// collisionBench: cost of the stochastic collision evaluation, collisionMass(grid, a, b, ...)
// (docs/model.md eq. 9 with the grid's window fields interpolated at the segment), in segments
// per second, on the 2D and 3D grids of depositionBench, for 1e3 to 1e6 segments per call
// sweep (to show the cost is linear in the number of segments and independent of where the
// segments lie), with 1 sample per segment (the paper) and with automatic sampling (one
// sample per node spacing spanned) for segments 4 spacings long.
//
// Usage: collisionBench [--repeats N]
//
// Workload: grid box 5 x 7 cm, h = 0.5 mm (2D 101 x 141, 3D 101 x 141 x 101), window of one
// step holding 1e5 parcels (r_p = 10 um, n = 150) spread uniformly; segments in fibers of
// 100 consecutive segments (random, gently turning chains starting in the middle half of the
// box, turned back at its walls), segment length h / 2 (1 sample) or 2 mm (auto), fiber
// radius 3 um, moving at 0.1 m/s; dt = 1e-4 s.
#include "BenchCommon.hpp"

#include "collision/CollisionMass.hpp"

#include <cstdio>
#include <cstring>
#include <vector>

using namespace dropletFiber;

namespace
{

GridSpec makeSpec(int dimension)
{
    GridSpec spec;
    spec.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    spec.upper = dimension == 2 ? Eigen::Vector3d(0.05, 0.07, 0.01) : Eigen::Vector3d(0.05, 0.07, 0.05);
    spec.nodes = dimension == 2 ? std::array<int, 3>{{101, 141, 1}} : std::array<int, 3>{{101, 141, 101}};
    return spec;
}

struct Segment
{
    Eigen::Vector3d a, b;
};

} // namespace

int main(int argc, char** argv)
{
    int repeats = 5;
    for (int a = 1; a < argc; ++a)
    {
        if (!std::strcmp(argv[a], "--repeats") && a + 1 < argc)
        {
            repeats = std::max(1, std::atoi(argv[++a]));
        }
    }
    const double dt = 1e-4;
    const double fiberRadius = 3e-6;
    const Eigen::Vector3d segmentVelocity(0.1, 0.0, 0.0);

    std::printf("== collisionBench: collisionMass(grid, segment) per segment ==\n");
    std::printf("%3s %8s %8s %8s | %11s %9s %7s | %6s %5s\n", "dim", "samples", "len/h", "segments",
                "Msegment/s", "ns/seg", "lin", "spread", "reps");
    for (int dimension : {2, 3})
    {
        const GridSpec spec = makeSpec(dimension);
        DensityGrid grid(spec, KernelSettings{}, 1);
        bench::Random rng(42 + dimension);
        for (int p = 0; p < 100000; ++p)
        {
            Parcel parcel;
            for (int d = 0; d < 3; ++d)
            {
                parcel.position[d] = rng.uniform(spec.lower[d], spec.upper[d]);
            }
            parcel.velocity = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-3, -1), rng.uniform(-1, 1));
            parcel.diameter = 2e-5;
            parcel.nParticle = 150.0;
            parcel.rhoDroplet = 1000.0;
            grid.deposit(parcel, dt);
        }
        grid.commitStep();

        for (int mode = 0; mode < 2; ++mode)
        {
            CollisionOptions options;
            options.samples = mode == 0 ? 1 : 0;
            const double length = mode == 0 ? 2.5e-4 : 2e-3;
            double baseline = 0.0;
            for (double count : {1e3, 1e4, 1e5, 1e6})
            {
                // fibers of 100 consecutive segments (a random, gently turning chain that
                // stays in the box), as the fiber solver hands them over
                std::vector<Segment> segments(static_cast<std::size_t>(count));
                Eigen::Vector3d point, direction;
                for (std::size_t k = 0; k < segments.size(); ++k)
                {
                    if (k % 100 == 0)
                    {
                        for (int d = 0; d < 3; ++d)
                        {
                            point[d] = rng.uniform(spec.lower[d] + 0.25 * (spec.upper[d] - spec.lower[d]),
                                                   spec.upper[d] - 0.25 * (spec.upper[d] - spec.lower[d]));
                        }
                        direction = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                                    dimension == 3 ? rng.uniform(-1, 1) : 0.0);
                    }
                    direction += 0.3
                        * Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                          dimension == 3 ? rng.uniform(-1, 1) : 0.0);
                    direction.normalize();
                    Eigen::Vector3d next = point + length * direction;
                    for (int d = 0; d < 3; ++d)
                    {
                        if (!spec.flat(d)
                            && (next[d] < spec.lower[d] + length || next[d] > spec.upper[d] - length))
                        {
                            direction[d] = -direction[d]; // turn back at the walls
                        }
                    }
                    next = point + length * direction;
                    segments[k].a = point;
                    segments[k].b = next;
                    if (dimension == 2)
                    {
                        segments[k].a.z() = segments[k].b.z() = 0.005;
                    }
                    point = next;
                }
                const int inner = static_cast<int>(std::max(1.0, 2e5 / count));
                double totalMass = 0.0;
                long totalSamples = 0;
                const bench::Timing t
                    = bench::timeRepeated(repeats,
                                          [&]
                                          {
                                              for (int r = 0; r < inner; ++r)
                                              {
                                                  for (const Segment& s : segments)
                                                  {
                                                      const SegmentCollision c
                                                          = collisionMass(grid, s.a, s.b, fiberRadius,
                                                                          segmentVelocity, dt, options);
                                                      totalMass += c.mass;
                                                      totalSamples += c.samples;
                                                  }
                                              }
                                          });
                bench::sink(totalMass);
                const double ns = t.best / (count * inner) * 1e9;
                if (count == 1e3)
                {
                    baseline = ns;
                }
                std::printf("%3d %8s %8.1f %8s | %11.2f %9.1f %7.2f | %5.1f%% %5d\n", dimension,
                            mode == 0 ? "1" : "auto", length / 5e-4, bench::formatCount(count).c_str(),
                            1e3 / ns, ns, ns / baseline, t.spreadPercent(), t.repeats);
                if (mode == 1 && count == 1e3)
                {
                    std::printf("    (auto: %.2f samples per segment)\n",
                                static_cast<double>(totalSamples) / (count * inner * (repeats)));
                }
            }
        }
    }
    std::printf("lin = ns/segment relative to the 1e3-segment row (1.00 = linear)\n");
    return 0;
}
