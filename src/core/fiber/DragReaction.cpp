#include "fiber/DragReaction.hpp"

#include <algorithm>

namespace dropletFiber
{

void DragReaction::reset(Eigen::Index points)
{
    impulse.setZero(3, points);
    coefficientTime.setZero(points);
}

void addImmobileFiberReaction(const Fiber& fiber, const AirSample& air, Eigen::Index firstAir,
                              const DragSettings& drag, double dt, DragReaction& reaction,
                              Eigen::Index firstPoint)
{
    if (drag.model == DragModelType::none)
        return;
    const Eigen::Index n = fiber.pointCount();
    const Eigen::Matrix3Xd& x = fiber.positions();
    const Eigen::VectorXd nodal = fiber.nodalLengths();
    const double radius = fiber.material().radius;
    const double logarithm = fiberLogarithm(radius, fiber.length());
    for (Eigen::Index i = 0; i < n; ++i)
    {
        // The solver's nodal tangent: the neighbours' chord, one-sided at the ends
        const Eigen::Index hi = std::min(i + 1, n - 1), lo = std::max(i - 1, Eigen::Index(0));
        const Eigen::Vector3d t = (x.col(hi) - x.col(lo)).normalized();
        const Eigen::Vector3d w = air.velocity.col(firstAir + i);
        const double wt = t.dot(w);
        const double normalSpeed = (w - wt * t).norm();
        const DragCoefficients c = dragCoefficientsOfFiber(
            drag, air.density(firstAir + i), air.viscosity(firstAir + i), radius, logarithm, normalSpeed);
        const double cn = nodal(i) * c.normal, ct = nodal(i) * c.tangential;
        reaction.impulse.col(firstPoint + i) += dt * (cn * w + (ct - cn) * wt * t);
        reaction.coefficientTime(firstPoint + i) += dt * isotropicDragCoefficient(cn, ct);
    }
}

} // namespace dropletFiber
