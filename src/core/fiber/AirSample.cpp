#include "fiber/AirSample.hpp"

namespace dropletFiber
{

Eigen::Index airSamplePointCount(const Fiber& fiber)
{
    return fiber.immobile() ? 0 : fiber.pointCount();
}

AirSampleLayout airSampleLayout(const std::vector<Fiber>& fibers)
{
    AirSampleLayout layout;
    layout.firstPoint.reserve(fibers.size());
    for (const Fiber& fiber : fibers)
    {
        layout.firstPoint.push_back(layout.pointCount);
        layout.pointCount += airSamplePointCount(fiber);
    }
    return layout;
}

Eigen::Matrix3Xd airSamplePoints(const std::vector<Fiber>& fibers)
{
    const AirSampleLayout layout = airSampleLayout(fibers);
    Eigen::Matrix3Xd points(3, layout.pointCount);
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        if (airSamplePointCount(fibers[f]) > 0)
        {
            points.middleCols(layout.firstPoint[f], fibers[f].pointCount()) = fibers[f].positions();
        }
    }
    return points;
}

AirSample airSampleOfFibers(const AirSample& sample, const std::vector<Fiber>& fibers,
                            const std::vector<std::size_t>& subset)
{
    AirSample part;
    if (sample.pointCount() == 0)
        return part;
    const AirSampleLayout layout = airSampleLayout(fibers);
    Eigen::Index partPoints = 0;
    for (const std::size_t f : subset)
        partPoints += airSamplePointCount(fibers[f]);
    part.velocity.resize(3, partPoints);
    part.density.resize(partPoints);
    part.viscosity.resize(partPoints);
    Eigen::Index at = 0;
    for (const std::size_t f : subset)
    {
        const Eigen::Index n = airSamplePointCount(fibers[f]);
        const Eigen::Index from = layout.firstPoint[f];
        part.velocity.middleCols(at, n) = sample.velocity.middleCols(from, n);
        part.density.segment(at, n) = sample.density.segment(from, n);
        part.viscosity.segment(at, n) = sample.viscosity.segment(from, n);
        at += n;
    }
    return part;
}

AirSample uniformAir(const std::vector<Fiber>& fibers, const Eigen::Vector3d& velocity, double density,
                     double viscosity)
{
    const Eigen::Index n = airSampleLayout(fibers).pointCount;
    AirSample air;
    air.velocity = velocity.replicate(1, n);
    air.density = Eigen::VectorXd::Constant(n, density);
    air.viscosity = Eigen::VectorXd::Constant(n, viscosity);
    return air;
}

} // namespace dropletFiber
