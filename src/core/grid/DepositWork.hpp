// DepositWork: the steady deposit's work over the grid, the input of
// GridPartition::depositBisection (grid blocks sized by the deposit's work, docs/scaleOut.md).
//
// Two terms, on the tile lattice of a TileWork:
// - Parcels: a parcel is evaluated in full (its kernel is normalised over its whole deposit
//   box, DensityGrid::depositBox, eq. 24) by every block its box meets (depositCopy(), and
//   deposit() on its holder where the box meets the holder's block: StepDeposit::wants).
//   Its work (the node weights of its box times the cost of one) is charged in full to
//   every block its box meets; its holder pays nothing beyond that (it skips the parcels
//   whose box misses its block). Parcels are grouped by the tiles their box meets, the
//   work of a group summed: blocks made of whole tiles meet a group exactly when they meet
//   each of its parcels' boxes, so the grouping loses nothing for them, and the list is
//   bounded by the distinct tile boxes, not by the parcels.
// - Touched nodes: the window update of the nodes the steps touch, a cost per node,
//   spread evenly over the nodes of a box (TileWork::addBox).
// Every processor adds its parcels; the groups are gathered (addGroup: the function object
// sends seven numbers each, the tile box and the work) and summed in the same order on
// every processor, so that all make the same partition.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/TileWork.hpp"

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace dropletFiber
{

class DepositWork
{
public:
    // Parcels whose deposit boxes meet the same tiles, their summed work.
    struct ParcelGroup
    {
        IndexBox tiles;
        double work = 0.0;
    };

    // Tiles over the grid's nodes, at most maxTilesPerDirection per direction (TileWork).
    DepositWork(const std::array<int, 3>& gridNodes, int maxTilesPerDirection);

    // A parcel's deposit box (grid node indices, clipped to the grid; empty: nothing) and
    // its work.
    void addParcel(const IndexBox& depositBox, double work);
    // A group of another processor (tile indices), its work added to that of the same tiles.
    void addGroup(const IndexBox& tiles, double work);
    // perNode for every node of the box (grid indices), the window update of touched nodes.
    void addTouched(const IndexBox& nodes, double perNode) { touched_.addBox(nodes, perNode); }

    // The groups in the order of their tile boxes (the same on every processor).
    std::vector<ParcelGroup> groups() const;
    std::size_t groupCount() const { return groups_.size(); }
    const TileWork& touched() const { return touched_; }
    TileWork& touched() { return touched_; }
    const std::array<int, 3>& tiles() const { return touched_.tiles(); }

    // The work of a block (grid node indices): every group whose tiles' nodes meet the
    // block, in full, plus its touched nodes' work. Exact for blocks of whole tiles; for
    // others a group counts when any tile of it meets the block.
    double workOf(const IndexBox& block) const;
    // The parcels' work counted once, plus the touched nodes' (the serial deposit).
    double total() const;

private:
    std::map<std::array<int, 6>, double> groups_; // tiles' lo, hi
    TileWork touched_;
};

} // namespace dropletFiber
