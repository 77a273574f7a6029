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
    const ::dropletFiber::SpreadLevel& level =
        levels.level(::dropletFiber::levelOfKey(key));
    const int r = level.ratio();
    const std::array<int, 3> c =
        ::dropletFiber::nodeIndicesOfFlat
        (
            level.spec().nodes, ::dropletFiber::nodeOfKey(key)
        );
    ::dropletFiber::IndexBox hat;
    for (int d = 0; d < 3; ++d)
    {
        hat.lo[d] = spec_.flat(d) ? 0 : std::max(0, r*(c[d] - 1) + 1);
        hat.hi[d] =
            spec_.flat(d) ? 0 : std::min(spec_.nodes[d] - 1, r*(c[d] + 1) - 1);
    }
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
    const auto owned = [&](const std::size_t n) { return grid.owns(n); };
    for (const auto& node : levels.prolong(spreadHeld_, owned))
    {
        limit_.addSpread(node.node, node.share, node.depth);
    }
}


::dropletFiber::LevelTable Foam::dropletFiber::gridBlocks::restrictOverBlocks
(
    const ::dropletFiber::LevelTable& asked,
    const std::function<double(std::size_t)>& value,
    parallelStatistics& statistics
)
{
    const ::dropletFiber::SpreadPopulations& levels = *spreadLevels_;
    const auto owned = [&](const std::size_t n) { return ownerOf(n) == Pstream::myProcNo(); };
    // This block's part at the level nodes it holds, a zero term at the
    // keys asked: the sums come back to both
    ::dropletFiber::LevelTerms terms(1);
    terms.add(levels.restrictToLevels(spreadHeld_, owned, value));
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
    const auto owned = [&](const std::size_t n) { return ownerOf(n) == Pstream::myProcNo(); };
    const auto granted = levels.prolong(spreadHeld_, owned);
    const auto hits = levels.prolong(ratios, owned);
    std::size_t h = 0;
    for (const auto& node : granted)
    {
        while (h < hits.size() && hits[h].node < node.node)
        {
            ++h;
        }
        const double supply = limit_.grantedSupply(node.node);
        const double r =
            h < hits.size() && hits[h].node == node.node ? hits[h].share : 0;
        if (supply > 0)
        {
            realised.addNode(node.node, supply*node.share, supply*r);
        }
    }
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
