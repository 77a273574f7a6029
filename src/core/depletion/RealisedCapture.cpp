#include "depletion/RealisedCapture.hpp"

#include <algorithm>
#include <stdexcept>

namespace dropletFiber
{

namespace
{
// A parcel left with less than this fraction of its droplets has lost them all
// (CaptureLimitRemoval.cpp's rule for c_p)
constexpr double allCapturedWithin = 1e-12;
} // namespace

void RealisedCapture::add(const SampleCapture& sample, double realisedOverGranted, const CaptureLimit& limit)
{
    if (!(realisedOverGranted >= 0.0))
    {
        throw std::invalid_argument("RealisedCapture::add: the realised over granted ratio must be >= 0");
    }
    for (int c = 0; c < sample.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        const double granted = sample.mass[u] * limit.grantedRatio(sample.node[u]);
        nodes_[sample.node[u]].emplace_back(granted, realisedOverGranted * granted);
    }
}

RealisedCapture::NodeParts RealisedCapture::summed(Terms terms)
{
    std::sort(terms.begin(), terms.end());
    NodeParts parts;
    for (const auto& [granted, realised] : terms)
    {
        parts.granted += granted;
        parts.realised += realised;
    }
    return parts;
}

void RealisedCapture::scaleRemoval(CaptureLimit& limit) const
{
    for (const auto& [node, terms] : nodes_)
    {
        const NodeParts parts = summed(terms);
        if (parts.granted > 0.0)
        {
            limit.scaleRemoval(node, parts.realised / parts.granted);
        }
    }
}

double RealisedCapture::realisedMass() const
{
    double sum = 0.0;
    for (const auto& entry : nodes_)
    {
        sum += summed(entry.second).realised;
    }
    return sum;
}

double RealisedCapture::realisedAt(std::size_t node) const
{
    const auto entry = nodes_.find(node);
    return entry == nodes_.end() ? 0.0 : summed(entry->second).realised;
}

double realisedRemoval(double summedParts)
{
    // The whole-droplet excess of P32 stays with the fibers
    return summedParts > 1.0 - allCapturedWithin ? 1.0 : std::max(0.0, summedParts);
}

std::vector<double> realisedFractions(const CaptureLimit& limit, const ParcelReaches& reaches)
{
    std::vector<double> fraction(reaches.parcels.size(), 0.0);
    for (std::size_t p = 0; p < reaches.parcels.size(); ++p)
    {
        const ParcelReach& entry = reaches.parcels[p];
        fraction[p] = realisedRemoval(limit.removedFraction(reaches, p, entry.saturated, entry.depth));
    }
    return fraction;
}

} // namespace dropletFiber
