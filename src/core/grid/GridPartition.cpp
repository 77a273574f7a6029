#include "grid/GridPartition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
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

// The work of each tile layer of tileBox along d (node counts where the box holds no work:
// the cut then evens the nodes).
std::vector<double> layerWork(const TileWork& work, const IndexBox& tileBox, int d)
{
    const std::array<int, 3> n = tileBox.extents();
    std::vector<double> layers(static_cast<std::size_t>(n[d]), 0.0);
    std::vector<double> nodes(layers.size(), 0.0);
    double sum = 0.0;
    for (int k = tileBox.lo[2]; k <= tileBox.hi[2]; ++k)
    {
        for (int j = tileBox.lo[1]; j <= tileBox.hi[1]; ++j)
        {
            for (int i = tileBox.lo[0]; i <= tileBox.hi[0]; ++i)
            {
                const std::array<int, 3> at{{i, j, k}};
                const auto layer = static_cast<std::size_t>(at[d] - tileBox.lo[d]);
                const double w = work.work()[flatNodeIndex(work.tiles(), i, j, k)];
                layers[layer] += w;
                sum += w;
                nodes[layer] += static_cast<double>(work.nodesOf(IndexBox{at, at}).nodeCount());
            }
        }
    }
    return sum > 0.0 ? layers : nodes;
}

// The tile layers below the cut along d: the lower part's share of the work nearest, each
// part keeping a tile per processor (-1: no such cut along d).
int cutLayers(const TileWork& work, const IndexBox& tileBox, int d, int lowerParts, int parts)
{
    const std::array<int, 3> n = tileBox.extents();
    const long others = static_cast<long>(tileBox.nodeCount()) / n[d];
    const long first = (lowerParts + others - 1) / others;
    const long last = n[d] - (parts - lowerParts + others - 1) / others;
    if (first < 1 || first > last)
    {
        return -1;
    }
    const std::vector<double> layers = layerWork(work, tileBox, d);
    const double total = std::accumulate(layers.begin(), layers.end(), 0.0);
    const double share = total * static_cast<double>(lowerParts) / static_cast<double>(parts);
    double below = std::accumulate(layers.begin(), layers.begin() + first, 0.0);
    long best = first;
    double bestMiss = std::abs(below - share);
    for (long c = first + 1; c <= last; ++c)
    {
        below += layers[static_cast<std::size_t>(c - 1)];
        if (std::abs(below - share) < bestMiss)
        {
            bestMiss = std::abs(below - share);
            best = c;
        }
    }
    return static_cast<int>(best);
}

void bisectWeighted(const TileWork& work, const IndexBox& tileBox, int first, int parts,
                    std::vector<IndexBox>& boxes)
{
    if (parts == 1)
    {
        boxes[static_cast<std::size_t>(first)] = work.nodesOf(tileBox);
        return;
    }
    const std::array<int, 3> n = tileBox.extents();
    std::array<int, 3> order{{0, 1, 2}};
    std::stable_sort(order.begin(), order.end(), [&n](int a, int b) { return n[a] > n[b]; });
    const int lowerParts = parts / 2;
    for (const int d : order)
    {
        const int layers = cutLayers(work, tileBox, d, lowerParts, parts);
        if (layers > 0)
        {
            IndexBox lower = tileBox;
            IndexBox upper = tileBox;
            lower.hi[d] = tileBox.lo[d] + layers - 1;
            upper.lo[d] = tileBox.lo[d] + layers;
            bisectWeighted(work, lower, first, lowerParts, boxes);
            bisectWeighted(work, upper, first + lowerParts, parts - lowerParts, boxes);
            return;
        }
    }
    throw std::invalid_argument("GridPartition::weightedBisection: no cut of " + boxText(tileBox)
                                + " (tiles) leaves a tile to each of " + std::to_string(parts) + " parts");
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

GridPartition GridPartition::weightedBisection(const TileWork& work, int parts)
{
    if (parts < 1 || static_cast<std::size_t>(parts) > work.tileCount())
    {
        throw std::invalid_argument("GridPartition::weightedBisection: parts must be 1 to the "
                                    + std::to_string(work.tileCount()) + " tiles, not "
                                    + std::to_string(parts));
    }
    std::vector<IndexBox> boxes(static_cast<std::size_t>(parts));
    const std::array<int, 3>& t = work.tiles();
    bisectWeighted(work, IndexBox{{{0, 0, 0}}, {{t[0] - 1, t[1] - 1, t[2] - 1}}}, 0, parts, boxes);
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
