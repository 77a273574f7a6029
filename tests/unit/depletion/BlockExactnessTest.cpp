// Serial = parallel to the bit for the function object's own sums (docs/model.md sec. 4,
// exact sums): the same parcels deposited on the whole grid (in any cloud order) and on
// grid blocks (each block its own parcels and the copies of the others', DepositOrder)
// give every node the same bits; depletion over the blocks (demand parts arriving in
// another order, A_p and X_p as exact parts added up in any block order, the removal's
// terms from own parcels and copies) gives every parcel the same c_p and c'_p and every
// node the same grant. Each check compares with ==, and a control shows that the plain
// orders (own parcels first, then copies; parts added as doubles) do differ.
#include "depletion/CaptureLimit.hpp"
#include "depletion/FixedPointSum.hpp"
#include "grid/DepositOrder.hpp"
#include "grid/GridPartition.hpp"

#include "../grid/TestGrids.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>

using namespace dropletFiber;

namespace
{

constexpr double dt = 1e-3;

struct Blocks
{
    std::vector<std::unique_ptr<DensityGrid>> grids;
    std::vector<std::vector<Parcel>> own; // the parcels each block's processor holds
};

// Each parcel held by a random block; every block deposits its own and the others' that
// reach it, in key order (keyOrder) or own first, then copies (the plain order)
Blocks depositOnBlocks(const GridSpec& spec, const GridPartition& partition,
                       const std::vector<Parcel>& parcels, bool keyOrder, unsigned seed)
{
    Blocks blocks;
    const auto count = static_cast<std::size_t>(partition.processors());
    blocks.own.resize(count);
    std::mt19937_64 random(seed);
    std::uniform_int_distribution<std::size_t> anyBlock(0, count - 1);
    for (const Parcel& parcel : parcels)
    {
        blocks.own[anyBlock(random)].push_back(parcel);
    }
    for (std::size_t b = 0; b < count; ++b)
    {
        const GridBlock block{partition.owned(static_cast<int>(b)), spec.fullBox()};
        blocks.grids.push_back(std::make_unique<DensityGrid>(spec, KernelSettings{}, 1, block));
        std::vector<Parcel> copies;
        for (std::size_t other = 0; other < count; ++other)
        {
            for (const Parcel& parcel : blocks.own[other])
            {
                const IndexBox reached = blocks.grids[b]->depositBox(parcel, dt);
                if (other != b && !reached.intersected(block.owned).empty())
                {
                    copies.push_back(parcel);
                }
            }
        }
        std::vector<DepositEntry> order = depositOrder(blocks.own[b], copies);
        if (!keyOrder)
        {
            std::stable_sort(order.begin(), order.end(),
                             [](const DepositEntry& x, const DepositEntry& y) { return !x.copy && y.copy; });
        }
        for (const DepositEntry& entry : order)
        {
            entry.copy ? blocks.grids[b]->depositCopy(copies[entry.index], dt)
                       : blocks.grids[b]->deposit(blocks.own[b][entry.index], dt);
        }
        blocks.grids[b]->commitStep();
    }
    return blocks;
}

// Nodes of the blocks whose step values differ from the whole grid's in any bit
int differingNodes(const GridSpec& spec, const DensityGrid& whole, const Blocks& blocks)
{
    int differing = 0;
    for (std::size_t node = 0; node < spec.nodeCount(); ++node)
    {
        for (const auto& grid : blocks.grids)
        {
            if (!grid->owns(node))
            {
                continue;
            }
            for (int q = 0; q < nQuantities; ++q)
            {
                differing += grid->lastStepValue(node, q) != whole.lastStepValue(node, q) ? 1 : 0;
            }
        }
    }
    return differing;
}

DensityGrid& wholeGridInCloudOrder(std::unique_ptr<DensityGrid>& whole, const GridSpec& spec,
                                   std::vector<Parcel> parcels, unsigned seed)
{
    // A serial run meets the parcels in the cloud's order: shuffled, then key order
    std::shuffle(parcels.begin(), parcels.end(), std::mt19937_64(seed));
    whole = std::make_unique<DensityGrid>(spec, KernelSettings{}, 1);
    for (const DepositEntry& entry : depositOrder(parcels, {}))
    {
        whole->deposit(parcels[entry.index], dt);
    }
    whole->commitStep();
    return *whole;
}

} // namespace

TEST(BlockExactness, DepositInKeyOrderGivesTheWholeGridsNodeValues)
{
    for (const GridSpec& spec : {test::grid2D(), test::grid3D()})
    {
        const std::vector<Parcel> parcels = test::randomParcels(spec, 400, 5);
        std::unique_ptr<DensityGrid> holder;
        const DensityGrid& whole = wholeGridInCloudOrder(holder, spec, parcels, 9);
        for (int processors : {2, 3})
        {
            const GridPartition partition = GridPartition::bisection(spec, processors);
            EXPECT_EQ(differingNodes(spec, whole, depositOnBlocks(spec, partition, parcels, true, 17)), 0)
                << processors << " blocks";
            // Control: own parcels first, then the copies, differs in some nodes' last bits
            EXPECT_GT(differingNodes(spec, whole, depositOnBlocks(spec, partition, parcels, false, 17)), 0)
                << processors << " blocks";
        }
    }
}

TEST(BlockExactness, DepletionOverBlocksGivesTheWholeGridsFractionsAndGrants)
{
    const GridSpec spec = test::grid2D();
    const std::vector<Parcel> parcels = test::randomParcels(spec, 300, 8);
    std::unique_ptr<DensityGrid> holder;
    DensityGrid& whole = wholeGridInCloudOrder(holder, spec, parcels, 3);
    const GridPartition partition = GridPartition::bisection(spec, 3);
    Blocks blocks = depositOnBlocks(spec, partition, parcels, true, 21);
    // Demand: several samples' parts per node, the blocks get them in reverse order
    std::mt19937_64 random(2);
    std::uniform_int_distribution<std::size_t> anyNode(0, spec.nodeCount() - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<NodeMass> demand;
    for (int n = 0; n < 600; ++n)
    {
        const std::size_t node = anyNode(random);
        demand.push_back({node, 0.7 * unit(random) * (whole.lastStepValue(node, quantityMass) + 1e-12)});
    }
    CaptureLimit wholeLimit;
    std::vector<CaptureLimit> limits(blocks.grids.size());
    for (const NodeMass& part : demand)
    {
        wholeLimit.addDemand(part.node, part.mass);
    }
    for (auto part = demand.rbegin(); part != demand.rend(); ++part)
    {
        for (std::size_t b = 0; b < limits.size(); ++b)
        {
            if (blocks.grids[b]->owns(part->node))
            {
                limits[b].addDemand(part->node, part->mass);
            }
        }
    }
    CaptureLimitReport wholeReport = wholeLimit.limit(whole);
    ParcelReaches wholeReaches;
    const std::vector<double> wholeFraction
        = wholeLimit.removeFromParcels(whole, parcels, dt, wholeReport, &wholeReaches);
    // Blocks: each parcel's exact parts added in a block order of its own
    std::vector<ParcelReaches> reaches(limits.size());
    for (std::size_t b = 0; b < limits.size(); ++b)
    {
        limits[b].limit(*blocks.grids[b]);
        for (const Parcel& parcel : parcels)
        {
            limits[b].reach(*blocks.grids[b], parcel, dt, reaches[b]);
        }
    }
    int plainDiffers = 0;
    for (std::size_t p = 0; p < parcels.size(); ++p)
    {
        FixedPointSum saturated, depth;
        double plainDepth = 0.0;
        for (std::size_t k = 0; k < limits.size(); ++k)
        {
            const std::size_t b = (p + k) % limits.size();
            saturated.add(reaches[b].parcels[p].saturatedSum);
            depth.add(reaches[b].parcels[p].depthSum);
            plainDepth += reaches[b].parcels[p].depth;
        }
        plainDiffers += plainDepth != depth.value() ? 1 : 0;
        EXPECT_EQ(CaptureLimit::capturedFraction(saturated.value(), depth.value()), wholeFraction[p]) << p;
        for (std::size_t b = 0; b < limits.size(); ++b)
        {
            reaches[b].parcels[p].saturated = saturated.value();
            reaches[b].parcels[p].depth = depth.value();
        }
    }
    EXPECT_GT(plainDiffers, 0); // the parts added as doubles would not do
    // The removal: each block its nodes' terms, parcels in reverse order
    for (std::size_t b = 0; b < limits.size(); ++b)
    {
        for (std::size_t p = parcels.size(); p-- > 0;)
        {
            const ParcelReach& entry = reaches[b].parcels[p];
            limits[b].remove(reaches[b], p, parcelMass(parcels[p]), entry.saturated, entry.depth);
        }
        CaptureLimitReport part;
        limits[b].grant(part);
    }
    int granted = 0;
    for (const NodeMass& part : demand)
    {
        for (std::size_t b = 0; b < limits.size(); ++b)
        {
            if (blocks.grids[b]->owns(part.node))
            {
                EXPECT_EQ(limits[b].grantedRatio(part.node), wholeLimit.grantedRatio(part.node));
                granted += wholeLimit.grantedRatio(part.node) > 0.0 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(granted, 100);
    // Discrete hits' removal with q_n = 1: the exact parts give the whole grid's c'_p
    for (std::size_t p = 0; p < parcels.size(); ++p)
    {
        FixedPointSum fraction;
        for (std::size_t b = limits.size(); b-- > 0;)
        {
            const ParcelReach& entry = reaches[b].parcels[p];
            fraction.add(limits[b].removedFractionSum(reaches[b], p, entry.saturated, entry.depth));
        }
        const ParcelReach& whole = wholeReaches.parcels[p];
        EXPECT_EQ(fraction.value(),
                  wholeLimit.removedFraction(wholeReaches, p, whole.saturated, whole.depth));
    }
}
