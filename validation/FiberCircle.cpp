#include "FiberCircle.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dropletFiber
{
namespace validation
{

namespace
{
constexpr double pi = 3.14159265358979323846;
}

double formulaCollisionMass(double rho, double meanRadius, const FiberCircle& fiber, double depth,
                            const Eigen::Vector3d& velocity, double dt)
{
    return collisionMass(rho, meanRadius, fiber.radius, Eigen::Vector3d(0.0, 0.0, depth), velocity, dt);
}

double gridCollisionMass(const DensityGrid& grid, const FiberCircle& fiber, double depth, double zMid,
                         double dt, const Eigen::Vector3d& flowDirection, const Eq9Options& options)
{
    CollisionOptions collision;
    collision.radiusAverage = options.radiusAverage;
    collision.samples = 1;
    const Eigen::Vector3d halfAxis(0.0, 0.0, 0.5 * depth);
    if (options.sampling == Eq9Sampling::Axis)
    {
        const Eigen::Vector3d centre(fiber.x, fiber.y, zMid);
        return collisionMass(grid, centre - halfAxis, centre + halfAxis, fiber.radius,
                             Eigen::Vector3d::Zero(), dt, collision)
            .mass;
    }
    if (options.outlineSegments < 3 || !(options.maxSegmentInSpacings > 0.0))
    {
        throw std::invalid_argument("gridCollisionMass: the outline needs >= 3 segments of positive length");
    }
    double spacing = 0.0;
    for (int d = 0; d < 3; ++d)
    {
        if (!grid.spec().flat(d))
        {
            spacing = spacing == 0.0 ? grid.spec().spacing(d) : std::min(spacing, grid.spec().spacing(d));
        }
    }
    const double perimeter = 2.0 * pi * fiber.radius;
    const int n = std::max(options.outlineSegments,
                           static_cast<int>(std::ceil(perimeter / (options.maxSegmentInSpacings * spacing))));
    const Eigen::Vector3d u = flowDirection.normalized();
    std::vector<double> weights(static_cast<std::size_t>(n));
    std::vector<Eigen::Vector3d> midpoints(static_cast<std::size_t>(n));
    double weightSum = 0.0;
    for (int k = 0; k < n; ++k)
    {
        const double a0 = 2.0 * pi * k / n, a1 = 2.0 * pi * (k + 1) / n;
        const Eigen::Vector3d p0(fiber.x + fiber.radius * std::cos(a0), fiber.y + fiber.radius * std::sin(a0),
                                 zMid);
        const Eigen::Vector3d p1(fiber.x + fiber.radius * std::cos(a1), fiber.y + fiber.radius * std::sin(a1),
                                 zMid);
        const double w = (p1 - p0).cross(u).norm(); // projected width normal to the flow
        weights[static_cast<std::size_t>(k)] = w;
        midpoints[static_cast<std::size_t>(k)] = 0.5 * (p0 + p1);
        weightSum += w;
    }
    double mass = 0.0;
    for (int k = 0; k < n; ++k)
    {
        const Eigen::Vector3d& m = midpoints[static_cast<std::size_t>(k)];
        const double segmentMass = collisionMass(grid, m - halfAxis, m + halfAxis, fiber.radius,
                                                 Eigen::Vector3d::Zero(), dt, collision)
                                       .mass;
        mass += weights[static_cast<std::size_t>(k)] / weightSum * segmentMass;
    }
    return mass;
}

} // namespace validation
} // namespace dropletFiber
