/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "memoryEstimate.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "grid/GridSpec.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- MemAvailable of this host [bytes]; < 0 when it cannot be read
scalar hostMemoryAvailable()
{
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double kB = 0;
    while (meminfo >> key >> kB)
    {
        if (key == "MemAvailable:")
        {
            return 1024*kB;
        }
        meminfo.ignore(256, '\n');
    }
    return -1;
}


//- Number of processors on this processor's host (itself included)
label processorsOnThisHost()
{
    List<string> hosts(Pstream::nProcs());
    hosts[Pstream::myProcNo()] = hostName();
    Pstream::gatherList(hosts);
    Pstream::scatterList(hosts);
    return label
    (
        std::count(hosts.begin(), hosts.end(), hosts[Pstream::myProcNo()])
    );
}


//- Bytes as MB with three significant digits
string inMB(const scalar bytes)
{
    OStringStream os;
    os.precision(3);
    os  << bytes/Foam::dropletFiber::bytesPerMB << " MB";
    return os.str();
}


//- The grid entry a user changes to change the node count
word nodesEntry(const dictionary& gridDict)
{
    return gridDict.found("spacing") ? "spacing" : "nodes";
}


//- The node counts and what they come from, for the messages
string describeNodes
(
    const dictionary& gridDict,
    const vector& nodes,
    const scalar total
)
{
    OStringStream os;
    if (gridDict.found("spacing"))
    {
        os  << "Entry 'spacing' " << gridDict.get<scalar>("spacing")
            << " gives ";
    }
    else
    {
        os  << "Entry 'nodes' gives ";
    }
    os  << "nodes " << nodes << ", " << total << " nodes in all";
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::scalar Foam::dropletFiber::gridHeldBytes
(
    const scalar nodes,
    const label averagingSteps
)
{
    return nodes*((averagingSteps + 2)*bytesPerNodeAndStep + 8);
}


Foam::scalar Foam::dropletFiber::gridTransientBytes
(
    const scalar nodes,
    const label averagingSteps
)
{
    // The restart state's copy of the slots, the grid VTK file, or the
    // parallel sum: whichever is largest (they never overlap)
    return nodes*max(averagingSteps*bytesPerNodeAndStep, scalar(120));
}


void Foam::dropletFiber::checkGridSize
(
    const dictionary& gridDict,
    const vector& nodes,
    const label averagingSteps
)
{
    const scalar total = nodes.x()*nodes.y()*nodes.z();
    const scalar largest = max(nodes.x(), max(nodes.y(), nodes.z()));
    if (total <= ::dropletFiber::GridSpec::maxNodes && largest <= labelMax)
    {
        return;
    }
    const scalar bytes =
        gridHeldBytes(total, averagingSteps)
      + gridTransientBytes(total, averagingSteps);
    FatalIOErrorInFunction(gridDict)
        << describeNodes(gridDict, nodes, total).c_str() << ": the grid would"
        << " need an estimated " << inMB(bytes).c_str() << " in all"
        << " (averagingSteps " << averagingSteps << ")." << nl
        << "    Allowed are at most " << ::dropletFiber::GridSpec::maxNodes
        << " nodes: a coarser '" << nodesEntry(gridDict) << "'."
        << exit(FatalIOError);
}


Foam::scalar Foam::dropletFiber::availableMemoryPerProcessor()
{
    const scalar host = hostMemoryAvailable();
    const label sharing = processorsOnThisHost();
    // Unknown on a processor: it does not limit the others
    const scalar mine = host < 0 ? VGREAT : host/sharing;
    const scalar smallest = returnReduce(mine, minOp<scalar>());
    return smallest < VGREAT ? smallest : -1;
}


namespace
{

//- "(N nodes", in parallel "on the processor with the largest block (N of
//  M nodes"
Foam::string heldNodes(const Foam::dropletFiber::memoryEstimate& e)
{
    Foam::OStringStream os;
    if (Foam::Pstream::parRun())
    {
        os  << " on the processor with the largest block (" << e.nodesHeld
            << " of " << e.nodes << " nodes";
    }
    else
    {
        os  << " (" << e.nodes << " nodes";
    }
    return os.str();
}

} // End anonymous namespace


Foam::dropletFiber::memoryEstimate Foam::dropletFiber::estimateMemory
(
    const gridSettings& grid,
    const scalar nodesHeld,
    const std::vector<::dropletFiber::FiberInjectorSpec>& injectors,
    const scalar deltaT
)
{
    memoryEstimate e;
    const auto& n = grid.spec.nodes;
    e.nodes = scalar(n[0])*scalar(n[1])*scalar(n[2]);
    e.nodesHeld = nodesHeld;
    e.averagingSteps = grid.averagingSteps;
    e.gridHeld = gridHeldBytes(e.nodesHeld, grid.averagingSteps);
    e.gridTransient = gridTransientBytes(e.nodesHeld, grid.averagingSteps);
    for (const auto& injector : injectors)
    {
        const scalar births = std::ceil(injector.rate*deltaT) + 1;
        e.fibersPerStep += births*injector.points*bytesPerFiberPoint;
    }

    const scalar available = availableMemoryPerProcessor();
    e.allowed = available;
    e.allowedSource = "MemAvailable of the host shared by its processors";
    if (grid.maxMemory > 0 && (available < 0 || grid.maxMemory < available))
    {
        e.allowed = grid.maxMemory;
        e.allowedSource = "the limit grid.maxMemory";
    }
    return e;
}


void Foam::dropletFiber::checkMemory
(
    const dictionary& dict,
    const memoryEstimate& estimate,
    const std::vector<::dropletFiber::FiberInjectorSpec>& injectors,
    const scalar deltaT
)
{
    if (estimate.allowed < 0 || estimate.total() <= estimate.allowed)
    {
        return;
    }
    const dictionary gridDict = dict.subOrEmptyDict("grid");
    const scalar grid = estimate.gridHeld + estimate.gridTransient;
    const label steps = estimate.averagingSteps;
    if (grid >= estimate.fibersPerStep)
    {
        FatalIOErrorInFunction(gridDict)
            << "The grid needs an estimated " << inMB(grid).c_str()
            << heldNodes(estimate).c_str() << ", "
            << "averagingSteps " << steps << ": (averagingSteps + 2) x 56 + 8"
            << " bytes per node, up to " << inMB(estimate.gridTransient).c_str()
            << " of it only while writing), with the fibers of a step "
            << inMB(estimate.total()).c_str() << ": more than the "
            << inMB(estimate.allowed).c_str() << " allowed ("
            << estimate.allowedSource.c_str() << ")." << nl
            << "    Allowed: a coarser '" << nodesEntry(gridDict)
            << "', fewer 'averagingSteps', a smaller box (lower, upper)"
            << (gridDict.found("maxMemory") ? ", or a larger 'maxMemory'" : "")
            << "." << exit(FatalIOError);
    }
    // The fibers of one step: the largest injector's rate
    const ::dropletFiber::FiberInjectorSpec* largest = &injectors.front();
    for (const auto& injector : injectors)
    {
        if (injector.rate*injector.points > largest->rate*largest->points)
        {
            largest = &injector;
        }
    }
    const dictionary injectorsDict =
        dict.subOrEmptyDict("fibers").subOrEmptyDict("injectors");
    const dictionary injectorDict =
        injectorsDict.subOrEmptyDict(word(largest->name));
    FatalIOErrorInFunction(injectorDict)
        << "Entry 'rate' " << largest->rate << " of injector '"
        << largest->name.c_str() << "': the fibers injected in one step of "
        << deltaT << " s need an estimated "
        << inMB(estimate.fibersPerStep).c_str() << " (about "
        << bytesPerFiberPoint << " bytes per point), with the grid "
        << inMB(estimate.total()).c_str() << ": more than the "
        << inMB(estimate.allowed).c_str() << " allowed ("
        << estimate.allowedSource.c_str() << ")." << nl
        << "    Allowed: a smaller 'rate' or fewer 'points'."
        << exit(FatalIOError);
}


void Foam::dropletFiber::reportMemory
(
    Ostream& os,
    const memoryEstimate& estimate,
    const scalar fiberPoints
)
{
    // An upper bound: a block's pages are resident only where its deposits
    // reached (NodeValueArray), the whole block where the spray fills it
    os  << "    memory per processor (estimate): grid "
        << inMB(estimate.gridHeld).c_str() << " (";
    if (Pstream::parRun())
    {
        os  << "largest block: " << estimate.nodesHeld << " of ";
    }
    os  << estimate.nodes << " nodes x ((averagingSteps "
        << estimate.averagingSteps << " + 2) x 56 + 8 bytes)), up to "
        << inMB(estimate.gridTransient).c_str() << " more while writing;"
        << " fibers " << inMB(fiberPoints*bytesPerFiberPoint).c_str()
        << " now, " << inMB(estimate.fibersPerStep).c_str()
        << " more per step injected; allowed ";
    if (estimate.allowed < 0)
    {
        os  << "unknown (no /proc/meminfo)";
    }
    else
    {
        os  << inMB(estimate.allowed).c_str() << " ("
            << estimate.allowedSource.c_str() << ")";
    }
    os  << nl;
}

// ************************************************************************* //
