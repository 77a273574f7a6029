// kernelCutBench: what the two settings that shorten a wide kernel's reach cost and change
// (docs/model.md sec. 4, cost of wide kernels; docs/performance.md). On a 3D grid of 1 mm:
//  1. negligibleWeight 1e-17, 1e-12, 1e-8, 1e-6 against 0 (every node within r_max): nodes
//     visited and deposit time per parcel, and the largest node-value error of one parcel
//     relative to its largest node value (the bound of docs/model.md, P10 tail);
//     configurations interleaved per round, median and range over the rounds;
//  2. rMaxCap at 2, 3, 4 and 6 kernel widths against none: the density through the parcel
//     at 0..4 widths from it, and the density integrated along a straight line passing at
//     0..4 widths (the eq. 9 mass a fixed fiber there would capture), relative to no cap.
//
// Usage: kernelCutBench [--rounds N] [--parcels N]
// Parcels: droplets rho_p 1000 kg/m^3 of the spray3D case (bench/spray3D): r_p 15 um with
// n = 3,400 (width ~1.5 spacings) and r_p 10 um with n = 11,000 (~3 spacings), at random
// positions within 5 mm of the grid's centre, stationary or moving 0.5 mm in the step.
#include "BenchCommon.hpp"

#include "grid/DensityGrid.hpp"
#include "grid/ParcelKernel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace dropletFiber;

namespace
{

constexpr double spacing = 1e-3;
constexpr double dt = 1e-3;

GridSpec cube()
{
    GridSpec s; // 6 cm cube, 61^3 nodes: the widest kernel (reach ~27 mm at 1e-17) fits
    s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
    s.upper = Eigen::Vector3d(0.06, 0.06, 0.06);
    s.nodes = {{61, 61, 61}};
    return s;
}

struct ParcelClass
{
    const char* name;
    double radius;
    double n;
    double speed;
};

std::vector<Parcel> makeParcels(const ParcelClass& c, int count)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> offset(-5e-3, 5e-3);
    std::vector<Parcel> parcels(static_cast<std::size_t>(count));
    for (Parcel& p : parcels)
    {
        p.position = Eigen::Vector3d(0.03 + offset(random), 0.03 + offset(random), 0.03 + offset(random));
        p.velocity = Eigen::Vector3d(c.speed, 0.0, 0.0);
        p.diameter = 2.0 * c.radius;
        p.nParticle = c.n;
        p.rhoDroplet = 1000.0;
    }
    return parcels;
}

KernelSettings withCut(double negligibleWeight, double cap = 0.0)
{
    KernelSettings s;
    s.negligibleWeight = negligibleWeight;
    s.rMaxCap = cap;
    return s;
}

// Node values (kg/m^3) of one committed step of the given parcels.
std::vector<double> density(const KernelSettings& settings, const std::vector<Parcel>& parcels)
{
    DensityGrid grid(cube(), settings);
    for (const Parcel& p : parcels)
    {
        grid.deposit(p, dt);
    }
    grid.commitStep();
    std::vector<double> rho(61u * 61u * 61u);
    for (std::size_t node = 0; node < rho.size(); ++node)
    {
        rho[node] = grid.nodeValue(node).rho;
    }
    return rho;
}

double largestRelativeError(const std::vector<double>& value, const std::vector<double>& reference)
{
    double largest = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < value.size(); ++i)
    {
        largest = std::max(largest, reference[i]);
        worst = std::max(worst, std::abs(value[i] - reference[i]));
    }
    return worst / largest;
}

void negligibleWeightTable(const ParcelClass& c, int rounds, int count)
{
    const std::vector<double> cuts{0.0, 1e-17, 1e-12, 1e-8, 1e-6};
    const std::vector<Parcel> parcels = makeParcels(c, count);
    std::vector<std::vector<double>> nsPerParcel(cuts.size());
    std::vector<double> nodesPerParcel(cuts.size());
    for (int round = 0; round < rounds; ++round)
    {
        for (std::size_t i = 0; i < cuts.size(); ++i) // interleaved: every cut in every round
        {
            DensityGrid grid(cube(), withCut(cuts[i]));
            const auto start = bench::Clock::now();
            for (const Parcel& p : parcels)
            {
                grid.deposit(p, dt);
            }
            nsPerParcel[i].push_back(1e9 * bench::secondsSince(start) / count);
            nodesPerParcel[i] = static_cast<double>(grid.stepStatistics().nodesVisited) / count;
            bench::sink(grid.stepValues()[0]);
        }
    }
    const std::vector<Parcel> one(parcels.begin(), parcels.begin() + 1);
    const std::vector<double> reference = density(withCut(0.0), one);
    const ParcelKernel kernel(0.5 * one[0].diameter, one[0].nParticle, withCut(1e-17), 3);
    std::printf("\n%s: width %.2f spacings, r_max %.0f spacings (%d parcels, %d rounds)\n", c.name,
                kernel.width() / spacing, c.radius * c.n / spacing, count, rounds);
    std::printf("  negligibleWeight  nodes/parcel  us/parcel median [min-max]  ns/node  error/largest\n");
    for (std::size_t i = 0; i < cuts.size(); ++i)
    {
        std::vector<double> t = nsPerParcel[i];
        std::sort(t.begin(), t.end());
        const double median = t[t.size() / 2];
        const double error = i == 0 ? 0.0 : largestRelativeError(density(withCut(cuts[i]), one), reference);
        std::printf("  %-16g  %12.0f  %9.1f [%.1f-%.1f]  %12.1f  %.2e\n", cuts[i], nodesPerParcel[i],
                    1e-3 * median, 1e-3 * t.front(), 1e-3 * t.back(), median / nodesPerParcel[i], error);
    }
}

// Density integrated along the line through (x0 + offset, y, z0) for y across the grid.
double lineIntegral(const DensityGrid& grid, const Eigen::Vector3d& centre, double offset)
{
    double sum = 0.0;
    const int samples = 1200;
    for (int s = 0; s < samples; ++s)
    {
        const Eigen::Vector3d point(centre.x() + offset, 0.06 * (s + 0.5) / samples, centre.z());
        sum += grid.sample(point).rho * 0.06 / samples;
    }
    return sum;
}

void capTable(const ParcelClass& c)
{
    Parcel p = makeParcels(c, 1)[0];
    p.position = Eigen::Vector3d(0.0302, 0.0304, 0.0301);
    p.velocity = Eigen::Vector3d::Zero();
    const double width = ParcelKernel(0.5 * p.diameter, p.nParticle, withCut(0.0), 3).width();
    std::vector<double> caps{0.0, 2.0, 3.0, 4.0, 6.0};
    std::vector<std::unique_ptr<DensityGrid>> grids;
    for (const double cap : caps)
    {
        grids.push_back(std::make_unique<DensityGrid>(cube(), withCut(0.0, cap * width)));
        grids.back()->deposit(p, dt);
        grids.back()->commitStep();
    }
    std::printf("\n%s, width %.2f mm: rMaxCap against none (negligibleWeight 0)\n", c.name, 1e3 * width);
    std::printf("  rMaxCap [widths]  density at 0, 1, 2, 3, 4 widths / uncapped  | line integral at 0, 1, 2, "
                "3, 4 widths / uncapped\n");
    for (std::size_t k = 1; k < caps.size(); ++k)
    {
        std::printf("  %-16g ", caps[k]);
        for (int d = 0; d <= 4; ++d)
        {
            const Eigen::Vector3d at = p.position + Eigen::Vector3d(d * width, 0.0, 0.0);
            std::printf(" %6.3f", grids[k]->sample(at).rho / grids[0]->sample(at).rho);
        }
        std::printf("  |");
        for (int d = 0; d <= 4; ++d)
        {
            std::printf(" %6.3f",
                        lineIntegral(*grids[k], p.position, d * width)
                            / lineIntegral(*grids[0], p.position, d * width));
        }
        std::printf("\n");
    }
}

} // namespace

int main(int argc, char** argv)
{
    int rounds = 5, count = 40;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        if (std::strcmp(argv[i], "--rounds") == 0)
        {
            rounds = std::stoi(argv[i + 1]);
        }
        else if (std::strcmp(argv[i], "--parcels") == 0)
        {
            count = std::stoi(argv[i + 1]);
        }
    }
    const std::vector<ParcelClass> classes{{"r_p 15 um, n 3400, stationary", 15e-6, 3400.0, 0.0},
                                           {"r_p 15 um, n 3400, moving 0.5 mm", 15e-6, 3400.0, 0.5},
                                           {"r_p 10 um, n 11000, stationary", 10e-6, 11000.0, 0.0},
                                           {"r_p 10 um, n 11000, moving 0.5 mm", 10e-6, 11000.0, 0.5}};
    for (const ParcelClass& c : classes)
    {
        negligibleWeightTable(c, rounds, count);
    }
    capTable(classes[0]);
    capTable(classes[2]);
    return 0;
}
