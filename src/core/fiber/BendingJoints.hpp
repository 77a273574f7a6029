// BendingJoints: the discrete bending energy of a line strip (docs/model.md eq. 2, the
// -S_b d_ssss x term) as a sum over joints,
//     E_b = sum_k (S_b / l*_k) |b_k|^2 / 2,   b_k = e_k - e_{k-1},   e_j = (x_{j+1}-x_j)/l_j,
// with dual length l*_k = (l_{k-1} + l_k)/2 (a Hencky bar chain: rotational springs
// S_b / l* at the joints). With |e_j| = 1 held by the constraints, |b_k| = 2 sin(angle/2),
// so E_b -> (S_b/2) int kappa^2 ds. Because e_j is linear in x, E_b is quadratic in x:
// the bending force is linear and constant-coefficient, which is what lets the time
// step treat it implicitly at no extra cost. A clamped end adds a joint between the
// clamp direction d and the end segment, b = e_0 - d, with dual length l_0/2 (the
// ghost-point clamp, second-order accurate). Free and pinned ends add nothing
// (zero moment there).
#pragma once

#include "fiber/Fiber.hpp"

#include <array>
#include <vector>

namespace dropletFiber
{

struct BendingJoint
{
    int pointCount = 0; // 2 (clamp) or 3 (interior joint)
    std::array<Eigen::Index, 3> point{};
    std::array<double, 3> coefficient{}; // b = sum_a coefficient_a x_point_a + offset
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    double stiffness = 0.0; // S_b / l* [N m]
};

// Empty when S_b = 0 (limp fiber).
std::vector<BendingJoint> bendingJoints(const Fiber& fiber);
// The same into an existing list (replaced; its capacity is reused by the solver).
void bendingJoints(const Fiber& fiber, std::vector<BendingJoint>& joints);

// Inline: evaluated for every joint in every Newton iteration.
inline Eigen::Vector3d jointVector(const BendingJoint& joint, const Eigen::Matrix3Xd& x)
{
    Eigen::Vector3d b = joint.offset;
    for (int a = 0; a < joint.pointCount; ++a)
    {
        b += joint.coefficient[static_cast<std::size_t>(a)] * x.col(joint.point[static_cast<std::size_t>(a)]);
    }
    return b;
}

double bendingEnergy(const std::vector<BendingJoint>& joints, const Eigen::Matrix3Xd& x);

} // namespace dropletFiber
