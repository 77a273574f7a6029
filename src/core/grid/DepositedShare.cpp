#include "grid/DepositedShare.hpp"

namespace dropletFiber
{

void FractionSum::addListed(const NodeOmegas& nodes, double inverseSum, const IndexBox& box)
{
    for (const auto& [node, omega] : nodes)
    {
        add(node, omega * inverseSum);
    }
    statistics().nodesWeighted += static_cast<std::int64_t>(nodes.size());
}

void FractionSum::addSeparable(SeparableWeight& rows, const SeparableTables& tables, double inverseSum,
                               const IndexBox& box)
{
    // The nodes of the (folded) box that may have a fraction, the deposit's weights to the
    // bit (a part of a row is that part of the whole row).
    std::int64_t weighted = 0;
    const IndexBox asked = box.intersected(region_);
    const auto first = static_cast<std::size_t>(asked.lo[0] - box.lo[0]);
    forEachRow(asked, gridNodes_,
               [&](const IndexRow& row)
               {
                   const double* omega = rows.row(row.j - box.lo[1], row.k - box.lo[2], first, row.length);
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const double weight = omega[i] * inverseSum;
                       if (weight > 0.0)
                       {
                           add(row.first + i, weight);
                           ++weighted;
                       }
                   }
               });
    statistics().nodesWeighted += weighted;
}

void SparseFractionSum::addListed(const NodeOmegas& weightedNodes, double inverseSum, const IndexBox& box)
{
    // The weighted nodes and the sink's are both in node order: one pass over each.
    const std::vector<NodeValue>& nodes = fractions_.nodes();
    auto next = nodes.begin();
    for (const auto& [node, omega] : weightedNodes)
    {
        while (next != nodes.end() && next->node < node)
        {
            ++next;
        }
        if (next == nodes.end())
        {
            break;
        }
        if (next->node == node)
        {
            sum_ += omega * inverseSum * next->value;
            keep(static_cast<std::size_t>(next - nodes.begin()), omega * inverseSum);
        }
    }
    statistics().nodesWeighted += static_cast<std::int64_t>(weightedNodes.size());
}

void SparseFractionSum::addSeparable(SeparableWeight& rows, const SeparableTables& tables, double inverseSum,
                                     const IndexBox& box)
{
    // The sink's nodes inside the (folded) box, in node order: the terms the row-by-row
    // sum over the box adds where the fraction is not 0, each weight the row's to the bit.
    fractions_.forEachIn(box, gridNodes_,
                         [&](const NodeValue& node)
                         {
                             const double weight
                                 = tables.omega(node.index[0] - box.lo[0], node.index[1] - box.lo[1],
                                                node.index[2] - box.lo[2])
                                 * inverseSum;
                             if (weight > 0.0)
                             {
                                 sum_ += weight * node.value;
                                 keep(static_cast<std::size_t>(&node - fractions_.nodes().data()), weight);
                                 statistics().nodesWeighted += 1;
                             }
                         });
}

void SparseFractionSum::add(std::size_t node, double weight)
{
    const std::size_t position = fractions_.position(node);
    if (position < fractions_.nodes().size())
    {
        sum_ += weight * fractions_.nodes()[position].value;
        keep(position, weight);
    }
}

} // namespace dropletFiber
