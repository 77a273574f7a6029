/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Spread populations over the grid's blocks (docs/model.md sec. 12, P51,
    P53): a level node's terms come from the processors holding the fibers
    near it and act on the grid nodes its hat reaches, which several blocks
    may own. Each level node has an owner, the owner of the grid node
    nearest it in the box: the processors send it their terms (summed per
    key), it adds them in processor order and sends the sums on, to the
    processors that gave terms (the count, the grants) or to the blocks its
    hat reaches (the demand, the realised hits). What travels is set by the
    level nodes the fibers reach: for each, its few values to its owner and
    back, not the grid nodes under its hat.

\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "levelSums.H"

#include <algorithm>
#include <utility>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::dropletFiber::gridBlocks::levelOwner
(
    const ::dropletFiber::SpreadPopulations& levels,
    const ::dropletFiber::LevelKey key
) const
{
    const ::dropletFiber::SpreadLevel& level =
        levels.level(::dropletFiber::levelOfKey(key));
    const std::array<int, 3> c =
        ::dropletFiber::nodeIndicesOfFlat
        (
            level.spec().nodes, ::dropletFiber::nodeOfKey(key)
        );
    std::array<int, 3> fine{};
    for (int d = 0; d < 3; ++d)
    {
        fine[d] = std::min(level.ratio()*c[d], spec_.nodes[d] - 1);
        fine[d] = spec_.flat(d) ? 0 : fine[d];
    }
    return partition_.owner(fine[0], fine[1], fine[2]);
}


void Foam::dropletFiber::gridBlocks::levelBlocks
(
    const ::dropletFiber::SpreadPopulations& levels,
    const ::dropletFiber::LevelKey key,
    std::vector<int>& blocks
) const
{
    const ::dropletFiber::IndexBox hat =
        levels.level(::dropletFiber::levelOfKey(key))
       .hatBox(::dropletFiber::nodeOfKey(key));
    partition_.holdersOf(hat, -1, blocks);
}


void Foam::dropletFiber::gridBlocks::spreadOntoNodes
(
    const ::dropletFiber::DensityGrid& grid,
    const spreadStep& spread,
    parallelStatistics& statistics
)
{
    const ::dropletFiber::SpreadPopulations& levels = *spread.populations;
    spreadLevels_ = spread.populations;
    spreadHeld_ = sumLevelTable(levels, spread.demand, true, statistics);
    // P_n and P'_n over the owned nodes the hats reach, in node order
    spreadRegion_ = owned_.intersected(levels.reach(spreadHeld_));
    std::vector<double> share, depth;
    levels.prolongOnto(spreadHeld_, spreadRegion_, share, depth);
    forEachRegionNode
    (
        [&](const std::size_t at, const std::size_t node)
        {
            if (share[at] > 0)
            {
                limit_.addSpread(node, share[at], depth[at]);
            }
        }
    );
}


template<class F>
void Foam::dropletFiber::gridBlocks::forEachRegionNode(F&& f) const
{
    const ::dropletFiber::IndexBox& r = spreadRegion_;
    if (r.empty())
    {
        return;
    }
    std::size_t at = 0;
    for (int k = r.lo[2]; k <= r.hi[2]; ++k)
    {
        for (int j = r.lo[1]; j <= r.hi[1]; ++j)
        {
            for (int i = r.lo[0]; i <= r.hi[0]; ++i, ++at)
            {
                f(at, spec_.flatIndex(i, j, k));
            }
        }
    }
}


::dropletFiber::LevelTable Foam::dropletFiber::gridBlocks::restrictOverBlocks
(
    const ::dropletFiber::LevelTable& asked,
    const bool unremoved,
    parallelStatistics& statistics
)
{
    const ::dropletFiber::SpreadPopulations& levels = *spreadLevels_;
    // This block's part at the level nodes it holds, a zero term at the
    // keys asked: the sums come back to both
    std::vector<double> values;
    limit_.grantedSupplies(spreadRegion_, unremoved, values);
    ::dropletFiber::LevelTerms terms(1);
    terms.add(levels.restrictFrom(spreadHeld_, spreadRegion_, values));
    for (const ::dropletFiber::LevelKey key : asked.keys)
    {
        terms.add(key, 0.0);
    }
    return sumLevelTable(levels, terms.summed(), false, statistics);
}


void Foam::dropletFiber::gridBlocks::realiseSpread
(
    const spreadStep& spread,
    ::dropletFiber::RealisedCapture& realised,
    parallelStatistics& statistics
)
{
    // Per node s_n g_n P_n granted and s_n g_n (prolonged r_s terms)
    // realised: the populations' part of q_n (P31)
    const ::dropletFiber::SpreadPopulations& levels = *spread.populations;
    const ::dropletFiber::LevelTable ratios =
        sumLevelTable(levels, spread.realised, true, statistics);
    std::vector<double> granted, hits, none, supply;
    levels.prolongOnto(spreadHeld_, spreadRegion_, granted, none);
    levels.prolongOnto(ratios, spreadRegion_, hits, none);
    limit_.grantedSupplies(spreadRegion_, false, supply);
    forEachRegionNode
    (
        [&](const std::size_t at, const std::size_t node)
        {
            if (supply[at] > 0 && granted[at] > 0)
            {
                realised.addNode(node, supply[at]*granted[at], supply[at]*hits[at]);
            }
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

::dropletFiber::LevelTable Foam::dropletFiber::gridBlocks::sumLevelTable
(
    const ::dropletFiber::SpreadPopulations& levels,
    const ::dropletFiber::LevelTable& local,
    const bool toBlocks,
    parallelStatistics& statistics
)
{
    const auto owner = [&](const ::dropletFiber::LevelKey key)
    {
        return levelOwner(levels, key);
    };
    levelReceivers blocks;
    if (toBlocks)
    {
        blocks = [&](const ::dropletFiber::LevelKey key, std::vector<int>& to)
        {
            levelBlocks(levels, key, to);
        };
    }
    return sumOverProcessors
    (
        local, owner, blocks, statistics,
        parallelStatistics::traffic::gridQueries
    );
}


// ************************************************************************* //
