// GridPartition: which processor owns which nodes of the density grid (docs/model.md
// sec. 4, grid blocks). P disjoint boxes of node indices that tile the grid; every
// processor knows all of them, so the owner of a node is a look-up.
//
// From the mesh decomposition (fromSubdomainBounds): processor p's subdomain bounding box
// [min, max] gives, per active direction, the index range
//     [ceil((min - lower) / h), ceil((max - lower) / h) - 1],
// half-open in space, so a node on a plane shared by two subdomains belongs to exactly
// one of them (both compute the same ceil from the same coordinate); a box reaching the
// grid's lower face starts at 0, one reaching its upper face ends at the last node.
// Decompositions by cell count (simple, hierarchical) share the layer of cells at a cut
// between the subdomains on either side, so their bounding boxes overlap by a cell: each
// subdomain's upper bound is first moved down to the nearest lower bound of another
// subdomain inside its span (the cut). Flat
// directions: the single node layer belongs to every box that covers the slab. Simple
// and hierarchical decompositions (and manual ones that happen to be boxes) tile the grid
// that way and each processor owns the nodes around its own cells, where its parcels and
// fibers are. When the boxes do not tile the grid (irregular manual decompositions, a
// grid larger than the mesh, subdomains that are not boxes: tiles() says so), bisection()
// splits the grid instead: recursively along the longest index direction, the parts'
// node counts in proportion to their processor counts (deterministic; correct, only the
// blocks then match the processors' parcels less well: more traffic).
//
// depositBisection(): blocks sized by the steady deposit's work (docs/scaleOut.md, balanced
// blocks; DepositWork, DepositBisection.cpp): the same recursion on a lattice of tiles
// (TileWork), the lower part's processors first, each cut (any direction, any tile layer
// leaving a tile per processor) minimising max(lower / lowerParts, upper / upperParts),
// where a side's work is every parcel group whose tiles meet it, in full (a parcel is
// evaluated by each block its box reaches), plus its touched nodes' work. Bound: with L
// the largest work of the groups meeting one tile layer plus that layer's touched work (any
// direction, whole grid), some cut leaves each side within 2 L of its share, so every
// part's work lies within W / P + 4.5 L, W = DepositWork::total() (4.5: the sum over the
// levels of 2 L over the side's processors, 1, 2, 3, 5, 9, ...), while the tiles per part
// do not constrain the cuts. Deterministic: the same groups in the same order give the
// same boxes.
//
// holdersOf(): the processors whose owned nodes a box of nodes meets (the blocks a
// parcel's deposit reaches, DensityGrid::depositBox).
#pragma once

#include "grid/GridSpec.hpp"

#include <array>
#include <limits>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

class DepositWork;

// A subdomain's bounding box: min x y z, max x y z.
using SubdomainBounds = std::array<double, 6>;

class GridPartition
{
public:
    GridPartition() = default;
    explicit GridPartition(std::vector<IndexBox> boxes) : boxes_(std::move(boxes)) {}

    // The boxes of the subdomain bounds (one per processor), as above; check tiles().
    static GridPartition fromSubdomainBounds(const GridSpec& spec,
                                             const std::vector<SubdomainBounds>& bounds);
    // Recursive bisection of the grid into `parts` boxes (parts >= 1).
    static GridPartition bisection(const GridSpec& spec, int parts);
    // Recursive bisection by the steady deposit's work (above); parts >= 1 and at most the
    // number of tiles (std::invalid_argument otherwise). maxNodesPerPart: a cut must leave
    // each side at most this many nodes per processor of it, so that a block's memory stays
    // near 1/P where the spray is in a corner; where no cut of a box allows it (tile layers
    // too coarse), the cut that exceeds it least.
    static GridPartition depositBisection(const DepositWork& work, int parts,
                                          double maxNodesPerPart = std::numeric_limits<double>::infinity());

    // True when the boxes are pairwise disjoint, inside the grid, and hold every node.
    bool tiles(const GridSpec& spec) const;
    int processors() const { return static_cast<int>(boxes_.size()); }
    const IndexBox& owned(int processor) const { return boxes_[static_cast<std::size_t>(processor)]; }
    const std::vector<IndexBox>& boxes() const { return boxes_; }
    // The processor owning node (i, j, k); -1 when none does (not for a tiling partition).
    int owner(int i, int j, int k) const;
    // The processors other than `except` whose owned nodes meet the box, in processor
    // order (into holders, cleared first: the caller reuses it for every parcel).
    void holdersOf(const IndexBox& box, int except, std::vector<int>& holders) const;

private:
    std::vector<IndexBox> boxes_;
    mutable std::size_t lastOwner_ = 0; // owner(): neighbouring look-ups hit the same box
};

} // namespace dropletFiber
