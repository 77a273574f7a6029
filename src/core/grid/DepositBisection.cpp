// GridPartition::depositBisection: grid blocks of whole tiles sized by the steady deposit's
// work (DepositWork): a side of a cut does the work of every group whose tiles meet it, in
// full, plus its touched nodes' work.
#include "grid/DepositWork.hpp"
#include "grid/GridPartition.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{

using Groups = std::vector<DepositWork::ParcelGroup>;

// The processors of a part, first to first + parts - 1.
struct Processors
{
    int first = 0;
    int parts = 1;
};

struct Cut
{
    int direction = -1;
    int layers = 0;     // tile layers of the box below the cut
    double score = 0.0; // max(lower / lowerParts, upper / upperParts)
    // max over the sides of nodes / (parts x maxNodesPerPart): a cut within the cap <= 1
    double overCap = 0.0;
    // Within the cap before over it; then the lower score (or the lower excess).
    bool betterThan(const Cut& other) const
    {
        if (direction < 0 || other.direction < 0)
        {
            return direction >= 0;
        }
        const bool within = overCap <= 1.0;
        if (within != (other.overCap <= 1.0))
        {
            return within;
        }
        return within ? score < other.score : overCap < other.overCap;
    }
};

// The node count of each tile layer of tileBox along d.
std::vector<double> layerNodes(const TileWork& touched, const IndexBox& tileBox, int d)
{
    const std::array<int, 3> n = tileBox.extents();
    std::vector<double> nodes(static_cast<std::size_t>(n[d]), 0.0);
    for (int t = 0; t < n[d]; ++t)
    {
        IndexBox layer = tileBox;
        layer.lo[d] = tileBox.lo[d] + t;
        layer.hi[d] = tileBox.lo[d] + t;
        nodes[static_cast<std::size_t>(t)] = static_cast<double>(touched.nodesOf(layer).nodeCount());
    }
    return nodes;
}

// The touched nodes' work of each tile layer of tileBox along d; the layers' node counts
// where the box holds no work at all (then the cut evens the nodes).
std::vector<double> touchedLayers(const TileWork& touched, const IndexBox& tileBox, int d, bool noGroups)
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
                const double w = touched.work()[flatNodeIndex(touched.tiles(), i, j, k)];
                layers[layer] += w;
                sum += w;
                nodes[layer] += static_cast<double>(touched.nodesOf(IndexBox{at, at}).nodeCount());
            }
        }
    }
    return sum > 0.0 || !noGroups ? layers : nodes;
}

// The best cut of tileBox along d (direction -1: no cut leaves a tile to each processor).
// lower(c) = the groups starting below layer c plus the touched layers below; upper(c)
// likewise: prefix sums.
Cut bestCutAlong(const Groups& groups, const TileWork& touched, const IndexBox& tileBox, int d,
                 const Processors& part, double maxNodesPerPart)
{
    const int lowerParts = part.parts / 2;
    const Processors lowerSide{part.first, lowerParts};
    const Processors upperSide{part.first + lowerParts, part.parts - lowerParts};
    const std::array<int, 3> n = tileBox.extents();
    const long others = static_cast<long>(tileBox.nodeCount()) / n[d];
    const long first = (lowerSide.parts + others - 1) / others;
    const long last = n[d] - (upperSide.parts + others - 1) / others;
    Cut best;
    if (first < 1 || first > last)
    {
        return best;
    }
    const std::vector<double> layers = touchedLayers(touched, tileBox, d, groups.empty());
    std::vector<double> startsIn(layers);
    std::vector<double> endsIn(layers);
    for (const DepositWork::ParcelGroup& g : groups)
    {
        startsIn[static_cast<std::size_t>(g.tiles.lo[d] - tileBox.lo[d])] += g.work;
        endsIn[static_cast<std::size_t>(g.tiles.hi[d] - tileBox.lo[d])] += g.work;
    }
    double upper = 0.0;
    for (const double w : endsIn)
    {
        upper += w;
    }
    double lower = 0.0;
    const std::vector<double> nodes = layerNodes(touched, tileBox, d);
    const double boxNodes = static_cast<double>(touched.nodesOf(tileBox).nodeCount());
    double lowerNodes = 0.0;
    for (long c = 1; c <= last; ++c)
    {
        lower += startsIn[static_cast<std::size_t>(c - 1)];
        upper -= endsIn[static_cast<std::size_t>(c - 1)];
        lowerNodes += nodes[static_cast<std::size_t>(c - 1)];
        const double score = std::max(lower / lowerSide.parts, upper / upperSide.parts);
        const double overCap
            = std::max(lowerNodes / lowerSide.parts, (boxNodes - lowerNodes) / upperSide.parts)
            / maxNodesPerPart;
        const Cut cut{d, static_cast<int>(c), score, overCap};
        if (c >= first && cut.betterThan(best))
        {
            best = cut;
        }
    }
    return best;
}

// The groups meeting a side of the cut, clipped to it.
Groups side(const Groups& groups, int d, int from, int to)
{
    Groups out;
    for (DepositWork::ParcelGroup g : groups)
    {
        if (g.tiles.hi[d] >= from && g.tiles.lo[d] <= to)
        {
            g.tiles.lo[d] = std::max(g.tiles.lo[d], from);
            g.tiles.hi[d] = std::min(g.tiles.hi[d], to);
            out.push_back(g);
        }
    }
    return out;
}

void bisectByDeposit(const Groups& groups, const TileWork& touched, const IndexBox& tileBox,
                     const Processors& part, double maxNodesPerPart, std::vector<IndexBox>& boxes)
{
    if (part.parts == 1)
    {
        boxes[static_cast<std::size_t>(part.first)] = touched.nodesOf(tileBox);
        return;
    }
    const std::array<int, 3> n = tileBox.extents();
    std::array<int, 3> order{{0, 1, 2}};
    std::stable_sort(order.begin(), order.end(), [&n](int a, int b) { return n[a] > n[b]; });
    Cut best;
    for (const int d : order)
    {
        const Cut cut = bestCutAlong(groups, touched, tileBox, d, part, maxNodesPerPart);
        if (cut.betterThan(best))
        {
            best = cut;
        }
    }
    if (best.direction < 0)
    {
        throw std::invalid_argument("GridPartition::depositBisection: no cut of " + boxText(tileBox)
                                    + " (tiles) leaves a tile to each of " + std::to_string(part.parts)
                                    + " parts");
    }
    const int d = best.direction;
    const int cutAt = tileBox.lo[d] + best.layers;
    IndexBox lower = tileBox;
    IndexBox upper = tileBox;
    lower.hi[d] = cutAt - 1;
    upper.lo[d] = cutAt;
    const int lowerParts = part.parts / 2;
    bisectByDeposit(side(groups, d, tileBox.lo[d], cutAt - 1), touched, lower,
                    Processors{part.first, lowerParts}, maxNodesPerPart, boxes);
    bisectByDeposit(side(groups, d, cutAt, tileBox.hi[d]), touched, upper,
                    Processors{part.first + lowerParts, part.parts - lowerParts}, maxNodesPerPart, boxes);
}

} // namespace

GridPartition GridPartition::depositBisection(const DepositWork& work, int parts, double maxNodesPerPart)
{
    if (!(maxNodesPerPart > 0.0))
    {
        throw std::invalid_argument("GridPartition::depositBisection: maxNodesPerPart must be positive, not "
                                    + std::to_string(maxNodesPerPart));
    }
    const TileWork& touched = work.touched();
    if (parts < 1 || static_cast<std::size_t>(parts) > touched.tileCount())
    {
        throw std::invalid_argument("GridPartition::depositBisection: parts must be 1 to the "
                                    + std::to_string(touched.tileCount()) + " tiles, not "
                                    + std::to_string(parts));
    }
    std::vector<IndexBox> boxes(static_cast<std::size_t>(parts));
    bisectByDeposit(work.groups(), touched, wholeBox(touched.tiles()), Processors{0, parts}, maxNodesPerPart,
                    boxes);
    return GridPartition(std::move(boxes));
}

} // namespace dropletFiber
