// paperSettingBench: the stochastic grid method against the explicit geometric method in
// the paper's evaluation setting (Schroeder et al. 2011, sec. 6; docs/model.md sec. 5): cost per
// time step and statistical error of the droplet mass hitting a circular fiber, and the
// speed ratio at equal statistical error.
//
// Usage: paperSettingBench [--steps N] [--quick]
//   --steps  time steps per configuration for the error statistics (default 200)
//   --quick  60 steps, n = 1, 10, 100 only (default: n = 1, 10, 30, 100, 300, 1000)
//
// Setting. Box x in [-2.5, 2.5] cm, y in [0, 7] cm; fiber: circle of radius R = 1 cm centred
// at (0, 3) cm, M = 100 straight segments, at rest, fiber radius r_F = 0.2 mm (the paper's
// fig. 9 range) or 5 um (a glass-wool fiber). Droplets r_p = 10 um, rho_p = 1000 kg/m^3,
// all moving straight down at 1 m/s; dt = 0.25 ms (path 0.25 mm per step). D = 10^4
// droplets enter per step at the top, as D / n parcels of n droplets at uniformly random
// x in [-2.49, 2.49] cm (the random sampling of a CFD injector; the paper's parallel streams
// would make the geometric count a deterministic staircase), so the box holds 2.8e6 / n
// parcels in steady state (filled from the first step).
// The 2D setting read in 3D: the plane is a slab of depth T = 1 cm (the tutorial's depth),
// droplets at uniformly random depth z in [-T/2, T/2], the fiber in the mid-plane z = 0.
// Then eq. 9 with rho = droplet mass per volume and the explicit count (a droplet hits when
// its path passes within r_F + r_p of the fiber, ExplicitCollision.hpp) have the same
// expected value, so both can be scored against the same reference:
//     m_ref per step = sum over segments 2 rho (r_F + r_p) |l x v| dt   (true rho, eq. 9).
//
// Grid method (the core): DensityGrid 101 x 141 nodes (h = 0.5 mm, thickness T), window of
// one step, kernel reach r_max = n r_p, then collisionMass() of every segment at its
// midpoint; two variants on the same parcels: the kernel for every parcel (the paper,
// cloudInCellBelow 0) and cloudInCellBelow 0.5 (the function object's default: parcels whose
// kernel is narrower than h/2 are deposited with cloud-in-cell weights). Explicit method: every parcel's path against the fiber, by brute force and
// with a uniform-grid segment hash (1 mm cells); a hit of a parcel counts its n droplets.
//
// Error per step: e = (estimate - m_ref) / m_ref for the total mass on the fiber. Reported:
// bias = mean e over the steps, noise = standard deviation of e (the statistical error),
// rms = sqrt(mean e^2); and per segment the rms of (estimate_s - ref_s) / mean(ref_s).
//
// Equal statistical error: the explicit method's noise follows Poisson statistics of parcel
// hits, noise_e(n) = sqrt(n / lambda) (lambda = expected droplet hits per step; checked
// against the measured noise). The grid method with n_g droplets per parcel has the
// measured noise_g; the explicit method matches it with n_e = noise_g^2 lambda droplets per
// parcel, i.e. D / n_e parcels. When n_e < 1 even tracking every droplet (n = 1) leaves the
// explicit method noisier than the grid method; its cost at n = 1 is then a lower bound of
// the cost at equal error. Costs are linear in the parcel count (shown), so the cost at n_e
// is the measured cost per parcel times D / n_e per step. When n_e < 1 the explicit method
// must average K = noise_e(1)^2 / noise_g^2 independent evaluations (K times the cost of
// n = 1) to reach the grid's noise: cost x variance, the usual Monte-Carlo efficiency.
#include "BenchCommon.hpp"
#include "ExplicitCollision.hpp"

#include "collision/CollisionMass.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace dropletFiber;
using bench::BruteForce;
using bench::FiberSegments;
using bench::SegmentHash;

namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double xHalf = 0.025, yTop = 0.07, depth = 0.01;
constexpr double injectHalf = 0.0249;
constexpr double speed = 1.0, dt = 2.5e-4, pathLength = speed * dt;
constexpr double dropletRadius = 1e-5, rhoDroplet = 1000.0;
constexpr double dropletsPerStep = 1e4;
constexpr double circleRadius = 0.01, circleY = 0.03;
constexpr int circleSegments = 100;

double dropletMassOf()
{
    return rhoDroplet * 4.0 / 3.0 * pi * std::pow(dropletRadius, 3);
}

// The droplet population (end-of-step positions, structure of arrays), all with velocity
// (0, -speed, 0) and n droplets per parcel.
struct Spray
{
    std::vector<double> x, y, z;
    int parcelsPerStep = 0;
    double nParticle = 1.0;
    bench::Random rng{2011};

    Spray(double n, std::uint64_t seed) : nParticle(n), rng(seed)
    {
        parcelsPerStep = static_cast<int>(std::lround(dropletsPerStep / n));
        // steady state at once: parcels uniform over the box height
        const std::size_t initial = static_cast<std::size_t>(parcelsPerStep * (yTop / pathLength));
        for (std::size_t i = 0; i < initial; ++i)
        {
            add(rng.uniform(0.0, yTop));
        }
    }
    void add(double yEnd)
    {
        x.push_back(rng.uniform(-injectHalf, injectHalf));
        y.push_back(yEnd);
        z.push_back(rng.uniform(-0.5 * depth, 0.5 * depth));
    }
    // One step of the (trivial) Lagrangian tracking: move, drop what left, inject.
    void advance()
    {
        std::size_t keep = 0;
        for (std::size_t i = 0; i < y.size(); ++i)
        {
            const double yn = y[i] - pathLength;
            if (yn - 0.0 > -pathLength) // path still touches the box (start above y = 0)
            {
                x[keep] = x[i];
                y[keep] = yn;
                z[keep] = z[i];
                ++keep;
            }
        }
        x.resize(keep);
        y.resize(keep);
        z.resize(keep);
        for (int k = 0; k < parcelsPerStep; ++k)
        {
            add(yTop - pathLength * rng.uniform()); // entered during this step
        }
    }
    std::size_t size() const { return x.size(); }
};

FiberSegments makeCircle()
{
    FiberSegments segments;
    for (int k = 0; k < circleSegments; ++k)
    {
        const double a0 = 2.0 * pi * k / circleSegments, a1 = 2.0 * pi * (k + 1) / circleSegments;
        segments.add(Eigen::Vector3d(circleRadius * std::cos(a0), circleY + circleRadius * std::sin(a0), 0.0),
                     Eigen::Vector3d(circleRadius * std::cos(a1), circleY + circleRadius * std::sin(a1), 0.0),
                     0);
    }
    return segments;
}

// Running error statistics of one method.
struct ErrorStats
{
    double sum = 0.0, sumSquares = 0.0, segmentSquares = 0.0;
    long steps = 0, segmentSamples = 0;
    void add(double estimate, double reference) // total per step
    {
        const double e = (estimate - reference) / reference;
        sum += e;
        sumSquares += e * e;
        ++steps;
    }
    void addSegments(const std::vector<double>& estimate, const std::vector<double>& reference,
                     double meanReference)
    {
        for (std::size_t s = 0; s < estimate.size(); ++s)
        {
            const double e = (estimate[s] - reference[s]) / meanReference;
            segmentSquares += e * e;
            ++segmentSamples;
        }
    }
    double bias() const { return sum / steps; }
    double noise() const { return std::sqrt(std::max(0.0, sumSquares / steps - bias() * bias())); }
    double rms() const { return std::sqrt(sumSquares / steps); }
    double segmentRms() const { return std::sqrt(segmentSquares / segmentSamples); }
};

struct MethodCost
{
    double best = 1e300;
    std::vector<double> all;
    void add(double s)
    {
        best = std::min(best, s);
        all.push_back(s);
    }
    double median()
    {
        std::vector<double> v = all;
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        return v[v.size() / 2];
    }
};

struct RunResult
{
    double n = 0.0;
    double parcels = 0.0;                            // in the box, mean
    std::array<MethodCost, 2> gridCost, gridDeposit; // per grid variant
    std::array<ErrorStats, 2> explicitStats;         // per fiber radius
    std::array<MethodCost, 2> hashCost;
    std::array<double, 2> bruteBest{{0.0, 0.0}};
    std::array<double, 2> meanHits{{0.0, 0.0}};            // parcel hits per step
    std::array<std::array<ErrorStats, 2>, 2> gridByRadius; // [variant][fiber radius]
    std::array<double, 2> cloudInCellFraction{{0.0, 0.0}};
    bool bruteChecked = true;
};

const std::array<double, 2> fiberRadii{{2e-4, 5e-6}};
// Grid variants: KernelSettings::cloudInCellBelow = 0 (the kernel for every parcel, the
// paper) and 0.5 (the function object's default: kernels narrower than h/2 -> cloud-in-cell).
const std::array<double, 2> cloudInCellBelow{{0.0, 0.5}};
const std::array<const char*, 2> variantName{
    {"kernel (paper, cloudInCellBelow 0)", "cloudInCellBelow 0.5 (function object default)"}};

RunResult run(double n, int steps, bool withBrute, bool withGrid)
{
    RunResult result;
    result.n = n;
    Spray spray(n, 1000 + static_cast<std::uint64_t>(n));
    const FiberSegments circle = makeCircle();
    const double m = dropletMassOf();
    const Eigen::Vector3d velocity(0.0, -speed, 0.0);
    const Eigen::Vector3d displacement = velocity * dt;

    // references per segment and radius
    const double numberDensity = dropletsPerStep / (2.0 * injectHalf * pathLength * depth);
    const double rho = numberDensity * m;
    std::array<std::vector<double>, 2> reference;
    std::array<double, 2> referenceTotal{{0.0, 0.0}};
    for (int r = 0; r < 2; ++r)
    {
        for (std::size_t k = 0; k < circle.size(); ++k)
        {
            const double mass = collisionMass(rho, dropletRadius, fiberRadii[static_cast<std::size_t>(r)],
                                              circle.vector[k], velocity, dt);
            reference[static_cast<std::size_t>(r)].push_back(mass);
            referenceTotal[static_cast<std::size_t>(r)] += mass;
        }
    }

    GridSpec spec;
    spec.lower = Eigen::Vector3d(-xHalf, 0.0, -0.5 * depth);
    spec.upper = Eigen::Vector3d(xHalf, yTop, 0.5 * depth);
    spec.nodes = {{101, 141, 1}};
    std::vector<DensityGrid> grids;
    for (double below : cloudInCellBelow)
    {
        KernelSettings settings;
        settings.cloudInCellBelow = below;
        grids.emplace_back(spec, settings, 1);
    }
    SegmentHash hash(circle, spec.lower, spec.upper, 1e-3, fiberRadii[0] + dropletRadius);
    BruteForce brute(circle);

    std::vector<double> segmentMass(circle.size());
    double parcelSum = 0.0;
    int bruteSteps = 0;
    for (int step = 0; step < steps; ++step)
    {
        spray.advance();
        parcelSum += static_cast<double>(spray.size());
        // --- grid method: deposit every parcel, commit, collision mass of every segment
        for (std::size_t v = 0; v < grids.size() && withGrid; ++v)
        {
            DensityGrid& grid = grids[v];
            const auto start = bench::Clock::now();
            Parcel p;
            p.velocity = velocity;
            p.diameter = 2.0 * dropletRadius;
            p.nParticle = n;
            p.rhoDroplet = rhoDroplet;
            for (std::size_t i = 0; i < spray.size(); ++i)
            {
                p.position = Eigen::Vector3d(spray.x[i], spray.y[i], spray.z[i]);
                grid.deposit(p, dt);
            }
            result.cloudInCellFraction[v] = static_cast<double>(grid.stepStatistics().parcelsCloudInCell)
                / static_cast<double>(std::max<std::int64_t>(1, grid.stepStatistics().parcels));
            grid.commitStep();
            const double depositSeconds = bench::secondsSince(start);
            // the grid's collision mass is linear in (r_F + <r>): evaluate for both radii, time the first
            for (int r = 0; r < 2; ++r)
            {
                const auto collisionStart = bench::Clock::now();
                double total = 0.0;
                for (std::size_t k = 0; k < circle.size(); ++k)
                {
                    const SegmentCollision c
                        = collisionMass(grid, circle.start[k], circle.start[k] + circle.vector[k],
                                        fiberRadii[static_cast<std::size_t>(r)], Eigen::Vector3d::Zero(), dt);
                    segmentMass[k] = c.mass;
                    total += c.mass;
                }
                if (r == 0)
                {
                    result.gridCost[v].add(depositSeconds + bench::secondsSince(collisionStart));
                    result.gridDeposit[v].add(depositSeconds);
                }
                ErrorStats& stats = result.gridByRadius[v][static_cast<std::size_t>(r)];
                stats.add(total, referenceTotal[static_cast<std::size_t>(r)]);
                stats.addSegments(segmentMass, reference[static_cast<std::size_t>(r)],
                                  referenceTotal[static_cast<std::size_t>(r)]
                                      / static_cast<double>(circle.size()));
            }
        }
        // --- explicit method, hashed (every step) and brute force (a few steps, checked equal)
        for (int r = 0; r < 2; ++r)
        {
            const double reach = fiberRadii[static_cast<std::size_t>(r)] + dropletRadius;
            std::fill(segmentMass.begin(), segmentMass.end(), 0.0);
            long hits = 0;
            const auto start = bench::Clock::now();
            for (std::size_t i = 0; i < spray.size(); ++i)
            {
                const Eigen::Vector3d end(spray.x[i], spray.y[i], spray.z[i]);
                hash.query(end - displacement, displacement, reach,
                           [&](int segment)
                           {
                               ++hits;
                               segmentMass[static_cast<std::size_t>(segment)] += n * m;
                           });
            }
            result.hashCost[static_cast<std::size_t>(r)].add(bench::secondsSince(start));
            double total = 0.0;
            for (double s : segmentMass)
            {
                total += s;
            }
            result.explicitStats[static_cast<std::size_t>(r)].add(
                total, referenceTotal[static_cast<std::size_t>(r)]);
            result.explicitStats[static_cast<std::size_t>(r)].addSegments(
                segmentMass, reference[static_cast<std::size_t>(r)],
                referenceTotal[static_cast<std::size_t>(r)] / static_cast<double>(circle.size()));
            result.meanHits[static_cast<std::size_t>(r)] += static_cast<double>(hits) / steps;

            if (withBrute && bruteSteps < 2 && step >= 1)
            {
                long bruteHits = 0;
                const auto bruteStart = bench::Clock::now();
                for (std::size_t i = 0; i < spray.size(); ++i)
                {
                    const Eigen::Vector3d end(spray.x[i], spray.y[i], spray.z[i]);
                    brute.query(end - displacement, displacement, reach, [&](int) { ++bruteHits; });
                }
                const double seconds = bench::secondsSince(bruteStart);
                double& best = result.bruteBest[static_cast<std::size_t>(r)];
                best = best == 0.0 ? seconds : std::min(best, seconds);
                if (bruteHits != hits)
                {
                    result.bruteChecked = false;
                }
                if (r == 1)
                {
                    ++bruteSteps;
                }
            }
        }
    }
    result.parcels = parcelSum / steps;
    return result;
}

} // namespace

int main(int argc, char** argv)
{
    int steps = 200;
    bool quick = false;
    for (int a = 1; a < argc; ++a)
    {
        if (!std::strcmp(argv[a], "--steps") && a + 1 < argc)
        {
            steps = std::max(10, std::atoi(argv[++a]));
        }
        else if (!std::strcmp(argv[a], "--quick"))
        {
            quick = true;
            steps = 60;
        }
    }
    const double m = dropletMassOf();
    const double numberDensity = dropletsPerStep / (2.0 * injectHalf * pathLength * depth);
    std::printf(
        "== paperSettingBench: grid method vs explicit geometric method, paper's sec. 6 setting ==\n");
    std::printf(
        "box 5 x 7 cm x depth %.0f mm, circle R = 1 cm (100 segments), droplets r_p = 10 um at 1 m/s down,\n"
        "dt = %.2g s, %.0f droplets per step (%.3g kg/s), droplet number density %.3g /m^3, %d steps per "
        "row\n\n",
        depth * 1e3, dt, dropletsPerStep, dropletsPerStep * m / dt, numberDensity, steps);

    std::vector<double> ns
        = quick ? std::vector<double>{1, 10, 100} : std::vector<double>{1, 10, 30, 100, 300, 1000};
    std::vector<RunResult> results;
    for (double n : ns)
    {
        // n = 1: r_max = r_p is far below the node spacing (every parcel would fall back to
        // cloud-in-cell weights) and 2.8e6 parcels per step: the grid method is not run there
        results.push_back(run(n, steps, true, n > 1.0));
        const RunResult& r = results.back();
        std::fprintf(stderr, "  n = %g done (%.0f parcels)\n", n, r.parcels);
    }

    std::printf(
        "-- cost per step (best over the steps; ms) and per parcel (ns); grid = deposit + commit + collision "
        "of\n"
        "   the 100 segments, variant K = kernel for every parcel (paper), C = cloudInCellBelow 0.5 --\n");
    std::printf("%6s %9s | %9s %9s %6s | %9s %9s %6s | %10s %10s %9s | %10s %9s | %s\n", "n", "parcels",
                "grid K ms", "ns/parcel", "", "grid C ms", "ns/parcel", "cic", "hash ms rF1", "hash ms rF2",
                "ns/parcel", "brute ms", "ns/pair", "brute=hash");
    for (RunResult& r : results)
    {
        for (std::size_t v = 0; v < 2; ++v)
        {
            if (r.gridCost[v].all.empty())
            {
                r.gridCost[v].best = r.gridDeposit[v].best = 0.0;
            }
        }
        std::printf(
            "%6.0f %9.0f | %9.2f %9.1f %6s | %9.2f %9.1f %5.0f%% | %10.2f %10.2f %9.1f | %10.1f %9.2f | %s\n",
            r.n, r.parcels, 1e3 * r.gridCost[0].best, r.gridCost[0].best / r.parcels * 1e9, "",
            1e3 * r.gridCost[1].best, r.gridCost[1].best / r.parcels * 1e9, 100.0 * r.cloudInCellFraction[1],
            1e3 * r.hashCost[0].best, 1e3 * r.hashCost[1].best, r.hashCost[0].best / r.parcels * 1e9,
            1e3 * r.bruteBest[0], r.bruteBest[0] / (r.parcels * circleSegments) * 1e9,
            r.bruteChecked ? "yes" : "NO");
    }

    for (int rIndex = 0; rIndex < 2; ++rIndex)
    {
        const double rF = fiberRadii[static_cast<std::size_t>(rIndex)];
        const std::size_t ri = static_cast<std::size_t>(rIndex);
        // expected droplet hits per step (reference mass / droplet mass)
        double refTotal = 0.0;
        {
            const FiberSegments circle = makeCircle();
            for (std::size_t k = 0; k < circle.size(); ++k)
            {
                refTotal += collisionMass(numberDensity * m, dropletRadius, rF, circle.vector[k],
                                          Eigen::Vector3d(0.0, -speed, 0.0), dt);
            }
        }
        const double lambda = refTotal / m;
        std::printf("\n-- errors, fiber radius r_F = %g m: reference %.4g kg per step = %.1f droplet hits "
                    "per step --\n",
                    rF, refTotal, lambda);
        std::printf("%6s | %8s %8s %8s | %8s %8s %8s | %8s %8s %8s %8s %10s\n", "n", "K bias", "noise",
                    "seg rms", "C bias", "noise", "seg rms", "expl bias", "noise", "Poisson", "seg rms",
                    "hits/step");
        for (RunResult& r : results)
        {
            const ErrorStats& e = r.explicitStats[ri];
            std::printf("%6.0f |", r.n);
            for (std::size_t v = 0; v < 2; ++v)
            {
                const ErrorStats& g = r.gridByRadius[v][ri];
                if (g.steps == 0)
                {
                    std::printf(" %8s %8s %8s |", "-", "-", "-");
                }
                else
                {
                    std::printf(" %8.4f %8.4f %8.3f |", g.bias(), g.noise(), g.segmentRms());
                }
            }
            std::printf(" %8.4f %8.4f %8.4f %8.3f %10.2f\n", e.bias(), e.noise(), std::sqrt(r.n / lambda),
                        e.segmentRms(), r.meanHits[ri]);
        }
        // equal statistical error
        const RunResult& ones = results.front(); // n = 1: cost per parcel of the explicit method
        const double hashPerParcel = ones.hashCost[ri].best / ones.parcels;
        const double brutePerParcel = ones.bruteBest[ri] > 0.0 ? ones.bruteBest[ri] / ones.parcels : 0.0;
        const double noiseOne = ones.explicitStats[ri].noise(); // measured explicit noise at n = 1
        std::printf(
            "\n   equal statistical error (r_F = %g m): grid method with n_g droplets per parcel against "
            "the\n"
            "   explicit method with n_e = noise_g^2 * lambda droplets per parcel (D / n_e parcels per "
            "step).\n"
            "   n_e < 1 cannot be tracked (every droplet is its own parcel at n = 1); then\n"
            "     A = explicit at n = 1 (still noisier than the grid: a lower bound of its cost), and\n"
            "     B = explicit at n = 1 averaged over K = noise_e(1)^2 / noise_g^2 independent evaluations\n"
            "         (steps or replicas), the cost of actually reaching the grid's noise (= A when n_e >= "
            "1).\n",
            rF);
        for (std::size_t v = 0; v < 2; ++v)
        {
            std::printf("   grid variant: %s\n", variantName[v]);
            std::printf("%6s %9s %9s | %9s %9s %10s | %10s %8s %8s | %10s %8s %8s\n", "n_g", "noise_g",
                        "grid ms", "n_e", "K", "parcels_e", "hash ms B", "ratio A", "ratio B", "brute ms B",
                        "ratio A", "ratio B");
            for (RunResult& r : results)
            {
                if (r.gridCost[v].all.empty())
                {
                    continue;
                }
                const double noise = r.gridByRadius[v][ri].noise();
                const double nEqual = noise * noise * lambda;
                const double nUsed = std::max(1.0, nEqual);
                const double parcelsE = ones.parcels / nUsed;
                const double k = nEqual < 1.0 ? std::max(1.0, noiseOne * noiseOne / (noise * noise)) : 1.0;
                const double hashA = 1e3 * hashPerParcel * parcelsE;
                const double bruteA = 1e3 * brutePerParcel * parcelsE;
                const double gridMs = 1e3 * r.gridCost[v].best;
                std::printf(
                    "%6.0f %9.4f %9.2f | %9.3f %9.1f %10.0f | %10.2f %7.1fx %7.1fx | %10.0f %7.0fx %7.0fx\n",
                    r.n, noise, gridMs, nEqual, k, parcelsE, k * hashA, hashA / gridMs, k * hashA / gridMs,
                    k * bruteA, bruteA / gridMs, k * bruteA / gridMs);
            }
        }
    }
    std::printf(
        "\nratio = explicit cost / grid cost per step at equal statistical error (> 1: grid method faster).\n"
        "Explicit costs count only the collision test, not the Lagrangian tracking of the n_g / n_e times\n"
        "more parcels it needs.\n");
    return 0;
}
