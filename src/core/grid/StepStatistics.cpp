#include "grid/StepStatistics.hpp"

#include <algorithm>

namespace dropletFiber
{

StepStatistics& StepStatistics::operator+=(const StepStatistics& other)
{
    parcels += other.parcels;
    parcelsEmpty += other.parcelsEmpty;
    parcelsOutside += other.parcelsOutside;
    parcelsPartlyOutside += other.parcelsPartlyOutside;
    parcelsCapped += other.parcelsCapped;
    parcelsFallback += other.parcelsFallback;
    parcelsCloudInCell += other.parcelsCloudInCell;
    parcelsSeparable += other.parcelsSeparable;
    nodesVisited += other.nodesVisited;
    nodesWeighted += other.nodesWeighted;
    massIn += other.massIn;
    massDeposited += other.massDeposited;
    massOutside += other.massOutside;
    widestKernelWidth = std::max(widestKernelWidth, other.widestKernelWidth);
    widestKernelReach = std::max(widestKernelReach, other.widestKernelReach);
    return *this;
}

} // namespace dropletFiber
