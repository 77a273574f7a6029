#include "grid/SparseNodeValues.hpp"

#include <algorithm>

namespace dropletFiber
{

void SparseNodeValues::assign(std::vector<NodeValue> nodes, const std::array<int, 3>& gridNodes)
{
    for (NodeValue& entry : nodes)
    {
        entry.index = nodeIndicesOfFlat(gridNodes, entry.node);
    }
    // Stable: of several entries of a node the last one given is kept (an overwritten value).
    std::stable_sort(nodes.begin(), nodes.end(),
                     [](const NodeValue& x, const NodeValue& y) { return x.node < y.node; });
    nodes_.clear();
    box_ = IndexBox{};
    for (const NodeValue& entry : nodes)
    {
        if (!nodes_.empty() && nodes_.back().node == entry.node)
        {
            nodes_.back() = entry;
            continue;
        }
        nodes_.push_back(entry);
        IndexBox one;
        one.lo = one.hi = entry.index;
        box_ = box_.united(one);
    }
}

double SparseNodeValues::at(std::size_t node) const
{
    const auto entry = lowerBound(nodes_.begin(), node);
    return entry != nodes_.end() && entry->node == node ? entry->value : 0.0;
}

std::size_t SparseNodeValues::position(std::size_t node) const
{
    const auto entry = lowerBound(nodes_.begin(), node);
    return entry != nodes_.end() && entry->node == node ? static_cast<std::size_t>(entry - nodes_.begin())
                                                        : nodes_.size();
}

std::vector<NodeValue>::const_iterator
SparseNodeValues::lowerBound(std::vector<NodeValue>::const_iterator from, std::size_t node) const
{
    return std::lower_bound(from, nodes_.end(), node,
                            [](const NodeValue& entry, std::size_t n) { return entry.node < n; });
}

} // namespace dropletFiber
