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
#include "grid/WindowTransfer.hpp"

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
    std::vector<::dropletFiber::WindowState> parts;
    const bool moved = coreCall
    (
        "re-partitioning the grid blocks",
        [&]()
        {
            return blocks_->rebalance
            (
                *grid_, stepParcels_, dt, parallelStatistics_, parts
            );
        }
    );
    if (!moved)
    {
        return;
    }
    // The old grid freed before the new window is joined: at most two
    // windows' memory at a time
    using stage = dropletFiber::parallelStatistics::stage;
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
                    ::dropletFiber::WindowState window =
                        ::dropletFiber::joinedWindowState
                        (
                            parts, blocks_->block().owned
                        );
                    parts.clear();
                    parts.shrink_to_fit();
                    rebuildGrid(&window);
                }
            );
        }
    );
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
