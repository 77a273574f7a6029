// Spread populations on a random mat of heavily weighted fixed fibers (docs/model.md sec. 12,
// the validation case; docs/validation.md "A converged veil"): M fibers of weight N at a
// fixed S = M N c / W, crossed by a uniform spray (SpreadMat.hpp). The penetration, averaged
// over mats, must be exp(-S) within 3 % at three grid spacings a factor 2 apart and for
// N = 1, 10, 100, where P40 alone (today's weighted fibers) falls with the spacing: its
// populations sit on their lines, S N c / 4h to first order (P55). The captured mass equals
// the mass removed from the spray to round-off (P51).
#include "SpreadMat.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

using namespace dropletFiber;

namespace
{
constexpr std::array<double, 3> inverseSpacings = {{32.0, 64.0, 128.0}};
constexpr std::array<double, 3> weights = {{1.0, 10.0, 100.0}};
constexpr int mats = 8;

struct MeanOverMats
{
    double ratio = 0.0; // mean of P / exp(-S)
    double lowest = 1e9, highest = 0.0;
    double balance = 0.0; // the largest |captured - removed| / removed
    double meanRatio = 0.0;
};

MeanOverMats meanOverMats(double S, double N, double inverseSpacing, bool spread)
{
    test::SpreadMat mat;
    mat.S = S;
    mat.weight = N;
    mat.h = 1.0 / inverseSpacing;
    mat.spread = spread;
    MeanOverMats m;
    for (int seed = 0; seed < mats; ++seed)
    {
        const test::SpreadMatResult r = mat.run(static_cast<unsigned>(1000 + seed));
        const double ratio = r.penetration / r.theory;
        m.ratio += ratio / mats;
        m.lowest = std::min(m.lowest, ratio);
        m.highest = std::max(m.highest, ratio);
        m.balance = std::max(m.balance, std::abs(r.captured - r.removed) / r.removed);
        m.meanRatio += r.meanRatio / mats;
    }
    return m;
}
} // namespace

TEST(SpreadMat, PenetrationWithinThreePercentOfExpMinusSAtEverySpacingAndWeight)
{
    for (const double S : {1.0, 2.302585092994046})
    {
        for (const double N : weights)
        {
            for (const double inverse : inverseSpacings)
            {
                const MeanOverMats spread = meanOverMats(S, N, inverse, true);
                const MeanOverMats today = meanOverMats(S, N, inverse, false);
                std::printf("S %.2f N %5.0f 1/h %4.0f: spread %.4f (%.4f-%.4f, H/h %.1f)  P40 alone %.4f\n",
                            S, N, inverse, spread.ratio, spread.lowest, spread.highest, spread.meanRatio,
                            today.ratio);
                EXPECT_LT(std::abs(spread.ratio - 1.0), 0.03)
                    << "S " << S << " N " << N << " 1/h " << inverse;
                EXPECT_LT(spread.balance, 1e-12) << "S " << S << " N " << N << " 1/h " << inverse;
                EXPECT_LT(today.balance, 1e-12) << "S " << S << " N " << N << " 1/h " << inverse;
            }
        }
    }
}

TEST(SpreadMat, WeightOneIsTodayToTheBit)
{
    // N = 1: no population, the same arithmetic as without spread
    test::SpreadMat mat;
    mat.weight = 1.0;
    mat.S = 2.0;
    const test::SpreadMatResult with = mat.run(3);
    mat.spread = false;
    const test::SpreadMatResult without = mat.run(3);
    EXPECT_EQ(with.penetration, without.penetration);
    EXPECT_EQ(with.captured, without.captured);
}

TEST(SpreadMat, TodaysWeightedFibersFallWithTheSpacing)
{
    // The fault the populations remove: at N = 100, S = ln 10, P40 alone passes more with
    // every halving of h (S N c / 4h: +7 %, +14 %, +29 % to first order)
    const double S = 2.302585092994046;
    const MeanOverMats coarse = meanOverMats(S, 100.0, 32.0, false);
    const MeanOverMats fine = meanOverMats(S, 100.0, 128.0, false);
    EXPECT_GT(coarse.ratio, 1.05);
    EXPECT_GT(fine.ratio, coarse.ratio + 0.2);
}
