#include "fiber/BinderDistribution.hpp"

#include <algorithm>
#include <cmath>

namespace dropletFiber
{

void BinderSums::add(const Fiber& fiber)
{
    const Eigen::VectorXd& lengths = fiber.restLengths();
    const Eigen::VectorXd& mass = fiber.capturedMassPerSegment();
    const Eigen::VectorXd& hits = fiber.state().segmentHits;
    for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
    {
        values[0] += lengths(j);
        values[1] += mass(j) > 0.0 ? 0.0 : lengths(j);
        values[2] += mass(j);
        values[3] += mass(j) * mass(j) / lengths(j);
        values[4] += hits.size() > j ? hits(j) : 0.0;
        values[5] += 1.0;
    }
}

BinderSums& BinderSums::operator+=(const BinderSums& other)
{
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        values[i] += other.values[i];
    }
    return *this;
}

BinderFigures binderFigures(const BinderSums& sums)
{
    BinderFigures f;
    const double length = sums.values[0];
    if (!(length > 0.0))
    {
        return f;
    }
    f.length = length;
    f.bareFraction = sums.values[1] / length;
    f.meanSigma = sums.values[2] / length;
    f.hitsPerLength = sums.values[4] / length;
    if (f.meanSigma > 0.0)
    {
        // sum l (sigma - mean)^2 / L = sum l sigma^2 / L - mean^2 (sum l sigma = mean L)
        const double variance = std::max(0.0, sums.values[3] / length - f.meanSigma * f.meanSigma);
        f.sigmaVariation = std::sqrt(variance) / f.meanSigma;
    }
    return f;
}

} // namespace dropletFiber
