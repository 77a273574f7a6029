#include "depletion/RealisedCapture.hpp"

#include <stdexcept>

namespace dropletFiber
{

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
        NodeParts& parts = nodes_[sample.node[u]];
        parts.granted += granted;
        parts.realised += realisedOverGranted * granted;
    }
}

void RealisedCapture::scaleRemoval(CaptureLimit& limit) const
{
    for (const auto& [node, parts] : nodes_)
    {
        if (parts.granted > 0.0)
        {
            limit.scaleTakenFraction(node, parts.realised / parts.granted);
        }
    }
}

double RealisedCapture::realisedMass() const
{
    double sum = 0.0;
    for (const auto& entry : nodes_)
    {
        sum += entry.second.realised;
    }
    return sum;
}

} // namespace dropletFiber
