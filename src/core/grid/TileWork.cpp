#include "grid/TileWork.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace dropletFiber
{

namespace
{

// The tiles a box of nodes meets (tile indices), given the nodes per tile.
IndexBox tilesMet(const IndexBox& nodes, const std::array<int, 3>& tileNodes)
{
    IndexBox tiles;
    for (int d = 0; d < 3; ++d)
    {
        tiles.lo[d] = nodes.lo[d] / tileNodes[d];
        tiles.hi[d] = nodes.hi[d] / tileNodes[d];
    }
    return tiles;
}

} // namespace

TileWork::TileWork(const std::array<int, 3>& gridNodes, int maxTilesPerDirection) : gridNodes_(gridNodes)
{
    if (maxTilesPerDirection < 1)
    {
        throw std::invalid_argument("TileWork: maxTilesPerDirection must be at least 1");
    }
    std::size_t count = 1;
    for (int d = 0; d < 3; ++d)
    {
        if (gridNodes[d] < 1)
        {
            throw std::invalid_argument("TileWork: the grid needs at least one node per direction");
        }
        tileNodes_[d] = (gridNodes[d] + maxTilesPerDirection - 1) / maxTilesPerDirection;
        tiles_[d] = (gridNodes[d] + tileNodes_[d] - 1) / tileNodes_[d];
        count *= static_cast<std::size_t>(tiles_[d]);
    }
    work_.assign(count, 0.0);
}

IndexBox TileWork::nodesOf(const IndexBox& tileBox) const
{
    if (tileBox.empty())
    {
        return IndexBox{};
    }
    IndexBox nodes;
    for (int d = 0; d < 3; ++d)
    {
        nodes.lo[d] = tileBox.lo[d] * tileNodes_[d];
        nodes.hi[d] = std::min((tileBox.hi[d] + 1) * tileNodes_[d], gridNodes_[d]) - 1;
    }
    return nodes;
}


void TileWork::addBox(const IndexBox& box, double perNode)
{
    const IndexBox nodes = box.intersected(wholeBox(gridNodes_));
    if (nodes.empty())
    {
        return;
    }
    const IndexBox tiles = tilesMet(nodes, tileNodes_);
    for (int k = tiles.lo[2]; k <= tiles.hi[2]; ++k)
    {
        for (int j = tiles.lo[1]; j <= tiles.hi[1]; ++j)
        {
            for (int i = tiles.lo[0]; i <= tiles.hi[0]; ++i)
            {
                const IndexBox tile = nodesOf(IndexBox{{{i, j, k}}, {{i, j, k}}});
                work_[flatNodeIndex(tiles_, i, j, k)]
                    += perNode * static_cast<double>(tile.intersected(nodes).nodeCount());
            }
        }
    }
}

double TileWork::workIn(const IndexBox& box) const
{
    const IndexBox nodes = box.intersected(wholeBox(gridNodes_));
    if (nodes.empty())
    {
        return 0.0;
    }
    const IndexBox tiles = tilesMet(nodes, tileNodes_);
    double sum = 0.0;
    for (int k = tiles.lo[2]; k <= tiles.hi[2]; ++k)
    {
        for (int j = tiles.lo[1]; j <= tiles.hi[1]; ++j)
        {
            for (int i = tiles.lo[0]; i <= tiles.hi[0]; ++i)
            {
                const IndexBox tile = nodesOf(IndexBox{{{i, j, k}}, {{i, j, k}}});
                const double share = static_cast<double>(tile.intersected(nodes).nodeCount())
                    / static_cast<double>(tile.nodeCount());
                sum += work_[flatNodeIndex(tiles_, i, j, k)] * share;
            }
        }
    }
    return sum;
}

double TileWork::total() const
{
    return std::accumulate(work_.begin(), work_.end(), 0.0);
}

} // namespace dropletFiber
