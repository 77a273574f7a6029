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


void appendState
(
    DynamicList<scalar>& out,
    const ::dropletFiber::WindowState& state
)
{
    out.append(scalar(state.counters.size()));
    for (const std::int64_t c : state.counters)
    {
        out.append(scalar(c));
    }
    out.append(scalar(state.values.size()));
    for (const double v : state.values)
    {
        out.append(v);
    }
}


::dropletFiber::WindowState readState(const List<scalar>& in)
{
    ::dropletFiber::WindowState state;
    label at = 0;
    const label counters = label(in[at++]);
    for (label i = 0; i < counters; ++i)
    {
        state.counters.push_back(std::int64_t(in[at++]));
    }
    const label values = label(in[at++]);
    state.values.assign(in.cdata() + at, in.cdata() + at + values);
    return state;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

::dropletFiber::DepositWork Foam::dropletFiber::gridBlocks::depositWork
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    parallelStatistics& statistics
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
        }
    );
    return work;
}


std::vector<::dropletFiber::WindowState>
Foam::dropletFiber::gridBlocks::movedWindowParts
(
    const ::dropletFiber::DensityGrid& grid,
    const ::dropletFiber::GridPartition& next,
    parallelStatistics& statistics
)
{
    std::vector<::dropletFiber::WindowState> parts;
    forAll(outgoing_, proci)
    {
        outgoing_[proci].clear();
        const ::dropletFiber::IndexBox part = owned_.intersected(next.owned(proci));
        if (part.empty())
        {
            continue;
        }
        if (proci == Pstream::myProcNo())
        {
            parts.push_back(grid.saveWindowPart(part));
            continue;
        }
        appendState(outgoing_[proci], grid.saveWindowPart(part));
    }
    const List<List<scalar>> received =
        exchangeLists(statistics, parallelStatistics::traffic::parcels);
    forAll(outgoing_, proci)
    {
        // The window's size, not to be kept between steps
        outgoing_[proci].clearStorage();
    }
    forAll(received, proci)
    {
        if (!received[proci].empty())
        {
            parts.push_back(readState(received[proci]));
        }
    }
    return parts;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dropletFiber::gridBlocks::rebalance
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    parallelStatistics& statistics,
    std::vector<::dropletFiber::WindowState>& windowParts
)
{
    if (!Pstream::parRun())
    {
        return false;
    }
    const ::dropletFiber::DepositWork work =
        depositWork(grid, parcels, dt, statistics);
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
    if
    (
        next.boxes() == partition_.boxes()
     || now.first <= 0
     || then.first > (1 - worthMoving)*now.first
    )
    {
        Info<< "    grid blocks kept: busiest block's predicted work / mean "
            << now.first/max(now.second, VSMALL) << " (re-partitioned: "
            << then.first/max(then.second, VSMALL) << ")" << nl;
        return false;
    }
    windowParts = movedWindowParts(grid, next, statistics);
    Info<< "    grid blocks re-partitioned by deposit work: busiest block's"
        << " predicted work / mean " << now.first/max(now.second, VSMALL)
        << " -> " << then.first/max(then.second, VSMALL)
        << " (busiest " << now.first/max(then.first, VSMALL)
        << " times the new busiest)" << nl;
    partition_ = next;
    owned_ = partition_.owned(Pstream::myProcNo());
    balanced_ = true;
    bisected_ = false;
    return true;
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
