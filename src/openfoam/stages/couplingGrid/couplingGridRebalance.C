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

#include "couplingGrid.H"
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

//- A move's phases on this processor: thread CPU time [ms] of the weighing,
//  the old window's parts saved, their exchange, the new window and the
//  spray's pages faulted in; resident memory [MiB] after the save and at
//  the end; the log's line gives each one's maximum over processors
struct movePhases
{
    Foam::scalarList ms = Foam::scalarList(7, Foam::Zero);
    Foam::scalar start = Foam::dropletFiber::threadCpuTime();

    void end(const Foam::label phase)
    {
        const Foam::scalar now = Foam::dropletFiber::threadCpuTime();
        ms[phase] = 1e3*(now - start);
        start = now;
    }

    void report()
    {
        using namespace Foam;
        Pstream::listCombineGather(ms, maxEqOp<scalar>());
        Pstream::listCombineScatter(ms);
        Info<< "    window moved (busiest processor's thread CPU ms): weighing "
            << ms[0] << ", parts saved " << ms[1] << ", exchanged " << ms[2]
            << ", new window " << ms[3] << ", spray's pages " << ms[4]
            << "; resident " << ms[5] << " / " << ms[6]
            << " MiB after the save / the move" << nl;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::couplingGrid::rebalance
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const scalar dt,
    parallelStatistics& statistics
)
{
    if
    (
        !Pstream::parRun()
     || !settings_.balancedBlocks
     || grid_->committedSteps() % settings_.balanceSteps != 0
    )
    {
        return;
    }
    using stage = parallelStatistics::stage;
    movePhases phases;
    std::vector<::dropletFiber::WindowState> parts;
    bool moved = false;
    statistics.timed
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
                        parcels,
                        dt,
                        settings_.balanceSteps,
                        settings_.moveCost,
                        statistics,
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
    phases.end(0);
    phases.ms[1] = 1e3*blocks_->savingCpuTime();
    phases.ms[0] -= phases.ms[1];
    phases.ms[5] = residentMiB();
    // The old window's pages were given back part by part as saved; the old
    // grid is freed before the parts arrive, and each part once copied into
    // the new window
    statistics.timed
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
                    blocks_->receiveWindowParts(statistics, parts);
                    phases.end(2);
                    rebuildGrid(nullptr);
                    grid_->restoreWindowParts(parts);
                    parts.clear();
                    phases.end(3);
                    grid_->makeResident(blocks_->sprayNodes());
                    phases.end(4);
                }
            );
        }
    );
    phases.ms[6] = residentMiB();
    phases.report();
}


// ************************************************************************* //
