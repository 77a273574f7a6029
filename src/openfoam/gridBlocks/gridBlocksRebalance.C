/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Balanced grid blocks (grid.blocks balanced, gridBlocks.H): the grid
    re-partitioned by the deposit work of a step, and the averaging windows
    moved with their nodes.

    The steady deposit's work (DepositWork, docs/scaleOut.md): a parcel costs
    16 ns per node of its deposit box (DensityGrid::depositBox), charged in
    full to every block the box meets (each evaluates the whole kernel: eq.
    24 normalises over it; the processor holding the parcel evaluates it
    only where the box meets its own block, StepDeposit::wants), and a
    touched node 3.7 ns (its step values and window update), the touched
    nodes taken as the nodes of the tiles in the bounding box of all
    parcels' tiles. Tiles of the grid at most 64 per direction; each
    processor sends its parcels grouped by their boxes' tiles (seven numbers
    a group, at most one per parcel) to all through the master, and every
    processor sums them in processor order: the same groups, the same
    partition (GridPartition::depositBisection), each block at most 1.5
    times its share of the nodes.

    Moving the windows: processor p sends processor q the node values of
    its window on the nodes of its old block inside q's new block, 56 bytes
    per node and filled step (averagingSteps): the traffic is that of the
    nodes changing owner only.

\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "threadCpuTime.H"

#include <algorithm>
#include <utility>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Thread CPU time per node weight of a parcel's deposit box and per
//  touched node of a step [s] (docs/scaleOut.md: fitted to each
//  processor's steady steps in bench/scaleOut.sh -localised, 1 and 4 ranks)
constexpr scalar costPerNodeWeight = 16e-9;
constexpr scalar costPerTouchedNode = 3.7e-9;

//- Tiles per direction of the work field: 64^3 = 2.6e5 at most, the cut
//  placed to within a 64th of the grid
constexpr int maxTilesPerDirection = 64;

//- A block holds at most this many times its share of the grid's nodes
//  (its memory near 1/P): on the localised bench 1.5 keeps the steady
//  deposit's max / mean at 4 ranks (1.22), 1.25 raised it to 1.33
constexpr scalar maxNodesShare = 1.5;

//- A new partition is taken when the busiest block's work falls by more
constexpr scalar worthMoving = 0.05;

//- Tiles added to each side of the parcels' tiles (sprayNodes): where the
//  spray may spread before the next weighing
constexpr int sprayMargin = 1;


//- The busiest block's work and the mean over the blocks (each block's
//  work: the parcels whose deposit boxes meet it, in full)
std::pair<scalar, scalar> busiestAndMean
(
    const ::dropletFiber::DepositWork& work,
    const ::dropletFiber::GridPartition& partition
)
{
    scalar most = 0;
    scalar sum = 0;
    for (label p = 0; p < partition.processors(); ++p)
    {
        const scalar w = work.workOf(partition.owned(p));
        most = max(most, w);
        sum += w;
    }
    return {most, sum/max(partition.processors(), 1)};
}


//- The nodes of the tiles of box, grown by sprayMargin tiles a side
::dropletFiber::IndexBox grownNodes
(
    const ::dropletFiber::DepositWork& work,
    ::dropletFiber::IndexBox tiles
)
{
    if (tiles.empty())
    {
        return ::dropletFiber::IndexBox();
    }
    for (int d = 0; d < 3; ++d)
    {
        tiles.lo[d] = max(tiles.lo[d] - sprayMargin, 0);
        tiles.hi[d] = min(tiles.hi[d] + sprayMargin, work.tiles()[d] - 1);
    }
    return work.touched().nodesOf(tiles);
}


//- A window part as its counters (labels) and its values as one binary
//  block (no per-value token)
void writeState(UOPstream& os, const ::dropletFiber::WindowState& state)
{
    os  << label(state.counters.size());
    for (const std::int64_t c : state.counters)
    {
        os  << label(c);
    }
    os  << label(state.values.size());
    os.write
    (
        reinterpret_cast<const char*>(state.values.data()),
        std::streamsize(state.values.size()*sizeof(double))
    );
}


::dropletFiber::WindowState readState(UIPstream& is)
{
    ::dropletFiber::WindowState state;
    label counters = 0;
    is  >> counters;
    state.counters.resize(counters);
    for (std::int64_t& c : state.counters)
    {
        label value = 0;
        is  >> value;
        c = value;
    }
    label values = 0;
    is  >> values;
    state.values.resize(values);
    is.read
    (
        reinterpret_cast<char*>(state.values.data()),
        std::streamsize(state.values.size()*sizeof(double))
    );
    return state;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

::dropletFiber::DepositWork Foam::dropletFiber::gridBlocks::depositWork
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    parallelStatistics& statistics,
    ::dropletFiber::IndexBox& sprayNodes
) const
{
    using stage = parallelStatistics::stage;
    List<scalarList> sparse(Pstream::nProcs());
    statistics.timed
    (
        stage::deposit,
        [&]()
        {
            ::dropletFiber::DepositWork local(spec_.nodes, maxTilesPerDirection);
            for (const ::dropletFiber::Parcel& parcel : parcels)
            {
                const ::dropletFiber::IndexBox box = grid.depositBox(parcel, dt);
                // The holder weighs the parcel only where its box meets
                // the holder's block, as any block
                local.addParcel(box, costPerNodeWeight*scalar(box.nodeCount()));
            }
            // Seven numbers a group: the tile box and the work
            DynamicList<scalar> mine(7*label(local.groupCount()));
            for (const auto& group : local.groups())
            {
                for (int d = 0; d < 3; ++d)
                {
                    mine.append(scalar(group.tiles.lo[d]));
                }
                for (int d = 0; d < 3; ++d)
                {
                    mine.append(scalar(group.tiles.hi[d]));
                }
                mine.append(group.work);
            }
            sparse[Pstream::myProcNo()].transfer(mine);
        }
    );
    statistics.countSent
    (
        sparse[Pstream::myProcNo()].byteSize(), parallelStatistics::traffic::parcels
    );
    Pstream::gatherList(sparse);
    Pstream::scatterList(sparse);
    // In processor order: the same sums on every processor
    ::dropletFiber::DepositWork work(spec_.nodes, maxTilesPerDirection);
    statistics.timed
    (
        stage::deposit,
        [&]()
        {
            ::dropletFiber::IndexBox touched;
            forAll(sparse, proci)
            {
                const scalarList& in = sparse[proci];
                for (label i = 0; i + 6 < in.size(); i += 7)
                {
                    ::dropletFiber::IndexBox tiles;
                    for (int d = 0; d < 3; ++d)
                    {
                        tiles.lo[d] = int(in[i + d]);
                        tiles.hi[d] = int(in[i + 3 + d]);
                    }
                    work.addGroup(tiles, in[i + 6]);
                    touched = touched.united(tiles);
                }
            }
            work.addTouched(work.touched().nodesOf(touched), costPerTouchedNode);
            sprayNodes = grownNodes(work, touched);
        }
    );
    return work;
}


void Foam::dropletFiber::gridBlocks::sendWindowParts
(
    ::dropletFiber::DensityGrid& grid,
    const ::dropletFiber::GridPartition& next,
    parallelStatistics& statistics,
    std::vector<::dropletFiber::WindowState>& kept
)
{
    windowBuffers_.reset
    (
        new PstreamBuffers(Pstream::commsTypes::nonBlocking)
    );
    kept.clear();
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        const ::dropletFiber::IndexBox part =
            owned_.intersected(next.owned(proci));
        if (part.empty())
        {
            continue;
        }
        // Each part's pages given back once saved: the window and its
        // parts are not held twice
        if (proci == Pstream::myProcNo())
        {
            kept.push_back(grid.saveWindowPart(part));
            grid.releaseWindowPages(part);
            continue;
        }
        // Straight into the send buffer: one copy of the part at a time
        const ::dropletFiber::WindowState state = grid.saveWindowPart(part);
        grid.releaseWindowPages(part);
        UOPstream os(proci, *windowBuffers_);
        writeState(os, state);
        statistics.countSent
        (
            state.values.size()*sizeof(double), parallelStatistics::traffic::parcels
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dropletFiber::gridBlocks::rebalance
(
    ::dropletFiber::DensityGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    const label balanceSteps,
    const scalar moveCost,
    parallelStatistics& statistics,
    std::vector<::dropletFiber::WindowState>& windowParts
)
{
    if (!Pstream::parRun())
    {
        return false;
    }
    const ::dropletFiber::DepositWork work =
        depositWork(grid, parcels, dt, statistics, sprayNodes_);
    if (work.touched().tileCount() < std::size_t(Pstream::nProcs()))
    {
        return false;
    }
    // The same work on every processor: the same decision
    const ::dropletFiber::GridPartition next =
        ::dropletFiber::GridPartition::depositBisection
        (
            work,
            Pstream::nProcs(),
            maxNodesShare*scalar(spec_.nodeCount())/Pstream::nProcs()
        );
    const std::pair<scalar, scalar> now = busiestAndMean(work, partition_);
    const std::pair<scalar, scalar> then = busiestAndMean(work, next);
    const scalar gain = (now.first - then.first)*scalar(balanceSteps);
    // A move's cost: every value of the old window is saved and copied into
    // a new one (the part a processor keeps too), and the spray's pages
    // faulted in: moveCost per value of the busiest window
    const scalar values =
        returnReduce(scalar(grid.windowValueCount()), maxOp<scalar>());
    const scalar cost = moveCost*values;
    Info<< "    grid blocks weighed: busiest block's predicted work / mean "
        << now.first/max(now.second, VSMALL) << ", re-partitioned "
        << then.first/max(then.second, VSMALL) << "; predicted gain over "
        << balanceSteps << " steps " << 1e3*gain << " ms, move "
        << 1e3*cost << " ms (" << values << " window values): ";
    if
    (
        next.boxes() == partition_.boxes()
     || now.first <= 0
     || then.first > (1 - worthMoving)*now.first
     || gain <= cost
    )
    {
        Info<< "kept" << nl;
        return false;
    }
    Info<< "re-partitioned by deposit work" << nl;
    const scalar saving = threadCpuTime();
    sendWindowParts(grid, next, statistics, windowParts);
    savingCpuTime_ = threadCpuTime() - saving;
    partition_ = next;
    owned_ = partition_.owned(Pstream::myProcNo());
    balanced_ = true;
    bisected_ = false;
    return true;
}


void Foam::dropletFiber::gridBlocks::receiveWindowParts
(
    parallelStatistics& statistics,
    std::vector<::dropletFiber::WindowState>& windowParts
)
{
    if (!windowBuffers_.valid())
    {
        return;
    }
    labelList recvSizes;
    windowBuffers_->finishedSends(recvSizes);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci] > 0)
        {
            UIPstream is(proci, *windowBuffers_);
            windowParts.push_back(readState(is));
        }
    }
    // The window's size, not to be kept between steps
    windowBuffers_.clear();
}


bool Foam::dropletFiber::gridBlocks::adopt(const labelList& boxes)
{
    if (!Pstream::parRun() || boxes.size() != 6*Pstream::nProcs())
    {
        return false;
    }
    std::vector<::dropletFiber::IndexBox> given(Pstream::nProcs());
    for (std::size_t p = 0; p < given.size(); ++p)
    {
        for (int d = 0; d < 3; ++d)
        {
            given[p].lo[d] = int(boxes[label(6*p) + d]);
            given[p].hi[d] = int(boxes[label(6*p) + 3 + d]);
        }
        if (given[p].empty())
        {
            return false;
        }
    }
    const ::dropletFiber::GridPartition partition(std::move(given));
    if (!partition.tiles(spec_))
    {
        return false;
    }
    balanced_ = balanced_ || partition.boxes() != partition_.boxes();
    partition_ = partition;
    owned_ = partition_.owned(Pstream::myProcNo());
    return true;
}


Foam::labelList Foam::dropletFiber::gridBlocks::boxesList() const
{
    labelList boxes(6*partition_.processors());
    for (label p = 0; p < partition_.processors(); ++p)
    {
        const ::dropletFiber::IndexBox& b = partition_.owned(p);
        for (int d = 0; d < 3; ++d)
        {
            boxes[6*p + d] = b.lo[d];
            boxes[6*p + 3 + d] = b.hi[d];
        }
    }
    return boxes;
}


// ************************************************************************* //
