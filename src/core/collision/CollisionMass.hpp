// CollisionMass: expected droplet mass (and momentum) that hits one fiber segment during
// a time step, from the droplet field of a DensityGrid (docs/model.md sec. 2-3, eqs. 4-10):
//     m_coll = 2 rho (r_F + <r>) |l x v_rel| dt              (eq. 9, with the identity
//                                                              under eq. 5: no division)
//     I      = m_coll * u_droplet                            (eq. 7, momentum carried)
// l = b - a (segment vector), v_rel = u_droplet - segment velocity, rho, <r>, u_droplet
// from the grid, interpolated (DensityGrid::sample) at the segment midpoint, or, with
// CollisionOptions::samples > 1, at the midpoints of that many equal sub-segments whose
// contributions add up (a segment that spans several grid cells).
//
// Radius average <r> (see the note under eq. 10 in docs/model.md):
//   Mass   - sum n_i m_i r_i / sum n_i m_i. For droplets of radii r_i with number
//            densities n_i, the expected collected mass is
//            sum_i n_i m_i 2 (r_F + r_i) |l x v| dt = 2 rho (r_F + <r>_mass) |l x v| dt
//            exactly; a geometric Monte-Carlo count agrees (CollisionMassTest). Default.
//   Number - sum n_i r_i / sum n_i, the paper's eq. 10; equal to Mass for a monodisperse
//            spray, biased low for a polydisperse one.
//
// Sample points outside the grid box contribute nothing (the grid knows no droplets
// there); SegmentCollision::samplesOutside counts them so the caller can warn.
//
// Where to sample and the mass from the samples are apart (collisionSamples,
// samplePoint, collisionMassFromSamples): a grid split into blocks (parallel runs) gets
// the field values of the points from the blocks that own them, then forms the mass
// here; collisionMass(grid, ...) is the same with the grid's own sample().
#pragma once

#include "grid/DensityGrid.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products (eq. 9)

#include <cstdint>

namespace dropletFiber
{

enum class RadiusAverage
{
    Mass,  // mass-weighted mean radius (exact expected mass for a polydisperse spray)
    Number // number-weighted mean radius, eq. 10 of the paper
};

// What a segment receives per step (docs/model.md sec. 3, discrete hits): the expected
// mass of eq. 9 (the paper), or a whole number of droplets drawn from the Poisson law of
// that mean (DiscreteHits.hpp).
enum class CollisionMode
{
    Expected,
    Discrete
};

struct CollisionOptions
{
    RadiusAverage radiusAverage = RadiusAverage::Mass;
    // Sample points along the segment: 1 = midpoint (the paper); n > 1 = n equal
    // sub-segments; 0 = automatic, one per grid spacing spanned (at least 1).
    int samples = 1;
    CollisionMode mode = CollisionMode::Expected;
    std::uint32_t seed = 0; // key of the discrete hits' random numbers
};

struct SegmentCollision
{
    double mass = 0.0;                       // m_coll, kg
    Eigen::Vector3d momentum{0.0, 0.0, 0.0}; // sum of m_coll * u_droplet, kg m/s
    int samples = 0;                         // sample points used
    int samplesOutside = 0;                  // of which outside the grid box
};

// Eq. 9 for given droplet field values (the formula on its own).
double collisionMass(double rho, double meanRadius, double fiberRadius, const Eigen::Vector3d& segment,
                     const Eigen::Vector3d& relativeVelocity, double dt);

// Eq. 9 and the momentum for the segment from a to b, radius fiberRadius, moving with
// segmentVelocity, in the droplet field of the grid (its current averaging window).
SegmentCollision collisionMass(const DensityGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               double fiberRadius, const Eigen::Vector3d& segmentVelocity, double dt,
                               const CollisionOptions& options = CollisionOptions{});

// The number of sample points `options` gives for this segment on this grid.
int collisionSamples(const DensityGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const CollisionOptions& options);
int collisionSamples(const GridSpec& spec, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const CollisionOptions& options);

// Sample point s of `samples` along the segment from a to b: the midpoint of its s-th piece.
Eigen::Vector3d samplePoint(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int samples, int s);

// Eq. 9 and the momentum for the segment from a to b, from the droplet field at its
// `samples` sample points (fields[s] at samplePoint(a, b, samples, s)). With sampleMasses
// (`samples` values) each sample's m_coll too (0 outside the grid or where rho is 0): the
// segment's mass is their sum (depletion attributes them to the nodes, CaptureLimit.hpp).
SegmentCollision collisionMassFromSamples(const DropletFieldValue* fields, int samples,
                                          const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          double fiberRadius, const Eigen::Vector3d& segmentVelocity,
                                          double dt, const CollisionOptions& options,
                                          double* sampleMasses = nullptr);

} // namespace dropletFiber
