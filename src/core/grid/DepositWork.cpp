#include "grid/DepositWork.hpp"

namespace dropletFiber
{

DepositWork::DepositWork(const std::array<int, 3>& gridNodes, int maxTilesPerDirection)
    : touched_(gridNodes, maxTilesPerDirection)
{
}

void DepositWork::addParcel(const IndexBox& depositBox, double work)
{
    const IndexBox all = touched_.nodesOf(wholeBox(tiles()));
    const IndexBox nodes = depositBox.intersected(all);
    if (nodes.empty())
    {
        return;
    }
    const std::array<int, 3>& size = touched_.tileNodes();
    IndexBox tileBox;
    for (int d = 0; d < 3; ++d)
    {
        tileBox.lo[d] = nodes.lo[d] / size[d];
        tileBox.hi[d] = nodes.hi[d] / size[d];
    }
    addGroup(tileBox, work);
}

void DepositWork::addGroup(const IndexBox& tiles, double work)
{
    groups_[{{tiles.lo[0], tiles.lo[1], tiles.lo[2], tiles.hi[0], tiles.hi[1], tiles.hi[2]}}] += work;
}

namespace
{

IndexBox tilesOfKey(const std::array<int, 6>& key)
{
    return IndexBox{{{key[0], key[1], key[2]}}, {{key[3], key[4], key[5]}}};
}

} // namespace

std::vector<DepositWork::ParcelGroup> DepositWork::groups() const
{
    std::vector<ParcelGroup> out;
    out.reserve(groups_.size());
    for (const auto& [key, work] : groups_)
    {
        out.push_back(ParcelGroup{tilesOfKey(key), work});
    }
    return out;
}

double DepositWork::workOf(const IndexBox& block) const
{
    double work = block.empty() ? 0.0 : touched_.workIn(block);
    for (const auto& [key, w] : groups_)
    {
        if (!touched_.nodesOf(tilesOfKey(key)).intersected(block).empty())
        {
            work += w;
        }
    }
    return work;
}

double DepositWork::total() const
{
    double work = touched_.total();
    for (const auto& entry : groups_)
    {
        work += entry.second;
    }
    return work;
}

} // namespace dropletFiber
