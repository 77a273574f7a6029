// FiberCircle: the fiber of the paper's 2D test (sec. 6, figure 6) and eq. 9 for it.
//
// The fiber is a cylinder of radius r_F normal to the x-y plane of the spray; the plane
// shows its cross-section, the circle of radius r_F around (x, y). In 3D, eq. 9 for it is
// one fiber segment along z, of length `depth` (the slab of the 2D case):
//     m_coll = 2 rho (r_F + <r>) |l x v| dt,   l = (0, 0, depth),   |l x v| = depth |v|,
// i.e. the droplet mass flowing through the fiber's shadow of width 2 (r_F + <r>).
//
// Where rho and <r> are taken (Eq9Sampling):
//   Axis    - at the cylinder's axis (the circle's centre): the paper's midpoint rule,
//             one sample per segment.
//   Outline - on a closed polyline approximating the circle (PaperSetting::outlineSegments
//             segments). Polyline segment k evaluates eq. 9 (collisionMass on the z-segment
//             through its midpoint) and carries the weight
//                 w_k = |l_k x u| / sum_j |l_j x u|,   u = flow direction,
//             its share of the fiber's projected width. The weights sum to 1, so in a
//             uniform field this is exactly eq. 9; in a grid field it averages rho over the
//             width the fiber actually sweeps, which a cylinder 2 cm thick (40 grid cells
//             at 100x100) needs: a single sample sees one cell's value. The sum is a
//             midpoint rule across the interpolated field, so segments are at most a
//             quarter node spacing long (more segments than outlineSegments when needed):
//             a field that resolves single streams (fine grids) varies within one cell.
#pragma once

#include "collision/CollisionMass.hpp"
#include "grid/DensityGrid.hpp"

#include <Eigen/Core>

namespace dropletFiber
{
namespace validation
{

enum class Eq9Sampling
{
    Axis,
    Outline
};

struct FiberCircle
{
    double x = 0.0, y = 0.03; // centre, m
    double radius = 0.01;     // r_F, m
};

struct Eq9Options
{
    Eq9Sampling sampling = Eq9Sampling::Outline;
    int outlineSegments = 256;          // at least this many segments...
    double maxSegmentInSpacings = 0.25; // ...and none longer than this many node spacings
    RadiusAverage radiusAverage = RadiusAverage::Mass;
};

// Eq. 9 with given rho (kg/m^3) and <r>, droplets moving with `velocity` (fiber at rest).
double formulaCollisionMass(double rho, double meanRadius, const FiberCircle& fiber, double depth,
                            const Eigen::Vector3d& velocity, double dt);

// Eq. 9 with rho, <r> and droplet velocity from the grid's current window. zMid: the slab
// centre; flowDirection: the spray's direction (outline weights).
double gridCollisionMass(const DensityGrid& grid, const FiberCircle& fiber, double depth, double zMid,
                         double dt, const Eigen::Vector3d& flowDirection, const Eq9Options& options);

} // namespace validation
} // namespace dropletFiber
