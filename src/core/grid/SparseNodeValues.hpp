// SparseNodeValues: a value at a few nodes of the grid, 0 at all others (depletion's taken
// fractions f_n, docs/model.md sec. 7), held in node order with their grid indices, so that
// a sum over a parcel's weights times the values (DensityGrid::depositedShare) visits these
// nodes only, in the order a loop over every node would add them.
// Memory: 40 bytes per node held.
#pragma once

#include "grid/GridSpec.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

struct NodeValue
{
    std::size_t node = 0;       // global flat node index
    std::array<int, 3> index{}; // its grid indices (set by SparseNodeValues::assign)
    double value = 0.0;
};

class SparseNodeValues
{
public:
    // The nodes in increasing node order, one entry per node (assign() sorts).
    const std::vector<NodeValue>& nodes() const { return nodes_; }
    // The box of the nodes held (empty when none).
    const IndexBox& box() const { return box_; }
    bool empty() const { return nodes_.empty(); }

    // Replaces the nodes (node and value given; the indices are set from the node, in a
    // grid of gridNodes nodes per direction): sorted by node, the last entry of a node kept.
    void assign(std::vector<NodeValue> nodes, const std::array<int, 3>& gridNodes);
    // The value at a node (0 where none is held): a binary search.
    double at(std::size_t node) const;
    // The node's place in nodes() (nodes().size() where none is held): a binary search.
    std::size_t position(std::size_t node) const;
    // The held nodes inside the box (grid indices, within the grid of `gridNodes` nodes per
    // direction), in node order: per layer k of the box, the range between its first and last
    // node, filtered.
    template <class F>
    void forEachIn(const IndexBox& box, const std::array<int, 3>& gridNodes, F&& f) const
    {
        const IndexBox asked = box.intersected(box_);
        if (asked.empty())
        {
            return;
        }
        auto n = nodes_.begin();
        for (int k = asked.lo[2]; k <= asked.hi[2]; ++k)
        {
            const std::size_t first = flatNodeIndex(gridNodes, asked.lo[0], asked.lo[1], k);
            const std::size_t last = flatNodeIndex(gridNodes, asked.hi[0], asked.hi[1], k);
            for (n = lowerBound(n, first); n != nodes_.end() && n->node <= last; ++n)
            {
                if (asked.holds(n->index[0], n->index[1], n->index[2]))
                {
                    f(*n);
                }
            }
        }
    }

private:
    // The first node >= node, from `from` on.
    std::vector<NodeValue>::const_iterator lowerBound(std::vector<NodeValue>::const_iterator from,
                                                      std::size_t node) const;

    std::vector<NodeValue> nodes_;
    IndexBox box_;
};

} // namespace dropletFiber
