#include "grid/ParcelKernel.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{
constexpr double pi = 3.14159265358979323846;
}

void KernelSettings::validate() const
{
    if (!(beta > 0.0 && beta <= 1.0))
    {
        throw std::invalid_argument("kernel: beta must lie in (0, 1], got " + std::to_string(beta));
    }
    if (!std::isfinite(rMaxCap))
    {
        throw std::invalid_argument("kernel: rMaxCap must be finite (use 0 for no cap)");
    }
    if (!(cloudInCellBelow >= 0.0) || !std::isfinite(cloudInCellBelow))
    {
        throw std::invalid_argument(
            "kernel: cloudInCellBelow must be finite and >= 0 (0: always the kernel), got "
            + std::to_string(cloudInCellBelow));
    }
    // Up to 1e-6: the cut is meant to drop round-off, not to truncate the kernel visibly.
    if (!(negligibleWeight >= 0.0 && negligibleWeight <= 1e-6))
    {
        throw std::invalid_argument("kernel: negligibleWeight must lie in [0, 1e-6] (0: exact tails), got "
                                    + std::to_string(negligibleWeight));
    }
}

double influenceRadiusMax(double dropletRadius, double nParticle)
{
    return dropletRadius * nParticle;
}

double influenceRadiusMin(double dropletRadius, double nParticle, int dimension)
{
    if (dimension == 3)
    {
        return dropletRadius * std::cbrt(std::sqrt(18.0) * nParticle / pi);
    }
    return dropletRadius * std::sqrt(2.0 * std::sqrt(3.0) * nParticle / pi);
}

double kernelAlpha(double rMax, double rMin, double beta)
{
    const double inflection = beta * rMax + (1.0 - beta) * rMin;
    return rMax * rMax / (2.0 * inflection * inflection);
}

ParcelKernel::ParcelKernel(double dropletRadius, double nParticle, const KernelSettings& settings,
                           int dimension)
{
    if (!(dropletRadius > 0.0) || !(nParticle > 0.0) || !std::isfinite(dropletRadius)
        || !std::isfinite(nParticle))
    {
        throw std::invalid_argument("ParcelKernel: droplet radius and nParticle must be positive and finite");
    }
    rMax_ = influenceRadiusMax(dropletRadius, nParticle);
    rMin_ = influenceRadiusMin(dropletRadius, nParticle, dimension);
    alpha_ = kernelAlpha(rMax_, rMin_, settings.beta);
    double reach = rMax_;
    if (settings.rMaxCap > 0.0 && settings.rMaxCap < rMax_)
    {
        reach = settings.rMaxCap;
        capped_ = true;
    }
    setShape(alpha_ / (rMax_ * rMax_), reach);
}

ParcelKernel ParcelKernel::fromShape(double gamma, double reach)
{
    ParcelKernel kernel;
    kernel.rMax_ = reach;
    kernel.alpha_ = gamma * reach * reach;
    kernel.setShape(gamma, reach);
    return kernel;
}

void ParcelKernel::setShape(double gamma, double reach)
{
    gamma_ = gamma;
    reach_ = reach;
    edgeExponent_ = gamma * reach * reach;
    edgeValue_ = std::exp(-edgeExponent_);
}

double ParcelKernel::phi(double distance) const
{
    return phiOfSquaredDistance(distance * distance);
}

double ParcelKernel::phiOfSquaredDistance(double distanceSquared) const
{
    const double reach2 = reach_ * reach_;
    if (!(distanceSquared < reach2))
    {
        return 0.0;
    }
    // phi = exp(-a) * expm1(q) with q = gamma (reach^2 - d^2): near the edge of the support
    // (q small) the two exponentials of eq. 12 nearly cancel; expm1 keeps full precision.
    const double q = gamma_ * (reach2 - distanceSquared);
    if (q < 0.25)
    {
        return edgeValue_ * std::expm1(q);
    }
    return std::exp(-gamma_ * distanceSquared) - edgeValue_;
}

double ParcelKernel::width() const
{
    return rMax_ / std::sqrt(2.0 * alpha_);
}

} // namespace dropletFiber
