#include "collision/PoissonSampler.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{

double poissonByInversion(double lambda, UniformSource& uniforms)
{
    const double u = uniforms.next();
    double probability = std::exp(-lambda);
    double cumulative = probability;
    double k = 0.0;
    // P(k) underflows long after the cumulative has passed every uniform 1 - 2^-33
    while (u > cumulative && probability > 0.0)
    {
        k += 1.0;
        probability *= lambda / k;
        cumulative += probability;
    }
    return k;
}

// Hoermann's PTRS (1993, table 1 and algorithm PTRS), as in NumPy's random_poisson_ptrs.
double poissonByTransformedRejection(double lambda, UniformSource& uniforms)
{
    const double rootLambda = std::sqrt(lambda);
    const double logLambda = std::log(lambda);
    const double b = 0.931 + 2.53 * rootLambda;
    const double a = -0.059 + 0.02483 * b;
    const double inverseAlpha = 1.1239 + 1.1328 / (b - 3.4);
    const double acceptBelow = 0.9277 - 3.6224 / (b - 2.0);
    for (;;)
    {
        const double u = uniforms.next() - 0.5;
        const double v = uniforms.next();
        const double us = 0.5 - std::fabs(u);
        const double k = std::floor((2.0 * a / us + b) * u + lambda + 0.43);
        if (us >= 0.07 && v <= acceptBelow)
        {
            return k; // the squeeze: inside the hat's sure region
        }
        if (k < 0.0 || (us < 0.013 && v > us))
        {
            continue;
        }
        if (std::log(v) + std::log(inverseAlpha) - std::log(a / (us * us) + b)
            <= -lambda + k * logLambda - std::lgamma(k + 1.0))
        {
            return k;
        }
    }
}

} // namespace

double poissonCount(double lambda, UniformSource& uniforms)
{
    if (!(lambda >= 0.0) || !std::isfinite(lambda))
    {
        throw std::invalid_argument("poissonCount: the mean must be finite and >= 0, got "
                                    + std::to_string(lambda));
    }
    if (lambda == 0.0)
    {
        return 0.0;
    }
    return lambda < poissonInversionLimit ? poissonByInversion(lambda, uniforms)
                                          : poissonByTransformedRejection(lambda, uniforms);
}

} // namespace dropletFiber
