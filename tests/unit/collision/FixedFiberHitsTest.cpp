// A fixed fiber in a uniform monodisperse spray, collision mode discrete against expected
// (docs/validation.md, discrete hits): M segments across the flow, each step's granted mass
// from eq. 9 (collisionMassFromSamples), the count drawn per segment and step.
//   - the mean capture equals the expected mode's within 5 sampling errors, 1/sqrt(hits);
//   - per segment and step the index of dispersion is 1 within 5 x sqrt((2 + 1/lambda)/K)
//     (K segment-steps) and the counts pass chi-square against Poisson(lambda) at 0.1 %;
//   - the fraction of segments with no hit after n steps is exp(-n lambda) within 5
//     binomial errors sqrt(p (1 - p) / M);
//   - with large counts (N = n lambda per segment) each segment's sigma is the expected
//     mode's within 5 / sqrt(N), and the spread over the segments is 1 / sqrt(N) within 5
//     of its sampling errors, 1 / sqrt(2 M).
#include "collision/DiscreteHits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace dropletFiber;

namespace
{

struct FixedFiber
{
    double dropletRadius = 1e-5, liquidDensity = 1000.0, fiberRadius = 1e-5;
    double segmentLength = 1e-4, speed = 1.0, dt = 1e-4;
    int segments = 2000;
    double lambda = 0.2; // expected droplets per segment and step (sets the number density)

    double dropletMass() const { return 4.0 / 3.0 * M_PI * std::pow(dropletRadius, 3) * liquidDensity; }
    DropletFieldValue field() const
    {
        // Eq. 9 by hand: lambda = 2 n (r_F + r) l v dt
        DropletFieldValue f;
        f.numberDensity = lambda / (2.0 * (fiberRadius + dropletRadius) * segmentLength * speed * dt);
        f.rho = f.numberDensity * dropletMass();
        f.rMeanNumber = f.rMeanMass = dropletRadius;
        f.velocity = Eigen::Vector3d(speed, 0.0, 0.0);
        return f;
    }
    // The segment's granted (here eq. 9's) mass per step, the same for every segment.
    double expectedMass() const
    {
        const DropletFieldValue f = field();
        const Eigen::Vector3d a(0.0, 0.0, 0.0), b(0.0, 0.0, segmentLength);
        return collisionMassFromSamples(&f, 1, a, b, fiberRadius, Eigen::Vector3d::Zero(), dt,
                                        CollisionOptions{})
            .mass;
    }
    // counts[t][j]: segment j's hits in step t.
    std::vector<std::vector<double>> draw(int steps, CollisionMode mode) const
    {
        const double granted = expectedMass();
        const double mHit = hitMass(field(), fiberRadius, RadiusAverage::Mass);
        std::vector<std::vector<double>> counts(static_cast<std::size_t>(steps),
                                                std::vector<double>(static_cast<std::size_t>(segments)));
        for (int t = 0; t < steps; ++t)
        {
            for (int j = 0; j < segments; ++j)
            {
                const HitKey key{5u, 31u, std::uint32_t(j), 0u, std::uint64_t(t + 1)};
                counts[std::size_t(t)][std::size_t(j)] = sampleHits(mode, granted, mHit, key).count;
            }
        }
        return counts;
    }
};

double poissonProbability(double lambda, int k)
{
    return std::exp(-lambda + k * std::log(lambda) - std::lgamma(k + 1.0));
}

} // namespace

TEST(FixedFiberHits, MeanDispersionAndPoissonLawPerSegmentAndStep)
{
    const FixedFiber fiber;
    EXPECT_NEAR(hitMass(fiber.field(), fiber.fiberRadius, RadiusAverage::Mass), fiber.dropletMass(),
                1e-12 * fiber.dropletMass());
    EXPECT_NEAR(fiber.expectedMass() / fiber.dropletMass(), fiber.lambda, 1e-12);
    const int steps = 20;
    const auto counts = fiber.draw(steps, CollisionMode::Discrete);
    double sum = 0.0, sum2 = 0.0;
    std::vector<double> histogram(4, 0.0); // 0, 1, 2, >= 3 (each expects >= 5 in K = 40000)
    for (const auto& step : counts)
    {
        for (const double k : step)
        {
            sum += k;
            sum2 += k * k;
            histogram[std::size_t(std::min(k, 3.0))] += 1.0;
        }
    }
    const double K = double(steps) * fiber.segments;
    const double mean = sum / K, variance = (sum2 - K * mean * mean) / (K - 1.0);
    // Captured mass over expected mass = mean count over lambda: 5 sampling errors
    EXPECT_NEAR(mean * fiber.dropletMass() / fiber.expectedMass(), 1.0, 5.0 / std::sqrt(sum));
    EXPECT_NEAR(variance / mean, 1.0, 5.0 * std::sqrt((2.0 + 1.0 / fiber.lambda) / K));
    double chi2 = 0.0, below = 0.0;
    for (int k = 0; k < 3; ++k)
    {
        const double p = poissonProbability(fiber.lambda, k);
        below += p;
        chi2 += std::pow(histogram[std::size_t(k)] - K * p, 2) / (K * p);
    }
    chi2 += std::pow(histogram[3] - K * (1.0 - below), 2) / (K * (1.0 - below));
    EXPECT_LT(chi2, 16.27); // chi-square, 3 degrees of freedom, upper 0.1 % point
}

TEST(FixedFiberHits, BareSegmentsAfterNStepsAreExpMinusNLambda)
{
    const FixedFiber fiber;
    const auto counts = fiber.draw(20, CollisionMode::Discrete);
    std::vector<double> total(std::size_t(fiber.segments), 0.0);
    for (int n = 1; n <= 20; ++n)
    {
        double bare = 0.0;
        for (int j = 0; j < fiber.segments; ++j)
        {
            total[std::size_t(j)] += counts[std::size_t(n - 1)][std::size_t(j)];
            bare += total[std::size_t(j)] == 0.0 ? 1.0 : 0.0;
        }
        const double p = std::exp(-n * fiber.lambda);
        EXPECT_NEAR(bare / fiber.segments, p, 5.0 * std::sqrt(p * (1.0 - p) / fiber.segments)) << n;
    }
}

TEST(FixedFiberHits, LargeCountsGiveTheExpectedSigmaWithinOneOverRootN)
{
    FixedFiber fiber;
    fiber.lambda = 1000.0;
    fiber.segments = 400;
    const int steps = 10;
    const auto discrete = fiber.draw(steps, CollisionMode::Discrete);
    const auto expected = fiber.draw(steps, CollisionMode::Expected);
    const double N = steps * fiber.lambda;
    double squares = 0.0;
    for (int j = 0; j < fiber.segments; ++j)
    {
        double hits = 0.0, expectedHits = 0.0;
        for (int t = 0; t < steps; ++t)
        {
            hits += discrete[std::size_t(t)][std::size_t(j)];
            expectedHits += expected[std::size_t(t)][std::size_t(j)];
        }
        // sigma = hits x droplet mass / length in both modes: their ratio is the counts'
        const double deviation = hits / expectedHits - 1.0;
        EXPECT_LT(std::fabs(deviation), 5.0 / std::sqrt(N)) << j;
        squares += deviation * deviation;
    }
    const double spread = std::sqrt(squares / fiber.segments) * std::sqrt(N);
    EXPECT_NEAR(spread, 1.0, 5.0 / std::sqrt(2.0 * fiber.segments));
}
