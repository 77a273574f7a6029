#include "fiber/BendingJoints.hpp"

namespace dropletFiber
{

std::vector<BendingJoint> bendingJoints(const Fiber& fiber)
{
    std::vector<BendingJoint> joints;
    bendingJoints(fiber, joints);
    return joints;
}

void bendingJoints(const Fiber& fiber, std::vector<BendingJoint>& joints)
{
    joints.clear();
    const double stiffness = fiber.material().bendingStiffness();
    if (stiffness <= 0.0 || fiber.immobile())
    {
        return;
    }
    const Eigen::VectorXd& l = fiber.restLengths();
    const Eigen::Index n = fiber.pointCount();
    joints.reserve(static_cast<std::size_t>(n));

    if (fiber.startEnd().type == EndType::clamped)
    {
        BendingJoint joint;
        joint.pointCount = 2;
        joint.point = {0, 1, 0};
        joint.coefficient = {-1.0 / l(0), 1.0 / l(0), 0.0};
        joint.offset = -fiber.startEnd().clampDirection;
        joint.stiffness = stiffness / (0.5 * l(0));
        joints.push_back(joint);
    }
    for (Eigen::Index k = 1; k + 1 < n; ++k)
    {
        BendingJoint joint;
        joint.pointCount = 3;
        joint.point = {k - 1, k, k + 1};
        joint.coefficient = {1.0 / l(k - 1), -1.0 / l(k - 1) - 1.0 / l(k), 1.0 / l(k)};
        joint.stiffness = stiffness / (0.5 * (l(k - 1) + l(k)));
        joints.push_back(joint);
    }
    if (fiber.endEnd().type == EndType::clamped)
    {
        const Eigen::Index s = n - 2; // last segment
        BendingJoint joint;
        joint.pointCount = 2;
        joint.point = {n - 2, n - 1, 0};
        joint.coefficient = {1.0 / l(s), -1.0 / l(s), 0.0};
        joint.offset = fiber.endEnd().clampDirection;
        joint.stiffness = stiffness / (0.5 * l(s));
        joints.push_back(joint);
    }
}

double bendingEnergy(const std::vector<BendingJoint>& joints, const Eigen::Matrix3Xd& x)
{
    double energy = 0.0;
    for (const BendingJoint& joint : joints)
    {
        energy += 0.5 * joint.stiffness * jointVector(joint, x).squaredNorm();
    }
    return energy;
}

} // namespace dropletFiber
