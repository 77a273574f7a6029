// The deposit's separable rows added a box at a time (SeparableLanes::addRows, and
// SeparableWeight::addRowsInLanes over the tables of a parcel) against their arithmetic
// written out here, value by value:
//  - addRows: row factor r_q = (W_q Y_q(j)) Z_q(k), omega_i = r_0 X_0(i) then + r_q X_q(i)
//    by one FMA each (q in order), weight = omega_i inverseSum rounded, value = fma(weight,
//    total, value) (std::fma), to the bit, for Q = 1..12 (the unrolled Q and the general
//    loop), every row length 1..13 (every 1-3-node end), rows apart in memory: the values
//    between the rows and beyond the box are left as they were, whatever the prefetch
//    distance (prefetching never changes a value);
//  - addRowsInLanes on a moving parcel's tables, a part of the box (a grid block's stored
//    part): the same values, to the bit, as the row-by-row path (row(), then
//    SeparableLanes::addWeightedRow).
// On a CPU without AVX2 + FMA (or a build without the AVX2 code) the tests report a skip.
#include "grid/SeparableLanes.hpp"
#include "grid/SeparableWeight.hpp"

#include "RequireLanes.hpp"
#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace dropletFiber;

namespace
{

constexpr std::size_t nq = SeparableLanes::quantities;

std::vector<double> randomValues(std::mt19937_64& random, std::size_t count, double lowestExponent)
{
    std::uniform_real_distribution<double> exponent(lowestExponent, 0.0);
    std::vector<double> v(count);
    for (double& x : v)
    {
        x = std::pow(10.0, exponent(random));
    }
    return v;
}

} // namespace

TEST(SeparableBoxRows, EveryValueIsItsRowFactorOmegaAndOneFmaToTheBit)
{
    REQUIRE_LANES();
    std::mt19937_64 random(21);
    const std::size_t rows = 3, layers = 2, padding = 5; // nodes between two rows' values
    for (int points = 1; points <= SeparableLanes::maximumPoints; ++points)
    {
        const auto p = static_cast<std::size_t>(points);
        for (std::size_t count = 1; count <= 13; ++count)
        {
            const std::size_t stride = count + 2; // X_q tables longer than the rows
            const std::vector<double> weightedY = randomValues(random, rows * p, -3.0);
            const std::vector<double> z = randomValues(random, layers * p, -3.0);
            const std::vector<double> factor = randomValues(random, stride * p, -3.0);
            const std::vector<double> totals = randomValues(random, nq, -8.0);
            const double inverseSum = 1.0 / 7.3;
            const std::size_t rowStride = (count + padding) * nq;
            const std::size_t layerStride = rows * rowStride + 3 * nq;
            const std::vector<double> start = randomValues(random, layers * layerStride, -1.0);
            std::vector<double> expected = start;
            for (std::size_t k = 0; k < layers; ++k)
            {
                for (std::size_t j = 0; j < rows; ++j)
                {
                    for (std::size_t i = 0; i < count; ++i)
                    {
                        const double r0 = weightedY[j * p] * z[k * p];
                        double omega = r0 * factor[1 + i];
                        for (std::size_t q = 1; q < p; ++q)
                        {
                            omega = std::fma(weightedY[j * p + q] * z[k * p + q], factor[q * stride + 1 + i],
                                             omega);
                        }
                        const double weight = omega * inverseSum;
                        double* v = expected.data() + k * layerStride + j * rowStride + i * nq;
                        for (std::size_t m = 0; m < nq; ++m)
                        {
                            v[m] = std::fma(weight, totals[m], v[m]);
                        }
                    }
                }
            }
            for (std::size_t ahead : {std::size_t{0}, 2 * rowStride, 100 * layerStride})
            {
                std::vector<double> values = start;
                SeparableLanes::BoxRows box;
                box.weightedY = weightedY.data();
                box.z = z.data();
                box.rows = rows;
                box.layers = layers;
                box.points = points;
                box.factor = factor.data() + 1;
                box.stride = stride;
                box.count = count;
                box.values = values.data();
                box.rowStride = rowStride;
                box.layerStride = layerStride;
                box.prefetchAhead = ahead;
                box.available = values.size();
                SeparableLanes::addRows(box, inverseSum, totals.data());
                ASSERT_EQ(values, expected) << "Q " << points << " count " << count << " ahead " << ahead;
            }
        }
    }
}

TEST(SeparableBoxRows, PartOfAParcelsBoxAsTheRowByRowPathToTheBit)
{
    REQUIRE_LANES();
    const double h = 1e-3;
    const test::TestLattice grid = test::testLattice(-30, 60, h);
    const KernelSettings settings;
    const ParcelKernel kernel(2e-5, 2000.0, settings, 3);
    const Eigen::Vector3d start(3.3e-3, 1.2e-3, 0.4e-3), displacement(2e-3, -1e-3, 0.5e-3);
    const PathWeight path(kernel, start, displacement);
    const std::array<int, 3> lo{{-6, -7, -5}}, hi{{5, 4, 6}};
    const std::array<std::size_t, 3> n{{12, 12, 12}};
    const double totals[nq] = {1e-9, -2e-7, 3e-5, 4e-3, 5e-1, 6.0, 7e2};
    const double inverseSum = 1.0 / 3.7;
    for (int points : {1, 5, 7})
    {
        SeparableWeight tables(true);
        tables.prepare(path, start, displacement, points, grid.atIndexZero, lo, hi);
        // The part [1, 10] x [2, 11] x [0, 8] of the box, in an array of the whole box's nodes
        const std::array<int, 3> partLo{{1, 2, 0}}, partHi{{10, 11, 8}};
        const auto count = static_cast<std::size_t>(partHi[0] - partLo[0] + 1);
        std::vector<double> expected(n[0] * n[1] * n[2] * nq, 0.5), values = expected;
        auto valuesAt = [&](std::vector<double>& v, int j, int k)
        {
            const std::size_t node = static_cast<std::size_t>(partLo[0])
                + n[0] * (static_cast<std::size_t>(j) + n[1] * static_cast<std::size_t>(k));
            return v.data() + node * nq;
        };
        for (int k = partLo[2]; k <= partHi[2]; ++k)
        {
            for (int j = partLo[1]; j <= partHi[1]; ++j)
            {
                const double* omega = tables.row(j, k, static_cast<std::size_t>(partLo[0]), count);
                SeparableLanes::addWeightedRow(omega, count, inverseSum, totals, valuesAt(expected, j, k));
            }
        }
        SeparableLanes::BoxRows to;
        to.values = valuesAt(values, partLo[1], partLo[2]);
        to.rowStride = n[0] * nq;
        to.layerStride = n[0] * n[1] * nq;
        to.prefetchAhead = 2 * to.rowStride;
        to.available = values.size() - static_cast<std::size_t>(to.values - values.data());
        tables.addRowsInLanes(partLo, partHi, inverseSum, totals, to);
        ASSERT_EQ(values, expected) << "Q " << points;
        EXPECT_THROW(tables.addRowsInLanes(partLo, {{12, 11, 8}}, inverseSum, totals, to), std::out_of_range);
    }
}
