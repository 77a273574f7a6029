#include "CommandLine.hpp"

#include "CsvTable.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace dropletFiber
{
namespace cli
{

namespace
{

double parseNumber(const std::string& flag, const std::string& text)
{
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    {
        throw InputError(flag + ": not a finite number: '" + text + "'");
    }
    return value;
}

std::vector<std::string> splitCommas(const std::string& text)
{
    std::vector<std::string> parts;
    std::stringstream stream(text);
    std::string part;
    while (std::getline(stream, part, ','))
    {
        parts.push_back(part);
    }
    return parts;
}

Eigen::Vector3d parseVector(const std::string& flag, const std::string& text)
{
    const std::vector<std::string> parts = splitCommas(text);
    if (parts.size() != 3)
    {
        throw InputError(flag + ": expected three comma-separated numbers X,Y,Z, got '" + text + "'");
    }
    return Eigen::Vector3d(parseNumber(flag, parts[0]), parseNumber(flag, parts[1]),
                           parseNumber(flag, parts[2]));
}

int parseCount(const std::string& flag, const std::string& text, int minimum)
{
    const double value = parseNumber(flag, text);
    if (value != std::floor(value) || value < minimum || value > 1e9)
    {
        throw InputError(flag + ": expected a whole number >= " + std::to_string(minimum) + ", got '" + text
                         + "'");
    }
    return static_cast<int>(value);
}

} // namespace

std::string usage()
{
    return R"(dropletGrid - droplet density grid from parcels (docs/model.md sec. 4) and, optionally,
the stochastic collision mass of fiber segments (eq. 9). No OpenFOAM needed.

Usage:
  dropletGrid --parcels FILE --lower X,Y,Z --upper X,Y,Z --nodes NX,NY,NZ --dt DT [options]

Required:
  --parcels FILE        parcel CSV, header line with the columns (any order, extra columns
                        ignored): x,y,z,ux,uy,uz,d,nParticle,rhoDroplet  (SI units: m, m/s,
                        m, droplets, kg/m^3). Position = END of the time step; the parcel
                        moved from (x,y,z) - (ux,uy,uz)*dt to (x,y,z) during the step.
                        All parcels form one time step.
  --lower X,Y,Z         lower corner of the grid box, m
  --upper X,Y,Z         upper corner of the grid box, m
  --nodes NX,NY,NZ      nodes per direction, each >= 1; nodes lie on the bounds. A direction
                        with 1 node is flat (2D grid): its upper - lower is the thickness
                        (the case's depth) used in the node volume.
  --dt DT               time step, s (> 0)

Options:
  --output FILE         write the node fields as CSV:
                        i,j,k,x,y,z,rho,rMeanNumber,rMeanMass,ux,uy,uz
                        (rho in kg/m^3, radii in m, mean droplet velocity in m/s)
  --beta B              kernel inflection parameter of eq. 17/18, 0 < B <= 1 (default 0.025)
  --rmax-cap R          cap on the influence radius, m (default: none). Parcels whose
                        r_max = r_p n exceeds it are counted and reported.
  --dimension D         packing formula for r_min: auto, 2 or 3 (default auto: 3 on a grid
                        with three non-flat directions, else 2)
  --segments FILE       fiber segments CSV with the columns
                        ax,ay,az,bx,by,bz,fiberRadius,ux,uy,uz
                        (end points a and b in m, fiber radius in m, segment velocity in m/s);
                        evaluates eq. 9, m = 2 rho (r_F + <r>) |l x v_rel| dt, per segment
  --segments-output FILE  per-segment results CSV (default: standard output) with the columns
                        segment,mass,momentumX,momentumY,momentumZ,rho,rMean,samples,samplesOutside
                        (mass in kg, momentum in kg m/s, rho and rMean at the midpoint)
  --radius-average A    mean radius in eq. 9: mass (default; exact expected mass for a
                        polydisperse spray) or number (the paper's eq. 10)
  --samples N           sample points along each segment: N >= 1, or 0 = one per node
                        spacing spanned (default 1: the midpoint)
  --help                this text

Output: number of parcels, total mass in, mass on the grid (sum over the nodes), mass
outside the grid box, parcels capped / with fallback weights, and the time taken.
Exit codes: 0 success, 2 bad input (the message names the flag, or the file, line and field).
)";
}

namespace
{

using Values = std::map<std::string, std::string>;

// The flags given, each with its value (--flag VALUE or --flag=VALUE); help: --help seen.
Values readFlags(int argc, char** argv, bool& help)
{
    static const char* known[]
        = {"--parcels",         "--lower",          "--upper",    "--nodes",     "--dt",
           "--output",          "--beta",           "--rmax-cap", "--dimension", "--segments",
           "--segments-output", "--radius-average", "--samples"};
    Values values;
    for (int a = 1; a < argc; ++a)
    {
        std::string flag = argv[a];
        if (flag == "--help" || flag == "-h")
        {
            help = true;
            return values;
        }
        std::string value;
        const std::size_t equals = flag.find('=');
        if (equals != std::string::npos)
        {
            value = flag.substr(equals + 1);
            flag = flag.substr(0, equals);
        }
        else
        {
            if (a + 1 >= argc)
            {
                throw InputError(flag + ": missing value");
            }
            value = argv[++a];
        }
        bool isKnown = false;
        for (const char* k : known)
        {
            isKnown = isKnown || flag == k;
        }
        if (!isKnown)
        {
            throw InputError(flag + ": unknown option (see --help)");
        }
        values[flag] = value;
    }
    return values;
}

GridSpec parseGrid(Values& values)
{
    GridSpec grid;
    grid.lower = parseVector("--lower", values["--lower"]);
    grid.upper = parseVector("--upper", values["--upper"]);
    const std::vector<std::string> nodes = splitCommas(values["--nodes"]);
    if (nodes.size() != 3)
    {
        throw InputError("--nodes: expected three comma-separated counts NX,NY,NZ, got '" + values["--nodes"]
                         + "'");
    }
    for (int d = 0; d < 3; ++d)
    {
        grid.nodes[static_cast<std::size_t>(d)]
            = parseCount("--nodes", nodes[static_cast<std::size_t>(d)], 1);
    }
    try
    {
        grid.validate();
    }
    catch (const std::invalid_argument& e)
    {
        throw InputError(std::string("--lower/--upper/--nodes: ") + e.what());
    }
    return grid;
}

KernelSettings parseKernel(Values& values)
{
    KernelSettings kernel;
    if (values.count("--beta"))
    {
        kernel.beta = parseNumber("--beta", values["--beta"]);
        if (!(kernel.beta > 0.0 && kernel.beta <= 1.0))
        {
            throw InputError("--beta: must lie in (0, 1], got '" + values["--beta"] + "'");
        }
    }
    if (values.count("--rmax-cap"))
    {
        kernel.rMaxCap = parseNumber("--rmax-cap", values["--rmax-cap"]);
        if (!(kernel.rMaxCap > 0.0))
        {
            throw InputError("--rmax-cap: must be > 0, got '" + values["--rmax-cap"] + "'");
        }
    }
    if (values.count("--dimension"))
    {
        const std::string& d = values["--dimension"];
        if (d == "auto")
        {
            kernel.dimension = KernelDimension::Automatic;
        }
        else if (d == "2")
        {
            kernel.dimension = KernelDimension::TwoD;
        }
        else if (d == "3")
        {
            kernel.dimension = KernelDimension::ThreeD;
        }
        else
        {
            throw InputError("--dimension: expected auto, 2 or 3, got '" + d + "'");
        }
    }
    return kernel;
}

CollisionOptions parseCollision(Values& values)
{
    CollisionOptions collision;
    if (values.count("--radius-average"))
    {
        const std::string& r = values["--radius-average"];
        if (r == "mass")
        {
            collision.radiusAverage = RadiusAverage::Mass;
        }
        else if (r == "number")
        {
            collision.radiusAverage = RadiusAverage::Number;
        }
        else
        {
            throw InputError("--radius-average: expected mass or number, got '" + r + "'");
        }
    }
    if (values.count("--samples"))
    {
        collision.samples = parseCount("--samples", values["--samples"], 0);
    }
    return collision;
}

} // namespace

Options parseCommandLine(int argc, char** argv)
{
    Options options;
    Values values = readFlags(argc, argv, options.help);
    if (options.help)
    {
        return options;
    }
    for (const char* required : {"--parcels", "--lower", "--upper", "--nodes", "--dt"})
    {
        if (values.count(required) == 0)
        {
            throw InputError(std::string(required) + ": required (see --help)");
        }
    }
    options.parcelsFile = values["--parcels"];
    options.grid = parseGrid(values);
    options.dt = parseNumber("--dt", values["--dt"]);
    if (!(options.dt > 0.0))
    {
        throw InputError("--dt: must be > 0, got '" + values["--dt"] + "'");
    }
    options.nodesOutput = values.count("--output") ? values["--output"] : "";
    options.kernel = parseKernel(values);
    options.segmentsFile = values.count("--segments") ? values["--segments"] : "";
    options.segmentsOutput = values.count("--segments-output") ? values["--segments-output"] : "";
    options.collision = parseCollision(values);
    return options;
}

} // namespace cli
} // namespace dropletFiber
