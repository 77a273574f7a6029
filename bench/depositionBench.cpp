// depositionBench: cost of DensityGrid::deposit (docs/model.md sec. 4, eqs. 19-26), in parcels
// per second and nanoseconds per grid node, on 2D and 3D grids, for kernel reaches of
// about 1, 3 and 10 node spacings and 1e3 to 1e7 parcels per step; plus, in the same run,
// the cost of the elementary functions the kernel needs (exp, expm1, erf, erfc, the core's
// scaled-erfc rational function) and the memory bandwidth of this machine, so that the
// deposition's distance from a simple roofline can be stated (docs/performance.md).
//
// Usage: depositionBench [--quick] [--budget SECONDS] [--repeats N] [--vectorised 0|1]
//   --quick     parcels 1e3..1e5 only (a smoke run of a few seconds)
//   --budget    skip a configuration whose estimated time (all repeats) exceeds this
//               (default 40 s); skipped rows are printed as such
//   --repeats   timing repeats per configuration (default 3; best is reported)
//   --only DIM REACH PARCELS   one deposition configuration only, no elementary costs
//               (for profilers: perf record / valgrind --tool=callgrind)
//   --vectorised  KernelSettings::vectorised (default 1: the batched AVX2 + FMA node loop
//               where the CPU has it; 0: node by node); the output says which ran
//
// Workload (deterministic, seed fixed): grid box 5 x 7 cm (2D: 101 x 141 nodes, h = 0.5 mm,
// 1 cm thick; 3D: 101 x 141 x 101 nodes, 5 cm deep). Parcels of droplets r_p = 10 um,
// rho_p = 1000 kg/m^3, with n droplets so that r_max = r_p n = reach * h (reach 1, 3, 10 h:
// n = 50, 150, 500), at uniformly random end positions at least r_max + |v dt| inside the
// box, in random order, velocity of random direction with |v dt| = h / 2 (dt = 1e-4 s).
// One "step" = deposit() of every parcel + commitStep() (window length 1). KernelSettings{}:
// always the kernel (cloudInCellBelow = 0, the paper's method); a last table repeats the
// parcels with cloudInCellBelow = 0.5, the function object's default.
#include "BenchCommon.hpp"

#include "grid/DensityGrid.hpp"
#include "grid/ScaledErfc.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

using namespace dropletFiber;

namespace
{

// ---------------------------------------------------------------------------------------
// Elementary costs
// ---------------------------------------------------------------------------------------

struct ElementaryCost
{
    const char* name;
    double throughputNs; // independent evaluations (the loop over nodes is like this)
    double latencyNs;    // each input depends on the previous result
};

template <class F>
ElementaryCost measureFunction(const char* name, const std::vector<double>& inputs, F f, double feedScale)
{
    const std::size_t n = inputs.size();
    const int rounds = 400;
    // throughput: independent calls, results summed
    const bench::Timing through = bench::timeRepeated(5,
                                                      [&]
                                                      {
                                                          double s = 0.0;
                                                          for (int r = 0; r < rounds; ++r)
                                                          {
                                                              for (std::size_t i = 0; i < n; ++i)
                                                              {
                                                                  s += f(inputs[i]);
                                                              }
                                                          }
                                                          bench::sink(s);
                                                      });
    // latency: the next argument depends on the previous result (tiny perturbation)
    const bench::Timing latency = bench::timeRepeated(5,
                                                      [&]
                                                      {
                                                          double carry = 0.0;
                                                          for (int r = 0; r < rounds; ++r)
                                                          {
                                                              for (std::size_t i = 0; i < n; ++i)
                                                              {
                                                                  carry = f(inputs[i] + feedScale * carry);
                                                              }
                                                          }
                                                          bench::sink(carry);
                                                      });
    const double calls = static_cast<double>(rounds) * static_cast<double>(n);
    return {name, through.best / calls * 1e9, latency.best / calls * 1e9};
}

std::vector<ElementaryCost> measureElementary()
{
    bench::Random rng(7);
    std::vector<double> kernelArgs(4096), erfArgs(4096);
    for (std::size_t i = 0; i < kernelArgs.size(); ++i)
    {
        kernelArgs[i] = -rng.uniform(0.0, 40.0); // exp(-gamma d^2): exponents 0..-40
        erfArgs[i] = rng.uniform(0.0, 5.0);      // erf/erfc arguments of the path weight
    }
    std::vector<double> smallArgs(4096);
    for (double& x : smallArgs)
    {
        x = rng.uniform(0.0, 0.25); // expm1 of regime A
    }
    std::vector<ElementaryCost> costs;
    costs.push_back(measureFunction(
        "add (loop overhead)", kernelArgs, [](double x) { return x; }, 1e-300));
    costs.push_back(measureFunction(
        "std::exp", kernelArgs, [](double x) { return std::exp(x); }, 1e-300));
    costs.push_back(measureFunction(
        "std::expm1", smallArgs, [](double x) { return std::expm1(x); }, 1e-300));
    costs.push_back(measureFunction(
        "std::erf", erfArgs, [](double x) { return std::erf(x); }, 1e-300));
    costs.push_back(measureFunction(
        "std::erfc", erfArgs, [](double x) { return std::erfc(x); }, 1e-300));
    costs.push_back(measureFunction(
        "erfcScaledFraction (core)", erfArgs,
        [](double x)
        {
            const Fraction f = erfcScaledFraction(x);
            return f.numerator + f.denominator;
        },
        1e-300));
    costs.push_back(measureFunction(
        "erfcScaled = num/den (core)", erfArgs, [](double x) { return erfcScaled(x); }, 1e-300));
    costs.push_back(measureFunction(
        "division 1/x", erfArgs, [](double x) { return 1.0 / (x + 1.0); }, 1e-300));
    costs.push_back(measureFunction(
        "std::sqrt", erfArgs, [](double x) { return std::sqrt(x); }, 1e-300));
    return costs;
}

// ---------------------------------------------------------------------------------------
// Memory bandwidth: read-modify-write sweeps (what accumulate() and commitStep() do)
// ---------------------------------------------------------------------------------------

struct Bandwidth
{
    std::size_t bytes;
    double gbPerSecond; // bytes read + bytes written per second
};

Bandwidth measureBandwidth(std::size_t bytes)
{
    std::vector<double> a(bytes / sizeof(double), 1.0);
    const std::size_t sweeps = std::max<std::size_t>(1, (std::size_t(1) << 31) / bytes);
    const bench::Timing t = bench::timeRepeated(3,
                                                [&]
                                                {
                                                    for (std::size_t s = 0; s < sweeps; ++s)
                                                    {
                                                        double* p = a.data();
                                                        const std::size_t n = a.size();
                                                        for (std::size_t i = 0; i < n; ++i)
                                                        {
                                                            p[i] = p[i] * 0.999 + 1e-3;
                                                        }
                                                    }
                                                    bench::sink(a[a.size() / 2]);
                                                });
    return {bytes, 2.0 * static_cast<double>(bytes) * static_cast<double>(sweeps) / t.best / 1e9};
}

// ---------------------------------------------------------------------------------------
// Deposition
// ---------------------------------------------------------------------------------------

constexpr double spacing = 5e-4;       // h, m
constexpr double dropletRadius = 1e-5; // r_p, m
constexpr double dt = 1e-4;            // s

GridSpec makeSpec(int dimension)
{
    GridSpec spec;
    spec.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    if (dimension == 2)
    {
        spec.upper = Eigen::Vector3d(0.05, 0.07, 0.01);
        spec.nodes = {{101, 141, 1}};
    }
    else
    {
        spec.upper = Eigen::Vector3d(0.05, 0.07, 0.05);
        spec.nodes = {{101, 141, 101}};
    }
    return spec;
}

std::vector<Parcel> makeParcels(const GridSpec& spec, int dimension, double reachSpacings, std::size_t count,
                                std::uint64_t seed)
{
    bench::Random rng(seed);
    const double nParticle = reachSpacings * spacing / dropletRadius;
    const double pathLength = 0.5 * spacing;
    const double speed = pathLength / dt;
    const double margin = reachSpacings * spacing + pathLength;
    std::vector<Parcel> parcels(count);
    for (Parcel& p : parcels)
    {
        Eigen::Vector3d direction;
        do
        {
            direction = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                        dimension == 3 ? rng.uniform(-1, 1) : 0.0);
        } while (direction.squaredNorm() > 1.0 || direction.squaredNorm() < 1e-4);
        direction.normalize();
        for (int d = 0; d < 3; ++d)
        {
            if (spec.flat(d))
            {
                p.position[d] = 0.5 * (spec.lower[d] + spec.upper[d]);
            }
            else
            {
                p.position[d] = rng.uniform(spec.lower[d] + margin, spec.upper[d] - margin);
            }
        }
        p.velocity = speed * direction;
        p.diameter = 2.0 * dropletRadius;
        p.nParticle = nParticle;
        p.rhoDroplet = 1000.0;
    }
    return parcels;
}

// Sorts parcels by the flat index of their nearest node (the order of a cell-sorted
// Lagrangian cloud): better cache locality of the grid updates.
void sortByNode(const GridSpec& spec, std::vector<Parcel>& parcels)
{
    auto key = [&](const Parcel& p)
    {
        std::array<int, 3> idx{{0, 0, 0}};
        for (int d = 0; d < 3; ++d)
        {
            if (!spec.flat(d))
            {
                idx[d] = static_cast<int>(std::lround((p.position[d] - spec.lower[d]) / spec.spacing(d)));
            }
        }
        return spec.flatIndex(idx[0], idx[1], idx[2]);
    };
    std::sort(parcels.begin(), parcels.end(),
              [&](const Parcel& a, const Parcel& b) { return key(a) < key(b); });
}

struct DepositionResult
{
    bool skipped = false;
    double estimateSeconds = 0.0;
    double depositSeconds = 0.0; // best, per step
    double commitSeconds = 0.0;  // best, per step
    double spreadPercent = 0.0;  // of the deposit time
    int repeats = 0;
    double visitedPerParcel = 0.0;
    double weightedPerParcel = 0.0;
    double fallbackFraction = 0.0;
    double cloudInCellFraction = 0.0;
    double touchedBoxFraction = 0.0; // stepBox nodes / grid nodes
};

DepositionResult runDeposition(DensityGrid& grid, const std::vector<Parcel>& pool, std::size_t parcels,
                               int repeats)
{
    DepositionResult result;
    result.repeats = repeats;
    double best = 1e300, worst = 0.0, bestCommit = 1e300;
    // Small steps are repeated inside one timing sample so that it lasts >= ~50 ms.
    int inner = 1;
    for (int r = 0; r < repeats + 1; ++r) // first run: warm-up and calibration, not kept
    {
        double depositTime = 0.0, commitTime = 0.0;
        for (int s = 0; s < inner; ++s)
        {
            const auto start = bench::Clock::now();
            std::size_t left = parcels;
            while (left > 0)
            {
                const std::size_t chunk = std::min(left, pool.size());
                for (std::size_t i = 0; i < chunk; ++i)
                {
                    grid.deposit(pool[i], dt);
                }
                left -= chunk;
            }
            depositTime += bench::secondsSince(start);
            if (s == 0 && r == 0)
            {
                const StepStatistics& st = grid.stepStatistics();
                result.visitedPerParcel
                    = static_cast<double>(st.nodesVisited) / static_cast<double>(st.parcels);
                result.weightedPerParcel
                    = static_cast<double>(st.nodesWeighted) / static_cast<double>(st.parcels);
                result.fallbackFraction
                    = static_cast<double>(st.parcelsFallback) / static_cast<double>(st.parcels);
                result.cloudInCellFraction
                    = static_cast<double>(st.parcelsCloudInCell) / static_cast<double>(st.parcels);
                result.touchedBoxFraction = static_cast<double>(grid.stepBox().nodeCount())
                    / static_cast<double>(grid.spec().nodeCount());
            }
            const auto commitStart = bench::Clock::now();
            grid.commitStep();
            commitTime += bench::secondsSince(commitStart);
        }
        depositTime /= inner;
        commitTime /= inner;
        if (r == 0)
        {
            inner = static_cast<int>(
                std::min(1000.0, std::max(1.0, std::ceil(0.05 / std::max(depositTime, 1e-9)))));
            continue;
        }
        best = std::min(best, depositTime);
        worst = std::max(worst, depositTime);
        bestCommit = std::min(bestCommit, commitTime);
    }
    result.depositSeconds = best;
    result.commitSeconds = bestCommit;
    result.spreadPercent = 100.0 * (worst - best) / best;
    return result;
}

void printHeader()
{
    std::printf("%3s %5s %6s %8s | %8s %8s %6s | %10s %9s %9s %8s %8s | %8s %6s %5s\n", "dim", "reach",
                "order", "parcels", "visit/p", "wght/p", "fallb", "Mparcel/s", "ns/parcel", "commit ms",
                "ns/visit", "ns/wght", "lin", "spread", "reps");
}

} // namespace

int main(int argc, char** argv)
{
    bool quick = false;
    double budget = 40.0;
    int repeats = 3;
    int onlyDimension = 0;
    double onlyReach = 0.0, onlyCount = 0.0;
    KernelSettings kernelSettings; // the paper's method: cloudInCellBelow = 0
    for (int a = 1; a < argc; ++a)
    {
        if (!std::strcmp(argv[a], "--only") && a + 3 < argc)
        {
            onlyDimension = std::atoi(argv[++a]);
            onlyReach = std::atof(argv[++a]);
            onlyCount = std::atof(argv[++a]);
            continue;
        }
        if (!std::strcmp(argv[a], "--quick"))
        {
            quick = true;
        }
        else if (!std::strcmp(argv[a], "--budget") && a + 1 < argc)
        {
            budget = std::atof(argv[++a]);
        }
        else if (!std::strcmp(argv[a], "--repeats") && a + 1 < argc)
        {
            repeats = std::max(1, std::atoi(argv[++a]));
        }
        else if (!std::strcmp(argv[a], "--vectorised") && a + 1 < argc)
        {
            kernelSettings.vectorised = std::atoi(argv[++a]) != 0;
        }
        else
        {
            std::fprintf(stderr,
                         "usage: %s [--quick] [--budget SECONDS] [--repeats N] [--vectorised 0|1] "
                         "[--only DIM REACH PARCELS]\n",
                         argv[0]);
            return 2;
        }
    }
    const bool batched = DensityGrid(makeSpec(2), kernelSettings, 1).batchedKernel();
    std::printf("node weights: %s (vectorised %d, CPU has AVX2 + FMA: %s)\n",
                batched ? "batched AVX2 + FMA" : "per node", kernelSettings.vectorised ? 1 : 0,
                PathWeightBatch::cpuSupported() ? "yes" : "no");

    if (onlyDimension != 0)
    {
        const GridSpec spec = makeSpec(onlyDimension);
        DensityGrid grid(spec, kernelSettings, 1);
        const std::size_t count = static_cast<std::size_t>(onlyCount);
        const std::vector<Parcel> pool
            = makeParcels(spec, onlyDimension, onlyReach, std::min<std::size_t>(count, 1000000), 99);
        const DepositionResult r = runDeposition(grid, pool, count, repeats);
        printHeader();
        const double ns = r.depositSeconds / onlyCount * 1e9;
        std::printf(
            "%3d %5.0f %6s %8s | %8.1f %8.1f %5.1f%% | %10.3f %9.1f %9.2f %8.2f %8.2f | %8s %5.1f%% %5d\n",
            onlyDimension, onlyReach, "random", bench::formatCount(onlyCount).c_str(), r.visitedPerParcel,
            r.weightedPerParcel, 100.0 * r.fallbackFraction, onlyCount / r.depositSeconds / 1e6, ns,
            1e3 * r.commitSeconds, ns / r.visitedPerParcel, ns / r.weightedPerParcel, "-", r.spreadPercent,
            r.repeats);
        return 0;
    }
    std::printf("== depositionBench ==\n\n");
    std::printf("-- elementary costs on this machine (ns per call; throughput = independent calls,\n"
                "   latency = dependent chain; best of 5) --\n");
    const std::vector<ElementaryCost> elementary = measureElementary();
    for (const ElementaryCost& c : elementary)
    {
        std::printf("  %-30s throughput %7.2f ns   latency %7.2f ns\n", c.name, c.throughputNs, c.latencyNs);
    }

    std::printf("\n-- memory: read-modify-write sweep bandwidth (bytes read + written; best of 3) --\n");
    for (std::size_t bytes :
         {std::size_t(797496), std::size_t(32) << 20, std::size_t(80) << 20, std::size_t(1) << 30})
    {
        const Bandwidth b = measureBandwidth(bytes);
        std::printf("  array %9.1f MB: %7.1f GB/s\n", static_cast<double>(b.bytes) / 1048576.0,
                    b.gbPerSecond);
    }
    std::printf(
        "  (2D grid step accumulator: 101 x 141 nodes x 7 doubles = 0.76 MB; 3D: 101 x 141 x 101 = 76 MB)\n");

    std::printf(
        "\n-- deposition: one step = deposit() of every parcel + commitStep(); random parcel order unless "
        "'sorted';\n"
        "   Mparcel/s and ns/parcel from the deposit loop only, commit separately; ns/visit = per node in "
        "the\n"
        "   bounding boxes (StepStatistics::nodesVisited), ns/wght = per node that received mass;\n"
        "   lin = ns/parcel relative to the 1e5-parcel row of the same dim/reach (1.00 = linear) --\n");
    printHeader();

    const std::vector<double> reaches{1.0, 3.0, 10.0};
    std::vector<double> counts{1e3, 1e4, 1e5, 1e6, 1e7};
    if (quick)
    {
        counts = {1e3, 1e4, 1e5};
    }
    for (int dimension : {2, 3})
    {
        const GridSpec spec = makeSpec(dimension);
        for (double reach : reaches)
        {
            DensityGrid grid(spec, kernelSettings, 1);
            const std::size_t poolSize = static_cast<std::size_t>(std::min(counts.back(), 1e6));
            std::vector<Parcel> pool = makeParcels(spec, dimension, reach, poolSize,
                                                   1234 + dimension * 10 + static_cast<int>(reach));
            double nsPerParcel = 0.0; // from the last row run, for the estimate
            double baseline = 0.0;    // ns/parcel at 1e5
            for (double count : counts)
            {
                const std::size_t parcels = static_cast<std::size_t>(count);
                const double estimate = nsPerParcel * 1e-9 * count * (repeats + 1);
                if (nsPerParcel > 0.0 && estimate > budget)
                {
                    std::printf(
                        "%3d %5.0f %6s %8s | skipped: estimated %.0f s for %d+1 runs > budget %.0f s\n",
                        dimension, reach, "random", bench::formatCount(count).c_str(), estimate, repeats,
                        budget);
                    continue;
                }
                const int reps = (nsPerParcel * 1e-9 * count > 5.0) ? std::max(2, repeats - 1) : repeats;
                const DepositionResult r = runDeposition(grid, pool, parcels, reps);
                nsPerParcel = r.depositSeconds / count * 1e9;
                if (parcels == 100000)
                {
                    baseline = nsPerParcel;
                }
                const double lin = baseline > 0.0 ? nsPerParcel / baseline : 0.0;
                std::printf("%3d %5.0f %6s %8s | %8.1f %8.1f %5.1f%% | %10.3f %9.1f %9.2f %8.2f %8.2f | %8s "
                            "%5.1f%% %5d\n",
                            dimension, reach, "random", bench::formatCount(count).c_str(), r.visitedPerParcel,
                            r.weightedPerParcel, 100.0 * r.fallbackFraction, count / r.depositSeconds / 1e6,
                            nsPerParcel, 1e3 * r.commitSeconds, nsPerParcel / r.visitedPerParcel,
                            nsPerParcel / r.weightedPerParcel,
                            lin > 0.0 ? (std::to_string(lin).substr(0, 4)).c_str() : "-", r.spreadPercent,
                            r.repeats);
                std::fflush(stdout);
            }
            // Locality: the 1e6 (quick: 1e5) pool sorted by node
            const std::size_t sortedCount = quick ? std::min<std::size_t>(poolSize, 100000) : poolSize;
            if (nsPerParcel * 1e-9 * static_cast<double>(sortedCount) * (repeats + 1) <= budget)
            {
                std::vector<Parcel> sorted(pool.begin(),
                                           pool.begin() + static_cast<std::ptrdiff_t>(sortedCount));
                sortByNode(spec, sorted);
                const DepositionResult r = runDeposition(grid, sorted, sortedCount, repeats);
                const double ns = r.depositSeconds / static_cast<double>(sortedCount) * 1e9;
                std::printf("%3d %5.0f %6s %8s | %8.1f %8.1f %5.1f%% | %10.3f %9.1f %9.2f %8.2f %8.2f | %8s "
                            "%5.1f%% %5d\n",
                            dimension, reach, "sorted",
                            bench::formatCount(static_cast<double>(sortedCount)).c_str(), r.visitedPerParcel,
                            r.weightedPerParcel, 100.0 * r.fallbackFraction,
                            static_cast<double>(sortedCount) / r.depositSeconds / 1e6, ns,
                            1e3 * r.commitSeconds, ns / r.visitedPerParcel, ns / r.weightedPerParcel,
                            baseline > 0.0 ? std::to_string(ns / baseline).substr(0, 4).c_str() : "-",
                            r.spreadPercent, r.repeats);
                std::fflush(stdout);
            }
        }
    }
    // The function object's default: cloudInCellBelow = 0.5 (KernelSettings::cloudInCellBelow)
    std::printf("\n-- the same parcels with cloudInCellBelow = 0.5 (the function object's default): a parcel "
                "whose kernel\n"
                "   width r_max / sqrt(2 alpha) is below h / 2 is deposited with cloud-in-cell weights along "
                "its path --\n");
    std::printf("%3s %5s %8s %8s | %6s %8s %8s | %10s %9s | %6s %5s\n", "dim", "reach", "width/h", "parcels",
                "cic", "visit/p", "wght/p", "Mparcel/s", "ns/parcel", "spread", "reps");
    for (int dimension : {2, 3})
    {
        const GridSpec spec = makeSpec(dimension);
        KernelSettings settings = kernelSettings;
        settings.cloudInCellBelow = 0.5;
        for (double reach : reaches)
        {
            const double nParticle = reach * spacing / dropletRadius;
            const ParcelKernel kernel(dropletRadius, nParticle, settings, dimension);
            const double count = quick ? 1e4 : (dimension == 3 && reach >= 10.0 ? 1e3 : 1e5);
            DensityGrid grid(spec, settings, 1);
            const std::vector<Parcel> pool
                = makeParcels(spec, dimension, reach, static_cast<std::size_t>(count),
                              1234 + dimension * 10 + static_cast<int>(reach));
            const DepositionResult r = runDeposition(grid, pool, pool.size(), repeats);
            const double ns = r.depositSeconds / count * 1e9;
            std::printf("%3d %5.0f %8.2f %8s | %5.0f%% %8.1f %8.1f | %10.3f %9.1f | %5.1f%% %5d\n", dimension,
                        reach, kernel.width() / spacing, bench::formatCount(count).c_str(),
                        100.0 * r.cloudInCellFraction, r.visitedPerParcel, r.weightedPerParcel,
                        count / r.depositSeconds / 1e6, ns, r.spreadPercent, r.repeats);
            std::fflush(stdout);
        }
    }

    std::printf("\nNotes: nParticle = reach * h / r_p (50, 150, 500); kernel alpha grows with n (eq. 18).\n"
                "Parcels of the 1e7 rows cycle through a pool of 1e6 distinct parcels.\n");
    return 0;
}
