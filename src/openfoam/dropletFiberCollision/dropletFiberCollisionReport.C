/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The conductor's reports: the settings in force, each step's figures
    gathered from the stages for the output, and at write times the restart
    state, the binder table, the balances and the VTK files.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "collisionSettings.H"
#include "openfoamRelease.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dropletFiberCollision::reportStep
(
    dropletFiber::stepRow& step
)
{
    // Over all processors (collective: before the master's writing)
    step.fibers = population_.count();
    step.weighted = population_.weighted();
    if (step.weighted)
    {
        step.fibersRepresented = population_.represented();
    }
    step.fiberMass = population_.mass();
    step.laying = laydown_.on();
    step.laidGlass = laydown_.totals().glass;
    step.laidBinder = laydown_.totals().binder;
    step.capturedTotal = capture_.captured();
    step.depletion = capture_.depletion();
    if (step.depletion)
    {
        step.cloudMass = spray_.readCloudMassReport();
        step.removal = capture_.step();
        step.capturedSpecies = spray_.capturedSpecies();
    }
    output_.writeStep(step);
    // With turbulent air, the fibers' dispersion
    if (motion_.turbulent())
    {
        output_.writeFiberDispersion(population_.dispersionSums());
    }
    // The grid nodes this processor stores (its block) and the fibers it
    // holds, with the step's work, over processors
    statistics_.holding(grid_.storedNodes(), population_.fibers().size());
    output_.writeParallelStatistics(statistics_.overProcessors());
}


void Foam::functionObjects::dropletFiberCollision::writeAtWriteTime
(
    const dropletFiber::stepRow& step
)
{
    coreCall
    (
        "writing the restart state",
        [this]() { restart_.writeState(stateParts_, grid_.settings()); }
    );
    output_.writeBinderDistribution
    (
        population_.binderSums(),
        dropletFiber::collisionModeName(capture_.options().mode)
    );
    // The fibers' mass summed for the step's row: nothing moved since
    output_.reportConservation
    (
        grid_.totals(), population_.totals(), capture_.captured(),
        step.fiberMass,
        laydown_.on() ? laydown_.totals().glass + laydown_.totals().binder : -1
    );
    if (laydown_.on())
    {
        const scalar binderInAir = population_.binderSums().values[2];
        laydown_.reportAtWrite
        (
            step.fiberMass - binderInAir, binderInAir,
            population_.totals().massAdded, population_.totals().massRemoved,
            population_.totals().binderRemoved, capture_.captured()
        );
    }
    capture_.reportBinderBalance();
    statistics_.reportBalance(Info, type() + " " + name(), time_.timeName());
    spray_.reportCloudBalance(capture_.step().airborne, capture_.captured());
    grid_.reportAtWrite();
}


void Foam::functionObjects::dropletFiberCollision::reportSettings()
{
    Info<< type() << " " << name() << ":" << nl;
    dropletFiber::reportOpenfoamRelease(Info);
    spray_.report(Info);
    grid_.report(Info);
    capture_.report(Info);
    grid_.reportBlocks(Info);
    motion_.reportAir(Info);
    grid_.reportMemory(Info, population_.pointsHere());
    motion_.report(Info, population_.injectorCount(), population_.count());
    reaction_.report(Info);
    laydown_.report(Info);
    output_.report(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dropletFiberCollision::write()
{
    coreCall
    (
        "writing the VTK files",
        [this]()
        {
            output_.writeVtk
            (
                [this]
                (
                    const fileName& dir,
                    const scalar t,
                    ::dropletFiber::SeriesFile& series
                )
                {
                    population_.writeVtk(dir, t, series, motion_.turbulent());
                },
                [this]
                (
                    const fileName& dir,
                    const scalar t,
                    ::dropletFiber::SeriesFile& series
                )
                {
                    grid_.writeVtk(dir, t, series, statistics_);
                }
            );
        }
    );
    return true;
}


// ************************************************************************* //
