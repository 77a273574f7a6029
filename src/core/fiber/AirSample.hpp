// AirSample / AirSampler: the air seen by the fiber points, supplied by the caller
// (the OpenFOAM layer interpolates its CFD fields). The solver asks once per CFD
// step for all points of all movable fibers in one batch (one collective sample per
// step, which matters under MPI), in fiber order then point order; the sample is held
// for the whole step, attached to the point index.
#pragma once

#include <Eigen/Core>

#include <functional>

namespace dropletFiber {

struct AirSample {
    Eigen::Matrix3Xd velocity;   // u [m/s], one column per point
    Eigen::VectorXd density;     // rho [kg/m^3]
    Eigen::VectorXd viscosity;   // dynamic viscosity mu [Pa s]
};

using AirSampler = std::function<AirSample(const Eigen::Matrix3Xd& points)>;

// Same air everywhere (tests, simple cases).
AirSampler uniformAir(const Eigen::Vector3d& velocity, double density, double viscosity);

}  // namespace dropletFiber
