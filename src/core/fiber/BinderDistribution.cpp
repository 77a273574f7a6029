#include "fiber/BinderDistribution.hpp"

#include <algorithm>
#include <cmath>

namespace dropletFiber
{

void BinderSums::add(const Fiber& fiber)
{
    // Each of the N physical fibers it stands for counts (N times the sums of one)
    const double n = fiber.represents();
    const Eigen::VectorXd& lengths = fiber.restLengths();
    const Eigen::VectorXd& mass = fiber.capturedMassPerSegment();
    const Eigen::VectorXd& hits = fiber.state().segmentHits;
    const Eigen::VectorXd& expected = fiber.state().segmentExpectedMass;
    for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
    {
        values[0] += n * lengths(j);
        values[1] += n * (mass(j) > 0.0 ? 0.0 : lengths(j));
        values[2] += n * mass(j);
        values[3] += n * (mass(j) * mass(j) / lengths(j));
        values[4] += n * (hits.size() > j ? hits(j) : 0.0);
        values[5] += 1.0; // computed segments: the resolution, not weighted
        const double e = expected.size() > j ? expected(j) : mass(j);
        values[6] += n * (e > 0.0 ? 0.0 : lengths(j));
        values[7] += n * e;
        values[8] += n * (e * e / lengths(j));
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

namespace
{
// sqrt(sum l sigma^2 / L - mean^2) / mean (sum l (sigma - mean)^2 / L, as sum l sigma = mean L)
double variation(double sumLengthSigma2, double length, double mean)
{
    if (!(mean > 0.0))
    {
        return 0.0;
    }
    return std::sqrt(std::max(0.0, sumLengthSigma2 / length - mean * mean)) / mean;
}
} // namespace

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
    f.sigmaVariation = variation(sums.values[3], length, f.meanSigma);
    f.expectedBareFraction = sums.values[6] / length;
    f.expectedMeanSigma = sums.values[7] / length;
    f.expectedSigmaVariation = variation(sums.values[8], length, f.expectedMeanSigma);
    return f;
}

} // namespace dropletFiber
