// dropletGrid: command-line front end of the density grid (docs/model.md sec. 4) and the
// collision mass (eq. 9), for validation and for parcel data from outside OpenFOAM.
// Reads parcels (one time step) from CSV, deposits them, writes the node fields and,
// optionally, the collision mass of fiber segments. See --help (CommandLine.cpp).
#include "CommandLine.hpp"
#include "CsvTable.hpp"

#include "collision/CollisionMass.hpp"
#include "grid/DensityGrid.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

using namespace dropletFiber;
using namespace dropletFiber::cli;

namespace
{

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since)
{
    return std::chrono::duration<double>(Clock::now() - since).count();
}

std::vector<Parcel> readParcels(const std::string& path)
{
    const std::vector<std::string> columns{"x", "y", "z", "ux", "uy", "uz", "d", "nParticle", "rhoDroplet"};
    const std::vector<CsvRow> rows = readCsv(path, columns);
    std::vector<Parcel> parcels;
    parcels.reserve(rows.size());
    for (const CsvRow& row : rows)
    {
        const std::vector<double>& v = row.values;
        auto check = [&](std::size_t index, const char* what)
        {
            if (v[index] < 0.0)
            {
                throw InputError(path + ":" + std::to_string(row.line) + ": field '" + columns[index]
                                 + "': negative " + what + " " + std::to_string(v[index]));
            }
        };
        check(6, "diameter");
        check(7, "droplet count");
        check(8, "droplet density");
        parcels.push_back(parcelFromValues(v.data()));
    }
    return parcels;
}

void writeNodes(const DensityGrid& grid, const std::string& path)
{
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out)
    {
        throw InputError(path + ": cannot write file");
    }
    const GridSpec& spec = grid.spec();
    std::fprintf(out, "i,j,k,x,y,z,rho,rMeanNumber,rMeanMass,ux,uy,uz\n");
    for (int k = 0; k < spec.nodes[2]; ++k)
    {
        for (int j = 0; j < spec.nodes[1]; ++j)
        {
            for (int i = 0; i < spec.nodes[0]; ++i)
            {
                const Eigen::Vector3d g = spec.nodePosition(i, j, k);
                const DropletFieldValue f = grid.nodeValue(i, j, k);
                std::fprintf(out, "%d,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", i, j, k,
                             g.x(), g.y(), g.z(), f.rho, f.rMeanNumber, f.rMeanMass, f.velocity.x(),
                             f.velocity.y(), f.velocity.z());
            }
        }
    }
    if (std::fclose(out) != 0)
    {
        throw InputError(path + ": error while writing");
    }
}

void evaluateSegments(const DensityGrid& grid, const Options& options)
{
    const std::vector<std::string> columns{"ax", "ay",          "az", "bx", "by",
                                           "bz", "fiberRadius", "ux", "uy", "uz"};
    const std::vector<CsvRow> rows = readCsv(options.segmentsFile, columns);
    std::unique_ptr<std::ofstream> file;
    if (!options.segmentsOutput.empty())
    {
        file = std::make_unique<std::ofstream>(options.segmentsOutput);
        if (!*file)
        {
            throw InputError(options.segmentsOutput + ": cannot write file");
        }
    }
    std::ostream& out = file ? *file : std::cout;
    out.precision(17);
    out << "segment,mass,momentumX,momentumY,momentumZ,rho,rMean,samples,samplesOutside\n";
    double totalMass = 0.0;
    int index = 0;
    for (const CsvRow& row : rows)
    {
        const std::vector<double>& v = row.values;
        if (v[6] < 0.0)
        {
            throw InputError(options.segmentsFile + ":" + std::to_string(row.line)
                             + ": field 'fiberRadius': negative radius " + std::to_string(v[6]));
        }
        const Eigen::Vector3d a(v[0], v[1], v[2]), b(v[3], v[4], v[5]), velocity(v[7], v[8], v[9]);
        const SegmentCollision hit = collisionMass(grid, a, b, v[6], velocity, options.dt, options.collision);
        const DropletFieldValue mid = grid.sample(0.5 * (a + b));
        const double rMean
            = options.collision.radiusAverage == RadiusAverage::Mass ? mid.rMeanMass : mid.rMeanNumber;
        out << index << ',' << hit.mass << ',' << hit.momentum.x() << ',' << hit.momentum.y() << ','
            << hit.momentum.z() << ',' << mid.rho << ',' << rMean << ',' << hit.samples << ','
            << hit.samplesOutside << '\n';
        totalMass += hit.mass;
        ++index;
    }
    std::printf("  segments:              %d, collision mass %.6e kg per step%s\n", index, totalMass,
                options.segmentsOutput.empty() ? "" : (" (" + options.segmentsOutput + ")").c_str());
}

const char* dimensionName(KernelDimension d)
{
    return d == KernelDimension::TwoD ? "2" : d == KernelDimension::ThreeD ? "3" : "automatic";
}

// The deposit settings in force, in the dictionary's words (to set up the same deposit in
// a run, or to see which defaults applied).
void printKernel(const DensityGrid& grid, const KernelSettings& k)
{
    std::printf("  deposit settings:      beta %.15g, rMaxCap %.15g, dimension %s, cloudInCellBelow %.15g,\n"
                "                         negligibleWeight %.15g, depositMethod %s,\n"
                "                         vectorised %s (%s)\n",
                k.beta, k.rMaxCap, dimensionName(k.dimension), k.cloudInCellBelow, k.negligibleWeight,
                k.method == DepositMethod::Exact ? "exact" : "automatic", k.vectorised ? "true" : "false",
                grid.batchedKernel() ? "AVX2 + FMA loops in use"
                    : k.vectorised   ? "node by node: this CPU has no AVX2 + FMA"
                                     : "node by node");
}

void printStatistics(const DensityGrid& grid, std::size_t parcels)
{
    const StepStatistics& s = grid.lastStepStatistics();
    const auto count = [](std::int64_t n) { return static_cast<long long>(n); };
    std::printf("  mass in:               %.12e kg\n", s.massIn);
    std::printf("  mass on the grid:      %.12e kg (sum over the nodes)\n", grid.windowMassPerStep());
    std::printf("  mass outside:          %.12e kg (%lld parcels outside, %lld partly outside the box)\n",
                s.massOutside, count(s.parcelsOutside), count(s.parcelsPartlyOutside));
    std::printf("  kernel cap bound:      %lld parcels\n", count(s.parcelsCapped));
    std::printf("  no node in reach:      %lld parcels (multilinear fallback)\n", count(s.parcelsFallback));
    std::printf("  cloud-in-cell:         %lld parcels (kernel narrower than cloudInCellBelow spacings)\n",
                count(s.parcelsCloudInCell));
    std::printf("  separable weights:     %lld parcels (wide kernels, depositMethod automatic)\n",
                count(s.parcelsSeparable));
    std::printf("  nodes visited:         %lld (%.1f per parcel)\n", count(s.nodesVisited),
                parcels == 0 ? 0.0 : static_cast<double>(s.nodesVisited) / static_cast<double>(parcels));
}

int run(int argc, char** argv)
{
    const Clock::time_point start = Clock::now();
    const Options options = parseCommandLine(argc, argv);
    if (options.help)
    {
        std::cout << usage();
        return 0;
    }
    DensityGrid grid(options.grid, options.kernel, 1);

    Clock::time_point phase = Clock::now();
    const std::vector<Parcel> parcels = readParcels(options.parcelsFile);
    const double readTime = seconds(phase);

    phase = Clock::now();
    for (const Parcel& p : parcels)
    {
        grid.deposit(p, options.dt);
    }
    grid.commitStep();
    const double depositTime = seconds(phase);

    std::printf("dropletGrid: %zu parcels from %s, grid %dx%dx%d nodes, dt %g s\n", parcels.size(),
                options.parcelsFile.c_str(), options.grid.nodes[0], options.grid.nodes[1],
                options.grid.nodes[2], options.dt);
    printKernel(grid, options.kernel);
    printStatistics(grid, parcels.size());

    double writeTime = 0.0;
    if (!options.nodesOutput.empty())
    {
        phase = Clock::now();
        writeNodes(grid, options.nodesOutput);
        writeTime = seconds(phase);
        std::printf("  node fields:           %s\n", options.nodesOutput.c_str());
    }
    if (!options.segmentsFile.empty())
    {
        evaluateSegments(grid, options);
    }
    std::printf(
        "  time:                  read %.3f s, deposit %.3f s (%.3g parcels/s), write %.3f s, total %.3f s\n",
        readTime, depositTime, depositTime > 0.0 ? static_cast<double>(parcels.size()) / depositTime : 0.0,
        writeTime, seconds(start));
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        return run(argc, argv);
    }
    catch (const InputError& e)
    {
        std::cerr << "dropletGrid: error: " << e.what() << "\n";
        return 2;
    }
    catch (const std::invalid_argument& e)
    {
        std::cerr << "dropletGrid: error: " << e.what() << "\n";
        return 2;
    }
    catch (const std::exception& e)
    {
        std::cerr << "dropletGrid: internal error: " << e.what() << "\n";
        return 1;
    }
}
