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

} // namespace dropletFiber
