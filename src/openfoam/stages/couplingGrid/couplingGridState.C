/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The grid's part of the restart state: the deposit's totals and the
    averaging window. The window's state is the log of the parcels deposited
    in its steps (replayed on restart; 72 bytes per parcel) or its node
    values (56 bytes per node and step touched), by default whichever is
    smaller; it is the bulk of the state and goes to a binary OpenFOAM list
    beside the dictionary, exact and ten times faster to write than 17-digit
    text. In parallel the window is this processor's block of the grid.

\*---------------------------------------------------------------------------*/

#include "couplingGrid.H"
#include "dictionaryChecks.H"
#include "restartStateFiles.H"
#include "fiberStateIO.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::couplingGrid::writeWindowList
(
    const fileName& file,
    const std::vector<double>& values
) const
{
    Foam::dropletFiber::writeWindowList(file, values);
}


void Foam::dropletFiber::couplingGrid::checkWindowBlock
(
    const dictionary& state,
    const fileName& path
) const
{
    // A state without the entries was written by a serial run: the whole grid
    const auto& g = settings_.spec;
    const label savedProcessors =
        state.lookupOrDefault<label>("gridBlockProcessors", 1);
    const labelList savedBlock =
        state.lookupOrDefault<labelList>
        (
            "gridBlock",
            labelList({0, 0, 0, g.nodes[0] - 1, g.nodes[1] - 1, g.nodes[2] - 1})
        );
    const ::dropletFiber::IndexBox& b = grid_->ownedBox();
    const labelList block({b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]});
    // The same block, or one holding it (a serial run's whole grid, decomposed:
    // each processor takes its part)
    const bool holdsBlock =
        savedBlock.size() == 6
     && savedBlock[0] <= b.lo[0] && savedBlock[1] <= b.lo[1]
     && savedBlock[2] <= b.lo[2] && savedBlock[3] >= b.hi[0]
     && savedBlock[4] >= b.hi[1] && savedBlock[5] >= b.hi[2];
    if (savedBlock == block || holdsBlock)
    {
        return;
    }
    const label processors = Pstream::parRun() ? Pstream::nProcs() : 1;
    FatalIOErrorInFunction(state)
        << "Restart state " << path << ": its averaging window (entries "
        << "gridBlockProcessors " << savedProcessors << ", gridBlock "
        << savedBlock << ") was written for the block of the grid's nodes "
        << "a processor owned in a run on " << savedProcessors
        << " processor(s); in this run on " << processors
        << " processor(s) this processor owns the block " << block << "."
        << nl << "    Each processor keeps the window of its own block of the"
        << " grid: restart on " << savedProcessors << " processor(s) with"
        << " the same decomposition; for another count run reconstructPar"
        << " and reconstructDropletFiberState, then decomposePar; or set"
        << " 'restart fresh;' to start again from the dictionary's fibers and"
        << " an empty window."
        << exit(FatalIOError);
}


void Foam::dropletFiber::couplingGrid::restoreWindow
(
    const dictionary& state,
    const fileName& path
)
{
    // The blocks the state's windows were written for (balanced blocks
    // differ from the subdomains'); states without them: the subdomains'
    if
    (
        state.found("gridPartition")
     && blocks_->adopt(state.get<labelList>("gridPartition"))
     && grid_->ownedBox() != blocks_->block().owned
    )
    {
        rebuildGrid(nullptr);
    }
    checkWindowBlock(state, path);
    ::dropletFiber::WindowState window;
    window.counters = windowCounters(state);
    const fileName file = path + ".gridWindow";
    window.values = windowValues
    (
        file,
        requiredCount(state, "gridWindowValueCount"),
        !::dropletFiber::DepositLog::holdsLog(window)
    );
    // The core checks the layout against this grid (sizes, slot boxes, the
    // logged parcels) and replays a log of the parcels deposited
    try
    {
        grid_->restoreWindow(window);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(state)
            << "Restart state " << path << " with " << file << ": "
            << e.what() << "." << nl
            << "    Restart from an earlier time, or set 'restart fresh;'"
            << " (the dictionary's fibers, an empty window)."
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::couplingGrid::writeState
(
    const fileName& path,
    dictionary& state,
    dictionary& totals
)
{
    totals.add("parcelMass", totals_.parcelMass);
    totals.add("deposited", totals_.deposited);
    totals.add("outside", totals_.outside);
    totals.add("parcelsCapped", totals_.parcelsCapped);

    const ::dropletFiber::WindowState window =
        grid_->saveWindow(windowStateFormat_);
    writeWindowList(path + ".gridWindow", window.values);
    state.add
    (
        "gridWindowCounters",
        toScalarList
        (
            std::vector<double>(window.counters.begin(), window.counters.end())
        )
    );
    state.add("gridWindowValueCount", label(window.values.size()));
    if (Pstream::parRun())
    {
        // The window is this processor's block of the grid
        const ::dropletFiber::IndexBox& b = grid_->ownedBox();
        state.add("gridBlockProcessors", Pstream::nProcs());
        state.add
        (
            "gridBlock",
            labelList({b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]})
        );
        // Every processor's block (balanced blocks move): a restart on as
        // many processors takes them
        state.add("gridPartition", blocks_->boxesList());
    }
    if (writeWindowValues_)
    {
        const ::dropletFiber::WindowState values = grid_->saveWindowValues();
        writeWindowList(path + ".gridWindowValues", values.values);
        state.add
        (
            "gridWindowValuesCounters",
            toScalarList
            (
                std::vector<double>(values.counters.begin(), values.counters.end())
            )
        );
    }
}


void Foam::dropletFiber::couplingGrid::readState
(
    const dictionary& state,
    const fileName& path
)
{
    // All are sums of non-negative masses and counts
    const dictionary& totals = state.subDict("totals");
    const auto nonNegative = [&totals](const word& key)
    {
        return getCheckedScalar
        (
            totals, key, nullptr, [](scalar v) { return v >= 0; }, ">= 0"
        );
    };
    totals_.parcelMass = nonNegative("parcelMass");
    totals_.deposited = nonNegative("deposited");
    totals_.outside = nonNegative("outside");
    totals_.parcelsCapped =
        getLabelInRange(totals, "parcelsCapped", 0, 0, labelMax);
    restoreWindow(state, path);
}


// ************************************************************************* //
