/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "gridSettings.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"
#include "memoryEstimate.H"
#include "fiberStateIO.H"
#include "OStringStream.H"

#include <cmath>
#include <utility>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The entries of grid: read by readBounds, readNodeCounts,
//  readGridSettings and readKernelSettings below; radiusAverage, a
//  collision option, is still read here from its old place
//  (collisionSettings.C)
const wordList gridKeys
{
    "lower", "upper", "nodes", "spacing", "averagingSteps",
    "beta", "rMaxCap", "cloudInCellBelow", "negligibleWeight", "vectorised",
    "depositMethod", "dimension", "radiusAverage", "maxMemory", "blocks",
    "balanceSteps", "moveCost"
};


//- The grid's lower and upper bounds: the entries, else the mesh's bounds
std::pair<vector, vector> readBounds
(
    const dictionary& gridDict,
    const boundBox& meshBox
)
{
    const vector lower = gridDict.lookupOrDefault<vector>("lower", meshBox.min());
    const vector upper = gridDict.lookupOrDefault<vector>("upper", meshBox.max());
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (!(upper[d] > lower[d]))
        {
            FatalIOErrorInFunction(gridDict)
                << "Entries 'lower' " << lower << " and 'upper' " << upper
                << ": upper must be greater than lower in every direction "
                << "(a flat direction of a 2D grid still needs its thickness)."
                << exit(FatalIOError);
        }
    }
    return {lower, upper};
}


//- Nodes per direction: entry nodes, or from entry spacing, else 50; a 2D
//  mesh's empty direction is flat (one node layer) unless given. Doubles:
//  a tiny spacing gives counts no label holds (checkGridSize stops those)
vector readNodeCounts
(
    const dictionary& gridDict,
    const Vector<label>& geometricD,
    const vector& lower,
    const vector& upper
)
{
    vector nodes(50, 50, 50);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (geometricD[d] < 0)
        {
            nodes[d] = 1;
        }
    }
    if (gridDict.found("nodes") && gridDict.found("spacing"))
    {
        FatalIOErrorInFunction(gridDict)
            << "Entries 'nodes' and 'spacing' are both given: give one."
            << exit(FatalIOError);
    }
    if (gridDict.found("nodes"))
    {
        const Vector<label> given = gridDict.get<Vector<label>>("nodes");
        nodes = vector(given.x(), given.y(), given.z());
    }
    else if (gridDict.found("spacing"))
    {
        const scalar h = Foam::dropletFiber::getPositive(gridDict, "spacing");
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (nodes[d] != 1)
            {
                nodes[d] = max(scalar(2), std::round((upper[d] - lower[d])/h) + 1);
            }
        }
    }
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (nodes[d] < 1)
        {
            FatalIOErrorInFunction(gridDict)
                << "Entry 'nodes' is " << nodes
                << ": allowed are at least 1 node per direction (1: a flat "
                << "direction), and at least 2 directions with 2 or more."
                << exit(FatalIOError);
        }
    }
    return nodes;
}


vector toVector(const Eigen::Vector3d& v)
{
    return vector(v.x(), v.y(), v.z());
}


Vector<label> toLabels(const std::array<int, 3>& n)
{
    return Vector<label>(n[0], n[1], n[2]);
}


word methodName(const ::dropletFiber::DepositMethod m)
{
    return m == ::dropletFiber::DepositMethod::Exact ? "exact" : "automatic";
}

word dimensionName(const ::dropletFiber::KernelDimension d)
{
    return
        d == ::dropletFiber::KernelDimension::TwoD ? "2"
      : d == ::dropletFiber::KernelDimension::ThreeD ? "3"
      : "automatic";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::dropletFiber::gridSettings Foam::dropletFiber::readGridSettings
(
    const dictionary& gridDict,
    const fvMesh& mesh
)
{
    checkKeys(gridDict, gridKeys);
    gridSettings s;
    const std::pair<vector, vector> bounds = readBounds(gridDict, mesh.bounds());
    const vector nodes =
        readNodeCounts(gridDict, mesh.geometricD(), bounds.first, bounds.second);
    s.averagingSteps = getLabelInRange(gridDict, "averagingSteps", 1, 1, 100000);
    checkGridSize(gridDict, nodes, s.averagingSteps);

    s.spec.lower = toEigen(bounds.first);
    s.spec.upper = toEigen(bounds.second);
    s.spec.nodes = {{int(nodes.x()), int(nodes.y()), int(nodes.z())}};
    checkedCoreCall(gridDict, [&s]() { s.spec.validate(); });

    s.kernel = readKernelSettings(gridDict);

    // --- Entries not of the grid's state: a run-time edit is not compared
    // by checkGridUnchanged (the memory check is made once, at the start)
    // maxMemory [MB]: the user's limit on the memory per processor
    s.maxMemory = bytesPerMB*getNonNegative(gridDict, "maxMemory", 0);
    // blocks: who owns which nodes; any partition gives the same fields (to
    // round-off), and a restart takes the state's (gridBlocks.H)
    s.balancedBlocks =
        getChoice
        (
            gridDict, "blocks", "subdomains", {"subdomains", "balanced"}
        ) == "balanced";
    s.balanceSteps = getLabelInRange(gridDict, "balanceSteps", 100, 1, labelMax);
    s.moveCost = getNonNegative(gridDict, "moveCost", 0);
    return s;
}


::dropletFiber::KernelSettings Foam::dropletFiber::readKernelSettings
(
    const dictionary& gridDict
)
{
    ::dropletFiber::KernelSettings kernel;
    const scalar defaultBeta = 0.025;   // the paper's value
    kernel.beta =
        getCheckedScalar
        (
            gridDict, "beta", &defaultBeta,
            [](scalar b) { return b > 0 && b <= 1; },
            "in (0, 1] (eq. 18; the paper uses 0.025)"
        );
    kernel.rMaxCap = getNonNegative(gridDict, "rMaxCap", 0);
    // Better than the paper (docs/validation.md): parcels whose kernel the grid
    // cannot resolve are deposited with cloud-in-cell weights; 0 = the paper
    kernel.cloudInCellBelow = getNonNegative(gridDict, "cloudInCellBelow", 0.5);
    // Nodes whose weight would be below this fraction of the parcel's largest
    // are not evaluated (0 = exact tails). 1e-8: each node value within 5e-8
    // of the exact tails' (docs/model.md sec. 4), 3x fewer nodes than 1e-17 in 3D
    const scalar defaultNegligible = 1e-8;
    kernel.negligibleWeight =
        getCheckedScalar
        (
            gridDict, "negligibleWeight", &defaultNegligible,
            [](scalar e) { return e >= 0 && e <= 1e-6; },
            "in [0, 1e-6] (0: every node within reach is evaluated)"
        );
    // Node weights with the batched AVX2 + FMA loop where the CPU has it; false:
    // node by node, the same results to the bit on every CPU (src/core/grid/KernelBuild.hpp)
    kernel.vectorised = getSwitch(gridDict, "vectorised", true);
    // Wide kernels from per-axis tables where their error bound holds (docs/model.md
    // sec. 4, P16); exact: the per-node path integral for every parcel
    kernel.method =
        getChoice(gridDict, "depositMethod", "automatic", {"automatic", "exact"})
        == "exact"
      ? ::dropletFiber::DepositMethod::Exact
      : ::dropletFiber::DepositMethod::Automatic;
    const word dim =
        getChoice(gridDict, "dimension", "automatic", {"automatic", "2", "3"});
    kernel.dimension =
        dim == "2" ? ::dropletFiber::KernelDimension::TwoD
      : dim == "3" ? ::dropletFiber::KernelDimension::ThreeD
      : ::dropletFiber::KernelDimension::Automatic;
    checkedCoreCall(gridDict, [&kernel]() { kernel.validate(); });
    return kernel;
}


void Foam::dropletFiber::checkGridUnchanged
(
    const gridSettings& running,
    const gridSettings& edited,
    const dictionary& gridDict
)
{
    // The window holds the deposits of the last steps on these nodes, made
    // with this kernel; the core has no way to re-grid or re-weight them
    const char* geometry = "The grid's nodes hold the averaging window";
    checkUnchanged
    (
        gridDict, "lower",
        toVector(running.spec.lower), toVector(edited.spec.lower), geometry
    );
    checkUnchanged
    (
        gridDict, "upper",
        toVector(running.spec.upper), toVector(edited.spec.upper), geometry
    );
    if (running.spec.nodes != edited.spec.nodes)
    {
        // Entry spacing is compared by the node counts it gives
        OStringStream runningNodes, editedNodes;
        runningNodes << "nodes " << toLabels(running.spec.nodes);
        editedNodes << "nodes " << toLabels(edited.spec.nodes);
        stopEditedEntry
        (
            gridDict, gridDict.found("spacing") ? "spacing" : "nodes",
            runningNodes.str(), editedNodes.str(), geometry
        );
    }
    checkUnchanged
    (
        gridDict, "averagingSteps",
        running.averagingSteps, edited.averagingSteps,
        "The averaging window is sized to it"
    );

    const char* kernel = "The grid is built with its deposition kernel";
    const auto& a = running.kernel;
    const auto& b = edited.kernel;
    checkUnchanged(gridDict, "beta", a.beta, b.beta, kernel);
    checkUnchanged(gridDict, "rMaxCap", a.rMaxCap, b.rMaxCap, kernel);
    checkUnchanged
    (
        gridDict, "cloudInCellBelow", a.cloudInCellBelow, b.cloudInCellBelow, kernel
    );
    checkUnchanged
    (
        gridDict, "negligibleWeight", a.negligibleWeight, b.negligibleWeight, kernel
    );
    checkUnchanged
    (
        gridDict, "vectorised",
        word(Switch(a.vectorised).c_str()), word(Switch(b.vectorised).c_str()),
        kernel
    );
    checkUnchanged
    (
        gridDict, "depositMethod",
        methodName(a.method), methodName(b.method), kernel
    );
    checkUnchanged
    (
        gridDict, "dimension",
        dimensionName(a.dimension), dimensionName(b.dimension), kernel
    );
}

// ************************************************************************* //
