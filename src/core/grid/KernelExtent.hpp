// KernelExtent: how far the kernels of a step's parcels reach on the grid, in node spacings,
// for the report of wide kernels (docs/model.md sec. 4, "Cost of wide kernels"). The deposit
// of a parcel visits about (2 reach / h)^D nodes, so the widest kernel of a step says where
// its time goes and which setting would help (coarser spacing, negligibleWeight, rMaxCap).
//
// The figures are the deposit's own (eqs. 13-18, the rMaxCap support of P9 and the
// negligibleWeight cut of P10), recomputed per parcel from the parcel alone: a few
// operations, against the (reach/h)^D node evaluations of its deposit.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/Parcel.hpp"
#include "grid/ParcelKernel.hpp"
#include "grid/StepStatistics.hpp"

namespace dropletFiber
{

// P10: the distance from the path beyond which a node's weight is below negligibleWeight
// times the parcel's largest, or the kernel's support (reach()) when that is nearer or the
// cut is off (negligibleWeight 0). halfCellDiagonal: half the diagonal of a grid cell over
// the active directions; pathLength: |v dt| of the (clipped) path.
double negligibleReach(const ParcelKernel& kernel, double pathLength, double halfCellDiagonal,
                       double negligibleWeight);

struct KernelExtent
{
    double width = 0.0;       // r_max / sqrt(2 alpha) (eq. 16), in node spacings
    double reach = 0.0;       // distance to the farthest node evaluated (P9, P10), in node spacings
    bool cloudInCell = false; // width below cloudInCellBelow: deposited with cloud-in-cell weights
};

class KernelExtentMeter
{
public:
    // dimension: 2 or 3, the r_min formula the grid uses (DensityGrid::kernelDimension()).
    KernelExtentMeter(const GridSpec& spec, const KernelSettings& settings, int dimension);

    // In units of the largest node spacing of the active directions (the unit of
    // cloudInCellBelow). The path length is the whole step's |v dt| (the deposit clips it
    // to the grid box: its reach is then at most this).
    KernelExtent measure(const Parcel& parcel, double dt) const;
    // Raises stats.widestKernelWidth / widestKernelReach to the parcel's kernel (parcels
    // with no droplets and cloud-in-cell parcels excepted).
    void record(const Parcel& parcel, double dt, StepStatistics& stats) const;

    double spacing() const { return spacing_; }

private:
    KernelSettings settings_;
    int dimension_ = 2;
    double spacing_ = 0.0;          // largest node spacing over the active directions, m
    double halfCellDiagonal_ = 0.0; // m
};

} // namespace dropletFiber
