#include "collision/CollisionMass.hpp"

#include <Eigen/Geometry> // cross(): declared by Eigen/Core, defined here

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dropletFiber
{

double collisionMass(double rho, double meanRadius, double fiberRadius, const Eigen::Vector3d& segment,
                     const Eigen::Vector3d& relativeVelocity, double dt)
{
    // |l x v_rel| = |v_rel . n| |l| (identity under eq. 5): zero for v_rel parallel to l.
    return 2.0 * rho * (fiberRadius + meanRadius) * segment.cross(relativeVelocity).norm() * dt;
}

int collisionSamples(const DensityGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const CollisionOptions& options)
{
    return collisionSamples(grid.spec(), a, b, options);
}

int collisionSamples(const GridSpec& spec, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const CollisionOptions& options)
{
    if (options.samples > 0)
    {
        return options.samples;
    }
    if (options.samples < 0)
    {
        throw std::invalid_argument("collisionMass: samples must be >= 0");
    }
    // Automatic: one sample per node spacing spanned in the grid's active directions.
    double cells = 0.0;
    for (int d = 0; d < 3; ++d)
    {
        if (!spec.flat(d))
        {
            cells = std::max(cells, std::abs(b[d] - a[d]) / spec.spacing(d));
        }
    }
    return static_cast<int>(std::min(1e6, std::max(1.0, std::ceil(cells))));
}

Eigen::Vector3d samplePoint(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int samples, int s)
{
    const Eigen::Vector3d piece = (b - a) / samples;
    return a + (s + 0.5) * piece;
}

SegmentCollision collisionMassFromSamples(const DropletFieldValue* fields, int samples,
                                          const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          double fiberRadius, const Eigen::Vector3d& segmentVelocity,
                                          double dt, const CollisionOptions& options, double* sampleMasses)
{
    SegmentCollision result;
    const Eigen::Vector3d piece = (b - a) / samples;
    result.samples = samples;
    for (int s = 0; s < samples; ++s)
    {
        if (sampleMasses != nullptr)
        {
            sampleMasses[s] = 0.0;
        }
        const DropletFieldValue& field = fields[s];
        if (!field.inside)
        {
            ++result.samplesOutside;
            continue;
        }
        if (field.rho <= 0.0)
        {
            continue;
        }
        const double meanRadius
            = options.radiusAverage == RadiusAverage::Mass ? field.rMeanMass : field.rMeanNumber;
        const Eigen::Vector3d relative = field.velocity - segmentVelocity;
        const double mass = collisionMass(field.rho, meanRadius, fiberRadius, piece, relative, dt);
        result.mass += mass;
        result.momentum += mass * field.velocity;
        if (sampleMasses != nullptr)
        {
            sampleMasses[s] = mass;
        }
    }
    return result;
}

SegmentCollision collisionMass(const DensityGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               double fiberRadius, const Eigen::Vector3d& segmentVelocity, double dt,
                               const CollisionOptions& options)
{
    const int samples = collisionSamples(grid, a, b, options);
    std::vector<DropletFieldValue> fields(static_cast<std::size_t>(samples));
    for (int s = 0; s < samples; ++s)
    {
        fields[static_cast<std::size_t>(s)] = grid.sample(samplePoint(a, b, samples, s));
    }
    return collisionMassFromSamples(fields.data(), samples, a, b, fiberRadius, segmentVelocity, dt, options);
}

} // namespace dropletFiber
