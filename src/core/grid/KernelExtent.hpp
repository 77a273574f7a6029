// KernelExtent: how far a parcel's kernel reaches on the grid (docs/model.md sec. 4, the
// negligibleWeight cut P10, "Cost of wide kernels"). The deposit of a parcel visits about
// (2 reach / h)^D nodes; DensityGrid::deposit records the widest kernel of a step in its
// statistics (StepStatistics::widestKernelWidth/Reach) for the deposit report.
#pragma once

#include "grid/ParcelKernel.hpp"

namespace dropletFiber
{

// P10: the distance from the path beyond which a node's weight is below negligibleWeight
// times the parcel's largest, or the kernel's support (reach()) when that is nearer or the
// cut is off (negligibleWeight 0). halfCellDiagonal: half the diagonal of a grid cell over
// the active directions; pathLength: |v dt| of the (clipped) path.
double negligibleReach(const ParcelKernel& kernel, double pathLength, double halfCellDiagonal,
                       double negligibleWeight);

} // namespace dropletFiber
