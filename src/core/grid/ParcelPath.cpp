#include "grid/ParcelPath.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{

bool finite(const Eigen::Vector3d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// Liang-Barsky: the part [t0, t1] of start + t displacement, t in [0, 1], inside the closed
// box. Returns false when nothing is inside.
bool clipToBox(const GridSpec& spec, const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
               double& t0, double& t1)
{
    t0 = 0.0;
    t1 = 1.0;
    for (int d = 0; d < 3; ++d)
    {
        const double lo = spec.lower[d] - start[d];
        const double hi = spec.upper[d] - start[d];
        const double v = displacement[d];
        if (v == 0.0)
        {
            if (lo > 0.0 || hi < 0.0)
            {
                return false;
            }
            continue;
        }
        double a = lo / v;
        double b = hi / v;
        if (a > b)
        {
            std::swap(a, b);
        }
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1)
        {
            return false;
        }
    }
    return true;
}

} // namespace

void checkParcel(const Parcel& p, double dt)
{
    auto fail = [](const std::string& what) { throw std::invalid_argument("DensityGrid::deposit: " + what); };
    if (!finite(p.position))
    {
        fail("parcel position is not finite");
    }
    if (!finite(p.velocity))
    {
        fail("parcel velocity is not finite");
    }
    if (!(p.diameter >= 0.0) || !std::isfinite(p.diameter))
    {
        fail("parcel diameter must be finite and >= 0, got " + std::to_string(p.diameter));
    }
    if (!(p.nParticle >= 0.0) || !std::isfinite(p.nParticle))
    {
        fail("parcel nParticle must be finite and >= 0, got " + std::to_string(p.nParticle));
    }
    if (!(p.rhoDroplet >= 0.0) || !std::isfinite(p.rhoDroplet))
    {
        fail("droplet density must be finite and >= 0, got " + std::to_string(p.rhoDroplet));
    }
    if (!(dt >= 0.0) || !std::isfinite(dt))
    {
        fail("time step must be finite and >= 0, got " + std::to_string(dt));
    }
}

bool clipPath(const GridSpec& spec, const Parcel& parcel, double dt, double mass, StepStatistics& stats,
              ClippedPath& path)
{
    const Eigen::Vector3d displacement = parcel.velocity * dt;
    const Eigen::Vector3d start = parcel.position - displacement;
    double t0 = 0.0, t1 = 1.0;
    if (!clipToBox(spec, start, displacement, t0, t1))
    {
        ++stats.parcelsOutside;
        stats.massOutside += mass;
        return false;
    }
    path.fraction = (displacement.squaredNorm() > 0.0) ? t1 - t0 : 1.0;
    if (path.fraction < 1.0)
    {
        ++stats.parcelsPartlyOutside;
    }
    const double massInside = path.fraction * mass;
    stats.massDeposited += massInside;
    stats.massOutside += mass - massInside;
    if (!(path.fraction > 0.0))
    {
        return false; // touches the box in a single point: measure zero
    }
    // Projected into the active directions (flat: on the node layer).
    path.start = start + t0 * displacement;
    path.displacement = (t1 - t0) * displacement;
    for (int d = 0; d < 3; ++d)
    {
        if (spec.flat(d))
        {
            path.start[d] = spec.nodeCoordinate(d, 0);
            path.displacement[d] = 0.0;
        }
    }
    return true;
}

std::array<double, nQuantities> parcelTotals(const Parcel& parcel, double mass, double fraction)
{
    const double massInside = fraction * mass;
    const double radius = 0.5 * parcel.diameter;
    const double nParticle = parcel.nParticle;
    return {{massInside, fraction * nParticle, fraction * nParticle * radius, massInside * radius,
             massInside * parcel.velocity.x(), massInside * parcel.velocity.y(),
             massInside * parcel.velocity.z()}};
}

} // namespace dropletFiber
