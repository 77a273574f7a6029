/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The conductor: the settings read into the stages, and the coupling
    step. Read execute() from top to bottom to follow one parcel's mass:
    gathered, deposited on the grid, averaged, turned into collision mass on
    fiber segments, captured by the fibers and taken from the parcel.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"
#include "collisionSettings.H"
#include "plausibility.H"
#include "clockValue.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(dropletFiberCollision, 0);
    addToRunTimeSelectionTable
    (
        functionObject,
        dropletFiberCollision,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The entries of the function object's dictionary: its own, read by the
//  stages, and those OpenFOAM v1912 reads from every function object's
//  dictionary
const Foam::wordList functionObjectKeys
{
    "clouds", "gather", "grid", "collision", "air", "fibers",
    "writeVtk", "writeGridVtk", "writeWindowValues", "windowState", "restart",
    // functionObject, functionObjectList: the object itself
    "type", "libs", "functionObjectLibs", "enabled", "log",
    // regionFunctionObject (fvMeshFunctionObject)
    "region", "subRegion",
    // timeControl: when execute() and write() are called
    "executeControl", "executeInterval", "writeControl", "writeInterval",
    "outputControl", "outputInterval",
    "timeStart", "timeEnd", "triggerStart", "triggerEnd", "controlMode",
    "deltaTCoeff", "nStepsToStartTimeChange",
    // writeFile: the per-step table
    "writePrecision", "writeToFile", "useUserTime",
    // set by postProcess -func 'name(field, ...)'
    "field", "fields"
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::dropletFiberCollision::dropletFiberCollision
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    lastTimeIndex_(-1),
    output_(*this, mesh_, dict),
    spray_(*this, mesh_),
    grid_(*this, mesh_),
    population_(*this, mesh_),
    capture_(*this, mesh_),
    motion_(*this, mesh_),
    reaction_(*this, mesh_),
    laydown_(*this, mesh_),
    restart_(*this, mesh_),
    stateParts_(6)
{
    stateParts_.set(0, &population_);
    stateParts_.set(1, &capture_);
    stateParts_.set(2, &spray_);
    stateParts_.set(3, &grid_);
    stateParts_.set(4, &reaction_);
    stateParts_.set(5, &laydown_);
    read(dict);
    // The table's columns per liquid species; the state's totals of them
    if (capture_.depletion())
    {
        spray_.findLiquidSpecies();
    }

    // Fibers: from the restart state of the start time, else from the
    // dictionary
    const bool restored =
        restart_.readStateOnEveryProcessor(stateParts_, grid_.settings());
    if (!restored)
    {
        reaction_.startWithoutState();
    }
    grid_.warnBoxOutsideMesh();
    population_.start(restored, restart_.stateProcessors(), statistics_);
    spray_.applyRemovalBeforeFirstStep();

    output_.startVtk(dict);
    restart_.startMarker([this]() { return lastTimeIndex_; });
    reportSettings();
    output_.writeTableHeader
    (
        capture_.depletion(), spray_.liquidSpecies(), population_.weighted(),
        laydown_.on()
    );
}


Foam::functionObjects::dropletFiberCollision::~dropletFiberCollision() = default;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

::dropletFiber::StepStatistics
Foam::functionObjects::dropletFiberCollision::depositParcels
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const scalar dt
)
{
    // Depletion takes the captured droplets from the parcels whose deposit
    // reached the nodes of the cells the fibers lie in (every processor's):
    // their separable tables are kept for it
    ::dropletFiber::IndexBox nearFibers;
    if (capture_.depletion())
    {
        const auto box = population_.boundingBox();
        nearFibers = grid_.nodesOfCellsIn(box.first, box.second);
    }
    // Discrete hits draw whole droplets from the node sums: a last-bit
    // difference can change a count, so there the sums are made the same on
    // every decomposition (docs/model.md sec. 4, grid blocks)
    return coreCall
    (
        "depositing the parcels",
        [&]()
        {
            return grid_.deposit
            (
                parcels, dt, capture_.depletion() ? &nearFibers : nullptr,
                capture_.options().mode
             == ::dropletFiber::CollisionMode::Discrete,
                statistics_
            );
        }
    );
}


::dropletFiber::CaptureSources
Foam::functionObjects::dropletFiberCollision::collideAndDeplete
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const scalar dt
)
{
    ::dropletFiber::CaptureSources capture = coreCall
    (
        "colliding fibers and droplets",
        [&]()
        {
            return capture_.collide
            (
                population_.fibers(), grid_, parcels, dt, statistics_
            );
        }
    );
    if (capture_.depletion())
    {
        coreCall
        (
            "removing the captured droplets from the parcels",
            [&]()
            {
                capture_.closeRemoval
                (
                    spray_.writeBack(capture_.capturedFractions())
                );
            }
        );
    }
    return capture;
}


void Foam::functionObjects::dropletFiberCollision::advanceFibers
(
    ::dropletFiber::CaptureSources& capture,
    const scalar dt,
    dropletFiber::stepRow& step
)
{
    const ::dropletFiber::StepReport report = motion_.advance
    (
        population_.fibers(), population_.boxes(), dt, capture, statistics_,
        reaction_
    );
    step.capturedStep =
        capture_.countCaptured(population_.fibers(), capture);
    step.maxSegmentLengthError = report.maxSegmentLengthError;
    step.subSteps = report.subSteps;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dropletFiberCollision::read(const dictionary& dict)
{
    // Called at construction, and again whenever the dictionary was edited
    // during the run (runTimeModifiable): what carries no state is applied,
    // an edit of what does (the grid, the fibers' sources, depletion) stops
    // the run
    const bool running = grid_.built();
    dropletFiber::checkKeys(dict, functionObjectKeys);
    fvMeshFunctionObject::read(dict);
    output_.read(dict);
    grid_.readWindowOutput(dict);
    capture_.read(dict, running);
    spray_.read(dict, capture_.depletion());
    restart_.read(dict);
    const dropletFiber::gridSettings grid =
        dropletFiber::readGridSettings(dict.subOrEmptyDict("grid"), mesh_);
    motion_.read(dict);
    reaction_.readCoupling(dict);
    laydown_.read(dict, running);
    if (laydown_.on())
    {
        population_.countBinderRemoved();
    }
    if (running)
    {
        grid_.checkUnchanged(grid, dict.subOrEmptyDict("grid"));
        population_.read(dict, running);
        Info<< type() << " " << name() << ": settings re-read at time "
            << time_.timeName() << nl;
        reportSettings();
        return true;
    }
    // The injectors first: the memory check counts the fibers they give
    population_.read(dict, running);
    grid_.build(dict, grid, population_.injectorSpecs());
    // Unit slips run, warned once at the start
    dropletFiber::warnImplausibleFibers(dict.subOrEmptyDict("fibers"));
    dropletFiber::warnImplausibleAir(dict.subOrEmptyDict("air"));
    dropletFiber::warnImplausibleSpacing
    (
        dict.subOrEmptyDict("grid"), grid_.settings(), mesh_
    );
    return true;
}


bool Foam::functionObjects::dropletFiberCollision::execute()
{
    // Once per time step, whatever the function object's execute control
    if (time_.timeIndex() == lastTimeIndex_)
    {
        return true;
    }
    lastTimeIndex_ = time_.timeIndex();
    const scalar dt = time_.deltaTValue();
    dropletFiber::stepRow step;
    statistics_.startStep();

    // 1.-2. The parcels of this step (after a restart, with the removal of
    //       the step restarted from), onto the grid, averaged over the window
    clockValue clock(true);
    spray_.applyRestoredRemovalOnce();
    const auto& parcels = spray_.gather(step.parcels, step.droplets);
    step.deposit = depositParcels(parcels, dt);
    step.depositionTime = clock.elapsed();
    grid_.recordDeposit(step.deposit, step.depositionTime);

    // 3. New fibers
    clock.update();
    population_.inject(statistics_);
    step.fiberTime = clock.elapsed();

    // 4. Collision mass of every segment; with depletion taken from the parcels
    clock.update();
    ::dropletFiber::CaptureSources capture = collideAndDeplete(parcels, dt);
    step.collisionTime = clock.elapsed();

    // 5. Advance the fibers: capture, air drag, bending, inextensibility;
    // 6. fibers that left removed, the others to the processor holding them
    clock.update();
    advanceFibers(capture, dt, step);
    laydown_.layDown(population_.fibers());
    population_.removeLostAndPassOn(statistics_);
    step.fiberTime += scalar(clock.elapsed());
    grid_.rebalance(parcels, dt, statistics_);

    // 7. Report; at write times the restart state and the mass balances
    reportStep(step);
    if (time_.writeTime())
    {
        writeAtWriteTime(step);
    }
    return true;
}


// ************************************************************************* //
