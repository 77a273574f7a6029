// The separable weights' AVX2 + FMA loops (SeparableLanes, used by SeparableWeight and the
// deposit's accumulation on CPUs that have AVX2 + FMA) against plain evaluations written
// here:
//  - rows: omega_i = sum_q r_q X_q(i) in long double for Q = 1..12, every row length up to
//    41 and every start position (alignment), within the sum's rounding ((Q + 1) ulp, all
//    terms positive); a part of a row (every first, count) is those positions of the whole
//    row to the bit, whatever the part's split into 16-, 4- and 1-3-node pieces;
//  - tables: exp(-gamma (x - c)^2) within 1.5 ulp of std::exp's of the same argument (the
//    inline exp: 1.01 ulp);
//  - accumulation: each value is fma(omega inverseSum, total, value), to the bit (std::fma
//    here), for every row length and split;
//  - normalising sum: the per-axis compensated sums four tables at a time, and
//    SeparableWeight::sum from them, are Neumaier's sums written out here, to the bit;
//  - SeparableWeight with and without lanes: omega against eq. P16 evaluated in long double
//    from its definition within relativeRounding (1e-14) of omega + E, the bound's
//    allowance (docs/model.md P16), and the two within 1e-15 relative of each other; row
//    parts to the bit.
// On a CPU without AVX2 + FMA (or a build without the AVX2 code) the tests report a skip.
#include "grid/GaussLegendre.hpp"
#include "grid/SeparableLanes.hpp"
#include "grid/SeparableWeight.hpp"

#include "RequireLanes.hpp"
#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

using namespace dropletFiber;

namespace
{

// Q tables of `stride` positive factors in [1e-3, 1] and Q row factors in [1e-3, 1].
struct RandomRow
{
    std::vector<double> factor, rowFactor;
};

RandomRow randomRow(std::mt19937_64& random, int points, std::size_t stride)
{
    std::uniform_real_distribution<double> exponent(-3.0, 0.0);
    RandomRow r;
    r.factor.resize(static_cast<std::size_t>(points) * stride);
    r.rowFactor.resize(static_cast<std::size_t>(points));
    for (double& f : r.factor)
    {
        f = std::pow(10.0, exponent(random));
    }
    for (double& f : r.rowFactor)
    {
        f = std::pow(10.0, exponent(random));
    }
    return r;
}

} // namespace

TEST(SeparableLanes, RowIsTheSumOverThePointsToRounding)
{
    REQUIRE_LANES();
    std::mt19937_64 random(11);
    double worst = 0.0; // in units of the sum's ulp
    for (int points = 1; points <= SeparableWeight::maximumPoints; ++points)
    {
        for (std::size_t length = 1; length <= 41; ++length)
        {
            const RandomRow r = randomRow(random, points, length);
            for (std::size_t first = 0; first < length; ++first)
            {
                const std::size_t count = length - first;
                std::vector<double> omega(count, -1.0);
                SeparableLanes::row(r.rowFactor.data(), points, r.factor.data() + first, length, count,
                                    omega.data());
                for (std::size_t i = 0; i < count; ++i)
                {
                    long double exact = 0.0L;
                    for (int q = 0; q < points; ++q)
                    {
                        exact += static_cast<long double>(r.rowFactor[static_cast<std::size_t>(q)])
                            * r.factor[static_cast<std::size_t>(q) * length + first + i];
                    }
                    const long double error = std::abs(omega[i] - exact) / (exact * DBL_EPSILON / 2);
                    ASSERT_LE(error, points + 1.0L)
                        << "Q " << points << " length " << length << " first " << first << " node " << i;
                    worst = std::max(worst, static_cast<double>(error));
                }
            }
        }
    }
    std::printf("rows: worst error %.2f half-ulp of the sum (bound Q + 1)\n", worst);
}

TEST(SeparableLanes, PartOfARowIsThatPartOfTheWholeRowToTheBit)
{
    REQUIRE_LANES();
    std::mt19937_64 random(12);
    for (int points = 1; points <= SeparableWeight::maximumPoints; ++points)
    {
        for (std::size_t length : {1u, 3u, 5u, 7u, 17u, 23u, 37u, 51u})
        {
            const RandomRow r = randomRow(random, points, length);
            std::vector<double> whole(length), part(length);
            SeparableLanes::row(r.rowFactor.data(), points, r.factor.data(), length, length, whole.data());
            for (std::size_t first = 0; first < length; ++first)
            {
                for (std::size_t count = 1; first + count <= length; ++count)
                {
                    SeparableLanes::row(r.rowFactor.data(), points, r.factor.data() + first, length, count,
                                        part.data());
                    for (std::size_t i = 0; i < count; ++i)
                    {
                        ASSERT_EQ(part[i], whole[first + i])
                            << "Q " << points << " length " << length << " first " << first << " count "
                            << count << " node " << i;
                    }
                }
            }
        }
    }
}

TEST(SeparableLanes, GaussianTableWithinAnUlpAndAHalfOfStdExp)
{
    REQUIRE_LANES();
    std::mt19937_64 random(13);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (std::size_t count = 1; count <= 40; ++count)
    {
        const double h = 1e-3, gamma = (1.0 + 40.0 * unit(random)) / (h * h); // down to exp(-1600)
        std::vector<double> x(count), table(count);
        for (std::size_t i = 0; i < count; ++i)
        {
            x[i] = (static_cast<double>(i) - 3.0) * h;
        }
        const double centre = count * h * unit(random);
        SeparableLanes::gaussianTable(x.data(), count, centre, gamma, table.data());
        for (std::size_t i = 0; i < count; ++i)
        {
            const double s = x[i] - centre;
            const double expected = std::exp(-gamma * s * s);
            if (expected >= DBL_MIN)
            {
                const double ulps = std::abs(table[i] - expected) / (expected * DBL_EPSILON);
                ASSERT_LE(ulps, 1.5) << "count " << count << " entry " << i;
                worst = std::max(worst, ulps);
            }
            else
            {
                ASSERT_LE(std::abs(table[i] - expected), 2 * std::numeric_limits<double>::denorm_min());
            }
        }
    }
    std::printf("tables: worst %.3f ulp from std::exp\n", worst);
}

TEST(SeparableLanes, AccumulationIsOneFmaPerValueWhateverTheSplit)
{
    REQUIRE_LANES();
    constexpr std::size_t nq = SeparableLanes::quantities;
    std::mt19937_64 random(14);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t length = 1; length <= 23; ++length)
    {
        std::vector<double> omega(length), start(length * nq), totals(nq);
        for (double& o : omega)
        {
            o = unit(random);
        }
        for (double& v : start)
        {
            v = unit(random);
        }
        for (double& t : totals)
        {
            t = 1e-6 * unit(random);
        }
        const double inverseSum = 1.0 / (3.0 + unit(random));
        std::vector<double> expected = start;
        for (std::size_t i = 0; i < length; ++i)
        {
            const double weight = omega[i] * inverseSum;
            for (std::size_t q = 0; q < nq; ++q)
            {
                expected[i * nq + q] = std::fma(weight, totals[q], expected[i * nq + q]);
            }
        }
        for (std::size_t split = 0; split <= length; ++split)
        {
            std::vector<double> values = start;
            SeparableLanes::addWeightedRow(omega.data(), split, inverseSum, totals.data(), values.data());
            SeparableLanes::addWeightedRow(omega.data() + split, length - split, inverseSum, totals.data(),
                                           values.data() + split * nq);
            ASSERT_EQ(values, expected) << "length " << length << " split " << split;
        }
    }
}

TEST(SeparableLanes, SeparableWeightsWithinTheRoundingAllowanceOfTheirDefinition)
{
    REQUIRE_LANES();
    // A moving 3D parcel's tables on a lattice box for Q = 1..12: omega of every node against
    // sum_q W_q exp(-X_q), X_q = gamma |g - c_q|^2, in long double, with and without the
    // lanes. The products and sums round to a few ulp of omega (relativeRounding); the
    // exponents' arguments, rounded to ~3 ulp of X_q, add 3 u X_q W_q exp(-X_q) per point:
    // relative to omega that reaches ~1e-14 only where X_q > ~30, where the node's weight
    // is tiny (absolute, at most 3 u / e of the peak: docs/model.md P16).
    const double h = 1e-3;
    const int lowest = -30;
    const test::TestLattice grid = test::testLattice(lowest, 60, h);
    const std::array<const double*, 3>& lattice = grid.atIndexZero;
    const KernelSettings settings;
    const ParcelKernel kernel(2e-5, 2000.0, settings, 3);
    const long double gamma = kernel.gamma();
    const double edge = kernel.edgeValue();
    const double u = DBL_EPSILON / 2;
    const Eigen::Vector3d start(3.3e-3, 1.2e-3, 0.4e-3), displacement(2e-3, -1e-3, 0.5e-3);
    const PathWeight path(kernel, start, displacement);
    const std::array<int, 3> lo{{-12, -14, -15}}, hi{{18, 16, 15}};
    SeparableWeight lanes(true), portable(false);
    ASSERT_TRUE(lanes.vectorised());
    ASSERT_FALSE(portable.vectorised());
    const auto n = static_cast<std::size_t>(hi[0] - lo[0] + 1);
    // Worst error over its allowance; worst absolute error in units of the kernel's peak
    double worstLanes = 0.0, worstPortable = 0.0, worstBetween = 0.0, largestLanes = 0.0;
    for (int points = 1; points <= SeparableWeight::maximumPoints; ++points)
    {
        lanes.prepare(path, start, displacement, points, lattice, lo, hi);
        portable.prepare(path, start, displacement, points, lattice, lo, hi);
        std::array<double, SeparableWeight::maximumPoints> node{}, weight{};
        gaussLegendreRule(points, node.data(), weight.data());
        for (int k = lo[2]; k <= hi[2]; k += 3)
        {
            for (int j = lo[1]; j <= hi[1]; j += 2)
            {
                const std::vector<double> row(lanes.row(j - lo[1], k - lo[2]),
                                              lanes.row(j - lo[1], k - lo[2]) + n);
                const double* other = portable.row(j - lo[1], k - lo[2]);
                for (int i = lo[0]; i <= hi[0]; ++i)
                {
                    long double omega = 0.0L, argumentTerm = 0.0L;
                    for (int q = 0; q < points; ++q)
                    {
                        // The centres as SeparableWeight takes them: start + tau displacement in double
                        const double tau = 0.5 * (1.0 + node[static_cast<std::size_t>(q)]);
                        long double squared = 0.0L;
                        for (int d = 0; d < 3; ++d)
                        {
                            const double centre = start[d] + tau * displacement[d];
                            const int index = d == 0 ? i : (d == 1 ? j : k);
                            const long double s = static_cast<long double>(lattice[d][index]) - centre;
                            squared += s * s;
                        }
                        const long double x = gamma * squared;
                        const long double term = 0.5L * weight[static_cast<std::size_t>(q)] * std::exp(-x);
                        omega += term;
                        argumentTerm += 3.0L * u * x * term;
                    }
                    const auto p = static_cast<std::size_t>(i - lo[0]);
                    const double allowance
                        = SeparableWeight::relativeRounding * (static_cast<double>(omega) + edge)
                        + static_cast<double>(argumentTerm);
                    const double errorLanes = static_cast<double>(std::abs(row[p] - omega));
                    worstLanes = std::max(worstLanes, errorLanes / allowance);
                    worstPortable = std::max(worstPortable,
                                             static_cast<double>(std::abs(other[p] - omega)) / allowance);
                    worstBetween = std::max(worstBetween, std::abs(row[p] - other[p]) / allowance);
                    largestLanes = std::max(largestLanes, errorLanes);
                }
                // A part of the row: those positions, to the bit.
                const std::size_t first = static_cast<std::size_t>(j + k + 40) % n;
                const double* part = lanes.row(j - lo[1], k - lo[2], first, n - first);
                for (std::size_t i = 0; first + i < n; ++i)
                {
                    ASSERT_EQ(part[i], row[first + i]) << "Q " << points << " row " << j << " " << k;
                }
            }
        }
    }
    std::printf("omega vs definition, error over allowance: lanes %.3g, portable %.3g, between them %.3g; "
                "largest error (lanes) %.3g of the peak\n",
                worstLanes, worstPortable, worstBetween, largestLanes);
    EXPECT_LE(worstLanes, 1.0);
    EXPECT_LE(worstPortable, 1.0);
    EXPECT_LE(largestLanes, 3.0 * u / std::exp(1.0) + SeparableWeight::relativeRounding);
}

namespace
{

// Neumaier's compensated sum of positive terms, as SeparableWeight::sum's portable loop.
double neumaierSum(const double* f, std::size_t length)
{
    double sum = 0.0, compensation = 0.0;
    for (std::size_t i = 0; i < length; ++i)
    {
        const double next = sum + f[i];
        compensation += sum >= f[i] ? (sum - next) + f[i] : (f[i] - next) + sum;
        sum = next;
    }
    return sum + compensation;
}

} // namespace

TEST(SeparableLanes, CompensatedSumsAreNeumaiersSumsToTheBit)
{
    REQUIRE_LANES();
    std::mt19937_64 random(15);
    std::uniform_real_distribution<double> exponent(-17.0, 0.0);
    std::uniform_int_distribution<std::size_t> lengthOf(0, 40);
    for (int trial = 0; trial < 200; ++trial)
    {
        const std::size_t count = 1 + static_cast<std::size_t>(trial) % 4;
        std::vector<std::vector<double>> tables(count);
        std::vector<const double*> pointers(count);
        std::vector<std::size_t> lengths(count);
        for (std::size_t t = 0; t < count; ++t)
        {
            tables[t].resize(lengthOf(random));
            for (double& f : tables[t])
            {
                f = std::pow(10.0, exponent(random)); // terms over 17 decades: compensation matters
            }
            pointers[t] = tables[t].data();
            lengths[t] = tables[t].size();
        }
        std::vector<double> sums(count, -1.0);
        SeparableLanes::compensatedSums(pointers.data(), lengths.data(), count, sums.data());
        for (std::size_t t = 0; t < count; ++t)
        {
            ASSERT_EQ(sums[t], neumaierSum(tables[t].data(), lengths[t]))
                << "trial " << trial << " table " << t;
        }
    }
}

TEST(SeparableLanes, NormalisingSumInLanesIsTheProductOfNeumaiersSumsToTheBit)
{
    REQUIRE_LANES();
    const test::TestLattice grid = test::testLattice(-30, 60, 1e-3);
    const KernelSettings settings;
    const ParcelKernel kernel(2e-5, 2000.0, settings, 3);
    const Eigen::Vector3d start(3.3e-3, 1.2e-3, 0.4e-3), displacement(2e-3, -1e-3, 0.5e-3);
    const PathWeight path(kernel, start, displacement);
    SeparableWeight lanes(true);
    for (int points = 1; points <= SeparableWeight::maximumPoints; ++points)
    {
        lanes.prepare(path, start, displacement, points, grid.atIndexZero, {{-12, -9, -15}}, {{18, 10, 15}});
        const SeparableTables tables = lanes.tables();
        double expected = 0.0;
        for (int q = 0; q < points; ++q)
        {
            const auto u = static_cast<std::size_t>(q);
            double product = tables.weight[u];
            for (std::size_t d = 0; d < 3; ++d)
            {
                product *= neumaierSum(tables.factor[d] + u * tables.length[d], tables.length[d]);
            }
            expected += product;
        }
        ASSERT_EQ(lanes.sum(), expected) << "Q " << points;
    }
}
