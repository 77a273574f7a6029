// GridMethod: the density-grid route of the paper (sec. 5.1, eqs. 11-26) in the 2D test -
// deposit the spray's parcels on a regular N x N grid over the box (DensityGrid), average
// over a window of steps, and evaluate eq. 9 at the fiber from the interpolated field
// (FiberCircle). Also the "measured" field of the paper's formula curve: the actual
// droplet density counted in a control area.
#pragma once

#include "FiberCircle.hpp"
#include "PaperSetting.hpp"
#include "SprayStreams.hpp"

#include "grid/DensityGrid.hpp"

#include <string>

namespace dropletFiber
{
namespace validation
{

struct GridMethod
{
    std::string label = "grid";
    int nodes = 100;         // nodes per direction, N x N over the box
    KernelSettings kernel{}; // beta (eq. 18), cap on r_max
    int window = 1;          // steps averaged (eq. 26)
    Eq9Options eq9{};        // where eq. 9 samples the grid, which mean radius
    // The grid covers the box widened by `margin` on every side of x and y, with the
    // same node spacing as the N x N grid of the box (edge study).
    double margin = 0.0;
    // Deposit rule for parcels the grid cannot resolve: a parcel whose kernel width (the
    // inflection point of eq. 16, r_max / sqrt(2 alpha)) is below cloudInCellBelow times the
    // larger node spacing is deposited with cloud-in-cell (multilinear) weights along its
    // path instead of the kernel. 0: the paper (always the kernel). Why: eq. 24 normalises
    // a kernel much narrower than the spacing onto the one or two nearest nodes (nearest-
    // node assignment, which moves mass by up to half a cell); multilinear weights keep
    // the parcel's centre of mass (see docs/validation.md, accuracy study).
    // This is KernelSettings::cloudInCellBelow of the core.
    double cloudInCellBelow = 0.0;
};

struct GridOutcome
{
    double mass = 0.0;       // eq. 9 at the fiber, kg per step
    double rhoAtFiber = 0.0; // the grid's density at the fiber centre
    std::int64_t parcelsFallback
        = 0; // parcels of the last step deposited cloud-in-cell (no node reached, or unresolved)
    std::int64_t parcelsDeposited = 0;
};

// Grid spec of the method: the box (widened by margin), nodes N x N (more when widened),
// one node layer in z over the slab [zMid - depth/2, zMid + depth/2].
GridSpec gridSpecFor(const PaperSetting& setting, const GridMethod& method);

// Runs the steps 0 .. window-1 of the spray through a fresh grid and evaluates eq. 9.
// Only parcels whose kernel (or cloud-in-cell fallback) can reach the nodes that eq. 9
// interpolates are deposited: each parcel's weights are normalised on their own (eq. 24),
// so the others cannot change those nodes, and leaving them out changes no result.
GridOutcome runGridMethod(const PaperSetting& setting, const SprayDefinition& spray, const FiberCircle& fiber,
                          const GridMethod& method);

// The droplet field as counted directly: the time-averaged droplet mass inside the control
// area [xLow, xHigh] x [yLow, yHigh] (each parcel's mass times the fraction of its path
// inside) over steps 0 .. steps-1, per area, depth and step; mean radii weighted the same way.
struct MeasuredField
{
    double rho = 0.0;
    double rMeanMass = 0.0;
    double rMeanNumber = 0.0;
};
MeasuredField measureField(const SprayStreams& spray, double depth, double xLow, double xHigh, double yLow,
                           double yHigh, int steps);

} // namespace validation
} // namespace dropletFiber
