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

void RealisedCapture::add(const SampleCapture& sample, double realisedOverGranted, const CaptureLimit& limit,
                          double interceptors)
{
    if (!(realisedOverGranted >= 0.0))
    {
        throw std::invalid_argument("RealisedCapture::add: the realised over granted ratio must be >= 0");
    }
    for (int c = 0; c < sample.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        const double granted = interceptors * (sample.mass[u] * limit.grantedRatio(sample.node[u]));
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

void RealisedCapture::addNode(std::size_t node, double granted, double realised)
{
    if (!spread_.empty() && spread_.back().first >= node)
    {
        throw std::invalid_argument("RealisedCapture::addNode: nodes must come in increasing order");
    }
    NodeParts parts;
    parts.granted = granted;
    parts.realised = realised;
    spread_.emplace_back(node, parts);
}

RealisedCapture::NodeParts RealisedCapture::spreadAt(std::size_t node) const
{
    const auto at = std::lower_bound(spread_.begin(), spread_.end(), node,
                                     [](const auto& entry, std::size_t n) { return entry.first < n; });
    return at != spread_.end() && at->first == node ? at->second : NodeParts{};
}

void RealisedCapture::scaleRemoval(CaptureLimit& limit) const
{
    // The samples' nodes (with the populations' part there), then the populations' own
    for (const auto& [node, terms] : nodes_)
    {
        NodeParts parts = summed(terms);
        const NodeParts spread = spreadAt(node);
        parts.granted += spread.granted;
        parts.realised += spread.realised;
        if (parts.granted > 0.0)
        {
            limit.scaleRemoval(node, parts.realised / parts.granted);
        }
    }
    for (const auto& [node, parts] : spread_)
    {
        if (nodes_.count(node) == 0 && parts.granted > 0.0)
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
    for (const auto& entry : spread_)
    {
        sum += entry.second.realised;
    }
    return sum;
}

double RealisedCapture::realisedAt(std::size_t node) const
{
    const auto entry = nodes_.find(node);
    return (entry == nodes_.end() ? 0.0 : summed(entry->second).realised) + spreadAt(node).realised;
}

double realisedRemoval(double summedParts)
{
    // The whole-droplet excess of P32 is cut from the hits (P33)
    return summedParts > 1.0 - allCapturedWithin ? 1.0 : std::max(0.0, summedParts);
}

double unremovedMass(double summedParts, double mass)
{
    return summedParts > 1.0 ? mass * (1.0 - 1.0 / summedParts) : 0.0;
}

double unremovedOfSample(const SampleCapture& sample, const CaptureLimit& limit)
{
    double part = 0.0;
    for (int c = 0; c < sample.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        const double share = limit.unremovedShare(sample.node[u]);
        part += share > 0.0 ? sample.mass[u] * limit.grantedRatio(sample.node[u]) * share : 0.0;
    }
    return part;
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

RealisedRemoval realiseCapture(CaptureLimit& limit, const ParcelReaches& reaches,
                               const std::vector<double>& parcelMasses,
                               const std::vector<SampleCapture>& samples,
                               const std::vector<double>& realisedMass,
                               const std::vector<double>& interceptors)
{
    RealisedCapture realised;
    std::vector<double> ratio(samples.size(), 0.0);
    for (std::size_t s = 0; s < samples.size(); ++s)
    {
        const double granted = limit.grantedMass(samples[s]);
        ratio[s] = granted > 0.0 ? realisedMass[s] / granted : 0.0;
        realised.add(samples[s], ratio[s], limit, interceptors.empty() ? 1.0 : interceptors[s]);
    }
    realised.scaleRemoval(limit);
    RealisedRemoval result;
    result.fraction.assign(reaches.parcels.size(), 0.0);
    for (std::size_t p = 0; p < reaches.parcels.size(); ++p)
    {
        const ParcelReach& entry = reaches.parcels[p];
        const double parts = limit.removedFraction(reaches, p, entry.saturated, entry.depth);
        result.fraction[p] = realisedRemoval(parts);
        const double unremoved = unremovedMass(parts, parcelMasses[p]);
        if (unremoved > 0.0)
        {
            limit.addShortfall(reaches, p, entry.saturated, entry.depth, unremoved, parts);
            ++result.emptied;
        }
    }
    result.sampleMass = realisedMass;
    for (std::size_t s = 0; s < samples.size() && result.emptied > 0; ++s)
    {
        const double cut = ratio[s] * unremovedOfSample(samples[s], limit);
        result.sampleMass[s] = std::max(0.0, realisedMass[s] - cut);
    }
    return result;
}

} // namespace dropletFiber
