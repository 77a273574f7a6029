#include "SprayStreams.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropletFiber
{
namespace validation
{

namespace
{
std::uint64_t splitmix(std::uint64_t x)
{
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

constexpr double pi = 3.14159265358979323846;
} // namespace

double hashUniform(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d)
{
    std::uint64_t h = splitmix(a);
    h = splitmix(h ^ b);
    h = splitmix(h ^ c);
    h = splitmix(h ^ d);
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0); // 53 bits
}

SprayStreams::SprayStreams(const SprayDefinition& definition) : def_(definition)
{
    if (def_.streams < 1 || !(def_.speed > 0.0) || !(def_.dt > 0.0) || !(def_.injectionInterval > 0.0))
    {
        throw std::invalid_argument(
            "SprayStreams: streams, speed, dt and injection interval must be positive");
    }
    if (def_.polydisperse
        && !(def_.radiusHigh > def_.radiusLow && def_.radiusLow > 0.0 && def_.parcelMass > 0.0))
    {
        throw std::invalid_argument(
            "SprayStreams: polydisperse spray needs 0 < radiusLow < radiusHigh, parcelMass > 0");
    }
    spacing_ = 2.0 * def_.injectionHalfWidth / def_.streams;
}

double SprayStreams::streamX(int stream) const
{
    return -def_.injectionHalfWidth + (stream + 0.5) * spacing_;
}

double SprayStreams::massPerStep() const
{
    const double parcelsPerStep = def_.streams * def_.dt / def_.injectionInterval;
    if (def_.polydisperse)
    {
        return parcelsPerStep * def_.parcelMass;
    }
    const double m = def_.dropletDensity * 4.0 / 3.0 * pi * std::pow(def_.dropletRadius, 3);
    return parcelsPerStep * def_.dropletsPerParcel * m;
}

double SprayStreams::meanRadiusMass() const
{
    // Every parcel carries the same mass and r is uniform: the mass pdf of r is uniform.
    return def_.polydisperse ? 0.5 * (def_.radiusLow + def_.radiusHigh) : def_.dropletRadius;
}

double SprayStreams::meanRadiusNumber() const
{
    if (!def_.polydisperse)
    {
        return def_.dropletRadius;
    }
    // Droplets per parcel n(r) ~ r^-3, parcels uniform in r: number pdf ~ r^-3 on [a, b],
    // mean = int r^-2 / int r^-3 = 2 a b / (a + b).
    const double a = def_.radiusLow, b = def_.radiusHigh;
    return 2.0 * a * b / (a + b);
}

double SprayStreams::analyticDensity(double depth) const
{
    // Mass injected per unit time, spread over the injection width and carried at `speed`.
    return massPerStep() / def_.dt / (2.0 * def_.injectionHalfWidth * def_.speed * depth);
}

std::vector<SprayParcel> SprayStreams::parcels(std::int64_t step, double xLow, double xHigh, double yLow,
                                               double yHigh) const
{
    std::vector<SprayParcel> result;
    const double t = static_cast<double>(step) * def_.dt;
    const double v = def_.speed;
    const double margin = def_.jitter ? 0.5 * spacing_ : 0.0;
    const int first
        = std::max(0, static_cast<int>(std::floor((xLow - margin + def_.injectionHalfWidth) / spacing_)));
    const int last
        = std::min(def_.streams - 1,
                   static_cast<int>(std::floor((xHigh + margin + def_.injectionHalfWidth) / spacing_)));
    // Age a = t - t_k of the parcels whose path [y, y + v dt] meets [yLow, yHigh]:
    //     y = yInjection - v a <= yHigh   and   y + v dt >= yLow,   and a >= 0.
    const double ageMin = std::max(0.0, (def_.yInjection - yHigh) / v);
    const double ageMax = (def_.yInjection - yLow) / v + def_.dt;
    if (!(ageMax >= ageMin))
    {
        return result;
    }
    const double kHigh = std::floor((t - ageMin) / def_.injectionInterval - def_.injectionPhase);
    const double kLow = std::ceil((t - ageMax) / def_.injectionInterval - def_.injectionPhase);
    const std::uint64_t seed = def_.seed;
    for (int i = first; i <= last; ++i)
    {
        for (double kd = kLow; kd <= kHigh; kd += 1.0)
        {
            const auto k = static_cast<std::int64_t>(kd);
            const std::uint64_t id = (static_cast<std::uint64_t>(i) << 40) ^ static_cast<std::uint64_t>(k);
            const double age
                = (t - kd * def_.injectionInterval) - def_.injectionPhase * def_.injectionInterval;
            if (age < 0.0)
            {
                continue;
            }
            double x = streamX(i);
            if (def_.jitter)
            {
                x += spacing_
                    * (hashUniform(seed, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(k), 1)
                       - 0.5);
            }
            SprayParcel p;
            p.id = id;
            p.parcel.position = Eigen::Vector3d(x, def_.yInjection - v * age, def_.zMid);
            p.parcel.velocity = Eigen::Vector3d(0.0, -v, 0.0);
            p.parcel.rhoDroplet = def_.dropletDensity;
            if (def_.polydisperse)
            {
                const double u
                    = hashUniform(seed, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(k), 2);
                const double r = def_.radiusLow + u * (def_.radiusHigh - def_.radiusLow);
                p.parcel.diameter = 2.0 * r;
                p.parcel.nParticle = def_.parcelMass / (def_.dropletDensity * 4.0 / 3.0 * pi * r * r * r);
            }
            else
            {
                p.parcel.diameter = 2.0 * def_.dropletRadius;
                p.parcel.nParticle = def_.dropletsPerParcel;
            }
            result.push_back(p);
        }
    }
    return result;
}

std::vector<SprayParcel> SprayStreams::parcels(std::int64_t step, double yLow) const
{
    return parcels(step, -def_.injectionHalfWidth, def_.injectionHalfWidth, yLow, def_.yInjection);
}

} // namespace validation
} // namespace dropletFiber
