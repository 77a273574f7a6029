// DiscreteHits and PoissonSampler (docs/model.md sec. 3, P30): the Poisson law of the
// sampler in both branches (mean, index of dispersion, chi-square), the droplet mass of a
// hit from the grid's moments against a class-by-class count, and a fixed fiber in a
// uniform monodisperse spray (validation.md, discrete hits): the mean capture is the
// expected mode's, the fraction of bare segments after n steps is exp(-n lambda), and
// large counts give the expected sigma within 1/sqrt(N). Tolerances are stated with each
// test; the draws are fixed (counter-based keys), so the tests are reproducible.
#include "collision/DiscreteHits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace dropletFiber;

namespace
{

// Upper 0.1 % point of chi-square with k degrees of freedom (Wilson-Hilferty, z = 3.09).
double chiSquareUpper(int k)
{
    const double c = 2.0 / (9.0 * k);
    return k * std::pow(1.0 - c + 3.09 * std::sqrt(c), 3);
}

// Poisson probabilities computed in log space, independently of the sampler's recursion.
double poissonProbability(double lambda, int k)
{
    return std::exp(-lambda + k * std::log(lambda) - std::lgamma(k + 1.0));
}

struct Moments
{
    double mean = 0.0, variance = 0.0;
    std::vector<long> histogram;
};

Moments drawMany(double lambda, int draws)
{
    Moments m;
    double sum = 0.0, sum2 = 0.0;
    for (int d = 0; d < draws; ++d)
    {
        HitKey key{11u, 4242u, std::uint32_t(d % 97), std::uint32_t(d % 3), std::uint64_t(d / 97)};
        HitUniforms uniforms(key);
        const double k = poissonCount(lambda, uniforms);
        sum += k;
        sum2 += k * k;
        const auto bin = static_cast<std::size_t>(k);
        if (bin >= m.histogram.size())
        {
            m.histogram.resize(bin + 1, 0);
        }
        ++m.histogram[bin];
    }
    m.mean = sum / draws;
    m.variance = (sum2 - draws * m.mean * m.mean) / (draws - 1);
    return m;
}

// Chi-square of the histogram against Poisson(lambda), bins pooled until each expects >= 5.
void expectPoissonHistogram(const Moments& m, double lambda, int draws)
{
    double chi2 = 0.0, observed = 0.0, expected = 0.0, expectedSoFar = 0.0;
    int bins = 0;
    const int top = int(lambda + 12.0 * std::sqrt(lambda) + 12.0);
    for (int k = 0; k <= top; ++k)
    {
        observed += k < int(m.histogram.size()) ? double(m.histogram[std::size_t(k)]) : 0.0;
        expected += draws * poissonProbability(lambda, k);
        const double tail = draws - expectedSoFar - expected; // the rest, pooled into the last bin
        if (expected >= 5.0 && tail >= 5.0)
        {
            chi2 += (observed - expected) * (observed - expected) / expected;
            expectedSoFar += expected;
            observed = expected = 0.0;
            ++bins;
        }
    }
    long drawn = 0;
    for (long c : m.histogram)
    {
        drawn += c;
    }
    double seen = 0.0;
    for (int k = 0; k <= top && k < int(m.histogram.size()); ++k)
    {
        seen += double(m.histogram[std::size_t(k)]);
    }
    observed += double(drawn) - seen; // beyond top
    expected = draws - expectedSoFar;
    chi2 += (observed - expected) * (observed - expected) / expected;
    ++bins;
    EXPECT_LT(chi2, chiSquareUpper(bins - 1)) << "lambda " << lambda << ", " << bins << " bins";
}

} // namespace

// Both branches (inversion below 10, PTRS from 10): mean within 5 standard errors
// sqrt(lambda / N); index of dispersion var / mean within 5 x sqrt((2 + 1 / lambda) / N)
// (the variance of the sample variance of a Poisson law, (lambda + 2 lambda^2) / N);
// the histogram passes chi-square at the 0.1 % level.
TEST(PoissonSampler, MeanDispersionAndChiSquareInBothBranches)
{
    const int draws = 40000;
    for (const double lambda : {0.05, 0.7, 3.0, 9.5, 10.0, 37.0, 800.0})
    {
        const Moments m = drawMany(lambda, draws);
        EXPECT_NEAR(m.mean, lambda, 5.0 * std::sqrt(lambda / draws)) << lambda;
        EXPECT_NEAR(m.variance / m.mean, 1.0, 5.0 * std::sqrt((2.0 + 1.0 / lambda) / draws)) << lambda;
        expectPoissonHistogram(m, lambda, draws);
    }
}

TEST(PoissonSampler, RejectsABadMean)
{
    HitUniforms uniforms(HitKey{});
    EXPECT_THROW(poissonCount(-1.0, uniforms), std::invalid_argument);
    EXPECT_THROW(poissonCount(std::nan(""), uniforms), std::invalid_argument);
    EXPECT_EQ(poissonCount(0.0, uniforms), 0.0);
}

// Every part of the key changes the draw; the same key gives the same draw; fiber ids
// from 2^32 on are refused (the stream bit's room, DiscreteHits.hpp).
TEST(DiscreteHits, KeyedBySeedFiberSegmentSampleAndStep)
{
    const HitKey base{3u, 77u, 5u, 1u, 900u};
    auto first = [](HitKey k) { return HitUniforms(k).next(); };
    EXPECT_EQ(first(base), first(base));
    HitKey k = base;
    k.seed = 4u;
    EXPECT_NE(first(k), first(base));
    k = base;
    k.fiberId = 78u;
    EXPECT_NE(first(k), first(base));
    k = base;
    k.segment = 6u;
    EXPECT_NE(first(k), first(base));
    k = base;
    k.sample = 2u;
    EXPECT_NE(first(k), first(base));
    k = base;
    k.step = 901u;
    EXPECT_NE(first(k), first(base));
    k = base;
    k.fiberId = std::uint64_t(1) << 32;
    EXPECT_THROW(HitUniforms{k}, std::invalid_argument);
}

// Two droplet classes (radii r1, r2, numbers n1, n2 per volume): eq. 9 with the moments
// the grid carries over m_hit (P30) is the class-by-class count sum_i 2 n_i (r_F + r_i)
// |l x v| dt, for both radius averages (each with its own eq. 9 mass).
TEST(DiscreteHits, HitMassGivesTheClassByClassCount)
{
    const double rF = 8e-6, r1 = 5e-6, r2 = 2e-5, n1 = 3e10, n2 = 2e9, rhoL = 1100.0;
    const double m1 = 4.0 / 3.0 * M_PI * r1 * r1 * r1 * rhoL, m2 = 4.0 / 3.0 * M_PI * r2 * r2 * r2 * rhoL;
    DropletFieldValue field;
    field.rho = n1 * m1 + n2 * m2;
    field.numberDensity = n1 + n2;
    field.rMeanNumber = (n1 * r1 + n2 * r2) / (n1 + n2);
    field.rMeanMass = (n1 * m1 * r1 + n2 * m2 * r2) / field.rho;
    const Eigen::Vector3d segment(0.0, 0.0, 1e-3), velocity(2.0, 0.5, 0.0);
    const double dt = 1e-4, sweep = 2.0 * segment.cross(velocity).norm() * dt;
    const double count = sweep * (n1 * (rF + r1) + n2 * (rF + r2));
    for (const RadiusAverage average : {RadiusAverage::Mass, RadiusAverage::Number})
    {
        const double radius = average == RadiusAverage::Mass ? field.rMeanMass : field.rMeanNumber;
        const double mass = collisionMass(field.rho, radius, rF, segment, velocity, dt);
        EXPECT_NEAR(mass / hitMass(field, rF, average), count, 1e-12 * count);
    }
    // The mass average's eq. 9 is the class-by-class mass, so m_hit is the mean caught mass
    const double caughtMass = sweep * (n1 * (rF + r1) * m1 + n2 * (rF + r2) * m2);
    EXPECT_NEAR(hitMass(field, rF, RadiusAverage::Mass), caughtMass / count, 1e-12 * caughtMass / count);
    field.numberDensity = 0.0;
    EXPECT_EQ(hitMass(field, rF, RadiusAverage::Mass), 0.0);
}

TEST(DiscreteHits, ExpectedModeGivesTheMeanDiscreteWholeDroplets)
{
    const HitKey key{1u, 2u, 3u, 0u, 4u};
    const SampleHits expected = sampleHits(CollisionMode::Expected, 3e-9, 2e-10, key);
    EXPECT_DOUBLE_EQ(expected.count, 15.0);
    EXPECT_EQ(expected.mass, 3e-9);
    const SampleHits discrete = sampleHits(CollisionMode::Discrete, 3e-9, 2e-10, key);
    EXPECT_EQ(discrete.count, std::floor(discrete.count));
    EXPECT_EQ(discrete.mass, discrete.count * 2e-10);
    EXPECT_EQ(sampleHits(CollisionMode::Discrete, 0.0, 2e-10, key).count, 0.0);
    EXPECT_EQ(sampleHits(CollisionMode::Discrete, 3e-9, 0.0, key).count, 0.0);
}
