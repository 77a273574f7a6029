#include "GridMethod.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropletFiber
{
namespace validation
{

GridSpec gridSpecFor(const PaperSetting& setting, const GridMethod& method)
{
    if (method.nodes < 2)
    {
        throw std::invalid_argument("GridMethod: at least 2 nodes per direction");
    }
    const double hx = (setting.xMax - setting.xMin) / (method.nodes - 1);
    const double hy = (setting.yMax - setting.yMin) / (method.nodes - 1);
    // Widening keeps the spacing and the node positions of the box's grid: whole cells.
    const int extraX = static_cast<int>(std::ceil(method.margin / hx - 1e-9));
    const int extraY = static_cast<int>(std::ceil(method.margin / hy - 1e-9));
    GridSpec spec;
    spec.lower
        = Eigen::Vector3d(setting.xMin - extraX * hx, setting.yMin - extraY * hy, -0.5 * setting.depth);
    spec.upper = Eigen::Vector3d(setting.xMax + extraX * hx, setting.yMax + extraY * hy, 0.5 * setting.depth);
    spec.nodes = {{method.nodes + 2 * extraX, method.nodes + 2 * extraY, 1}};
    return spec;
}

GridOutcome runGridMethod(const PaperSetting& setting, const SprayDefinition& spray, const FiberCircle& fiber,
                          const GridMethod& method)
{
    const GridSpec spec = gridSpecFor(setting, method);
    KernelSettings kernelSettings = method.kernel;
    kernelSettings.cloudInCellBelow = method.cloudInCellBelow;
    DensityGrid grid(spec, kernelSettings, method.window);
    const SprayStreams streams(spray);
    const double h = std::max(spec.spacing(0), spec.spacing(1));
    // Nodes eq. 9 can interpolate: within one cell of the circle's bounding box.
    const double xLow = fiber.x - fiber.radius - h, xHigh = fiber.x + fiber.radius + h;
    const double yLow = fiber.y - fiber.radius - h, yHigh = fiber.y + fiber.radius + h;
    GridOutcome outcome;
    for (int step = 0; step < method.window; ++step)
    {
        for (const SprayParcel& sp : streams.parcels(step, spec.lower.y()))
        {
            const Parcel& p = sp.parcel;
            // Farthest a parcel reaches: its kernel's support, or one cell (cloud-in-cell
            // weights, or the fallback when the kernel reaches no node).
            const ParcelKernel kernel(0.5 * p.diameter, p.nParticle, kernelSettings, 2);
            const double reach = std::max(kernel.reach(), h);
            const double yEnd = p.position.y(), yStart = yEnd - p.velocity.y() * spray.dt;
            const double x = p.position.x();
            if (std::max(yEnd, yStart) < yLow - reach || std::min(yEnd, yStart) > yHigh + reach
                || x < xLow - reach || x > xHigh + reach)
            {
                continue;
            }
            grid.deposit(p, spray.dt);
            ++outcome.parcelsDeposited;
        }
        outcome.parcelsFallback
            = grid.stepStatistics().parcelsFallback + grid.stepStatistics().parcelsCloudInCell;
        grid.commitStep();
    }
    outcome.mass = gridCollisionMass(grid, fiber, setting.depth, 0.0, spray.dt,
                                     Eigen::Vector3d(0.0, -1.0, 0.0), method.eq9);
    outcome.rhoAtFiber = grid.sample(Eigen::Vector3d(fiber.x, fiber.y, 0.0)).rho;
    return outcome;
}

MeasuredField measureField(const SprayStreams& spray, double depth, double xLow, double xHigh, double yLow,
                           double yHigh, int steps)
{
    const double dt = spray.definition().dt;
    double mass = 0.0, massRadius = 0.0, count = 0.0, countRadius = 0.0;
    for (int step = 0; step < steps; ++step)
    {
        for (const SprayParcel& sp : spray.parcels(step, xLow, xHigh, yLow, yHigh))
        {
            const Parcel& p = sp.parcel;
            if (p.position.x() < xLow || p.position.x() > xHigh)
            {
                continue;
            }
            // Vertical path: the fraction of [yEnd, yStart] inside [yLow, yHigh].
            const double yEnd = p.position.y(), yStart = yEnd - p.velocity.y() * dt;
            const double a = std::min(yEnd, yStart), b = std::max(yEnd, yStart);
            const double inside = std::max(0.0, std::min(b, yHigh) - std::max(a, yLow));
            const double fraction = b > a ? inside / (b - a) : (a >= yLow && a <= yHigh ? 1.0 : 0.0);
            const double r = 0.5 * p.diameter;
            const double m = parcelMass(p) * fraction;
            mass += m;
            massRadius += m * r;
            count += p.nParticle * fraction;
            countRadius += p.nParticle * fraction * r;
        }
    }
    MeasuredField field;
    field.rho = mass / ((xHigh - xLow) * (yHigh - yLow) * depth * steps);
    field.rMeanMass = mass > 0.0 ? massRadius / mass : 0.0;
    field.rMeanNumber = count > 0.0 ? countRadius / count : 0.0;
    return field;
}

} // namespace validation
} // namespace dropletFiber
