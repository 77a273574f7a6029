#include "laydown/Belt.hpp"

#include "fiber/BinderDistribution.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace dropletFiber
{

void Belt::validate() const
{
    if (!(std::abs(normal.norm() - 1.0) <= 1e-9))
        throw std::invalid_argument("Belt: the normal must be a unit vector");
    if (!(std::abs(velocity.dot(normal)) <= 1e-9 * std::max(1.0, velocity.norm())))
        throw std::invalid_argument("Belt: the velocity must lie in the belt's plane");
}

Eigen::Vector3d Belt::alongDirection() const
{
    if (velocity.norm() > 0.0)
        return velocity.normalized();
    // At rest: the plane's direction closest to the axis least aligned with the normal
    Eigen::Index axis = 0;
    normal.cwiseAbs().minCoeff(&axis);
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
    return (e - e.dot(normal) * normal).normalized();
}

Eigen::Vector3d Belt::acrossDirection() const
{
    return normal.cross(alongDirection());
}

bool reachesBelt(const Fiber& fiber, const Belt& belt)
{
    return (fiber.centreOfMass() - belt.point).dot(belt.normal) >= 0.0;
}

LaidFiber layFiber(const Fiber& fiber, const Belt& belt, double time, long id)
{
    LaidFiber laid;
    laid.time = time;
    laid.id = id;
    const Eigen::Vector3d centre = fiber.centreOfMass();
    const Eigen::Vector3d foot = centre - (centre - belt.point).dot(belt.normal) * belt.normal;
    const Eigen::Vector3d ea = belt.alongDirection(), ec = belt.acrossDirection();
    laid.across = (foot - belt.point).dot(ec);
    laid.along = belt.speed() * time - (foot - belt.point).dot(ea);
    const Eigen::Matrix3Xd& x = fiber.positions();
    const Eigen::Vector3d ends = x.col(x.cols() - 1) - x.col(0);
    const double endToEnd = ends.norm();
    if (endToEnd > 0.0)
    {
        const Eigen::Vector3d t = ends / endToEnd;
        laid.orientation = Eigen::Vector3d(t.dot(ec), t.dot(ea), t.dot(belt.normal));
    }
    laid.endToEnd = endToEnd;
    laid.spread = fiber.state().populationSpread;
    laid.length = fiber.length();
    laid.binderMass = fiber.totalCapturedMass();
    laid.glassMass = fiber.totalMass() - laid.binderMass;
    laid.represents = fiber.represents();
    // One physical fiber's distribution (BinderSums counts a fiber N times: undone)
    BinderSums sums;
    sums.add(fiber);
    const BinderFigures figures = binderFigures(sums);
    laid.bareFraction = figures.bareFraction;
    laid.sigmaVariation = figures.sigmaVariation;
    return laid;
}

} // namespace dropletFiber
