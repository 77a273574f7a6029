// CommandLine: the dropletGrid tool's options (see usage() for every flag).
#pragma once

#include "collision/CollisionMass.hpp"
#include "grid/GridSpec.hpp"
#include "grid/ParcelKernel.hpp"

#include <string>

namespace dropletFiber
{
namespace cli
{

struct Options
{
    bool help = false;
    std::string parcelsFile;
    std::string nodesOutput;    // node fields CSV; empty: not written
    std::string segmentsFile;   // fiber segments CSV; empty: no collision evaluation
    std::string segmentsOutput; // per-segment results CSV; empty: standard output
    GridSpec grid;
    KernelSettings kernel; // as parsed: the function object's defaults (cloudInCellBelow 0.5)
    CollisionOptions collision;
    double dt = 0.0;
};

// Throws InputError (CsvTable.hpp) naming the flag on a missing or bad value.
Options parseCommandLine(int argc, char** argv);

std::string usage();

} // namespace cli
} // namespace dropletFiber
