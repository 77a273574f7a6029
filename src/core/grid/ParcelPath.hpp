// ParcelPath: a parcel's path during the time step as the density grid sees it: the
// checks of its values, the part of the path inside the grid box (the deposit's steps 1-2,
// docs/model.md sec. 4, eqs. 19 and 26) and what the parcel puts on the grid per quantity
// (step 7, eq. 25; GridQuantities.hpp).
//  1. Path: from position - velocity dt to position (Parcel.hpp convention).
//  2. The path is clipped to the grid box (flat directions: the slab [lower, upper]).
//     The parcel puts the fraction f of its mass on the grid that equals the fraction of
//     the step it spends inside the box; the rest is reported as mass outside. So a parcel
//     entirely outside gives nothing (even if its kernel would reach nodes: piling the
//     mass of droplets outside onto the edge nodes would bias them), and a parcel
//     crossing the boundary gives the time-averaged share of eq. 26.
#pragma once

#include "grid/GridQuantities.hpp"
#include "grid/GridSpec.hpp"
#include "grid/Parcel.hpp"
#include "grid/StepStatistics.hpp"

#include <Eigen/Core>

#include <array>

namespace dropletFiber
{

// The part of a parcel's path inside the grid box, on the node layer in flat directions;
// fraction: the share of the step spent inside the box.
struct ClippedPath
{
    Eigen::Vector3d start{0.0, 0.0, 0.0};
    Eigen::Vector3d displacement{0.0, 0.0, 0.0};
    double fraction = 0.0;
};

// Throws std::invalid_argument ("DensityGrid::deposit: ...") for non-finite values, a
// negative diameter, nParticle or density, and dt < 0.
void checkParcel(const Parcel& parcel, double dt);

// A parcel without droplets or of droplets without size: counted, never deposited.
inline bool emptyParcel(const Parcel& parcel)
{
    return parcel.nParticle == 0.0 || parcel.diameter == 0.0;
}

// Steps 1-2: the parcel's path (of mass `mass`) clipped to the grid box, its mass outside
// and the parcels outside or partly outside booked in stats; false when nothing of the
// parcel is to be deposited.
bool clipPath(const GridSpec& spec, const Parcel& parcel, double dt, double mass, StepStatistics& stats,
              ClippedPath& path);

// Step 7: what the parcel puts on the grid per quantity (GridQuantities.hpp), for the
// fraction of the step it spends inside the box.
std::array<double, nQuantities> parcelTotals(const Parcel& parcel, double mass, double fraction);

} // namespace dropletFiber
