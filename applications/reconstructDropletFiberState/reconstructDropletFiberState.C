/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Application
    reconstructDropletFiberState

Description
    Merges the restart states of dropletFiberCollision function objects that
    the processors of a parallel run wrote
    (processorN/\<time\>/uniform/dropletFiber/\<name\>) into the state a
    serial run writes (\<time\>/uniform/dropletFiber/\<name\>): the fibers'
    union, the global counts and totals (equal on every processor), the
    depletion removal lists, and the whole grid's averaging window joined
    from the processors' blocks (restartStateMerge.H). The restart state's
    reconstructPar.

    A serial run continues from the merged state; decomposePar copies it
    into the processor directories of any count. Every state is checked:
    a missing or damaged one, or one of another run, stops with a
    FatalIOError naming the file and the entry.

    Memory: the whole grid's averaging window (twice at the join), as
    reconstructPar holds whole fields.

Usage
    \b reconstructDropletFiberState [OPTION]

    Options:
      - \par -time \<ranges\>, -latestTime, ...
        The times of the case to merge (timeSelector, after reconstructPar;
        default: every time; a time no processor wrote a state at is skipped)

      - \par -name \<name\>
        Only the function object \<name\> (default: every function object of
        type dropletFiberCollision in system/controlDict)

    Restart a parallel run's state on another processor count:
    \verbatim
        reconstructPar -latestTime
        reconstructDropletFiberState -latestTime
        rm -rf processor*
        decomposePar -latestTime          # for the new count
        mpirun -np N <solver> -parallel   # or <solver> serially
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "timeSelector.H"
#include "Time.H"
#include "fvMesh.H"
#include "clockTime.H"
#include "gridSettings.H"
#include "restartStateMerge.H"

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

//- The dropletFiberCollision function objects of controlDict (only `only`,
//  if given): name -> dictionary
HashTable<dictionary> collisionFunctionObjects
(
    const Time& runTime,
    const word& only
)
{
    HashTable<dictionary> found;
    const dictionary& functions =
        runTime.controlDict().subOrEmptyDict("functions");
    for (const entry& e : functions)
    {
        if
        (
            e.isDict()
         && e.dict().lookupOrDefault<word>("type", word::null)
         == "dropletFiberCollision"
         && (only.empty() || e.keyword() == only)
        )
        {
            found.insert(e.keyword(), e.dict());
        }
    }
    if (found.empty())
    {
        FatalIOErrorInFunction(functions)
            << "No function object of type dropletFiberCollision"
            << (only.empty() ? word::null : word(" named '" + only + "'"))
            << " in " << runTime.controlDict().name() << "'s functions:"
            << " allowed are the names of those the case runs."
            << exit(FatalIOError);
    }
    return found;
}


//- Whether any processor holds the function object's state at the time
bool anyProcessorState
(
    const fileName& caseDir,
    const label processors,
    const word& timeName,
    const word& name
)
{
    for (label proci = 0; proci < processors; ++proci)
    {
        const fileName path =
            caseDir/("processor" + Foam::name(proci))/timeName/"uniform"
           /"dropletFiber"/name;
        if (isFile(path))
        {
            return true;
        }
    }
    return false;
}


//- Merge the states of function object `name` at runTime's time, if any
//  processor wrote one
void mergeStates
(
    const fileName& caseDir,
    const label processors,
    const Time& runTime,
    const fvMesh& mesh,
    const word& name,
    const dictionary& functionDict
)
{
    const word& timeName = runTime.timeName();
    if (!anyProcessorState(caseDir, processors, timeName, name))
    {
        Info<< "    " << name << ": no processor holds a restart state at"
            << " this time, skipped" << nl;
        return;
    }
    const clockTime clock;
    const Foam::dropletFiber::gridSettings grid =
        Foam::dropletFiber::readGridSettings
        (
            functionDict.subOrEmptyDict("grid"), mesh
        );
    const label fibers = Foam::dropletFiber::writeMergedRestartState
    (
        caseDir, timeName, name,
        Foam::dropletFiber::readProcessorStates
        (
            caseDir, processors, timeName, name
        ),
        grid
    );
    Info<< "    " << name << ": merged the restart states of " << processors
        << " processors into "
        << (runTime.timePath()/"uniform"/"dropletFiber"/name) << " ("
        << fibers << " fibers, the averaging window of "
        << grid.spec.nodes[0] << " x " << grid.spec.nodes[1] << " x "
        << grid.spec.nodes[2] << " nodes) in " << clock.elapsedTime()
        << " s" << nl;
}


// * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Merge the restart states of dropletFiberCollision that the"
        " processors of a parallel run wrote into a serial run's state"
        " (run reconstructPar first; decomposePar then copies it to any"
        " processor count)"
    );
    timeSelector::addOptions(true, true);
    argList::noParallel();
    argList::addOption
    (
        "name", "name",
        "only the function object <name> (default: every"
        " dropletFiberCollision function object of system/controlDict)"
    );
    #include "setRootCase.H"
    #include "createTime.H"

    const label processors = fileHandler().nProcs(args.path());
    if (processors == 0)
    {
        FatalErrorInFunction
            << "No processor directories in " << args.path() << ": the"
            << " restart states of a parallel run are merged from them"
            << " (a serial run's state needs no merge)." << exit(FatalError);
    }
    const HashTable<dictionary> functions =
        collisionFunctionObjects(runTime, args.opt<word>("name", word::null));
    const instantList times = timeSelector::select0(runTime, args);
    // The grid's default bounds and flat directions are the mesh's
    Info<< "Create mesh for time = " << runTime.timeName() << nl << endl;
    const fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion, runTime.timeName(), runTime,
            IOobject::MUST_READ
        )
    );

    forAll(times, timei)
    {
        runTime.setTime(times[timei], timei);
        Info<< "Time = " << times[timei].name() << nl;
        for (const word& name : functions.sortedToc())
        {
            mergeStates(args.path(), processors, runTime, mesh, name, functions[name]);
        }
    }
    Info<< nl << "End" << nl << endl;
    return 0;
}

// ************************************************************************* //
