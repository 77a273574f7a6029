/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The restart state read at the start: a missing state where a run
    restarts, a state of another processor count or of another time stop the
    run naming the file and what to do; else the parts read their entries,
    every value checked, and a processor's error stops all of them.

\*---------------------------------------------------------------------------*/

#include "couplingRestart.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "IFstream.H"
#include "stringOps.H"
#include "restartSources.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::couplingRestart::stopIfStateMissing
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


void Foam::dropletFiber::couplingRestart::stopIfRestartWithoutState
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


void Foam::dropletFiber::couplingRestart::checkStateProcessors
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


void Foam::dropletFiber::couplingRestart::checkStateTime
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


bool Foam::dropletFiber::couplingRestart::readState
(
    UPtrList<restartPart>& parts,
    const gridSettings& grid
)
{
    const fileName path = statePath(time_.timeName());
    if (fresh_)
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
    forAll(parts, parti)
    {
        parts[parti].readState(state, path);
    }
    // States of earlier versions have no sources to compare with
    if (state.found("sources"))
    {
        dropletFiber::warnSourcesDiffer
        (
            type() + " '" + name() + "'", state.subDict("sources"), path,
            fibers_, grid
        );
    }

    Info<< type() << " " << name() << ": restarted from " << path
        << ": captured mass so far "
        << state.subDict("totals").get<scalar>("captured") << " kg" << nl;
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dropletFiber::couplingRestart::readStateOnEveryProcessor
(
    UPtrList<restartPart>& parts,
    const gridSettings& grid
)
{
    // Each processor reads its own copy. OpenFOAM prints an error of a
    // function object's construction on the master only: the message of a
    // processor whose copy is missing or damaged goes to all of them, and
    // all stop.
    if (!Pstream::parRun())
    {
        return readState(parts, grid);
    }
    bool restored = false;
    List<string> failures(Pstream::nProcs());
    try
    {
        restored = readState(parts, grid);
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


// ************************************************************************* //
