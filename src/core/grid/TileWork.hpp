// TileWork: a work field over the grid on a coarse lattice of tiles: the touched nodes'
// term of DepositWork, and the tiles GridPartition::depositBisection cuts along (grid blocks
// sized by deposit work, docs/scaleOut.md). The grid's nodes are grouped in tiles of
// tileNodes[d] nodes per direction (the last tile of a direction may hold fewer); work[t]
// is the work of tile t (flat index over the tiles, i fastest). Coarse so that every
// processor can hold the whole field (at most maxTilesPerDirection per direction); work is
// taken as even over a tile's nodes where a box cuts a tile (workIn).
#pragma once

#include "grid/GridSpec.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

class TileWork
{
public:
    // Tiles over the grid's nodes, at most maxTilesPerDirection per direction (>= 1), all
    // work zero.
    TileWork(const std::array<int, 3>& gridNodes, int maxTilesPerDirection);

    const std::array<int, 3>& tiles() const { return tiles_; }
    const std::array<int, 3>& tileNodes() const { return tileNodes_; }
    std::size_t tileCount() const { return work_.size(); }
    std::vector<double>& work() { return work_; }
    const std::vector<double>& work() const { return work_; }
    // The grid nodes of the tiles in tileBox (tile indices).
    IndexBox nodesOf(const IndexBox& tileBox) const;
    // Adds perNode for every node of the box (grid indices, clipped to the grid) to the
    // tiles holding them.
    void addBox(const IndexBox& nodes, double perNode);
    // The work of the nodes of a box (grid indices), each tile's work spread evenly over
    // its nodes.
    double workIn(const IndexBox& nodes) const;
    double total() const;

private:
    std::array<int, 3> gridNodes_;
    std::array<int, 3> tileNodes_;
    std::array<int, 3> tiles_;
    std::vector<double> work_;
};

} // namespace dropletFiber
