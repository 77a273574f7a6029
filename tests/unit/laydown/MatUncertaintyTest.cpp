// The mat's statistical errors (P60-P61) against the scatter of independent realisations:
// 400 mats of a Poisson rain of weighted fibers (random places, orientations, weights and
// binder, some with a population's hat), each with its own seed. The errors each mat
// estimates from its own fibers must match the scatter over the mats: a cell's area weight
// and LOI, a column's area weight, the mat's LOI; and, for a uniform rain (a mat with no real
// non-uniformity), the profile's CoV^2 must be the noise's on average. For a rain
// whose density varies across, the real CoV must be the ensemble mean profile's.
#include "laydown/MatUncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dropletFiber;

namespace
{
constexpr double pi = 3.14159265358979323846;

// One mat: width 0.2 in 10 columns, rows 0-9 of 0.02; fibers' centres along 0.05-0.15 so
// that every footprint lies within the rows. Across density 1 + a sin(2 pi x / 0.2).
MatMap rain(unsigned seed, double amplitude)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::poisson_distribution<int> count(300);
    MatMap map(0.02, 0.0, 0.2);
    const int n = count(rng);
    for (int k = 0; k < n; ++k)
    {
        LaidFiber f;
        do
            f.across = 0.2 * u(rng);
        while (u(rng) * (1.0 + amplitude) > 1.0 + amplitude * std::sin(2.0 * pi * f.across / 0.2));
        f.along = 0.05 + 0.1 * u(rng);
        const double angle = 2.0 * pi * u(rng);
        f.orientation = Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
        f.endToEnd = 0.03;
        f.represents = u(rng) < 0.5 ? 1000.0 : 3000.0;
        f.spread = u(rng) < 0.5 ? 0.03 : 0.0;
        f.glassMass = 1e-9;
        f.binderMass = 1e-10 * u(rng);
        map.add(f);
    }
    return map;
}

struct Scatter
{
    double sum = 0.0, squares = 0.0, estimated = 0.0;
    int n = 0;
    void add(double value, double error)
    {
        sum += value;
        squares += value * value;
        estimated += error * error;
        ++n;
    }
    double variance() const { return squares / n - (sum / n) * (sum / n); }
    double estimatedVariance() const { return estimated / n; }
};
} // namespace

TEST(MatUncertainty, ErrorsMatchTheScatterOfSeeds)
{
    Scatter cell, loi, column, loiAll;
    const int mats = 400;
    for (int s = 0; s < mats; ++s)
    {
        const MatMap map = rain(1000u + static_cast<unsigned>(s), 0.0);
        const auto it = map.cells().find({4, 4});
        ASSERT_NE(it, map.cells().end());
        cell.add(cellAreaWeight(it->second, 4e-4).value, cellAreaWeight(it->second, 4e-4).error);
        loi.add(cellLoi(it->second).value, cellLoi(it->second).error);
        const AcrossProfile p = acrossProfileWithErrors(map, 0, 9);
        column.add(p.areaWeight[3].value, p.areaWeight[3].error);
        loiAll.add(p.loiAll.value, p.loiAll.error);
    }
    // The variance of a variance estimate over 400 draws: sqrt(2/400) = 7 %
    EXPECT_NEAR(cell.estimatedVariance() / cell.variance(), 1.0, 0.2);
    EXPECT_NEAR(loi.estimatedVariance() / loi.variance(), 1.0, 0.2);
    EXPECT_NEAR(column.estimatedVariance() / column.variance(), 1.0, 0.2);
    EXPECT_NEAR(loiAll.estimatedVariance() / loiAll.variance(), 1.0, 0.2);
}

TEST(MatUncertainty, NoiseAndRealNonUniformity)
{
    const int mats = 300;
    // A uniform rain: the observed CoV^2 is the noise's on average (its real part, CoV^2
    // less the noise's, is 0 on average; each mat's scatters about it)
    double observed2 = 0.0, noise2 = 0.0;
    for (int s = 0; s < mats; ++s)
    {
        const NonUniformity u = nonUniformity(acrossProfileWithErrors(rain(5000u + s, 0.0), 0, 9));
        observed2 += u.observed * u.observed / mats;
        noise2 += u.noise * u.noise / mats;
    }
    EXPECT_NEAR(observed2 / noise2, 1.0, 0.1);
    // Density 1 + 0.6 sin across: the real CoV is the ensemble's mean profile's
    std::vector<double> meanProfile(10, 0.0);
    double realSum2 = 0.0;
    int covered = 0;
    std::vector<NonUniformity> each;
    for (int s = 0; s < mats; ++s)
    {
        const AcrossProfile p = acrossProfileWithErrors(rain(9000u + s, 0.6), 0, 9);
        for (std::size_t i = 0; i < 10; ++i)
            meanProfile[i] += p.areaWeight[i].value / mats;
        each.push_back(nonUniformity(p));
        realSum2 += each.back().real * each.back().real / mats;
    }
    AcrossProfile ensemble;
    for (double v : meanProfile)
        ensemble.areaWeight.push_back({v, 0.0});
    const double trueReal = nonUniformity(ensemble).observed;
    for (const NonUniformity& u : each)
        covered += u.realUpper >= trueReal ? 1 : 0;
    EXPECT_NEAR(std::sqrt(realSum2) / trueReal, 1.0, 0.1);
    // The two-sigma bound assumes Gaussian columns; with weights 1 : 3 and 10 columns it
    // holds in 89 % of these mats (97.7 % for Gaussian ones)
    EXPECT_GT(covered, static_cast<int>(0.85 * mats));
}
