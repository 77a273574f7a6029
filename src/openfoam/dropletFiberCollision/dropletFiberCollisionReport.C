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

void Foam::functionObjects::dropletFiberCollision::reportStep()
{
    // Each stage its figures, summed over processors (collective: before
    // the master's writing)
    dropletFiber::stepFigures step;
    population_.addStepFigures(step);
    spray_.addStepFigures(step);
    grid_.addStepFigures(step);
    capture_.addStepFigures(step);
    motion_.addStepFigures(step);
    laydown_.addStepFigures(step);
    step.add("wallTimeDeposition", depositionTime_);
    step.add("wallTimeCollision", collisionTime_);
    step.add("wallTimeFibers", fiberTime_);
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


void Foam::functionObjects::dropletFiberCollision::writeAtWriteTime()
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
    output_.reportConservationHeading();
    grid_.reportConservation();
    population_.reportConservation(capture_.captured());
    laydown_.reportAtWrite();
    population_.reportBalanceAtWrite(capture_.captured());
    capture_.reportBinderBalance();
    capture_.reportSpread();
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


bool Foam::functionObjects::dropletFiberCollision::end()
{
    reaction_.warnIfAirFeelsNothing(true);
    return true;
}


// ************************************************************************* //
