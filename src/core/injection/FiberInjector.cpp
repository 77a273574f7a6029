#include "injection/FiberInjector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropletFiber
{

void FiberInjectorSpec::validate() const
{
    auto fail = [this](const std::string& entry, const std::string& what)
    { throw std::invalid_argument("injector '" + name + "': entry '" + entry + "' " + what); };
    if (!position.allFinite())
        fail("position", "must be finite");
    if (!velocity.allFinite())
        fail("velocity", "must be finite");
    if (!direction.allFinite() || direction.norm() == 0.0)
        fail("direction", "must be a non-zero vector");
    if (!(length > 0.0) || !std::isfinite(length))
        fail("length", "must be > 0");
    if (points < 2)
        fail("points", "must be >= 2");
    if (!(rate > 0.0) || !std::isfinite(rate))
        fail("rate", "must be > 0 (fibers per second)");
    if (!std::isfinite(startTime))
        fail("startTime", "must be finite");
    if (!(endTime > startTime))
        fail("endTime", "must be > startTime");
    if (!(material.radius > 0.0))
        fail("radius", "must be > 0");
    if (!(material.density > 0.0))
        fail("density", "must be > 0");
    if (!(material.youngsModulus >= 0.0))
        fail("youngsModulus", "must be >= 0");
    if (!(represents > 0.0) || !std::isfinite(represents))
        fail("represents", "must be finite and > 0 (the physical fibers each computed fiber stands for)");
}

double FiberInjectorSpec::massFlow() const
{
    return rate * represents * material.baseLineDensity() * length;
}

double representsForMassFlow(double massFlow, double rate, double length, const FiberMaterial& material)
{
    for (const double v : {massFlow, rate, length, material.radius, material.density})
    {
        if (!(v > 0.0) || !std::isfinite(v))
        {
            throw std::invalid_argument("representsForMassFlow: mass flow, rate, length, radius and density"
                                        " must be finite and > 0");
        }
    }
    return massFlow / (rate * material.baseLineDensity() * length);
}

FiberInjector::FiberInjector(FiberInjectorSpec spec) : spec_(std::move(spec))
{
    spec_.validate();
    spec_.direction.normalize();
}

long FiberInjector::bornBy(double t) const
{
    if (t < spec_.startTime)
    {
        return 0;
    }
    // Counted in double and converted once, after the cap by endTime: without an
    // endTime (a huge one) (end - start) rate exceeds every integer type, and its
    // conversion would overflow (SIGFPE, or no fibers at all).
    // t_k <= t  <=>  k <= (t - start) rate; a relative tolerance keeps a birth that
    // falls on a step boundary in that step, whatever the rounding of t (at most half
    // a birth interval: beyond 5e8 births it would count whole fibers early).
    const auto tolerance = [](double k) { return std::min(1e-9 * std::max(1.0, k), 0.5); };
    const double kMax = (t - spec_.startTime) * spec_.rate;
    const double upToT = std::floor(kMax + tolerance(kMax)) + 1.0;
    // t_k < endTime  <=>  k < (end - start) rate
    const double kEnd = (spec_.endTime - spec_.startTime) * spec_.rate;
    const double beforeEnd = std::ceil(kEnd - tolerance(kEnd));
    const double born = std::min(upToT, beforeEnd);
    if (!(born <= maxBirths))
    {
        throw std::overflow_error("injector '" + spec_.name + "': entry 'rate' " + std::to_string(spec_.rate)
                                  + " gives more than 2^53 fibers by time " + std::to_string(t)
                                  + " (births are no longer counted exactly)");
    }
    return static_cast<long>(born);
}

std::vector<Fiber> FiberInjector::inject(double t)
{
    std::vector<Fiber> born;
    const long total = bornBy(t);
    const double segment = spec_.length / (spec_.points - 1);
    for (long k = injected_; k < total; ++k)
    {
        const double birth = spec_.startTime + static_cast<double>(k) / spec_.rate;
        const Eigen::Vector3d start = spec_.position + spec_.velocity * (t - birth);
        Eigen::Matrix3Xd x(3, spec_.points);
        for (int i = 0; i < spec_.points; ++i)
        {
            x.col(i) = start + spec_.direction * (segment * i);
        }
        Fiber fiber(x, spec_.material);
        fiber.setVelocities(spec_.velocity.replicate(1, spec_.points));
        fiber.setRepresents(spec_.represents);
        born.push_back(std::move(fiber));
    }
    injected_ = std::max(injected_, total);
    return born;
}

} // namespace dropletFiber
