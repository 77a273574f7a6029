#include "grid/KernelExtent.hpp"

#include <algorithm>
#include <cmath>

namespace dropletFiber
{

double negligibleReach(const ParcelKernel& kernel, double pathLength, double halfCellDiagonal,
                       double negligibleWeight)
{
    // A node farther than d from the path has omega < exp(-gamma d^2); some node lies within
    // c + L/2 of every point of the path, so the largest weight is at least phi(c + L/2).
    // The cut binds only if exp(-gamma reach^2) < negligibleWeight (phi <= 1).
    const double reach = kernel.reach();
    if (!(negligibleWeight > 0.0) || !(kernel.edgeExponent() > -std::log(negligibleWeight)))
    {
        return reach;
    }
    const double best = kernel.phi(halfCellDiagonal + 0.5 * pathLength);
    if (!(best > 0.0))
    {
        return reach;
    }
    const double cutoffSquared = (-std::log(negligibleWeight) - std::log(best)) / kernel.gamma();
    return cutoffSquared < reach * reach ? std::sqrt(cutoffSquared) : reach;
}

KernelExtentMeter::KernelExtentMeter(const GridSpec& spec, const KernelSettings& settings, int dimension)
    : settings_(settings), dimension_(dimension)
{
    double diagonalSquared = 0.0;
    for (int d = 0; d < 3; ++d)
    {
        if (!spec.flat(d))
        {
            spacing_ = std::max(spacing_, spec.spacing(d));
            diagonalSquared += 0.25 * spec.spacing(d) * spec.spacing(d);
        }
    }
    halfCellDiagonal_ = std::sqrt(diagonalSquared);
}

KernelExtent KernelExtentMeter::measure(const Parcel& parcel, double dt) const
{
    KernelExtent extent;
    if (parcel.nParticle == 0.0 || parcel.diameter == 0.0 || !(spacing_ > 0.0))
    {
        return extent;
    }
    const ParcelKernel kernel(0.5 * parcel.diameter, parcel.nParticle, settings_, dimension_);
    const double pathLength = parcel.velocity.norm() * dt;
    extent.width = kernel.width() / spacing_;
    extent.reach
        = negligibleReach(kernel, pathLength, halfCellDiagonal_, settings_.negligibleWeight) / spacing_;
    extent.cloudInCell = extent.width < settings_.cloudInCellBelow;
    return extent;
}

void KernelExtentMeter::record(const Parcel& parcel, double dt, StepStatistics& stats) const
{
    const KernelExtent extent = measure(parcel, dt);
    if (extent.cloudInCell || extent.width == 0.0)
    {
        return;
    }
    stats.widestKernelWidth = std::max(stats.widestKernelWidth, extent.width);
    stats.widestKernelReach = std::max(stats.widestKernelReach, extent.reach);
}

} // namespace dropletFiber
