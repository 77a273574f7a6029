// Test helper (not a test file): parcels deposited and committed on the whole grid and on a
// block per part of a partition, as the depletion tests compare them. Storage = the whole
// grid: the exchange is GridBlocksTest's business; here each block gets the whole step (as
// after the exchange) and owns its box.
#pragma once

#include "grid/DensityGrid.hpp"
#include "grid/GridPartition.hpp"

#include <memory>
#include <vector>

namespace dropletFiber
{
namespace test
{

inline std::vector<std::unique_ptr<DensityGrid>>
depositedBlocks(const GridSpec& spec, const GridPartition& partition, const std::vector<Parcel>& parcels,
                double dt, DensityGrid& whole, const KernelSettings& settings = KernelSettings{})
{
    std::vector<std::unique_ptr<DensityGrid>> blocks;
    for (int b = 0; b < partition.processors(); ++b)
    {
        blocks.push_back(
            std::make_unique<DensityGrid>(spec, settings, 1, GridBlock{partition.owned(b), spec.fullBox()}));
    }
    for (const Parcel& parcel : parcels)
    {
        whole.deposit(parcel, dt);
        for (auto& block : blocks)
        {
            block->deposit(parcel, dt);
        }
    }
    whole.commitStep();
    for (auto& block : blocks)
    {
        block->commitStep();
    }
    return blocks;
}

} // namespace test
} // namespace dropletFiber
