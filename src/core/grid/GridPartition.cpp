#include "grid/GridPartition.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <stdexcept>

namespace dropletFiber
{

namespace
{

// The nodes of one direction a subdomain [min, max] owns (half-open in space).
void ownedRange(const GridSpec& spec, int d, double min, double max, int& lo, int& hi)
{
    const int last = spec.nodes[d] - 1;
    if (spec.flat(d))
    {
        const bool covers = max >= spec.lower[d] && min <= spec.upper[d];
        lo = covers ? 0 : 1;
        hi = 0;
        return;
    }
    const double h = spec.spacing(d);
    const double first = std::ceil((min - spec.lower[d]) / h);
    const double end = std::ceil((max - spec.lower[d]) / h) - 1.0;
    lo = first <= 0.0 ? 0 : static_cast<int>(std::min(first, static_cast<double>(last + 1)));
    // The subdomain reaching the grid's upper face takes it (its nodes sit on that face)
    hi = max >= spec.upper[d] ? last
                              : static_cast<int>(std::max(std::min(end, static_cast<double>(last)), -1.0));
}

void bisect(const IndexBox& box, int first, int parts, std::vector<IndexBox>& boxes)
{
    if (parts == 1)
    {
        boxes[static_cast<std::size_t>(first)] = box;
        return;
    }
    const std::array<int, 3> n = box.extents();
    int d = 0;
    for (int e = 1; e < 3; ++e)
    {
        d = n[e] > n[d] ? e : d;
    }
    const int lowerParts = parts / 2;
    // Node layers in proportion to the processors of each part (at least one each when
    // there are enough; a part may stay empty on a grid with fewer layers than parts)
    const int layers = static_cast<int>(std::llround(
        static_cast<double>(n[d]) * static_cast<double>(lowerParts) / static_cast<double>(parts)));
    IndexBox lower = box;
    IndexBox upper = box;
    lower.hi[d] = box.lo[d] + layers - 1;
    upper.lo[d] = box.lo[d] + layers;
    bisect(lower.empty() ? IndexBox{} : lower, first, lowerParts, boxes);
    bisect(upper.empty() ? IndexBox{} : upper, first + lowerParts, parts - lowerParts, boxes);
}

// A simple or hierarchical decomposition splits the cells by count, so the layer of
// cells at a cut is shared out between the subdomains on either side, and their bounding
// boxes overlap by that layer. Each subdomain's upper bound is moved down to the nearest
// lower bound of another subdomain within its span: the cut.
std::vector<SubdomainBounds> snappedToCuts(std::vector<SubdomainBounds> bounds)
{
    const std::vector<SubdomainBounds> original = bounds;
    for (std::size_t p = 0; p < bounds.size(); ++p)
    {
        for (std::size_t d = 0; d < 3; ++d)
        {
            const double min = original[p][d];
            double& max = bounds[p][3 + d];
            double cut = max;
            for (const SubdomainBounds& other : original)
            {
                const double otherMin = other[d];
                if (otherMin > min && otherMin < max && (cut == max || otherMin > cut))
                {
                    cut = otherMin;
                }
            }
            max = cut;
        }
    }
    return bounds;
}

} // namespace

GridPartition GridPartition::fromSubdomainBounds(const GridSpec& spec,
                                                 const std::vector<SubdomainBounds>& given)
{
    const std::vector<SubdomainBounds> bounds = snappedToCuts(given);
    std::vector<IndexBox> boxes(bounds.size());
    for (std::size_t p = 0; p < bounds.size(); ++p)
    {
        IndexBox box;
        for (int d = 0; d < 3; ++d)
        {
            ownedRange(spec, d, bounds[p][static_cast<std::size_t>(d)],
                       bounds[p][static_cast<std::size_t>(3 + d)], box.lo[d], box.hi[d]);
        }
        boxes[p] = box.empty() ? IndexBox{} : box;
    }
    return GridPartition(std::move(boxes));
}

GridPartition GridPartition::bisection(const GridSpec& spec, int parts)
{
    if (parts < 1)
    {
        throw std::invalid_argument("GridPartition::bisection: parts must be at least 1");
    }
    std::vector<IndexBox> boxes(static_cast<std::size_t>(parts));
    bisect(spec.fullBox(), 0, parts, boxes);
    return GridPartition(std::move(boxes));
}

bool GridPartition::tiles(const GridSpec& spec) const
{
    const IndexBox grid = spec.fullBox();
    std::size_t nodes = 0;
    for (std::size_t p = 0; p < boxes_.size(); ++p)
    {
        if (boxes_[p].empty())
        {
            continue;
        }
        if (boxes_[p].intersected(grid) != boxes_[p])
        {
            return false;
        }
        for (std::size_t q = p + 1; q < boxes_.size(); ++q)
        {
            if (!boxes_[p].intersected(boxes_[q]).empty())
            {
                return false;
            }
        }
        nodes += boxes_[p].nodeCount();
    }
    return nodes == spec.nodeCount();
}

int GridPartition::owner(int i, int j, int k) const
{
    // A scan of the P boxes, starting at the last one found (the nodes asked for come in
    // runs: a segment's sample corners, a parcel's overflow)
    const std::size_t n = boxes_.size();
    for (std::size_t s = 0; s < n; ++s)
    {
        const std::size_t p = (lastOwner_ + s) % n;
        if (boxes_[p].holds(i, j, k))
        {
            lastOwner_ = p;
            return static_cast<int>(p);
        }
    }
    return -1;
}

void GridPartition::holdersOf(const IndexBox& box, int except, std::vector<int>& holders) const
{
    holders.clear();
    for (int p = 0; p < processors(); ++p)
    {
        if (p != except && !box.intersected(owned(p)).empty())
        {
            holders.push_back(p);
        }
    }
}

} // namespace dropletFiber
