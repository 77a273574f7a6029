/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The restart state of dropletFiberCollision: written atomically at every
    write time, and at a restart read back with every value checked, so that
    a run either continues exactly or stops naming the file and the entry.

    Files, in \<time\>/uniform/dropletFiber/ (of every processor in parallel):
      \<name\>             fibers (fiber\<id\>; in parallel those the processor
                           holds, with the entries processors and processor),
                           injector counters, totals (dictionary)
      \<name\>.gridWindow  the averaging window's state (binary list): the
                           parcels deposited in its steps, replayed on
                           restart (DepositLog.hpp; formats 3, 4), or its
                           node values (AveragingWindow.hpp; formats 1, 2,
                           as earlier versions wrote): entry windowState,
                           by default the smaller; node values where a
                           step cannot be replayed
      \<name\>.gridWindowValues  with writeWindowValues only: the window's
                           node values (formats 1, 2; counters in the entry
                           gridWindowValuesCounters), for inspection and the
                           case tests comparing windows; not read back
      (in parallel the entries gridBlock, this processor's block of the
      grid, and gridPartition, every processor's: the blocks are taken
      from it on restart)
      \<name\>.marker      written by OpenFOAM with the fields, when the state
                           follows (restartStateMarker)

    A parallel run's states continue on the same processor count; on
    another, reconstructDropletFiberState merges them into a serial run's
    state (restartStateMerge.H), which decomposePar copies to any count.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "cloud.H"
#include "fiberStateIO.H"
#include "dictionaryChecks.H"
#include "restartStateMarker.H"
#include "restartSources.H"
#include "restartStateFiles.H"
#include "Time.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "stringOps.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::functionObjects::dropletFiberCollision::statePath
(
    const word& timeName
) const
{
    return time_.path()/timeName/"uniform"/"dropletFiber"/name();
}


Foam::scalar Foam::functionObjects::dropletFiberCollision::continuousTime()
{
    // deltaT added as Time::operator++ adds it, one step at a time
    while (clockIndex_ >= 0 && clockIndex_ < time_.timeIndex())
    {
        clock_ += time_.deltaTValue();
        ++clockIndex_;
    }
    if
    (
        clockIndex_ != time_.timeIndex()
     || mag(clock_ - time_.value()) > 1e-9*time_.deltaTValue()
    )
    {
        // A fresh run, or a time changed by hand: OpenFOAM's own
        clock_ = time_.value();
        clockIndex_ = time_.timeIndex();
    }
    return clock_;
}


bool Foam::functionObjects::dropletFiberCollision::stateFollowsWrite() const
{
    // Asked at OpenFOAM's write of the fields: execute() writes the state
    // after it when it ran the step before (or the run started then) and the
    // time lies within timeStart/timeEnd as timeControl sees it (triggers,
    // rarely used, are not looked at)
    const label previous =
        lastTimeIndex_ >= 0 ? lastTimeIndex_ : time_.startTimeIndex();
    const scalar t = time_.value();
    const scalar halfStep = 0.5*time_.deltaTValue();
    const scalar timeStart = dict_.lookupOrDefault<scalar>("timeStart", -VGREAT);
    const scalar timeEnd = dict_.lookupOrDefault<scalar>("timeEnd", VGREAT);
    return
        previous == time_.timeIndex() - 1
     && t >= time_.userTimeToTime(timeStart) - halfStep
     && t <= time_.userTimeToTime(timeEnd) + halfStep;
}


Foam::dictionary Foam::functionObjects::dropletFiberCollision::stateDict
(
    const ::dropletFiber::WindowState& window
) const
{
    // Entries added to a dictionary are turned into tokens at the default
    // precision: raise it for the restart state (bit-for-bit restart).
    const unsigned oldPrecision = IOstream::defaultPrecision(17);
    dictionary state;
    state.add("time", clockIndex_ == time_.timeIndex() ? clock_ : time_.value());
    state.add("timeIndex", time_.timeIndex());

    // In parallel: which of how many processors wrote it (a serial run's
    // state has neither, and can be decomposed onto any number)
    if (Pstream::parRun())
    {
        state.add("processors", Pstream::nProcs());
        state.add("processor", Pstream::myProcNo());
    }

    addFibersAndTotals(state);
    // The dictionary's geometry, for a restart to say what its own changes
    state.add
    (
        "sources",
        dropletFiber::restartSources(dict_.subOrEmptyDict("fibers"), gridSettings_)
    );

    // Depletion: the last step's removal, which the clouds' files of this
    // time do not hold yet
    if (depletion_)
    {
        dictionary removal;
        removal.add("origProc", removalProc_);
        removal.add("origId", removalId_);
        removal.add("fraction", removalFraction_);
        state.add("depletionRemoval", removal);
    }

    state.add
    (
        "gridWindowCounters",
        dropletFiber::toScalarList
        (
            std::vector<double>(window.counters.begin(), window.counters.end())
        )
    );
    // The window's values (the parcels of its steps, or node values) are the
    // bulk of the state: they go to a binary OpenFOAM list beside it, exact
    // and ten times faster to write than 17-digit text
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

    IOstream::defaultPrecision(oldPrecision);
    return state;
}


void Foam::functionObjects::dropletFiberCollision::addFibersAndTotals
(
    dictionary& state
) const
{
    // The count of the fibers written here: a restart checks the state's
    // fibers against it
    state.add("fiberCount", label(held_.size()));
    dictionary fibers;
    for (std::size_t f = 0; f < held_.size(); ++f)
    {
        dictionary d = dropletFiber::fiberStateDict(held_.fibers[f].state());
        d.add("origin", held_.origin[f]);
        fibers.add(word("fiber" + Foam::name(held_.id[f])), d);
    }
    state.add("fibers", fibers);

    dictionary injectors;
    for (const auto& injector : injectors_)
    {
        injectors.add(word(injector.spec().name), label(injector.injectedCount()));
    }
    state.add("injectors", injectors);

    dictionary totals;
    totals.add("parcelMass", totals_.parcelMass);
    totals.add("deposited", totals_.deposited);
    totals.add("outside", totals_.outside);
    totals.add("captured", totals_.captured);
    totals.add("fiberMassAdded", totals_.fiberMassAdded);
    totals.add("fiberMassRemoved", totals_.fiberMassRemoved);
    totals.add("fibersRemoved", totals_.fibersRemoved);
    totals.add("parcelsCapped", totals_.parcelsCapped);
    dictionary species;
    forAll(liquidSpecies_, i)
    {
        species.add(liquidSpecies_[i], capturedSpecies_[i]);
    }
    totals.add("capturedSpecies", species);
    state.add("totals", totals);
}


void Foam::functionObjects::dropletFiberCollision::writeState() const
{
    // Each processor writes its own state (processorN/<time>/uniform/...):
    // the fibers it holds and the averaging window of its block of the grid,
    // read back on restart with the same number of processors (on another,
    // after reconstructDropletFiberState merged them: restartStateMerge.H).
    // The window first, the dictionary last: a dictionary that exists
    // belongs to a complete state.
    // The window's state is the log of the parcels deposited in its steps
    // (replayed on restart; 72 bytes per parcel) or its node values (56
    // bytes per node and step touched), by default whichever is smaller.
    const ::dropletFiber::WindowState window =
        grid_->saveWindow(windowStateFormat_);
    const fileName path = statePath(time_.timeName());
    mkDir(path.path());
    writeWindowList(path + ".gridWindow", window.values);
    dictionary state = stateDict(window);
    if (writeWindowValues_)
    {
        const ::dropletFiber::WindowState values = grid_->saveWindowValues();
        writeWindowList(path + ".gridWindowValues", values.values);
        const unsigned oldPrecision = IOstream::defaultPrecision(17);
        state.add
        (
            "gridWindowValuesCounters",
            dropletFiber::toScalarList
            (
                std::vector<double>(values.counters.begin(), values.counters.end())
            )
        );
        IOstream::defaultPrecision(oldPrecision);
    }
    dropletFiber::writeStateDictionary
    (
        path, state,
        "dropletFiber restart state of function object " + name()
      + " at time " + time_.timeName()
    );
}


void Foam::functionObjects::dropletFiberCollision::writeWindowList
(
    const fileName& file,
    const std::vector<double>& values
) const
{
    dropletFiber::writeWindowList(file, values);
}


void Foam::functionObjects::dropletFiberCollision::stopIfStateMissing
(
    const fileName& path
) const
{
    const fileName marker =
        dropletFiber::restartStateMarker::path(time_, time_.timeName(), name());
    if (isFile(marker))
    {
        FatalIOErrorInFunction(path)
            << "Restart state " << path << " is missing, but " << marker
            << " says that " << type() << " '" << name() << "' ran up to"
            << " time " << time_.timeName() << ": the run was stopped"
            << " between OpenFOAM's write of the fields and the write of the"
            << " state (fibers, captured mass, averaging window)." << nl
            << "    Restart from an earlier time, or set 'restart fresh;' in"
            << " the function object to start again from the dictionary's"
            << " fibers and an empty window." << exit(FatalIOError);
    }
}


void Foam::functionObjects::dropletFiberCollision::stopIfRestartWithoutState
(
    const fileName& path
) const
{
    // A restart: the start time was written by a run (its uniform/time holds
    // the time index), or the case holds earlier times. Starting anew there
    // would lose the fibers and the captured mass without a word; a new
    // function object in a running case says so with 'restart fresh;'
    const scalar start = time_.startTime().value();
    const scalar tolerance = 0.5*time_.deltaTValue();
    DynamicList<word> earlier;
    for (const instant& t : time_.times())
    {
        // (findTimes lists 'constant' too, at time 0)
        if (t.value() < start - tolerance && t.name() != time_.constant())
        {
            earlier.append(t.name());
        }
    }
    // Before the function object's timeStart it has not run: nothing to lose
    const scalar timeStart = time_.userTimeToTime
    (
        dict_.lookupOrDefault<scalar>("timeStart", -VGREAT)
    );
    if
    (
        (time_.startTimeIndex() <= 0 && earlier.empty())
     || time_.value() <= timeStart + tolerance
    )
    {
        return;
    }
    OStringStream why;
    if (time_.startTimeIndex() > 0)
    {
        why << "time index " << time_.startTimeIndex() << ", written by a run";
    }
    if (!earlier.empty())
    {
        why << (time_.startTimeIndex() > 0 ? "; " : "") << "the case holds "
            << earlier.size() << " earlier time(s), the first "
            << earlier.first() << ", the last " << earlier.last();
    }
    FatalIOErrorInFunction(path)
        << "Restart state " << path << " is missing: this run restarts at"
        << " time " << time_.timeName() << " (" << why.str().c_str()
        << "), and without its state " << type() << " '" << name() << "'"
        << " would start anew: the fibers, their captured mass and the"
        << " averaging window would be lost." << nl
        << "    Copy " << path.path() << " from the run that wrote time "
        << time_.timeName() << ", restart from a time that has it, or set"
        << " 'restart fresh;' in the function object to start anew on"
        << " purpose (as when adding it to a running case)."
        << exit(FatalIOError);
}


bool Foam::functionObjects::dropletFiberCollision::readState()
{
    const fileName path = statePath(time_.timeName());
    if (restartFresh_)
    {
        Info<< type() << " " << name() << ": restart fresh: ";
        if (isFile(path))
        {
            Info<< "the restart state " << path << " is not read, ";
        }
        Info<< "starting from the dictionary's fibers and an empty grid"
            << " window" << nl;
        return false;
    }
    if (!isFile(path))
    {
        stopIfStateMissing(path);
        stopIfRestartWithoutState(path);
        Info<< type() << " " << name() << ": no restart state " << path
            << " (the case's first time, or not after the function object's"
            << " timeStart): starting from the dictionary's fibers and an"
            << " empty grid window" << nl;
        return false;
    }

    IFstream is(path);
    const dictionary state(is);
    checkStateProcessors(state, path);
    checkStateTime(state, path);
    clock_ = state.get<scalar>("time");
    clockIndex_ = state.get<label>("timeIndex");
    restoreFibers(state.subDict("fibers"));
    checkFiberCount(state, path);
    restoreInjectorCounts(state.subDict("injectors"), state.subOrEmptyDict("sources"));
    restoreTotals(state.subDict("totals"));
    if (state.found("depletionRemoval"))
    {
        restoreRemoval(state.subDict("depletionRemoval"));
    }
    restoreWindow(state, path);
    // States of earlier versions have no sources to compare with
    if (state.found("sources"))
    {
        dropletFiber::warnSourcesDiffer
        (
            type() + " '" + name() + "'", state.subDict("sources"), path,
            dict_.subOrEmptyDict("fibers"), gridSettings_
        );
    }

    Info<< type() << " " << name() << ": restarted from " << path
        << ": captured mass so far " << totals_.captured << " kg" << nl;
    return true;
}


bool Foam::functionObjects::dropletFiberCollision::readStateOnEveryProcessor()
{
    // Each processor reads its own copy. OpenFOAM prints an error of a
    // function object's construction on the master only: the message of a
    // processor whose copy is missing or damaged goes to all of them, and
    // all stop.
    if (!Pstream::parRun())
    {
        return readState();
    }
    bool restored = false;
    List<string> failures(Pstream::nProcs());
    try
    {
        restored = readState();
    }
    catch (const Foam::IOerror& err)
    {
        OStringStream os;
        err.write(os, false);
        failures[Pstream::myProcNo()] = stringOps::trim(os.str());
    }
    catch (const Foam::error& err)
    {
        OStringStream os;
        err.write(os, false);
        failures[Pstream::myProcNo()] = stringOps::trim(os.str());
    }
    const bool someRestored = returnReduce(restored, orOp<bool>());
    if (someRestored && !restored && failures[Pstream::myProcNo()].empty())
    {
        failures[Pstream::myProcNo()] =
            "Restart state " + statePath(time_.timeName()) + " is missing,"
            " while other processors have theirs.";
    }
    Pstream::gatherList(failures);
    Pstream::scatterList(failures);
    forAll(failures, proci)
    {
        if (!failures[proci].empty())
        {
            FatalIOErrorInFunction(dict_)
                << "processor " << proci << ": " << failures[proci].c_str()
                << exit(FatalIOError);
        }
    }
    return restored;
}


void Foam::functionObjects::dropletFiberCollision::checkStateProcessors
(
    const dictionary& state,
    const fileName& path
)
{
    // A serial run's state: every processor reads all fibers (decomposePar
    // copies uniform/ into each) and keeps its own (takeStartFibers)
    stateProcessors_ = state.lookupOrDefault<label>("processors", 0);
    const label writer = state.lookupOrDefault<label>("processor", 0);
    if
    (
        stateProcessors_ == 0
     || (stateProcessors_ == Pstream::nProcs() && writer == Pstream::myProcNo())
    )
    {
        return;
    }
    FatalIOErrorInFunction(state)
        << "Restart state " << path << " was written by processor " << writer
        << " of a run on " << stateProcessors_ << " processors and holds"
        << " only the fibers that processor held; this run is "
        << (Pstream::parRun() ? "processor " + Foam::name(Pstream::myProcNo())
            + " of " + Foam::name(Pstream::nProcs()) : word("serial"))
        << " (reconstructPar copies processor 0's state only)." << nl
        << "    Restart on " << stateProcessors_ << " processors from the"
        << " processor directories as that run wrote them; for another count"
        << " run reconstructPar and reconstructDropletFiberState, then"
        << " decomposePar for the new count (a serial run continues from the"
        << " reconstructed case); or set 'restart fresh;' (the dictionary's"
        << " fibers, an empty window)." << exit(FatalIOError);
}


void Foam::functionObjects::dropletFiberCollision::checkStateTime
(
    const dictionary& state,
    const fileName& path
) const
{
    // OpenFOAM's time and time index come from <time>/uniform/time: a state
    // of another time (copied from another folder, or another run's) would
    // put its fibers and window at the wrong time
    const scalar t = state.get<scalar>("time");
    const label index = state.get<label>("timeIndex");
    const scalar tolerance = 1e-3*time_.deltaTValue();
    if (!std::isfinite(t) || mag(t - time_.value()) > tolerance)
    {
        FatalIOErrorInFunction(state)
            << "Restart state " << path << ": entry 'time' is " << t
            << ", the run restarts at time " << time_.value() << " ("
            << time_.timeName() << "/uniform/time): the state belongs to"
            << " another time." << nl
            << "    Restart from the time the state was written at, or set"
            << " 'restart fresh;'." << exit(FatalIOError);
    }
    if (index != time_.timeIndex())
    {
        FatalIOErrorInFunction(state)
            << "Restart state " << path << ": entry 'timeIndex' is " << index
            << ", the run restarts at time index " << time_.timeIndex()
            << " (" << time_.timeName() << "/uniform/time, 0 without it):"
            << " the state was written by another run or at another step."
            << nl << "    Restart from the time folder as the run wrote it"
            << " (uniform/time included), or set 'restart fresh;'."
            << exit(FatalIOError);
    }
}


void Foam::functionObjects::dropletFiberCollision::checkFiberCount
(
    const dictionary& state,
    const fileName& path
) const
{
    // States of earlier versions have no count
    const label count = state.lookupOrDefault<label>("fiberCount", -1);
    if (count >= 0 && count != label(held_.size()))
    {
        FatalIOErrorInFunction(state)
            << "Restart state " << path << ": entry 'fiberCount' is " << count
            << ", its dictionary 'fibers' holds " << label(held_.size())
            << " fibers: the state is incomplete or was edited." << nl
            << "    Restart from an earlier time, or set 'restart fresh;'."
            << exit(FatalIOError);
    }
}


Foam::label
Foam::functionObjects::dropletFiberCollision::nextFiberIdAfterRestart
(
    const dictionary& dict
) const
{
    // The ids are birth numbers: the fixed fibers of the dictionary first,
    // then every fiber injected (the injectors' counts), as in the run that
    // wrote the state; above every id held, should the dictionary differ
    label born =
        label(dropletFiber::readFixedFibers(dict.subOrEmptyDict("fibers")).size());
    for (const auto& injector : injectors_)
    {
        born += label(injector.injectedCount());
    }
    label above = 0;
    for (const label id : held_.id)
    {
        above = max(above, id + 1);
    }
    return max(born, returnReduce(above, maxOp<label>()));
}


void Foam::functionObjects::dropletFiberCollision::restoreFibers
(
    const dictionary& fibers
)
{
    held_ = dropletFiber::heldFibers();
    for (const entry& e : fibers)
    {
        const dictionary& d = dropletFiber::requiredSubDict
        (
            fibers, e.keyword(), "the state of one fiber"
        );
        // fiber<id>: the id, a birth number
        label id = -1;
        const word& key = e.keyword();
        if
        (
            key.size() < 6 || key.substr(0, 5) != "fiber"
         || !Foam::read(key.substr(5), id) || id < 0
        )
        {
            FatalIOErrorInFunction(fibers)
                << "Entry '" << key << "': allowed are fiber<id> with an"
                << " id >= 0 (the fiber's birth number)." << exit(FatalIOError);
        }
        ::dropletFiber::FiberState s = dropletFiber::fiberStateFromDict(d);
        dropletFiber::checkedCoreCall
        (
            d, [&]() { held_.fibers.emplace_back(std::move(s)); }
        );
        held_.origin.push_back(d.get<word>("origin"));
        held_.id.push_back(id);
    }
}


void Foam::functionObjects::dropletFiberCollision::restoreInjectorCounts
(
    const dictionary& injectors,
    const dictionary& sources
)
{
    // An injector new to this run has injected none yet; none has injected
    // more than its rate gives by the state's time, where the state says
    // that the rate was the dictionary's (an injector edited since is
    // warned about: warnSourcesDiffer)
    for (auto& injector : injectors_)
    {
        const word key(injector.spec().name);
        const label count =
            dropletFiber::getLabelInRange(injectors, key, 0, 0, labelMax);
        const bool edited =
            !sources.empty()
         && !dropletFiber::sameSource
            (
                sources, dict_.subOrEmptyDict("fibers"), "injectors", key
            );
        if (edited)
        {
            injector.setInjectedCount(count);
            continue;
        }
        const label born = dropletFiber::checkedCoreCall
        (
            injectors,
            [&]() { return label(injector.bornBy(clock_)); }
        );
        if (count > born)
        {
            const auto& spec = injector.spec();
            FatalIOErrorInFunction(injectors)
                << "Entry '" << key << "' is " << count << ": injector '"
                << key << "' (rate " << spec.rate << ", startTime "
                << spec.startTime << ", endTime " << spec.endTime << ") has"
                << " given at most " << born << " fibers by time "
                << time_.timeName() << "." << nl
                << "    Restart from a state its run wrote, or set 'restart"
                << " fresh;'." << exit(FatalIOError);
        }
        injector.setInjectedCount(count);
    }
}


void Foam::functionObjects::dropletFiberCollision::applyRemovalBeforeFirstStep()
{
    // In the run that wrote the state the removal came before the clouds'
    // next step; the first execute comes after it (droplets left in would
    // evaporate, or drive the gas, for a step). Clouds that do not exist
    // yet (made by a function object constructed later) get it then.
    bool exist = removalRestored_ && !cloudNames_.empty();
    for (const word& cloudName : cloudNames_)
    {
        exist = exist && mesh_.foundObject<cloud>(cloudName);
    }
    if (exist)
    {
        coreCall
        (
            "removing the droplets captured before the restart",
            [this]() { applyRestoredRemoval(); }
        );
    }
}


void Foam::functionObjects::dropletFiberCollision::restoreTotals
(
    const dictionary& totals
)
{
    // All are sums of non-negative masses and counts
    const auto nonNegative = [&totals](const word& key)
    {
        return dropletFiber::getCheckedScalar
        (
            totals, key, nullptr, [](scalar v) { return v >= 0; }, ">= 0"
        );
    };
    totals_.parcelMass = nonNegative("parcelMass");
    totals_.deposited = nonNegative("deposited");
    totals_.outside = nonNegative("outside");
    totals_.captured = nonNegative("captured");
    totals_.fiberMassAdded = nonNegative("fiberMassAdded");
    totals_.fiberMassRemoved = nonNegative("fiberMassRemoved");
    totals_.fibersRemoved = dropletFiber::requiredCount(totals, "fibersRemoved");
    totals_.parcelsCapped =
        dropletFiber::getLabelInRange(totals, "parcelsCapped", 0, 0, labelMax);
    // Per liquid species (a state without them: none captured)
    const dictionary& species = totals.subOrEmptyDict("capturedSpecies");
    const scalar none = 0;
    forAll(liquidSpecies_, i)
    {
        capturedSpecies_[i] =
            dropletFiber::getCheckedScalar
            (
                species, liquidSpecies_[i], &none,
                [](scalar v) { return v >= 0; }, ">= 0"
            );
    }
}


void Foam::functionObjects::dropletFiberCollision::checkWindowBlock
(
    const dictionary& state,
    const fileName& path
) const
{
    // A state without the entries was written by a serial run: the whole grid
    const auto& g = gridSettings_.spec;
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


void Foam::functionObjects::dropletFiberCollision::restoreWindow
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
    window.counters = dropletFiber::windowCounters(state);
    const fileName file = path + ".gridWindow";
    window.values = dropletFiber::windowValues
    (
        file,
        dropletFiber::requiredCount(state, "gridWindowValueCount"),
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

// ************************************************************************* //
