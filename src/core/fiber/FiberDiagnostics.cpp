#include "fiber/FiberDiagnostics.hpp"

#include "fiber/BendingJoints.hpp"

namespace dropletFiber
{

FiberDiagnostics diagnose(const Fiber& fiber, const Eigen::Vector3d& gravity)
{
    FiberDiagnostics d;
    const Eigen::VectorXd m = fiber.pointMasses();
    const Eigen::Matrix3Xd& x = fiber.positions();
    const Eigen::Matrix3Xd& v = fiber.velocities();
    for (Eigen::Index i = 0; i < fiber.pointCount(); ++i)
    {
        d.kineticEnergy += 0.5 * m(i) * v.col(i).squaredNorm();
        d.gravitationalEnergy -= m(i) * gravity.dot(x.col(i));
    }
    d.elasticEnergy = bendingEnergy(bendingJoints(fiber), x);
    d.totalMass = fiber.totalMass();
    d.totalCapturedMass = fiber.totalCapturedMass();
    d.momentum = v * m;
    d.centreOfMass = x * m / m.sum();
    d.maxSegmentLengthError = fiber.maxSegmentLengthError();
    return d;
}

} // namespace dropletFiber
