#include "grid/DepositWork.hpp"

namespace dropletFiber
{

DepositWork::DepositWork(const std::array<int, 3>& gridNodes, int maxTilesPerDirection)
    : touched_(gridNodes, maxTilesPerDirection)
{
}

void DepositWork::addParcel(const IndexBox& depositBox, int holder, double work)
{
    const std::array<int, 3>& t = tiles();
    const IndexBox all = touched_.nodesOf(IndexBox{{{0, 0, 0}}, {{t[0] - 1, t[1] - 1, t[2] - 1}}});
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
    addGroup(tileBox, holder, work);
}

void DepositWork::addGroup(const IndexBox& tiles, int holder, double work)
{
    groups_[{{holder, tiles.lo[0], tiles.lo[1], tiles.lo[2], tiles.hi[0], tiles.hi[1], tiles.hi[2]}}] += work;
}

namespace
{

IndexBox tilesOfKey(const std::array<int, 7>& key)
{
    return IndexBox{{{key[1], key[2], key[3]}}, {{key[4], key[5], key[6]}}};
}

} // namespace

std::vector<DepositWork::ParcelGroup> DepositWork::groups() const
{
    std::vector<ParcelGroup> out;
    out.reserve(groups_.size());
    for (const auto& [key, work] : groups_)
    {
        out.push_back(ParcelGroup{tilesOfKey(key), key[0], work});
    }
    return out;
}

double DepositWork::workOf(const IndexBox& block, int processor) const
{
    double work = block.empty() ? 0.0 : touched_.workIn(block);
    for (const auto& [key, w] : groups_)
    {
        if (key[0] == processor || !touched_.nodesOf(tilesOfKey(key)).intersected(block).empty())
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
