// Depletion in dense fiber regions at the time steps users run (docs/model.md sec. 7, the
// per-parcel removal; docs/validation.md "Depletion: dense mats and the time step"): random
// mats of fixed fibers 6 spacings thick, -ln P = S = 0.1 ... 4.6 (P15), droplets travelling
// 1/8 ... 1 spacing per step, default deposit (cloud-in-cell, window of one step). The
// penetration against exp(-S) from the mat's fibers (each parcel crossing its nodes' optical
// depths, P14), the error against the travel per step, and the binder balance to 1e-12.
#include "LanesField.hpp"
#include "StraightSpray.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

using namespace dropletFiber;

namespace
{
constexpr double thickness = 6.0; // the mat, in spacings, from y0 = 2 spacings
constexpr double frontFace = 2.0;
constexpr std::array<double, 5> depths = {{0.1, 0.5, 1.0, 2.302585092994046, 4.6}};
constexpr std::array<double, 4> travels = {{1.0, 0.5, 0.25, 0.125}}; // v dt / h

struct MatRun
{
    double model = 0.0, theory = 0.0, balance = 0.0;
    double lanes = 0.0; // the model's limit for small steps for this mat (LanesField.hpp)
};

// A mat of N fibers at uniform random (x, y) in [0, W] x [2 h, 8 h], N from S: each fiber's
// interception strip 2 (r_F + r_p) is c = 0.002 of a spacing (a node column holds hundreds
// of fibers per unit of S: the grid's column means are the mat's, DepletionValidationTest).
MatRun denseMat(double S, double travel, unsigned seed)
{
    test::StraightSpray spray;
    spray.columns = 4;
    spray.rows = 10;
    spray.dt = travel * spray.h / spray.speed;
    spray.dropletRadius = 0.8e-6;
    spray.nParticle = 1000.0;
    const double strip = 0.002 * spray.h;
    spray.fiberRadius = 0.5 * strip - spray.dropletRadius;
    const double width = spray.columns * spray.h;
    const int count = static_cast<int>(std::lround(S * width / strip));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xs;
    for (int n = 0; n < count; ++n)
    {
        xs.push_back(width * unit(rng));
        spray.fibers.emplace_back(xs.back(), (frontFace + thickness * unit(rng)) * spray.h);
    }
    // Steady after the spray has crossed the box (10 spacings); then every step is alike.
    spray.run(static_cast<int>(std::lround(spray.rows / travel)) + 4, 2);
    double captured = 0.0;
    for (const double m : spray.fiberCaptured)
    {
        captured += m;
    }
    MatRun result;
    result.model = 1.0 - captured / spray.injectedMeasured;
    // P15 from the fibers placed: n_A 2 (r_F + r_p) t = N strip / W
    const double dF = 2.0 * spray.fiberRadius, dp = 2.0 * spray.dropletRadius;
    const double alpha = count * 3.14159265358979323846 * spray.fiberRadius * spray.fiberRadius
        / (width * thickness * spray.h);
    result.theory
        = std::exp(-4.0 * alpha * (1.0 + dp / dF) * thickness * spray.h / (3.14159265358979323846 * dF));
    result.lanes = test::lanesField(xs, strip, spray.h, spray.columns).shadowed;
    result.balance = (spray.sprayed - (spray.airborne() + spray.left + spray.captured)) / spray.sprayed;
    return result;
}

// What a rule per node (every parcel losing sum_n w_n (1 - e^-x_n)) would leave at the mat's
// faces (docs/model.md sec. 7, P18), to leading order in v dt: kappa_n goes 0, kappa / 2,
// kappa at a face on a node row (this mat), kappa^2 / 2 per face, so
//     ln(P_node / P) = (S / t)^2 v dt h / 12
// The per-parcel rule has no such term: the table shows it beside the error for comparison.
double faceError(double S, double travel)
{
    const double kappaH = S / thickness; // kappa h
    return kappaH * kappaH * travel / 12.0;
}

std::ofstream validationTable(const std::string& name)
{
    const char* folder = std::getenv("DROPLETFIBER_DEPLETION_CSV");
    return folder == nullptr ? std::ofstream{} : std::ofstream(std::string(folder) + "/" + name + ".csv");
}

// The mats of every depth at every travel per step (run once, both tests read them).
using Sweep = std::array<std::array<MatRun, travels.size()>, depths.size()>;
const Sweep& sweep()
{
    static const Sweep runs = []
    {
        Sweep all{};
        std::ofstream table = validationTable("depletionDenseMat");
        table.precision(10);
        table << "S,travel,model,theory,relativeError,faceErrorLeadingOrder\n";
        for (std::size_t i = 0; i < depths.size(); ++i)
        {
            std::printf("S %.3f:", depths[i]);
            for (std::size_t j = 0; j < travels.size(); ++j)
            {
                const MatRun& run = all[i][j] = denseMat(depths[i], travels[j], 7);
                const double error = run.model / run.theory - 1.0;
                std::printf("  %.3f: %.5f / %.5f (%+.2f %%; lanes %+.2f %%)", travels[j], run.model,
                            run.theory, 100.0 * error, 100.0 * (run.model / run.lanes - 1.0));
                table << depths[i] << ',' << travels[j] << ',' << run.model << ',' << run.theory << ','
                      << error << ',' << std::expm1(faceError(depths[i], travels[j])) << '\n';
            }
            std::printf("\n");
        }
        return all;
    }();
    return runs;
}
} // namespace

TEST(DenseMat, PenetrationWithinThreePercentOfExpMinusSAtEveryTravelPerStep)
{
    for (std::size_t i = 0; i < depths.size(); ++i)
    {
        for (std::size_t j = 0; j < travels.size(); ++j)
        {
            const MatRun& run = sweep()[i][j];
            const double S = depths[i], travel = travels[j];
            const double error = run.model / run.theory - 1.0;
            EXPECT_LT(std::abs(run.balance), 1e-12) << "S " << S << ", travel " << travel;
            // The target: within 3 % at every depth and travel per step
            EXPECT_LT(std::abs(error), 0.03) << "S " << S << ", travel " << travel;
            // No faces' term: where a rule per node would pass P18's leading-order term
            // (+5.0 % at S = 4.6 and a spacing per step) the error stays below a fifth of
            // it; besides it the grid's column means and the sample points' phase, 0.4 %
            // (docs/validation.md, dense mats)
            EXPECT_LT(std::abs(error), 0.2 * std::expm1(faceError(S, travel)) + 0.004)
                << "S " << S << ", travel " << travel;
        }
    }
}

TEST(DenseMat, ErrorConvergesToZeroWithTheTimeStep)
{
    // At S = ln 10 and 4.6, against the mat's own limit for small steps (its lanes' field,
    // LanesField.hpp: exp(-S) but for the mat's clustering at the grid's scale, -0.3 % here):
    // at an eighth of a spacing per step within 0.1 % (the node rule's faces' term alone was
    // +0.6 % there), and smaller than at half a spacing per step.
    for (const std::size_t i : {std::size_t{3}, std::size_t{4}})
    {
        const MatRun& finest = sweep()[i].back();
        const MatRun& half = sweep()[i][1];
        const double fine = std::abs(finest.model / finest.lanes - 1.0);
        EXPECT_LT(fine, 0.001) << "S " << depths[i];
        EXPECT_LT(fine, std::abs(half.model / half.lanes - 1.0)) << "S " << depths[i];
        EXPECT_LT(std::abs(finest.lanes / finest.theory - 1.0), 0.004) << "S " << depths[i];
    }
}
