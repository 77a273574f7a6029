// SpreadPopulations (docs/model.md sec. 12): a population's swept volume kept through its
// level onto the grid, the level's grants read back, the level's choice against a direct
// count of the fibers a ball meets, the table sums and bad input.
#include "depletion/SpreadPopulations.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace dropletFiber;

namespace
{
GridSpec box3D(int cells, double size)
{
    GridSpec g;
    g.lower = Eigen::Vector3d(0.1, -0.2, 0.3);
    g.upper = g.lower + Eigen::Vector3d(size, size, size);
    g.nodes = {{cells + 1, cells + 1, cells + 1}};
    return g;
}

double dualVolume(const GridSpec& g, std::size_t node)
{
    const std::array<int, 3> i = nodeIndicesOfFlat(g.nodes, node);
    return g.dualVolume(i[0], i[1], i[2]);
}

// f(n) at every node of g, in flat order (a field dense over the whole grid)
template <class F>
std::vector<double> field(const GridSpec& g, F&& f)
{
    std::vector<double> values(g.nodeCount());
    for (std::size_t n = 0; n < values.size(); ++n)
    {
        values[n] = f(n);
    }
    return values;
}

// Distance from point p to the segment a-b
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm();
}
} // namespace

TEST(SpreadPopulations, SweptVolumeIsKeptOnTheGridOnEveryLevel)
{
    // sum_n V_n P_n = (N - 1) kappa: the hats of a level node spread V_C over the grid
    const GridSpec g = box3D(24, 1.2);
    const SpreadPopulations spreads(g, 8.0);
    ASSERT_GE(spreads.levelCount(), 5);
    for (int l = 0; l < spreads.levelCount(); ++l)
    {
        LevelTerms terms(2);
        spreads.addDemand(Eigen::Vector3d(0.55, 0.31, 0.97), l, 2.5e-7, Eigen::Vector3d(1e-4, 0.0, 0.0), 11.0,
                          terms);
        const LevelTable demand = terms.summed();
        double swept = 0.0, deepest = 0.0;
        std::vector<double> share, depth;
        spreads.prolongOnto(demand, wholeBox(g.nodes), share, depth);
        for (std::size_t n = 0; n < share.size(); ++n)
        {
            swept += dualVolume(g, n) * share[n];
            deepest = share[n] > 0.0 ? std::max(deepest, depth[n] / share[n]) : deepest;
        }
        EXPECT_NEAR(swept, 2.5e-7, 1e-12 * 2.5e-7) << "level " << l;
        // The shadow factor 1 + sigma~ of a strip (N + 1) q on the level: above 1, and
        // smaller on coarser levels (q / H)
        EXPECT_GT(deepest, 1.0) << "level " << l;
    }
}

TEST(SpreadPopulations, GrantsReadBackAreTheGridsMeanOverTheKernel)
{
    // value(n) = c V_n restricted and read per volume is c wherever the kernel sits; a
    // linear field per volume, a + b.x, is read exactly as the kernel's mean at the point
    const GridSpec g = box3D(24, 1.2);
    const SpreadPopulations spreads(g, 8.0);
    const Eigen::Vector3d point(0.62, 0.27, 0.83);
    for (int l = 0; l < spreads.levelCount(); ++l)
    {
        LevelTerms terms(2);
        spreads.addDemand(point, l, 1.0, Eigen::Vector3d::Zero(), 2.0, terms);
        const LevelTable keys = terms.summed();
        const LevelTable constant = spreads.restrictFrom(
            keys, wholeBox(g.nodes), field(g, [&](std::size_t n) { return 3.0 * dualVolume(g, n); }));
        EXPECT_NEAR(spreads.readLevel(point, l, constant), 3.0, 1e-12) << "level " << l;
    }
    // Level 0 is the grid itself: the read is the multilinear interpolant
    LevelTerms terms(2);
    spreads.addDemand(point, 0, 1.0, Eigen::Vector3d::Zero(), 2.0, terms);
    const LevelTable linear = spreads.restrictFrom(
        terms.summed(), wholeBox(g.nodes),
        field(g,
              [&](std::size_t n)
              {
                  const std::array<int, 3> i = nodeIndicesOfFlat(g.nodes, n);
                  return (1.0 + 2.0 * g.nodePosition(i[0], i[1], i[2]).x()) * dualVolume(g, n);
              }));
    EXPECT_NEAR(spreads.readLevel(point, 0, linear), 1.0 + 2.0 * point.x(), 1e-12);
}

TEST(SpreadPopulations, ChosenKernelReachesTheNeighboursADirectCountFinds)
{
    // Randomly placed and oriented fibers of length L: the level chosen at a probe is the
    // finest whose ball of radius sigma = H / sqrt(3) meets k others by the counts
    // (Steiner: n (4/3 pi sigma^3 + pi sigma^2 L)); a direct count of the fibers within
    // sigma of the probe, averaged over probes, must agree with the reach the rule gives
    const GridSpec g = box3D(32, 1.6);
    const double L = 0.05;
    const int fibers = 4000;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    std::vector<Eigen::Vector3d> a(fibers), b(fibers);
    LevelTerms count(2);
    const SpreadPopulations spreads(g, 8.0);
    for (int f = 0; f < fibers; ++f)
    {
        const Eigen::Vector3d centre = g.lower + 1.6 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
        const Eigen::Vector3d along = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
        a[f] = centre - 0.5 * L * along;
        b[f] = centre + 0.5 * L * along;
        spreads.addLength(centre, L, count);
    }
    const LevelTable counted = count.summed();
    double reach = 0.0, found = 0.0;
    int probes = 0;
    for (int p = 0; p < 200; ++p)
    {
        // Probes away from the faces (the count is the box's there)
        const Eigen::Vector3d probe = g.lower + Eigen::Vector3d(0.5, 0.5, 0.5)
            + 0.6 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
        // Opaque populations (eps 10 / H): the level by the count alone
        const LevelChoice choice = spreads.choose(probe, 0.0, counted, 10.0);
        ASSERT_EQ(choice.why, LevelChoice::Why::reached);
        EXPECT_GE(choice.reach, 8.0);
        if (choice.level > 0)
        {
            EXPECT_LT(spreads.reachOn(choice.level - 1, probe, 0.0, counted), 8.0);
        }
        const double sigma = spreads.level(choice.level).spec().spacing(0) / std::sqrt(3.0);
        int within = 0;
        for (int f = 0; f < fibers; ++f)
        {
            within += distanceToSegment(probe, a[f], b[f]) < sigma ? 1 : 0;
        }
        reach += choice.reach;
        found += within;
        ++probes;
    }
    // The mean over 200 probes of counts of about 10: a few per cent of sampling error
    EXPECT_NEAR(found / reach, 1.0, 0.1) << "mean reach " << reach / probes << ", found " << found / probes;
}

TEST(SpreadPopulations, ThinPopulationsStayOnTheFinestLevelThatKeepsThemThin)
{
    // eps = (N - 1) c / (4 H) <= 0.05: the finest such level, whatever the count
    const GridSpec g = box3D(32, 1.6); // h = 0.05
    const SpreadPopulations spreads(g, 8.0);
    const LevelTable none;
    const Eigen::Vector3d centre(0.9, 0.6, 1.1);
    const LevelChoice thin = spreads.choose(centre, 0.1, none, 0.04 * 0.05);
    EXPECT_EQ(thin.level, 0);
    EXPECT_EQ(thin.why, LevelChoice::Why::thin);
    // 0.049 * 0.15: H = 0.15 (ratio 3) is the first that keeps it below 0.05
    const LevelChoice wider = spreads.choose(centre, 0.1, none, 0.049 * 0.15);
    EXPECT_EQ(spreads.level(wider.level).ratio(), 3);
    EXPECT_NEAR(wider.eps, 0.049, 1e-12);
    // Never thin and no other fibers: capped at the coarsest level
    const LevelChoice capped = spreads.choose(centre, 0.1, none, 100.0);
    EXPECT_EQ(capped.why, LevelChoice::Why::capped);
    EXPECT_EQ(capped.level, spreads.levelCount() - 1);
}

TEST(SpreadPopulations, LevelTermsSumPerKeyInKeyOrder)
{
    LevelTerms terms(2);
    const double x[2] = {1.0, 2.0}, y[2] = {0.5, 0.25}, z[2] = {4.0, 8.0};
    terms.add(levelKey(3, 17), x);
    terms.add(levelKey(0, 99), z);
    terms.add(levelKey(3, 17), y);
    const LevelTable table = terms.summed();
    ASSERT_EQ(table.size(), 2u);
    // Keys in node order, then level: (17, level 3) before (99, level 0)
    EXPECT_EQ(table.keys[1], levelKey(0, 99));
    EXPECT_EQ(levelOfKey(table.keys[0]), 3);
    EXPECT_EQ(nodeOfKey(table.keys[0]), 17u);
    EXPECT_EQ(table.value(levelKey(3, 17), 0), 1.5);
    EXPECT_EQ(table.value(levelKey(3, 17), 1), 2.25);
    EXPECT_EQ(table.find(levelKey(1, 17)), nullptr);
    LevelTerms other(1);
    EXPECT_THROW(other.add(table), std::invalid_argument);
}

TEST(SpreadPopulations, BadNeighboursAreRefused)
{
    const GridSpec g = box3D(8, 1.0);
    EXPECT_THROW(SpreadPopulations(g, 0.0), std::invalid_argument);
    EXPECT_THROW(SpreadPopulations(g, std::nan("")), std::invalid_argument);
    EXPECT_THROW(SpreadPopulations(g, 8.0, 0, -0.1), std::invalid_argument);
    // The default coarsest level: its spacing first reaches half the box
    const SpreadPopulations spreads(g, 8.0);
    EXPECT_EQ(spreads.level(spreads.levelCount() - 1).ratio(), 4);
}
