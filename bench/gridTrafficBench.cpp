// gridTrafficBench: how much of the density grid the cross-rank sum moves per time step.
// The function object sums the step accumulator over the ranks only inside the union of
// the ranks' DensityGrid::stepBox() (packStep / unpackStep; OpenFOAM's listCombineGather +
// listCombineScatter). This program deposits the parcels of each rank into its own grid,
// as the ranks do, and reports the union box against the full grid: bytes per message and
// the fraction of the full-grid sum that is avoided. It also times deposit() on these
// realistic sprays (all ranks' parcels on one grid = the serial cost).
//
// Usage:
//   gridTrafficBench --parcels PREFIX RANKS --lower X Y Z --upper X Y Z --spacing H
//                    [--flat DIR] [--cap RMAXCAP] [--cic BELOW] [--dt DT] [--label TEXT]
//       parcels from PREFIX0.txt .. PREFIX<RANKS-1>.txt (bench/foamParcels.py writes
//       them from an OpenFOAM case, one file per processor directory); --flat 2: one node
//       layer in z (the 2D case's empty direction, as the function object does); --cic:
//       KernelSettings::cloudInCellBelow (the function object's default is 0.5; default here 0)
//   gridTrafficBench --synthetic3d
//       a 3D cone spray (see makeCone), decomposed into 2 and 4 ranks
//
// Bytes: the union box of N nodes is sent as N * 7 doubles (GridQuantities); with P ranks,
// listCombineGather + listCombineScatter send 2 (P - 1) such messages per step. "touched %":
// nodes that received mass on some rank, the least any sparse exchange would have to move.
#include "BenchCommon.hpp"

#include "grid/DensityGrid.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace dropletFiber;

namespace
{

std::vector<Parcel> readParcels(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
    {
        std::fprintf(stderr, "gridTrafficBench: cannot read %s\n", path.c_str());
        std::exit(1);
    }
    std::vector<Parcel> parcels;
    std::string line;
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        std::istringstream s(line);
        Parcel p;
        s >> p.position.x() >> p.position.y() >> p.position.z() >> p.velocity.x() >> p.velocity.y()
            >> p.velocity.z() >> p.diameter >> p.nParticle >> p.rhoDroplet;
        if (s)
        {
            parcels.push_back(p);
        }
    }
    return parcels;
}

GridSpec specFromSpacing(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, double spacing,
                         int flat = -1)
{
    GridSpec spec;
    spec.lower = lower;
    spec.upper = upper;
    for (int d = 0; d < 3; ++d)
    {
        const double extent = upper[d] - lower[d];
        // a direction thinner than two spacings is flat (the 2D case's depth)
        spec.nodes[d]
            = (d == flat || extent < 2.0 * spacing) ? 1 : static_cast<int>(std::lround(extent / spacing)) + 1;
    }
    return spec;
}

struct TrafficRow
{
    std::string label;
    int ranks = 0;
    std::size_t parcels = 0;
    std::size_t gridNodes = 0;
    std::vector<std::size_t> rankBoxNodes;
    std::size_t unionNodes = 0;
    std::size_t touchedNodes = 0; // nodes with mass on any rank: what a sparse exchange would move
    double packSeconds = 0.0;     // packStep + unpackStep of the union box on one rank
    double visitedPerParcel = 0.0;
    double weightedPerParcel = 0.0;
    double nsPerParcel = 0.0; // serial deposit cost of all parcels on one grid
    double cappedFraction = 0.0;
};

TrafficRow measure(const std::string& label, const GridSpec& spec, const KernelSettings& kernel,
                   const std::vector<std::vector<Parcel>>& rankParcels, double dt)
{
    TrafficRow row;
    row.label = label;
    row.ranks = static_cast<int>(rankParcels.size());
    row.gridNodes = spec.nodeCount();
    IndexBox unionBox;
    std::vector<Parcel> all;
    std::vector<char> touched(spec.nodeCount(), 0);
    for (const std::vector<Parcel>& parcels : rankParcels)
    {
        DensityGrid grid(spec, kernel, 1);
        for (const Parcel& p : parcels)
        {
            grid.deposit(p, dt);
        }
        row.rankBoxNodes.push_back(grid.stepBox().empty() ? 0 : grid.stepBox().nodeCount());
        for (std::size_t node = 0; node < spec.nodeCount(); ++node)
        {
            touched[node] |= grid.stepValues()[node * nQuantities + quantityMass] != 0.0 ? 1 : 0;
        }
        unionBox = unionBox.united(grid.stepBox());
        all.insert(all.end(), parcels.begin(), parcels.end());
    }
    row.parcels = all.size();
    row.unionNodes = unionBox.empty() ? 0 : unionBox.nodeCount();
    for (char t : touched)
    {
        row.touchedNodes += t != 0 ? 1 : 0;
    }

    // serial deposition cost of the whole spray, and the pack/unpack cost of the union box
    DensityGrid grid(spec, kernel, 1);
    const bench::Timing t = bench::timeRepeated(
        5, [&] { grid.commitStep(); },
        [&]
        {
            for (const Parcel& p : all)
            {
                grid.deposit(p, dt);
            }
        });
    const StepStatistics& stats = grid.stepStatistics();
    const double n = static_cast<double>(std::max<std::size_t>(1, all.size()));
    row.visitedPerParcel = static_cast<double>(stats.nodesVisited) / n;
    row.weightedPerParcel = static_cast<double>(stats.nodesWeighted) / n;
    row.cappedFraction = static_cast<double>(stats.parcelsCapped) / n;
    row.nsPerParcel = t.best / n * 1e9;
    if (!unionBox.empty())
    {
        const bench::Timing pack = bench::timeRepeated(5,
                                                       [&]
                                                       {
                                                           std::vector<double> values
                                                               = grid.packStep(unionBox);
                                                           grid.unpackStep(unionBox, values);
                                                       });
        row.packSeconds = pack.best;
    }
    return row;
}

void printHeader()
{
    std::printf("%-34s %5s %7s %9s %10s | %-23s %9s %10s %9s | %8s %9s | %9s | %8s %7s %7s %6s\n", "spray",
                "ranks", "parcels", "nodes", "full MB", "rank boxes (% of grid)", "union %", "msg MB",
                "MB/step", "saved", "pack ms", "touched %", "ns/parc", "visit/p", "wght/p", "capped");
}

void printRow(const TrafficRow& r)
{
    const double bytesPerNode = nQuantities * sizeof(double);
    const double fullMB = static_cast<double>(r.gridNodes) * bytesPerNode / 1e6;
    const double msgMB = static_cast<double>(r.unionNodes) * bytesPerNode / 1e6;
    std::string boxes;
    for (std::size_t b : r.rankBoxNodes)
    {
        char buffer[16];
        std::snprintf(buffer, sizeof buffer, "%s%.0f", boxes.empty() ? "" : " ",
                      100.0 * static_cast<double>(b) / static_cast<double>(r.gridNodes));
        boxes += buffer;
    }
    std::printf("%-34s %5d %7zu %9zu %10.3f | %-23s %8.1f%% %10.3f %9.3f | %7.1f%% %9.3f | %8.1f%% | %8.0f "
                "%7.1f %7.1f "
                "%5.0f%%\n",
                r.label.c_str(), r.ranks, r.parcels, r.gridNodes, fullMB, boxes.c_str(),
                100.0 * static_cast<double>(r.unionNodes) / static_cast<double>(r.gridNodes), msgMB,
                2.0 * (r.ranks - 1) * msgMB, 100.0 * (1.0 - msgMB / fullMB), 1e3 * r.packSeconds,
                100.0 * static_cast<double>(r.touchedNodes) / static_cast<double>(r.gridNodes), r.nsPerParcel,
                r.visitedPerParcel, r.weightedPerParcel, 100.0 * r.cappedFraction);
}

// 3D cone spray: nozzle at the top centre of a 0.1 x 0.15 x 0.1 m box, spraying down into
// a cone of 20 deg half angle, parcels spread along the first 0.1 m of the cone (uniform in
// distance, uniform over the cone's cross-section), moving along their ray at 5 m/s slowing
// to 1 m/s; droplets 20-60 um, n such that r_p n is 1-8 mm (capped at 6 mm).
std::vector<Parcel> makeCone(std::size_t count)
{
    bench::Random rng(31);
    const Eigen::Vector3d nozzle(0.05, 0.145, 0.05);
    const double tanHalf = std::tan(20.0 * M_PI / 180.0);
    std::vector<Parcel> parcels(count);
    for (Parcel& p : parcels)
    {
        const double s = rng.uniform(0.002, 0.1);
        double a, b;
        do
        {
            a = rng.uniform(-1, 1);
            b = rng.uniform(-1, 1);
        } while (a * a + b * b > 1.0);
        const Eigen::Vector3d ray = Eigen::Vector3d(a * tanHalf, -1.0, b * tanHalf).normalized();
        p.position = nozzle + s / std::abs(ray.y()) * ray;
        p.velocity = (5.0 - 40.0 * s) * ray;
        p.diameter = rng.uniform(20e-6, 60e-6);
        p.nParticle = rng.uniform(1e-3, 8e-3) / (0.5 * p.diameter);
        p.rhoDroplet = 1000.0;
    }
    return parcels;
}

} // namespace

int main(int argc, char** argv)
{
    std::string prefix, label;
    int ranks = 0;
    bool synthetic = false;
    Eigen::Vector3d lower(0, 0, 0), upper(0, 0, 0);
    double spacing = 0.0, cap = 0.0, dt = 5e-4, cic = 0.0;
    int flat = -1;
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        if (arg == "--parcels" && a + 2 < argc)
        {
            prefix = argv[++a];
            ranks = std::atoi(argv[++a]);
        }
        else if (arg == "--lower" && a + 3 < argc)
        {
            for (int d = 0; d < 3; ++d)
            {
                lower[d] = std::atof(argv[++a]);
            }
        }
        else if (arg == "--upper" && a + 3 < argc)
        {
            for (int d = 0; d < 3; ++d)
            {
                upper[d] = std::atof(argv[++a]);
            }
        }
        else if (arg == "--spacing" && a + 1 < argc)
        {
            spacing = std::atof(argv[++a]);
        }
        else if (arg == "--flat" && a + 1 < argc)
        {
            flat = std::atoi(argv[++a]);
        }
        else if (arg == "--cap" && a + 1 < argc)
        {
            cap = std::atof(argv[++a]);
        }
        else if (arg == "--cic" && a + 1 < argc)
        {
            cic = std::atof(argv[++a]);
        }
        else if (arg == "--dt" && a + 1 < argc)
        {
            dt = std::atof(argv[++a]);
        }
        else if (arg == "--label" && a + 1 < argc)
        {
            label = argv[++a];
        }
        else if (arg == "--synthetic3d")
        {
            synthetic = true;
        }
        else if (arg == "--header")
        {
            printHeader();
            return 0;
        }
        else
        {
            std::fprintf(stderr, "gridTrafficBench: unknown argument %s (see the header of the source)\n",
                         argv[a]);
            return 2;
        }
    }
    KernelSettings kernel;
    kernel.rMaxCap = cap;
    kernel.cloudInCellBelow = cic;
    if (synthetic)
    {
        const GridSpec spec
            = specFromSpacing(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.15, 0.1), 0.002);
        kernel.rMaxCap = 0.006;
        const std::vector<Parcel> cone = makeCone(20000);
        // 2 ranks: upper/lower half (like the tutorial's simple (1 2 1)); 4 ranks: 2 x 2 in x, z
        std::vector<std::vector<Parcel>> two(2), four(4);
        for (const Parcel& p : cone)
        {
            two[p.position.y() < 0.075 ? 0 : 1].push_back(p);
            four[(p.position.x() < 0.05 ? 0 : 1) + (p.position.z() < 0.05 ? 0 : 2)].push_back(p);
        }
        printHeader();
        printRow(measure("3D cone, 2 mm grid, split in y", spec, kernel, two, 1e-4));
        printRow(measure("3D cone, 2 mm grid, split in x,z", spec, kernel, four, 1e-4));
        return 0;
    }
    if (prefix.empty() || ranks < 1 || spacing <= 0.0)
    {
        std::fprintf(stderr, "gridTrafficBench: need --parcels PREFIX RANKS, --lower, --upper, --spacing\n");
        return 2;
    }
    std::vector<std::vector<Parcel>> rankParcels;
    for (int r = 0; r < ranks; ++r)
    {
        rankParcels.push_back(readParcels(prefix + std::to_string(r) + ".txt"));
    }
    const GridSpec spec = specFromSpacing(lower, upper, spacing, flat);
    printRow(measure(label.empty() ? prefix : label, spec, kernel, rankParcels, dt));
    return 0;
}
