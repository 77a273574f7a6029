// The spread populations' levels (docs/model.md sec. 12, P53), each property derived
// independently of the code: the ratios' sequence written out; the hats a partition of
// unity at every grid node (so a restriction keeps its total, the volumes add up to the
// box's); restriction and prolongation adjoint (P51's grants on a level add up); a point's
// grid weights restricted equal to its own weights on the level (a multilinear function is
// its own interpolant on the finer nodes); level (h, 2r) the same lattice and weights as
// level (h / 2, 4r); ratio 1 the grid itself; bad ratios refused.
#include "grid/GridSpec.hpp"
#include "grid/MultilinearWeights.hpp"
#include "grid/SpreadLevel.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

using namespace dropletFiber;

namespace
{

double boxVolume(const GridSpec& s)
{
    return (s.upper - s.lower).prod();
}

std::vector<double> randomField(std::size_t n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> v(n);
    for (double& x : v)
    {
        x = u(rng);
    }
    return v;
}

Eigen::Vector3d randomPoint(const GridSpec& s, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return s.lower + (s.upper - s.lower).cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng)));
}

double sum(const std::vector<double>& v)
{
    return std::accumulate(v.begin(), v.end(), 0.0);
}

} // namespace

TEST(SpreadLevel, RatiosAreTwoPowersAndThreeTimesTwoPowers)
{
    EXPECT_EQ(spreadLevelRatios(1), (std::vector<int>{1}));
    EXPECT_EQ(spreadLevelRatios(5), (std::vector<int>{1, 2, 3, 4}));
    EXPECT_EQ(spreadLevelRatios(16), (std::vector<int>{1, 2, 3, 4, 6, 8, 12, 16}));
    EXPECT_EQ(spreadLevelRatios(48), (std::vector<int>{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48}));
    EXPECT_THROW(spreadLevelRatios(0), std::invalid_argument);
}

TEST(SpreadLevel, LatticeReachesTheBox)
{
    const GridSpec g = test::offsetGrid3D();
    const SpreadLevel level(g, 3);
    // ceil(8 / 3) + 1, ceil(6 / 3) + 1, ceil(4 / 3) + 1 nodes, spacing 3 h
    EXPECT_EQ(level.spec().nodes, (std::array<int, 3>{{4, 3, 3}}));
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_NEAR(level.spec().spacing(d), 3.0 * g.spacing(d), 1e-15);
        EXPECT_GE(level.spec().upper[d], g.upper[d] - 1e-15);
    }
    const SpreadLevel flat(test::offsetGrid2D(), 4);
    EXPECT_EQ(flat.spec().nodes, (std::array<int, 3>{{4, 5, 1}}));
    EXPECT_DOUBLE_EQ(flat.spec().upper.z() - flat.spec().lower.z(), 0.001);
}

TEST(SpreadLevel, HatsArePartitionOfUnityAtEveryGridNode)
{
    for (const GridSpec& g : {test::offsetGrid3D(), test::offsetGrid2D()})
    {
        for (int r : {1, 2, 3, 4, 6})
        {
            const SpreadLevel level(g, r);
            const std::vector<double> ones(level.spec().nodeCount(), 1.0);
            for (double v : level.prolong(ones))
            {
                EXPECT_NEAR(v, 1.0, 1e-14) << "ratio " << r;
            }
        }
    }
}

TEST(SpreadLevel, RestrictionKeepsTotalAndVolumesAddToTheBox)
{
    for (const GridSpec& g : {test::offsetGrid3D(), test::offsetGrid2D()})
    {
        for (int r : {2, 3, 4})
        {
            const SpreadLevel level(g, r);
            const std::vector<double> q = randomField(g.nodeCount(), 7u + static_cast<unsigned>(r));
            EXPECT_NEAR(sum(level.restrict(q)), sum(q), 1e-12 * sum(q));
            EXPECT_NEAR(sum(level.volumes()), boxVolume(g), 1e-12 * boxVolume(g));
            for (double v : level.volumes())
            {
                EXPECT_GE(v, 0.0);
            }
        }
    }
}

TEST(SpreadLevel, RestrictionAndProlongationAreAdjoint)
{
    const GridSpec g = test::offsetGrid3D();
    const SpreadLevel level(g, 3);
    const std::vector<double> q = randomField(g.nodeCount(), 11u);
    const std::vector<double> x = randomField(level.spec().nodeCount(), 12u);
    const std::vector<double> rq = level.restrict(q);
    const std::vector<double> px = level.prolong(x);
    const double onLevel = std::inner_product(rq.begin(), rq.end(), x.begin(), 0.0);
    const double onGrid = std::inner_product(q.begin(), q.end(), px.begin(), 0.0);
    EXPECT_NEAR(onLevel, onGrid, 1e-12 * std::abs(onGrid));
}

TEST(SpreadLevel, RestrictedGridWeightsAreThePointsLevelWeights)
{
    std::mt19937 rng(5);
    for (const GridSpec& g : {test::offsetGrid3D(), test::offsetGrid2D()})
    {
        for (int r : {2, 3, 4})
        {
            const SpreadLevel level(g, r);
            for (int trial = 0; trial < 50; ++trial)
            {
                const Eigen::Vector3d p = randomPoint(g, rng);
                const CornerWeights fine = multilinearWeights(g, p);
                std::vector<double> w(g.nodeCount(), 0.0);
                for (int c = 0; c < fine.count; ++c)
                {
                    w[fine.node[c]] += fine.weight[c];
                }
                const std::vector<double> restricted = level.restrict(w);
                std::vector<double> own(level.spec().nodeCount(), 0.0);
                const CornerWeights coarse = level.weightsAt(p);
                for (int c = 0; c < coarse.count; ++c)
                {
                    own[coarse.node[c]] += coarse.weight[c];
                }
                for (std::size_t n = 0; n < own.size(); ++n)
                {
                    EXPECT_NEAR(restricted[n], own[n], 1e-12) << "ratio " << r << ", level node " << n;
                }
            }
        }
    }
}

TEST(SpreadLevel, HalvingTheGridMapsLevelsOntoEachOther)
{
    const GridSpec coarse = test::offsetGrid3D();
    GridSpec fine = coarse;
    for (int d = 0; d < 3; ++d)
    {
        fine.nodes[d] = 2 * (coarse.nodes[d] - 1) + 1;
    }
    const SpreadLevel a(coarse, 2);
    const SpreadLevel b(fine, 4);
    ASSERT_EQ(a.spec().nodes, b.spec().nodes);
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_NEAR(a.spec().upper[d], b.spec().upper[d], 1e-14);
    }
    std::mt19937 rng(9);
    for (int trial = 0; trial < 50; ++trial)
    {
        const Eigen::Vector3d p = randomPoint(coarse, rng);
        const CornerWeights wa = a.weightsAt(p);
        const CornerWeights wb = b.weightsAt(p);
        ASSERT_EQ(wa.count, wb.count);
        for (int c = 0; c < wa.count; ++c)
        {
            EXPECT_EQ(wa.node[c], wb.node[c]);
            EXPECT_NEAR(wa.weight[c], wb.weight[c], 1e-12);
        }
    }
}

TEST(SpreadLevel, RatioOneIsTheGridItself)
{
    const GridSpec g = test::offsetGrid3D();
    const SpreadLevel level(g, 1);
    EXPECT_EQ(level.spec().nodes, g.nodes);
    const std::vector<double> q = randomField(g.nodeCount(), 3u);
    EXPECT_EQ(level.restrict(q), q);
    EXPECT_EQ(level.prolong(q), q);
    EXPECT_DOUBLE_EQ(level.volumes()[g.flatIndex(0, 0, 0)], g.dualVolume(0, 0, 0));
    EXPECT_DOUBLE_EQ(level.volumes()[g.flatIndex(4, 3, 2)], g.nodeVolume());
}

TEST(SpreadLevel, BadRatioAndSizesAreRefused)
{
    EXPECT_THROW(SpreadLevel(test::offsetGrid3D(), 0), std::invalid_argument);
    const SpreadLevel level(test::offsetGrid3D(), 2);
    EXPECT_THROW(level.restrict(std::vector<double>(3)), std::invalid_argument);
    EXPECT_THROW(level.prolong(std::vector<double>(3)), std::invalid_argument);
}
