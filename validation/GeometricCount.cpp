#include "GeometricCount.hpp"

#include "grid/ParcelKernel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropletFiber
{
namespace validation
{

namespace
{
constexpr double pi = 3.14159265358979323846;

double distanceToSegmentSquared(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
{
    const Eigen::Vector2d ab = b - a;
    const double lengthSquared = ab.squaredNorm();
    double t = lengthSquared > 0.0 ? (c - a).dot(ab) / lengthSquared : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    return (a + t * ab - c).squaredNorm();
}

// Largest r_min (eq. 14) and droplet radius the spray can produce: bounds for the search box.
void sprayBounds(const SprayDefinition& spray, double& rMinBound, double& radiusBound)
{
    if (!spray.polydisperse)
    {
        rMinBound = influenceRadiusMin(spray.dropletRadius, spray.dropletsPerParcel, 2);
        radiusBound = spray.dropletRadius;
        return;
    }
    // n(r) ~ r^-3, so r_min ~ r sqrt(n) ~ r^-1/2: largest for the smallest droplets.
    const double mLow = spray.dropletDensity * 4.0 / 3.0 * pi * std::pow(spray.radiusLow, 3);
    rMinBound = influenceRadiusMin(spray.radiusLow, spray.parcelMass / mLow, 2);
    radiusBound = spray.radiusHigh;
}
} // namespace

bool pathEntersCircle(const Eigen::Vector2d& start, const Eigen::Vector2d& end, const Eigen::Vector2d& centre,
                      double radius)
{
    const double r2 = radius * radius;
    if ((start - centre).squaredNorm() < r2)
    {
        return false; // already inside at the start of the step: entered earlier
    }
    return distanceToSegmentSquared(start, end, centre) < r2;
}

double geometricStepMass(const std::vector<SprayParcel>& parcels, const FiberCircle& fiber, double dt,
                         DropletPlacement placement, std::uint64_t seed)
{
    const Eigen::Vector2d centre(fiber.x, fiber.y);
    double mass = 0.0;
    for (const SprayParcel& sp : parcels)
    {
        const Parcel& p = sp.parcel;
        const double r = 0.5 * p.diameter;
        const double n = p.nParticle;
        const double dropletMass = p.rhoDroplet * 4.0 / 3.0 * pi * r * r * r;
        const Eigen::Vector2d end(p.position.x(), p.position.y());
        const Eigen::Vector2d start = end - dt * Eigen::Vector2d(p.velocity.x(), p.velocity.y());
        const double hitRadius = fiber.radius + r;
        if (placement == DropletPlacement::ParcelPoint)
        {
            if (pathEntersCircle(start, end, centre, hitRadius))
            {
                mass += n * dropletMass;
            }
            continue;
        }
        // Spread: droplets within r_min of the parcel. Quick rejection of parcels that no
        // droplet can enter from: the path too far, or every droplet already inside.
        const double rMin = influenceRadiusMin(r, n, 2);
        const double far = hitRadius + rMin;
        if (distanceToSegmentSquared(start, end, centre) >= far * far)
        {
            continue;
        }
        const double inner = hitRadius - rMin;
        if (inner > 0.0 && (start - centre).squaredNorm() < inner * inner)
        {
            continue;
        }
        const int droplets = std::max(1, static_cast<int>(std::ceil(n - 1e-9)));
        const double share = n / droplets * dropletMass;
        for (int j = 0; j < droplets; ++j)
        {
            // Uniform in the disc of radius r_min.
            const double u1 = hashUniform(seed, sp.id, static_cast<std::uint64_t>(j), 11);
            const double u2 = hashUniform(seed, sp.id, static_cast<std::uint64_t>(j), 12);
            const double rho = rMin * std::sqrt(u1), angle = 2.0 * pi * u2;
            const Eigen::Vector2d offset(rho * std::cos(angle), rho * std::sin(angle));
            if (pathEntersCircle(start + offset, end + offset, centre, hitRadius))
            {
                mass += share;
            }
        }
    }
    return mass;
}

MeanAndError geometricMass(const SprayDefinition& spray, const FiberCircle& fiber, DropletPlacement placement,
                           int seeds, int steps)
{
    if (seeds < 1 || steps < 1)
    {
        throw std::invalid_argument("geometricMass: seeds and steps must be >= 1");
    }
    double rMinBound = 0.0, radiusBound = 0.0;
    sprayBounds(spray, rMinBound, radiusBound);
    const double reach
        = fiber.radius + radiusBound + (placement == DropletPlacement::Spread ? rMinBound : 0.0);
    const double flight = spray.speed * spray.dt;
    std::vector<double> seedMeans;
    for (int s = 0; s < seeds; ++s)
    {
        SprayDefinition seeded = spray;
        seeded.seed = spray.seed + static_cast<std::uint64_t>(s);
        const SprayStreams streams(seeded);
        double sum = 0.0;
        for (int step = 0; step < steps; ++step)
        {
            const std::vector<SprayParcel> parcels = streams.parcels(
                step, fiber.x - reach, fiber.x + reach, fiber.y - reach, fiber.y + reach + flight);
            sum += geometricStepMass(parcels, fiber, spray.dt, placement, seeded.seed);
        }
        seedMeans.push_back(sum / steps);
    }
    MeanAndError result;
    result.samples = seeds;
    double mean = 0.0;
    for (double m : seedMeans)
    {
        mean += m;
    }
    mean /= seeds;
    double variance = 0.0;
    for (double m : seedMeans)
    {
        variance += (m - mean) * (m - mean);
    }
    result.mean = mean;
    result.standardError = seeds > 1 ? std::sqrt(variance / (seeds - 1) / seeds) : 0.0;
    return result;
}

} // namespace validation
} // namespace dropletFiber
