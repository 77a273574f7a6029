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

// The checks below give the function object's verdict on the same value of the same
// entry (src/openfoam/settings/gridSettings.C, dictionaryChecks.H), so that a value a run
// accepts is accepted here and one it stops on stops the tool, with the same allowed list.

// A finite number with allowed(value), else an error naming the flag, the value and what
// is allowed.
template <class Allowed>
double parseAllowed(const std::string& flag, const std::string& text, Allowed allowed,
                    const char* allowedText)
{
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || !allowed(value))
    {
        throw InputError(flag + ": got '" + text + "'; allowed are finite numbers " + allowedText);
    }
    return value;
}

// One of the words in allowed (case-sensitive, as a dictionary's words).
std::string parseChoice(const std::string& flag, const std::string& text,
                        const std::vector<std::string>& allowed)
{
    std::string list;
    for (const std::string& word : allowed)
    {
        if (word == text)
        {
            return text;
        }
        list += (list.empty() ? "" : (&word == &allowed.back() ? " or " : ", ")) + word;
    }
    throw InputError(flag + ": got '" + text + "'; allowed are " + list);
}

// The words OpenFOAM's Switch reads (getSwitch in dictionaryChecks.H: Switch's words and
// its one-letter forms, and the integers 1 and 0).
bool parseSwitch(const std::string& flag, const std::string& text)
{
    static const std::map<std::string, bool> words{
        {"true", true}, {"false", false}, {"on", true}, {"off", false}, {"yes", true},
        {"no", false},  {"t", true},      {"f", false}, {"y", true},    {"n", false},
        {"any", true},  {"none", false},  {"1", true},  {"0", false}};
    const auto found = words.find(text);
    if (found == words.end())
    {
        throw InputError(flag + ": got '" + text + "'; allowed are true or false (also on/off, yes/no, 1/0)");
    }
    return found->second;
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

Deposit options: the deposit entries of the function object's grid dictionary, with the
same names (--rmax-cap also as --rMaxCap), allowed values and defaults, so that the
deposit of a run can be repeated here (docs/reference.md, grid):
  --beta B              kernel shape: inflection point between r_min (0) and r_max (1),
                        eq. 17/18; 0 < B <= 1 (default 0.025, the paper's)
  --rmax-cap R, --rMaxCap R
                        cap on the influence radius, m; R >= 0, 0: no cap (default 0).
                        Parcels whose r_max = r_p n exceeds it are counted and reported.
  --dimension D         packing formula for r_min: automatic (also auto), 2 or 3 (default
                        automatic: 3 on a grid with three non-flat directions, else 2)
  --cloudInCellBelow C  parcels whose kernel width r_max / sqrt(2 alpha) is below C times
                        the largest node spacing are deposited with cloud-in-cell
                        (multilinear) weights along their path, which keeps the centre of
                        mass of kernels the grid cannot resolve; C >= 0, 0: always the
                        paper's kernel (default 0.5)
  --negligibleWeight E  nodes whose weight would be below E times the parcel's largest are
                        not evaluated (the weights are normalised over the kept nodes: the
                        mass stays on the grid; docs/model.md P10); 0 <= E <= 1e-6, 0: every
                        node within reach (default 1e-8)
  --depositMethod M     automatic: parcels whose kernel reaches at least 3 node spacings get
                        their weights from per-axis tables where a proven bound keeps every
                        weight within 1e-7 of the parcel's largest (docs/model.md P16);
                        exact: the per-node path integral (eq. 23) for every parcel
                        (default automatic)
  --vectorised S        true: node weights four at a time (AVX2 + FMA) where the CPU has
                        them; false: node by node, the same results to the bit on every
                        CPU (the two agree to ~1e-14 of the largest node value); true or
                        false, also on/off, yes/no, 1/0 (default true)

  --help                this text

Output: number of parcels, the deposit settings in force, total mass in, mass on the grid
(sum over the nodes), mass outside the grid box, parcels capped / with fallback weights /
with cloud-in-cell weights / with separable weights, nodes visited, and the time taken.
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
        = {"--parcels",          "--lower",          "--upper",        "--nodes",     "--dt",
           "--output",           "--beta",           "--rmax-cap",     "--dimension", "--segments",
           "--segments-output",  "--radius-average", "--samples",      "--rMaxCap",   "--cloudInCellBelow",
           "--negligibleWeight", "--vectorised",     "--depositMethod"};
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
        if (!values.emplace(flag, value).second)
        {
            throw InputError(flag + ": given twice, give it once");
        }
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

// The function object's default (gridSettings.C; KernelSettings' own is 0, the paper's
// kernel always), so that the tool's defaults deposit as a run with the default dictionary.
constexpr double defaultCloudInCellBelow = 0.5;

// The flag given of a deposit entry that has two spellings (the tool's older one and the
// dictionary's), or nullptr; both given is an error.
const char* givenFlag(const Values& values, const char* toolName, const char* dictionaryName)
{
    const bool tool = values.count(toolName) != 0;
    const bool dictionary = values.count(dictionaryName) != 0;
    if (tool && dictionary)
    {
        throw InputError(std::string(toolName) + " and " + dictionaryName
                         + ": the same option twice, give one");
    }
    return tool ? toolName : dictionary ? dictionaryName : nullptr;
}

// The deposit's entries of the function object's grid dictionary (gridSettings.C,
// readKernelSettings): the same names, allowed values and defaults.
KernelSettings parseKernel(Values& values)
{
    KernelSettings kernel;
    kernel.cloudInCellBelow = defaultCloudInCellBelow;
    if (values.count("--beta"))
    {
        kernel.beta = parseAllowed(
            "--beta", values["--beta"], [](double b) { return b > 0.0 && b <= 1.0; },
            "in (0, 1] (eq. 18; the paper uses 0.025)");
    }
    if (const char* flag = givenFlag(values, "--rmax-cap", "--rMaxCap"))
    {
        kernel.rMaxCap = parseAllowed(
            flag, values[flag], [](double r) { return r >= 0.0; }, ">= 0 (0: no cap)");
    }
    if (values.count("--dimension"))
    {
        // "auto": the tool's spelling before it took the dictionary's "automatic"
        const std::string d
            = parseChoice("--dimension", values["--dimension"], {"automatic", "auto", "2", "3"});
        kernel.dimension = d == "2" ? KernelDimension::TwoD
            : d == "3"              ? KernelDimension::ThreeD
                                    : KernelDimension::Automatic;
    }
    if (values.count("--cloudInCellBelow"))
    {
        kernel.cloudInCellBelow = parseAllowed(
            "--cloudInCellBelow", values["--cloudInCellBelow"], [](double c) { return c >= 0.0; },
            ">= 0 (0: always the paper's kernel)");
    }
    if (values.count("--negligibleWeight"))
    {
        kernel.negligibleWeight = parseAllowed(
            "--negligibleWeight", values["--negligibleWeight"],
            [](double e) { return e >= 0.0 && e <= 1e-6; },
            "in [0, 1e-6] (0: every node within reach is evaluated)");
    }
    if (values.count("--vectorised"))
    {
        kernel.vectorised = parseSwitch("--vectorised", values["--vectorised"]);
    }
    if (values.count("--depositMethod"))
    {
        kernel.method
            = parseChoice("--depositMethod", values["--depositMethod"], {"automatic", "exact"}) == "exact"
            ? DepositMethod::Exact
            : DepositMethod::Automatic;
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
