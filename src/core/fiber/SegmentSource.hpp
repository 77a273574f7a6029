// SegmentSource: droplet mass and momentum captured by one fiber segment in one CFD
// step (the f_contact of docs/model.md eq. 2, from the collision model of sec. 3, eq. 7-9).
// The capture is inelastic: the mass joins the segment (half to each end point) and
// its momentum is added, so fiber + droplet momentum is conserved.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace dropletFiber
{

struct SegmentSource
{
    double mass = 0.0;                                  // captured mass [kg]
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero(); // of those droplets [kg m/s]
    double hits = 0.0; // droplets (collision mode discrete: a whole number; expected: the expected count)
    double expectedMass = 0.0; // the expected mode's mass (eq. 9 after the limit) [kg], for the binder table
};

// One list per fiber, one entry per segment (an empty list means no capture).
using CaptureSources = std::vector<std::vector<SegmentSource>>;

} // namespace dropletFiber
