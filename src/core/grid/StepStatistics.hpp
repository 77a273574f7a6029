// StepStatistics: what happened to the parcels deposited in one time step, so that the
// caller can report and warn (mass outside the grid, capped kernels, fallbacks, wide
// kernels). All members but the two widest-kernel figures are sums, so per-rank statistics
// add up across MPI ranks; those two are maxima (operator+= takes the larger).
#pragma once

#include <cstdint>

namespace dropletFiber
{

struct StepStatistics
{
    std::int64_t parcels = 0;              // deposit() calls
    std::int64_t parcelsEmpty = 0;         // nParticle == 0 or diameter == 0: nothing to deposit
    std::int64_t parcelsOutside = 0;       // path entirely outside the grid box
    std::int64_t parcelsPartlyOutside = 0; // path leaves the box during the step
    std::int64_t parcelsCapped = 0;        // influence radius limited by KernelSettings::rMaxCap
    std::int64_t parcelsFallback = 0;      // kernel reached no node: multilinear weights used
    std::int64_t parcelsCloudInCell = 0;   // kernel narrower than KernelSettings::cloudInCellBelow allows
    std::int64_t parcelsSeparable = 0;     // weights from per-axis tables (SeparableWeight, wide kernels)
    std::int64_t nodesVisited = 0;         // nodes examined (bounding boxes of the swept capsules;
                                           // cloud-in-cell: corners of the path's points)
    std::int64_t nodesWeighted = 0;        // nodes that received mass (cloud-in-cell paths across
                                           // more than ~30 cells: corner updates)
    double massIn = 0.0;                   // sum of parcel masses n m(r_p), kg
    double massDeposited = 0.0;            // mass put on the grid nodes, kg
    double massOutside = 0.0;              // massIn - massDeposited (part of the step outside the box)
    // The widest kernel of the step, in node spacings (the largest spacing): its width
    // r_max / sqrt(2 alpha) (eq. 16) and its evaluated reach (support P9 or negligibleWeight
    // cut P10); cloud-in-cell parcels not counted. Filled by DensityGrid::deposit.
    double widestKernelWidth = 0.0;
    double widestKernelReach = 0.0;

    StepStatistics& operator+=(const StepStatistics& other);
};

} // namespace dropletFiber
