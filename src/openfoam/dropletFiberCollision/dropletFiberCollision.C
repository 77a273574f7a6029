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

//- The entries OpenFOAM v1912 reads from every function object's dictionary;
//  the function object's own are the stages' (checkEntries)
const Foam::wordList openFoamKeys
{
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
    stateParts_(6),
    depositionTime_(0),
    collisionTime_(0),
    fiberTime_(0)
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
    reaction_.warnIfAirFeelsNothing(false);
    output_.writeTableHeader(stepColumns());
}


Foam::functionObjects::dropletFiberCollision::~dropletFiberCollision() = default;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const std::vector<::dropletFiber::Parcel>&
Foam::functionObjects::dropletFiberCollision::gatherAndDeposit
(
    const scalar dt
)
{
    clockValue clock(true);
    spray_.applyRestoredRemovalOnce();
    const auto& parcels = spray_.gather();
    const ::dropletFiber::StepStatistics deposit = depositParcels(parcels, dt);
    depositionTime_ = clock.elapsed();
    grid_.recordDeposit(deposit, depositionTime_);
    return parcels;
}


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
    const scalar dt
)
{
    capture_.handPopulations(reaction_);
    population_.notePopulationSpreads(capture_.populationSpreads());
    population_.advance(motion_, dt, capture, statistics_, reaction_);
    capture_.countCaptured(population_.fibers(), capture);
    population_.removeLaid(laydown_.layDown(population_.fibers()));
    population_.removeLostAndPassOn(statistics_);
}


void Foam::functionObjects::dropletFiberCollision::checkEntries
(
    const dictionary& dict,
    const dictionary& fibersDict
)
{
    using namespace dropletFiber;
    checkKeys
    (
        dict,
        joinedKeys
        (
            {
                sprayParcels::entries(), couplingGrid::entries(),
                fiberCapture::entries(), fiberMotion::entries(),
                couplingOutput::entries(), couplingRestart::entries(),
                openFoamKeys
            }
        )
    );
    checkKeys
    (
        fibersDict,
        joinedKeys
        (
            {
                fiberMotion::fibersEntries(), fiberPopulation::fibersEntries(),
                airReaction::fibersEntries(), fiberLaydown::fibersEntries()
            }
        )
    );
}


Foam::wordList
Foam::functionObjects::dropletFiberCollision::stepColumns() const
{
    return dropletFiber::joinedKeys
    (
        {
            population_.stepColumns(), spray_.stepColumns(),
            grid_.stepColumns(), capture_.stepColumns(), motion_.stepColumns(),
            laydown_.stepColumns(),
            wordList
            {
                "wallTimeDeposition", "wallTimeCollision", "wallTimeFibers"
            }
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dropletFiberCollision::read(const dictionary& dict)
{
    // Called at construction, and again whenever the dictionary was edited
    // during the run (runTimeModifiable): what carries no state is applied,
    // an edit of what does (the grid, the fibers' sources, depletion, the
    // belt) stops the run. Each stage reads its own entries; fibers is
    // shared by the stages of the fibers
    const bool running = grid_.built();
    const dictionary fibers(dropletFiber::optionalSubDict(dict, "fibers"));
    checkEntries(dict, fibers);
    fvMeshFunctionObject::read(dict);
    output_.read(dict);
    capture_.read(dict, running);
    spray_.read(dict, capture_.depletion());
    restart_.read(dict, fibers);
    motion_.read(dropletFiber::optionalSubDict(dict, "air"), fibers, running);
    reaction_.read(fibers, output_.tablePrecision());
    laydown_.read(fibers, running, output_.tablePrecision());
    if (laydown_.on())
    {
        population_.countBinderRemoved();
    }
    // The injectors before the grid: its memory check counts their fibers
    population_.read(fibers, running);
    grid_.read(dict, running, population_.injectorSpecs());
    if (running)
    {
        Info<< type() << " " << name() << ": settings re-read at time "
            << time_.timeName() << nl;
        reportSettings();
    }
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
    statistics_.startStep();

    // 1.-2. The parcels of this step (after a restart, with the removal of
    //       the step restarted from), onto the grid, averaged over the window
    const auto& parcels = gatherAndDeposit(dt);

    // 3. New fibers
    clockValue clock(true);
    population_.inject(statistics_);
    fiberTime_ = clock.elapsed();

    // 4. Collision mass of every segment; with depletion taken from the parcels
    clock.update();
    ::dropletFiber::CaptureSources capture = collideAndDeplete(parcels, dt);
    collisionTime_ = clock.elapsed();

    // 5.-6. Advance the fibers: capture, air drag, bending, inextensibility;
    //       those on the belt or out of the mesh removed, the others passed on
    clock.update();
    advanceFibers(capture, dt);
    fiberTime_ += scalar(clock.elapsed());
    grid_.rebalance(parcels, dt, statistics_);

    // 7. Report; at write times the restart state and the mass balances
    reportStep();
    if (time_.writeTime())
    {
        writeAtWriteTime();
    }
    return true;
}


// ************************************************************************* //
