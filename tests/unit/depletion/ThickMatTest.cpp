// Depletion in a random mat of fibers thick against the grid spacing (docs/model.md sec. 7,
// "Thick fibers"; docs/validation.md, dense mats): the case of tests/cases/denseMat in core
// terms. Fibers of r_F = 50 um catching droplets of r_p = 20 um (strip 2 (r_F + r_p) = 0.14
// of the 1 mm spacing, against 0.002 in DenseMatTest), at random in a slab 6 spacings thick
// across a spray 20 spacings wide, 1/8 ... 1 spacing per step.
//
// What the model gives there: the mean over the parcels' lanes of exp(-S_I(x)), S_I the
// piecewise-linear interpolant across the flow of the nodes' depths (each fiber's strip spread
// over its two node columns by the hat weights of its x), the lanes' field, computed from the
// fibers' positions alone (LanesField.hpp). Without the self-shadow it is above exp(-S) (P15)
// by ~ exp(S c / 4h) for strips of width c: each fiber, smeared over its columns, shadows
// itself (a lane crossing its depth f keeps exp(-f), not 1 - f), P20. With it (P21) each
// column's depth is scaled so that the lanes lose the fiber's strip, whatever the step: the
// model is that mat's shadowed lanes' field at every step, and exp(-S) but for the mat's
// clustering at the grid's scale. The target of the issue: within 3 % of exp(-S) at every
// travel per step.
#include "LanesField.hpp"
#include "StraightSpray.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace dropletFiber;

namespace
{
constexpr std::array<double, 2> depths = {{1.0, 2.302585092994046}};
constexpr std::array<double, 4> travels = {{1.0, 0.5, 0.25, 0.125}}; // v dt / h

struct ThickRun
{
    double model = 0.0, expMinusS = 0.0;
    test::LanesField lanes;
};

ThickRun thickMat(double S, double travel, unsigned seed)
{
    test::StraightSpray spray;
    spray.columns = 20;
    spray.rows = 10;
    spray.dt = travel * spray.h / spray.speed;
    spray.dropletRadius = 2e-5;
    spray.fiberRadius = 5e-5;
    spray.nParticle = 10.0;
    const double strip = 2.0 * (spray.fiberRadius + spray.dropletRadius);
    const double width = spray.columns * spray.h;
    const int count = static_cast<int>(std::lround(S * width / strip));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xs;
    for (int n = 0; n < count; ++n)
    {
        xs.push_back(width * unit(rng));
        spray.fibers.emplace_back(xs.back(), (2.0 + 6.0 * unit(rng)) * spray.h);
    }
    spray.run(static_cast<int>(std::lround(spray.rows / travel)) + 4, 2);
    double captured = 0.0;
    for (const double m : spray.fiberCaptured)
    {
        captured += m;
    }
    ThickRun result;
    result.model = 1.0 - captured / spray.injectedMeasured;
    result.expMinusS = std::exp(-count * strip / width); // P15: n_A 2 (r_F + r_p) t = N c / W
    result.lanes = test::lanesField(xs, strip, spray.h, spray.columns);
    return result;
}

using Sweep = std::array<std::array<ThickRun, travels.size()>, depths.size()>;
const Sweep& sweep()
{
    static const Sweep runs = []
    {
        Sweep all{};
        for (std::size_t i = 0; i < depths.size(); ++i)
        {
            for (std::size_t j = 0; j < travels.size(); ++j)
            {
                const ThickRun& run = all[i][j] = thickMat(depths[i], travels[j], 7);
                std::printf("S %.3f, %.3f spacing per step: %.5f, exp(-S) %.5f (%+.2f %%), lanes' field "
                            "%.5f (%+.2f %%), without the self-shadow %.5f\n",
                            depths[i], travels[j], run.model, run.expMinusS,
                            100.0 * (run.model / run.expMinusS - 1.0), run.lanes.shadowed,
                            100.0 * (run.model / run.lanes.shadowed - 1.0), run.lanes.unshadowed);
            }
        }
        return all;
    }();
    return runs;
}
} // namespace

TEST(ThickMat, EveryStepGivesTheShadowedLanesField)
{
    // P21's depths are the lanes' whatever the step: the model is the shadowed lanes' field of
    // its mat (the mat's clustering at the grid's scale included) at every travel per step,
    // to the deposit points' phase and the third order in c / h. Without the self-shadow the
    // lanes would keep P20's excess, exp(S c / 4h) on average over mats.
    for (std::size_t i = 0; i < depths.size(); ++i)
    {
        for (std::size_t j = 0; j < travels.size(); ++j)
        {
            const ThickRun& run = sweep()[i][j];
            EXPECT_LT(std::abs(run.model / run.lanes.shadowed - 1.0), 0.008)
                << "S " << depths[i] << ", travel " << travels[j];
            EXPECT_GT(run.lanes.unshadowed / run.lanes.shadowed, std::exp(0.5 * depths[i] * 0.14 / 4.0))
                << "S " << depths[i];
        }
    }
}

// The target of the issue: within 3 % of exp(-S) at every travel per step, as DenseMat for
// thin fibers (docs/model.md sec. 7, P21).
TEST(ThickMat, PenetrationWithinThreePercentOfExpMinusS)
{
    for (std::size_t i = 0; i < depths.size(); ++i)
    {
        for (std::size_t j = 0; j < travels.size(); ++j)
        {
            const ThickRun& run = sweep()[i][j];
            EXPECT_LT(std::abs(run.model / run.expMinusS - 1.0), 0.03)
                << "S " << depths[i] << ", travel " << travels[j];
        }
    }
}
