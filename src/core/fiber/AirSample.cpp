#include "fiber/AirSample.hpp"

namespace dropletFiber {

AirSampler uniformAir(const Eigen::Vector3d& velocity, double density, double viscosity)
{
    return [velocity, density, viscosity](const Eigen::Matrix3Xd& points) {
        const Eigen::Index n = points.cols();
        AirSample air;
        air.velocity = velocity.replicate(1, n);
        air.density = Eigen::VectorXd::Constant(n, density);
        air.viscosity = Eigen::VectorXd::Constant(n, viscosity);
        return air;
    };
}

}  // namespace dropletFiber
