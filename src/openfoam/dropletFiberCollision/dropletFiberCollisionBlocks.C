/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Balanced grid blocks (grid.blocks balanced): after every balanceSteps-th
    committed step (the window's count, carried by the restart state, so a
    restarted run re-partitions at the steps the uninterrupted one did) the
    grid blocks are re-partitioned by that step's deposit work and the
    window moves with its nodes (gridBlocksRebalance.C). After the whole
    step: the depletion's and the hits' exchanges of the step used the old
    blocks; the next step's deposit uses the new ones.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "threadCpuTime.H"

#include <fstream>
#include <string>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- This process's resident memory (VmRSS of /proc/self/status) [MiB]; 0
//  where there is no such file
Foam::scalar residentMiB()
{
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key)
    {
        if (key == "VmRSS:")
        {
            double kB = 0;
            status >> kB;
            return kB/1024;
        }
        status.ignore(256, '\n');
    }
    return 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dropletFiberCollision::rebalanceBlocks
(
    const scalar dt
)
{
    if
    (
        !Pstream::parRun()
     || !gridSettings_.balancedBlocks
     || grid_->committedSteps() % gridSettings_.balanceSteps != 0
    )
    {
        return;
    }
    // Each phase's thread CPU time on this processor [ms] (the weighing,
    // the old window's parts saved, their exchange, the new window, the
    // spray's pages faulted in) and the resident memory [MiB] after the
    // save and at the end: the log's line on the move
    using stage = dropletFiber::parallelStatistics::stage;
    scalarList phases(7, Zero);
    scalar start = ::Foam::dropletFiber::threadCpuTime();
    auto endPhase = [&](const label phase)
    {
        const scalar now = ::Foam::dropletFiber::threadCpuTime();
        phases[phase] = 1e3*(now - start);
        start = now;
    };
    std::vector<::dropletFiber::WindowState> parts;
    bool moved = false;
    parallelStatistics_.timed
    (
        stage::deposit,
        [&]()
        {
            moved = coreCall
            (
                "re-partitioning the grid blocks",
                [&]()
                {
                    return blocks_->rebalance
                    (
                        *grid_,
                        stepParcels_,
                        dt,
                        gridSettings_.balanceSteps,
                        gridSettings_.moveCost,
                        parallelStatistics_,
                        parts
                    );
                }
            );
        }
    );
    if (!moved)
    {
        return;
    }
    endPhase(0);
    phases[1] = 1e3*blocks_->savingCpuTime();
    phases[0] -= phases[1];
    phases[5] = residentMiB();
    // The old grid freed before the parts arrive, each part freed once
    // copied into the new window: the old window and the parts sent, then
    // the parts received and the new window
    parallelStatistics_.timed
    (
        stage::deposit,
        [&]()
        {
            coreCall
            (
                "moving the averaging window to the new grid blocks",
                [&]()
                {
                    grid_.reset();
                    blocks_->receiveWindowParts(parallelStatistics_, parts);
                    endPhase(2);
                    rebuildGrid(nullptr);
                    grid_->restoreWindowParts(parts);
                    parts.clear();
                    endPhase(3);
                    grid_->makeResident(blocks_->sprayNodes());
                    endPhase(4);
                }
            );
        }
    );
    phases[6] = residentMiB();
    Pstream::listCombineGather(phases, maxEqOp<scalar>());
    Pstream::listCombineScatter(phases);
    Info<< "    window moved (busiest processor's thread CPU ms): weighing "
        << phases[0] << ", parts saved " << phases[1] << ", exchanged "
        << phases[2] << ", new window " << phases[3] << ", spray's pages "
        << phases[4] << "; resident " << phases[5] << " / " << phases[6]
        << " MiB after the save / the move" << nl;
}


void Foam::functionObjects::dropletFiberCollision::rebuildGrid
(
    const ::dropletFiber::WindowState* window
)
{
    grid_.reset();
    grid_.reset
    (
        new ::dropletFiber::DensityGrid
        (
            gridSettings_.spec,
            gridSettings_.kernel,
            int(gridSettings_.averagingSteps),
            blocks_->block()
        )
    );
    if (window)
    {
        grid_->restoreWindow(*window);
    }
}


// ************************************************************************* //
