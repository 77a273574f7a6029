/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The restart state written and read: where, when, the checks of the
    state's processors and time, and the keys' order.

\*---------------------------------------------------------------------------*/

#include "couplingRestart.H"
#include "dictionaryChecks.H"
#include "restartSources.H"
#include "restartStateFiles.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The keys of the state and of its totals in the order states have always
//  had: a state compares byte for byte with one written before the stages
//  wrote their parts (tests/regression/compareRuns.sh). Keys not named
//  follow in the order the parts added them.
const Foam::wordList stateOrder
{
    "time", "timeIndex", "processors", "processor", "fiberCount", "fibers",
    "injectors", "totals", "sources", "depletionRemoval",
    "gridWindowCounters", "gridWindowValueCount", "gridBlockProcessors",
    "gridBlock", "gridPartition", "gridWindowValuesCounters"
};

const Foam::wordList totalsOrder
{
    "parcelMass", "deposited", "outside", "captured", "fiberMassAdded",
    "fiberMassRemoved", "fibersRemoved", "parcelsCapped", "capturedSpecies"
};


//- dict's entries, those named in order first, in that order
Foam::dictionary inOrder
(
    const Foam::dictionary& dict,
    const Foam::wordList& order
)
{
    Foam::dictionary ordered;
    for (const Foam::word& key : order)
    {
        const Foam::entry* e = dict.findEntry(key, Foam::keyType::LITERAL);
        if (e)
        {
            ordered.add(*e);
        }
    }
    for (const Foam::entry& e : dict)
    {
        if (!order.found(e.keyword()))
        {
            ordered.add(e);
        }
    }
    return ordered;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::couplingRestart::couplingRestart
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    fresh_(false),
    stateProcessors_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::dropletFiber::couplingRestart::statePath
(
    const word& timeName
) const
{
    return time_.path()/timeName/"uniform"/"dropletFiber"/name();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::couplingRestart::read
(
    const dictionary& dict,
    const dictionary& fibersDict
)
{
    dict_ = dict;
    fibers_ = fibersDict;
    // Used at the start only: fresh ignores the restart state
    fresh_ =
        getChoice(dict, "restart", "continue", {"continue", "fresh"})
     == "fresh";
}


void Foam::dropletFiber::couplingRestart::startMarker
(
    const std::function<label()>& lastTimeIndex
)
{
    marker_.reset
    (
        new restartStateMarker
        (
            time_, name(),
            [this, lastTimeIndex]() { return stateFollowsWrite(lastTimeIndex()); }
        )
    );
}


bool Foam::dropletFiber::couplingRestart::stateFollowsWrite(const label lastTimeIndex) const
{
    // Asked at OpenFOAM's write of the fields: execute() writes the state
    // after it when it ran the step before (or the run started then) and the
    // time lies within timeStart/timeEnd as timeControl sees it (triggers,
    // rarely used, are not looked at)
    const label previous =
        lastTimeIndex >= 0 ? lastTimeIndex : time_.startTimeIndex();
    const scalar t = time_.value();
    const scalar halfStep = 0.5*time_.deltaTValue();
    const scalar timeStart = dict_.lookupOrDefault<scalar>("timeStart", -VGREAT);
    const scalar timeEnd = dict_.lookupOrDefault<scalar>("timeEnd", VGREAT);
    return
        previous == time_.timeIndex() - 1
     && t >= time_.userTimeToTime(timeStart) - halfStep
     && t <= time_.userTimeToTime(timeEnd) + halfStep;
}


void Foam::dropletFiber::couplingRestart::writeState
(
    UPtrList<restartPart>& parts,
    const gridSettings& grid
)
{
    // Each processor writes its own state (processorN/<time>/uniform/...):
    // the fibers it holds and the averaging window of its block of the grid,
    // read back on restart with the same number of processors (on another,
    // after reconstructDropletFiberState merged them: restartStateMerge.H).
    // The parts' files first, the dictionary last: a dictionary that exists
    // belongs to a complete state.
    const fileName path = statePath(time_.timeName());
    mkDir(path.path());
    // Entries added to a dictionary are turned into tokens at the default
    // precision: raise it for the restart state (bit-for-bit restart)
    const unsigned oldPrecision = IOstream::defaultPrecision(17);
    dictionary state;
    dictionary totals;
    // In parallel: which of how many processors wrote it (a serial run's
    // state has neither, and can be decomposed onto any number)
    if (Pstream::parRun())
    {
        state.add("processors", Pstream::nProcs());
        state.add("processor", Pstream::myProcNo());
    }
    forAll(parts, parti)
    {
        parts[parti].writeState(path, state, totals);
    }
    state.add("totals", inOrder(totals, totalsOrder));
    // The dictionary's geometry, for a restart to say what its own changes
    state.add("sources", restartSources(fibers_, grid));
    IOstream::defaultPrecision(oldPrecision);
    writeStateDictionary
    (
        path, inOrder(state, stateOrder),
        "dropletFiber restart state of function object " + name()
      + " at time " + time_.timeName()
    );
}


//- The function object's entries the restart reads
static const Foam::wordList restartKeys
{
    "restart"
};


Foam::wordList Foam::dropletFiber::couplingRestart::entries()
{
    return restartKeys;
}


// ************************************************************************* //
