#include "grid/WindowSampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

WindowSampler::WindowSampler(const GridSpec& spec, const IndexBox& owned)
    : spec_(spec), owned_(owned), ownsWholeGrid_(owned == spec.fullBox()), nodeVolume_(spec.nodeVolume())
{
}

bool WindowSampler::owns(std::size_t node) const
{
    const std::array<int, 3> n = nodeIndicesOfFlat(spec_.nodes, node);
    return node < spec_.nodeCount() && owned_.holds(n[0], n[1], n[2]);
}

std::size_t WindowSampler::windowIndex(std::size_t node) const
{
    const std::array<int, 3> n = nodeIndicesOfFlat(spec_.nodes, node);
    if (node >= spec_.nodeCount() || !owned_.holds(n[0], n[1], n[2]))
    {
        throw std::out_of_range("DensityGrid: node " + std::to_string(node) + " is not owned by this block");
    }
    return flatIndexInBox(owned_, n[0], n[1], n[2]);
}

void WindowSampler::windowTotal(const AveragingWindow& window, std::size_t node, double* sums) const
{
    window.nodeTotal(ownsWholeGrid_ ? node : windowIndex(node), sums);
}

double WindowSampler::lastStepValue(const AveragingWindow& window, std::size_t node, int q) const
{
    return window.newestStepValue(ownsWholeGrid_ ? node : windowIndex(node), q);
}

DropletFieldValue WindowSampler::fieldFromSums(const AveragingWindow& window, const QuantitySums& s) const
{
    DropletFieldValue value;
    const int steps = window.filled();
    if (steps == 0)
    {
        return value;
    }
    const double volumeSteps = nodeVolume_ * steps;
    const double mass = s[quantityMass];
    const double count = s[quantityCount];
    if (mass > 0.0)
    {
        value.rho = mass / volumeSteps;
        value.rMeanMass = s[quantityMassRadius] / mass;
        value.velocity
            = Eigen::Vector3d(s[quantityMomentumX], s[quantityMomentumY], s[quantityMomentumZ]) / mass;
    }
    if (count > 0.0)
    {
        value.numberDensity = count / volumeSteps;
        value.rMeanNumber = s[quantityCountRadius] / count;
    }
    return value;
}

double WindowSampler::cellsPerNodeVolume(std::size_t node) const
{
    const std::array<int, 3> n = nodeIndicesOfFlat(spec_.nodes, node);
    return std::ldexp(1.0, spec_.boundaryDirections(n[0], n[1], n[2]));
}

DropletFieldValue WindowSampler::nodeValue(const AveragingWindow& window, std::size_t node) const
{
    QuantitySums sums{};
    windowTotal(window, node, sums.data());
    return nodeValueFromTotals(window, node, sums.data());
}

DropletFieldValue WindowSampler::nodeValueFromTotals(const AveragingWindow& window, std::size_t node,
                                                     const double* totals) const
{
    QuantitySums sums{};
    std::copy(totals, totals + nQuantities, sums.begin());
    // Sums per whole cell (a power of two: exact; the means are unchanged).
    const double scale = cellsPerNodeVolume(node);
    for (double& sum : sums)
    {
        sum *= scale;
    }
    return fieldFromSums(window, sums);
}

DropletFieldValue WindowSampler::sample(const AveragingWindow& window, const Eigen::Vector3d& point) const
{
    if (!insideActiveBox(spec_, point))
    {
        DropletFieldValue outside;
        outside.inside = false;
        return outside;
    }
    const CornerWeights corners = multilinearWeights(spec_, point);
    QuantitySums sums{};
    double total[nQuantities];
    for (int c = 0; c < corners.count; ++c)
    {
        // windowTotal throws for a corner owned elsewhere
        windowTotal(window, corners.node[static_cast<std::size_t>(c)], total);
        addCornerSum(corners, c, total, sums);
    }
    return fieldFromSums(window, sums);
}

void WindowSampler::addOwnedCornerSums(const AveragingWindow& window, const CornerWeights& corners,
                                       QuantitySums& sums) const
{
    double total[nQuantities];
    for (int c = 0; c < corners.count; ++c)
    {
        const std::size_t node = corners.node[static_cast<std::size_t>(c)];
        if (owns(node))
        {
            windowTotal(window, node, total);
            addCornerSum(corners, c, total, sums);
        }
    }
}

void WindowSampler::prefetchOwnedCornerSums(const AveragingWindow& window, const CornerWeights& corners) const
{
    for (int c = 0; c < corners.count; ++c)
    {
        const std::size_t node = corners.node[static_cast<std::size_t>(c)];
        if (ownsWholeGrid_)
        {
            window.prefetchNodeTotal(node);
        }
        else if (owns(node))
        {
            const std::array<int, 3> n = nodeIndicesOfFlat(spec_.nodes, node);
            window.prefetchNodeTotal(flatIndexInBox(owned_, n[0], n[1], n[2]));
        }
    }
}

DropletFieldValue WindowSampler::interpolated(const AveragingWindow& window, const CornerWeights& corners,
                                              const double* cornerTotals) const
{
    QuantitySums sums{};
    for (int c = 0; c < corners.count; ++c)
    {
        addCornerSum(corners, c, cornerTotals + c * nQuantities, sums);
    }
    return fieldFromSums(window, sums);
}

void WindowSampler::addCornerSum(const CornerWeights& corners, int c, const double* total,
                                 QuantitySums& sums) const
{
    // Densities are interpolated: the sums per whole cell (scale 1 inside the box).
    const double w = corners.weight[static_cast<std::size_t>(c)];
    const double scale = cellsPerNodeVolume(corners.node[static_cast<std::size_t>(c)]);
    for (int q = 0; q < nQuantities; ++q)
    {
        sums[static_cast<std::size_t>(q)] += w * (scale * total[q]);
    }
}

double WindowSampler::densityParts(const CornerWeights& corners, const double* cornerTotals,
                                   double* parts) const
{
    double sum = 0.0;
    for (int c = 0; c < corners.count; ++c)
    {
        const std::size_t node = corners.node[static_cast<std::size_t>(c)];
        const double w = corners.weight[static_cast<std::size_t>(c)];
        parts[c] = w * (cellsPerNodeVolume(node) * cornerTotals[c * nQuantities + quantityMass]);
        sum += parts[c];
    }
    return sum;
}

double WindowSampler::windowMassPerStep(const AveragingWindow& window) const
{
    const int steps = window.filled();
    if (steps == 0)
    {
        return 0.0;
    }
    double mass = 0.0;
    const NodeValueArray& total = window.total();
    for (std::size_t n = 0; n < owned_.nodeCount(); ++n)
    {
        mass += total[n * nQuantities + quantityMass];
    }
    return mass / steps;
}

} // namespace dropletFiber
