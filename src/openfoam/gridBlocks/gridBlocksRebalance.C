/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Balanced grid blocks (grid.blocks balanced, gridBlocks.H): the grid
    re-partitioned by the deposit work of a step, and the averaging windows
    moved with their nodes.

    Work per node (docs/scaleOut.md, measured with bench/scaleOut.sh): the
    window update, 8.4 ns per node of a block, plus 47 ns per node weight
    evaluated, where a parcel's deposit box (DensityGrid::depositBox) is the
    node weights it costs, whichever blocks hold the nodes (its own
    processor's and those its copies go to). Summed on tiles of the grid
    (TileWork, at most 64 per direction) over the processors: each sends its
    parcels' non-zero tiles, two numbers each, to all (gather and scatter
    through the master).

    Moving the windows: processor p sends processor q the node values of
    its window on the nodes of its old block inside q's new block, 56 bytes
    per node and filled step (averagingSteps): the traffic is that of the
    nodes changing owner only.

\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Thread CPU time per node of a block's window update and per node weight
//  of the deposit [s] (docs/scaleOut.md, the localised case's deposit)
constexpr scalar windowCostPerNode = 8.4e-9;
constexpr scalar costPerNodeWeight = 47e-9;

//- Tiles per direction of the work field: 64^3 = 2.6e5 at most, the cut
//  placed to within a 64th of the grid
constexpr int maxTilesPerDirection = 64;

//- A new partition is taken when the busiest block's work falls by more
constexpr scalar worthMoving = 0.05;


//- The busiest block's work under the tile work
scalar busiest
(
    const ::dropletFiber::TileWork& work,
    const ::dropletFiber::GridPartition& partition
)
{
    scalar most = 0;
    for (const auto& box : partition.boxes())
    {
        most = max(most, work.workIn(box));
    }
    return most;
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

::dropletFiber::TileWork Foam::dropletFiber::gridBlocks::depositWork
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    parallelStatistics& statistics
) const
{
    using stage = parallelStatistics::stage;
    ::dropletFiber::TileWork local(spec_.nodes, maxTilesPerDirection);
    List<scalarList> sparse(Pstream::nProcs());
    statistics.timed
    (
        stage::deposit,
        [&]()
        {
            for (const ::dropletFiber::Parcel& parcel : parcels)
            {
                local.addBox(grid.depositBox(parcel, dt), costPerNodeWeight);
            }
            DynamicList<scalar> mine;
            const std::vector<double>& work = local.work();
            for (std::size_t t = 0; t < work.size(); ++t)
            {
                if (work[t] > 0)
                {
                    mine.append(scalar(t));
                    mine.append(work[t]);
                }
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
    // In processor order, then the windows: the same sums on every processor
    ::dropletFiber::TileWork work(spec_.nodes, maxTilesPerDirection);
    statistics.timed
    (
        stage::deposit,
        [&]()
        {
            forAll(sparse, proci)
            {
                const scalarList& in = sparse[proci];
                for (label i = 0; i + 1 < in.size(); i += 2)
                {
                    work.work()[std::size_t(in[i])] += in[i + 1];
                }
            }
            work.addBox(spec_.fullBox(), windowCostPerNode);
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
    const ::dropletFiber::TileWork work =
        depositWork(grid, parcels, dt, statistics);
    if (work.tileCount() < std::size_t(Pstream::nProcs()))
    {
        return false;
    }
    // The same work on every processor: the same decision
    const ::dropletFiber::GridPartition next =
        ::dropletFiber::GridPartition::weightedBisection(work, Pstream::nProcs());
    const scalar now = busiest(work, partition_);
    const scalar then = busiest(work, next);
    if (next.boxes() == partition_.boxes() || then > (1 - worthMoving)*now)
    {
        return false;
    }
    windowParts = movedWindowParts(grid, next, statistics);
    Info<< "    grid blocks re-partitioned by deposit work: busiest block's"
        << " predicted work " << now/(work.total()/Pstream::nProcs())
        << " -> " << then/(work.total()/Pstream::nProcs())
        << " of the mean" << nl;
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
