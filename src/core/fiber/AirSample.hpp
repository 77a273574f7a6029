// AirSample: the air seen by the fiber points, supplied by the caller (the OpenFOAM
// layer interpolates its CFD fields), and its layout, defined here once: all points of
// all movable fibers, in fiber order then point order (immobile fibers feel no drag
// and are not sampled). The caller samples airSamplePoints(fibers) once per CFD step
// in one batch (one collective sample per step, which matters under MPI) and hands
// the sample to FiberSolver::step, which holds it for the whole step. A caller that
// steps a subset of its fibers hands on that subset's part (airSampleOfFibers).
#pragma once

#include "fiber/Fiber.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace dropletFiber
{

struct AirSample
{
    Eigen::Matrix3Xd velocity; // u [m/s], one column per point
    Eigen::VectorXd density;   // rho [kg/m^3]
    Eigen::VectorXd viscosity; // dynamic viscosity mu [Pa s]

    Eigen::Index pointCount() const { return velocity.cols(); }
};

// Where each fiber's points start in the sample (an immobile fiber: where the next
// fiber's would), and how many points the sample has.
struct AirSampleLayout
{
    std::vector<Eigen::Index> firstPoint;
    Eigen::Index pointCount = 0;
};

// Points a fiber has in the sample: all of a movable fiber, none of an immobile one.
Eigen::Index airSamplePointCount(const Fiber& fiber);

AirSampleLayout airSampleLayout(const std::vector<Fiber>& fibers);

// The points to sample, in the layout's order.
Eigen::Matrix3Xd airSamplePoints(const std::vector<Fiber>& fibers);

// The part of sample (laid out for fibers) that belongs to the fibers numbered
// subset (in increasing order), laid out as the sample of those fibers alone. An
// empty sample (no drag) gives an empty one.
AirSample airSampleOfFibers(const AirSample& sample, const std::vector<Fiber>& fibers,
                            const std::vector<std::size_t>& subset);

// Same air at every point of fibers' sample (tests, simple cases).
AirSample uniformAir(const std::vector<Fiber>& fibers, const Eigen::Vector3d& velocity, double density,
                     double viscosity);

} // namespace dropletFiber
