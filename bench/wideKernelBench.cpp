// wideKernelBench: cost of DensityGrid::deposit for parcels of many droplets (wide kernels,
// docs/model.md P16), the exact per-node path integral against the separable weights, in
// one run (docs/performance.md, "Wide kernels").
//
// Rows: 3D grid box 5 x 5 x 5 cm, node spacing h = 0.5 mm (101^3 nodes) or 2 mm (26^3);
// parcels of n = 10, 100, 1000, 5000 droplets of r_p = 5 or 50 um (rho_p 1000 kg/m^3) at
// uniformly random end positions in the box (random order; kernels near the faces are
// folded), stationary or moving h/2 per step in a random direction (dt = 1e-4 s). Default
// KernelSettings (negligibleWeight 1e-8, cloudInCellBelow 0: always the kernel).
// Columns, each the same parcels, one deposit() each (timed), then commitStep() (not timed):
//   per node : method exact, vectorised false (PathWeight node by node)
//   batched  : method exact, vectorised true (AVX2 + FMA where the CPU has it)
//   separable: method automatic (SeparableWeight where chosen; the share of parcels that
//              took it is printed)
//   floor    : no weights at all: the seven quantities of each parcel added with a constant
//              weight into every node of its deposit box (DensityGrid::depositBox, the folded
//              box) of an array laid out as the grid's accumulator: what adding into the
//              accumulator alone costs, the least any deposit that adds every box node pays
//              (the per-node code adds only the nodes within the cut, about pi/6 of a 3D box)
//   as filed : the deposit's defaults when the wide-kernel work began (issue "spray-solver
//              parcels": "10x faster than today's per-node code"): method exact, vectorised
//              (batched where the CPU has it), negligibleWeight 1e-17 (reach ~8.9 widths
//              instead of ~6): the before of "before and after" with default settings
// Printed: ns per parcel (best of the repeats, and the spread (slowest - fastest) /
// fastest), ns per node touched (box nodes: StepStatistics::nodesVisited), the kernel's
// reach after the negligible-weight cut in spacings, the speed-up of separable over per
// node, and per node over the floor: the most a deposit adding every box node could gain
// over it, and of separable over as filed. The five columns run interleaved (A B C D E A B C D
// E ...). Figures, not a test.
//
// Usage: wideKernelBench [--repeats N] [--seconds S] [--parcels N] [--spacing MM]
//   --repeats  interleaved rounds (default 3)
//   --seconds  target time of one timed run of the per-node column (default 0.15 s): the
//              parcel count of a row is chosen from it (at least 1, at most 4000)
//   --parcels  the parcel count of every row instead (builds compared A/B: a step's first
//              writes into each row, zeroing it, weigh per parcel by the count)
//   --spacing  the rows of one node spacing only (0.5 or 2)
#include "BenchCommon.hpp"

#include "grid/DensityGrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

using namespace dropletFiber;

namespace
{

constexpr double dt = 1e-4;
constexpr double boxSize = 0.05;

struct Row
{
    double spacing;
    double radius;
    double n;
    bool moving;
};

GridSpec gridSpec(double spacing)
{
    GridSpec s;
    const int nodes = static_cast<int>(std::lround(boxSize / spacing)) + 1;
    s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    s.upper = Eigen::Vector3d(boxSize, boxSize, boxSize);
    s.nodes = {{nodes, nodes, nodes}};
    return s;
}

std::vector<Parcel> makeParcels(const Row& row, int count)
{
    bench::Random random(11);
    std::vector<Parcel> parcels(static_cast<std::size_t>(count));
    for (Parcel& p : parcels)
    {
        p.position = Eigen::Vector3d(random.uniform(0.0, boxSize), random.uniform(0.0, boxSize),
                                     random.uniform(0.0, boxSize));
        Eigen::Vector3d direction(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0),
                                  random.uniform(-1.0, 1.0));
        p.velocity = row.moving ? Eigen::Vector3d(direction.normalized() * (0.5 * row.spacing / dt))
                                : Eigen::Vector3d(Eigen::Vector3d::Zero());
        p.diameter = 2.0 * row.radius;
        p.nParticle = row.n;
        p.rhoDroplet = 1000.0;
    }
    return parcels;
}

// Columns 0 per node, 1 batched, 2 separable, 3 as filed (the floor has no grid).
KernelSettings settingsOf(int column)
{
    KernelSettings s;
    s.method = column == 2 ? DepositMethod::Automatic : DepositMethod::Exact;
    s.vectorised = column != 0;
    if (column == 3)
    {
        s.negligibleWeight = 1e-17;
    }
    return s;
}

struct Run
{
    double seconds;
    StepStatistics statistics;
};

Run depositAll(DensityGrid& grid, const std::vector<Parcel>& parcels)
{
    // The deposit only: commitStep() costs per node of the touched box whatever the method
    // (docs/performance.md, averaging window).
    const double start = bench::Clock::now();
    for (const Parcel& p : parcels)
    {
        grid.deposit(p, dt);
    }
    const double seconds = bench::secondsSince(start);
    grid.commitStep();
    return {seconds, grid.lastStepStatistics()};
}

// The floor column: each parcel's seven totals (any values: a constant weight times fixed
// totals) added into every node of its deposit box, in the grid's accumulator layout.
double accumulateOnly(const DensityGrid& grid, const std::vector<Parcel>& parcels,
                      std::vector<double>& values)
{
    const std::array<int, 3>& nodes = grid.spec().nodes;
    const double totals[nQuantities] = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0};
    const double start = bench::Clock::now();
    for (const Parcel& p : parcels)
    {
        const IndexBox box = grid.depositBox(p, dt);
        for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        {
            for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            {
                const std::size_t first = flatNodeIndex(nodes, box.lo[0], j, k);
                double* v = values.data() + first * nQuantities;
                const std::size_t count = static_cast<std::size_t>(box.hi[0] - box.lo[0] + 1);
                for (std::size_t i = 0; i < count * nQuantities; i += nQuantities)
                {
                    for (int q = 0; q < nQuantities; ++q)
                    {
                        v[i + static_cast<std::size_t>(q)] += 1e-3 * totals[q];
                    }
                }
            }
        }
    }
    return bench::secondsSince(start);
}

// The kernel's reach after the negligible-weight cut (P10) in node spacings, and its width
// (eq. 16) in spacings.
std::pair<double, double> kernelInSpacings(const Row& row)
{
    const KernelSettings settings;
    const ParcelKernel kernel(row.radius, row.n, settings, 3);
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * row.spacing;
    const double best = kernel.phi(halfDiagonal + (row.moving ? 0.25 * row.spacing : 0.0));
    double reach = kernel.reach();
    if (kernel.edgeExponent() > -std::log(settings.negligibleWeight) && best > 0.0)
    {
        reach = std::min(reach,
                         std::sqrt((-std::log(settings.negligibleWeight) - std::log(best)) / kernel.gamma()));
    }
    return {reach / row.spacing, kernel.width() / row.spacing};
}

void benchRow(const Row& row, int repeats, double targetSeconds, int fixedCount)
{
    const GridSpec spec = gridSpec(row.spacing);
    std::vector<DensityGrid> grids;
    for (int column = 0; column < 4; ++column)
    {
        grids.emplace_back(spec, settingsOf(column));
    }
    // Parcel count from one parcel of the per-node column.
    const Run probe = depositAll(grids[0], makeParcels(row, 1));
    const int count = fixedCount > 0
        ? fixedCount
        : static_cast<int>(std::clamp(targetSeconds / std::max(probe.seconds, 1e-9), 1.0, 4000.0));
    const std::vector<Parcel> parcels = makeParcels(row, count);
    // seconds: per node, batched, separable, floor, as filed
    std::vector<std::vector<double>> seconds(5);
    std::vector<StepStatistics> statistics(4);
    std::vector<double> accumulator(grids[0].stepValues().size(), 0.0);
    for (int r = 0; r < repeats; ++r)
    {
        for (int column = 0; column < 3; ++column)
        {
            const Run run = depositAll(grids[static_cast<std::size_t>(column)], parcels);
            seconds[static_cast<std::size_t>(column)].push_back(run.seconds);
            statistics[static_cast<std::size_t>(column)] = run.statistics;
        }
        seconds[3].push_back(accumulateOnly(grids[0], parcels, accumulator));
        const Run filed = depositAll(grids[3], parcels);
        seconds[4].push_back(filed.seconds);
        statistics[3] = filed.statistics;
    }
    const double nodes = static_cast<double>(statistics[0].nodesVisited);
    const double filedNodes = static_cast<double>(statistics[3].nodesVisited);
    const auto [reach, width] = kernelInSpacings(row);
    std::printf("%4.1f %4.0f %5.0f %-4s %6d %7.1f %7.2f |", row.spacing * 1e3, row.radius * 1e6, row.n,
                row.moving ? "mov" : "sta", count, reach, width);
    double best[5];
    for (int column = 0; column < 5; ++column)
    {
        const std::vector<double>& s = seconds[static_cast<std::size_t>(column)];
        best[column] = *std::min_element(s.begin(), s.end());
        const double spread = 100.0 * (*std::max_element(s.begin(), s.end()) - best[column]) / best[column];
        std::printf(" %10.0f %6.2f %3.0f%% |", best[column] / count * 1e9,
                    best[column] / (column == 4 ? filedNodes : nodes) * 1e9, spread);
    }
    const double separableShare = static_cast<double>(statistics[2].parcelsSeparable) / count;
    std::printf(" %5.1fx %5.1fx %4.0f%% %5.1fx %5.1fx\n", best[0] / best[2], best[1] / best[2],
                100.0 * separableShare, best[0] / best[3], best[4] / best[2]);
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
    int repeats = 3;
    double targetSeconds = 0.15;
    double onlySpacing = 0.0;
    int fixedCount = 0;
    for (int a = 1; a < argc; ++a)
    {
        if (std::strcmp(argv[a], "--repeats") == 0 && a + 1 < argc)
        {
            repeats = std::max(1, std::atoi(argv[++a]));
        }
        else if (std::strcmp(argv[a], "--seconds") == 0 && a + 1 < argc)
        {
            targetSeconds = std::atof(argv[++a]);
        }
        else if (std::strcmp(argv[a], "--parcels") == 0 && a + 1 < argc)
        {
            fixedCount = std::max(1, std::atoi(argv[++a]));
        }
        else if (std::strcmp(argv[a], "--spacing") == 0 && a + 1 < argc)
        {
            onlySpacing = std::atof(argv[++a]) * 1e-3;
        }
        else
        {
            std::fprintf(stderr,
                         "usage: wideKernelBench [--repeats N] [--seconds S] [--parcels N] [--spacing MM]\n");
            return 1;
        }
    }
    std::printf("wideKernelBench: 3D box 5 cm, deposit() ns per parcel and per box node; best of %d "
                "interleaved repeats, spread = (slowest - fastest) / fastest; batched kernel %s\n",
                repeats, DensityGrid(gridSpec(2e-3)).batchedKernel() ? "AVX2 + FMA" : "not available");
    std::printf("h/mm r/um     n path parcels reach/h width/h |  per node: ns/parcel ns/node spread |"
                "   batched: ns/parcel ns/node spread | separable: ns/parcel ns/node spread |"
                " floor: ns/parcel ns/node spread | as filed: ns/parcel ns/node spread |"
                " separable vs per node, vs batched, separable share, per node vs floor,"
                " separable vs as filed\n");
    for (double spacing : {2e-3, 5e-4})
    {
        if (onlySpacing > 0.0 && std::abs(spacing - onlySpacing) > 1e-9)
        {
            continue;
        }
        for (double radius : {5e-6, 5e-5})
        {
            for (double n : {10.0, 100.0, 1000.0, 5000.0})
            {
                for (bool moving : {false, true})
                {
                    benchRow(Row{spacing, radius, n, moving}, repeats, targetSeconds, fixedCount);
                }
            }
        }
    }
    return 0;
}
