// CTest checks of the validation (reduced sizes of PaperSetting::reduced()). Expected values
// come from the flow rate (analyticCollisionMass: the spray's mass per step times the
// fiber's share 2 (r_F + r) / W of the injection width) or from the geometric counts,
// never from the grid code itself.
#include "Experiments.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace dropletFiber;
using namespace dropletFiber::validation;

namespace
{
const PaperSetting setting = PaperSetting::reduced();

double relative(double value, double reference)
{
    return value / reference - 1.0;
}

struct ConstantDensityCase
{
    int streams;
    double dropletsPerParcel;
};

// The reduced sweeps of figures 7 (fixed flow rate) and 8 (100 streams).
std::vector<ConstantDensityCase> constantDensityCases()
{
    std::vector<ConstantDensityCase> cases;
    for (int streams : setting.fig7Streams)
    {
        cases.push_back({streams, setting.fig7DropletsPerStep / streams});
    }
    for (double n : setting.fig8DropletsPerParcel)
    {
        cases.push_back({setting.fig8Streams, n});
    }
    return cases;
}
} // namespace

// --- pieces ---------------------------------------------------------------------------------

TEST(Pieces, PathEntersCircleCountsEachPassOnce)
{
    const Eigen::Vector2d c(0.0, 0.0);
    // Straight down through the circle in steps of 0.3: entered in exactly one step.
    int entries = 0;
    for (int step = 0; step < 20; ++step)
    {
        const Eigen::Vector2d start(0.5, 3.0 - 0.3 * step), end(0.5, 3.0 - 0.3 * (step + 1));
        entries += pathEntersCircle(start, end, c, 1.0) ? 1 : 0;
    }
    EXPECT_EQ(entries, 1);
    // Passing beside it: never; starting inside: not again.
    EXPECT_FALSE(pathEntersCircle(Eigen::Vector2d(1.2, 2.0), Eigen::Vector2d(1.2, -2.0), c, 1.0));
    EXPECT_FALSE(pathEntersCircle(Eigen::Vector2d(0.0, 0.5), Eigen::Vector2d(0.0, -3.0), c, 1.0));
    EXPECT_TRUE(pathEntersCircle(Eigen::Vector2d(0.0, 3.0), Eigen::Vector2d(0.0, -3.0), c, 1.0)); // through
}

TEST(Pieces, SteadySprayHasTheFlowRateDensity)
{
    // The density counted in the box equals the flow rate over (width speed depth), in
    // every step: the parcels' paths tile the stream lines.
    const SprayStreams spray(monodisperseSpray(setting, 100, 7.0));
    for (int steps : {1, 3})
    {
        const MeasuredField f = measureField(spray, setting.depth, -setting.injectionHalfWidth,
                                             setting.injectionHalfWidth, 0.01, 0.06, steps);
        EXPECT_NEAR(relative(f.rho, spray.analyticDensity(setting.depth)), 0.0, 1e-12);
        EXPECT_NEAR(f.rMeanMass, setting.dropletRadius, 1e-18);
    }
    // Mass per step: 100 streams x 7 droplets.
    EXPECT_NEAR(relative(spray.massPerStep(), 700.0 * setting.dropletMass(setting.dropletRadius)), 0.0,
                1e-14);
}

TEST(Pieces, PolydisperseMeanRadiiMatchTheirDefinitions)
{
    // Equal-mass parcels, radius uniform in [a, b]: mass mean (a + b) / 2 and number mean
    // 2ab / (a + b); compared with the parcels actually injected.
    const SprayStreams spray(polydisperseSpray(setting, 200));
    const MeasuredField f = measureField(spray, setting.depth, -setting.injectionHalfWidth,
                                         setting.injectionHalfWidth, 0.0, 0.07, 20);
    EXPECT_NEAR(relative(f.rMeanMass, spray.meanRadiusMass()), 0.0, 0.005);
    EXPECT_NEAR(relative(f.rMeanNumber, spray.meanRadiusNumber()), 0.0, 0.005);
    EXPECT_GT(spray.meanRadiusMass() / spray.meanRadiusNumber(), 1.2); // far apart: a sharp question
}

TEST(Pieces, OutlineSamplingEqualsEquationNineInUniformField)
{
    // On a grid holding a uniform spray the outline's weights sum to one: same as one
    // sample at the axis.
    const SprayDefinition spray = monodisperseSpray(setting, 100, 1000.0);
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    GridMethod outline = paperGridMethod(setting, 100);
    GridMethod axis = outline;
    axis.eq9.sampling = Eq9Sampling::Axis;
    const double truth = analyticCollisionMass(SprayStreams(spray), fiber);
    EXPECT_NEAR(relative(runGridMethod(setting, spray, fiber, outline).mass, truth), 0.0, 1e-3);
    EXPECT_NEAR(relative(runGridMethod(setting, spray, fiber, axis).mass, truth), 0.0, 1e-3);
}

// --- constant density (figures 7 and 8) ------------------------------------------------------

TEST(ConstantDensity, FormulaWithCountedDensityWithinTenthOfPercent)
{
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    for (const ConstantDensityCase& c : constantDensityCases())
    {
        const SprayStreams spray(monodisperseSpray(setting, c.streams, c.dropletsPerParcel));
        const double truth = analyticCollisionMass(spray, fiber);
        const double formula = formulaFromCount(setting, spray, fiber, RadiusAverage::Mass);
        EXPECT_LT(std::abs(relative(formula, truth)), 1e-3)
            << c.streams << " streams, n = " << c.dropletsPerParcel;
    }
}

TEST(ConstantDensity, ImprovedGridBelowOnePercentAt100x100)
{
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    double worst = 0.0;
    for (const ConstantDensityCase& c : constantDensityCases())
    {
        const SprayDefinition spray = monodisperseSpray(setting, c.streams, c.dropletsPerParcel);
        const double truth = analyticCollisionMass(SprayStreams(spray), fiber);
        const double error
            = relative(runGridMethod(setting, spray, fiber, improvedGridMethod(setting, 100)).mass, truth);
        EXPECT_LT(std::abs(error), 0.01) << c.streams << " streams, n = " << c.dropletsPerParcel;
        worst = std::max(worst, std::abs(error));
    }
    RecordProperty("worstRelativeError", std::to_string(worst));
}

TEST(ConstantDensity, FinerGridNotWorse)
{
    // The paper's claim (figure 10) for its deposit: the mean error over the sweeps at
    // 250x250 is not larger than at 100x100 (the finer grid resolves the narrow kernels).
    // With the improved deposit both are at the ~0.1 % floor of stream and path-sampling
    // aliasing, where 250x250 is not systematically better; there both stay below 1 %.
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    double paper100 = 0.0, paper250 = 0.0;
    for (const ConstantDensityCase& c : constantDensityCases())
    {
        const SprayDefinition spray = monodisperseSpray(setting, c.streams, c.dropletsPerParcel);
        const double truth = analyticCollisionMass(SprayStreams(spray), fiber);
        paper100 += std::abs(
            relative(runGridMethod(setting, spray, fiber, paperGridMethod(setting, 100)).mass, truth));
        paper250 += std::abs(
            relative(runGridMethod(setting, spray, fiber, paperGridMethod(setting, 250)).mass, truth));
        const double improved250
            = relative(runGridMethod(setting, spray, fiber, improvedGridMethod(setting, 250)).mass, truth);
        EXPECT_LT(std::abs(improved250), 0.01) << c.streams << " streams, n = " << c.dropletsPerParcel;
    }
    const double cases = static_cast<double>(constantDensityCases().size());
    RecordProperty("meanErrorPaper100", std::to_string(paper100 / cases));
    RecordProperty("meanErrorPaper250", std::to_string(paper250 / cases));
    EXPECT_LE(paper250, paper100);
}

// --- geometric method ------------------------------------------------------------------------

TEST(Geometric, ErrorWithManyDropletsPerParcelWithinPaperThreePercent)
{
    // 100 streams, 1000 droplets per parcel (figure 8's right end): against eq. 9.
    const FiberCircle fiber = fiberOf(setting, setting.fiberRadius);
    const SprayDefinition spray = monodisperseSpray(setting, 100, 1000.0);
    const double formula = formulaFromCount(setting, SprayStreams(spray), fiber, RadiusAverage::Mass);
    const double geometric = geometricMass(spray, fiber, DropletPlacement::ParcelPoint, 1, 4).mean;
    RecordProperty("relativeError", std::to_string(relative(geometric, formula)));
    EXPECT_LT(std::abs(relative(geometric, formula)), 0.03);
}

TEST(Geometric, ErrorIsTheStreamStaircase)
{
    // Why: the count is (streams inside the shadow of width 2 (r_F + r)) x parcel mass, and
    // a lattice of spacing s puts 2 (r_F + r) / s +- less than one stream inside. So the
    // relative error stays below s / (2 (r_F + r)) (2.5 % for 100 streams and r_F = 1 cm)
    // and sweeps that whole range as r_F moves across the lattice.
    const SprayDefinition spray = monodisperseSpray(setting, 100, 10.0);
    const SprayStreams streams(spray);
    double lowest = 0.0, highest = 0.0;
    for (double radius = 9.5e-3; radius < 10.0e-3; radius += 2.5e-5)
    {
        const FiberCircle fiber = fiberOf(setting, radius);
        const double error = relative(geometricMass(spray, fiber, DropletPlacement::ParcelPoint, 1, 2).mean,
                                      analyticCollisionMass(streams, fiber));
        const double bound = streams.streamSpacing() / (2.0 * (radius + setting.dropletRadius));
        EXPECT_LT(std::abs(error), bound) << "r_F = " << radius;
        lowest = std::min(lowest, error);
        highest = std::max(highest, error);
    }
    EXPECT_LT(lowest, -0.02);
    EXPECT_GT(highest, 0.02);
}

TEST(Geometric, FineReferenceConvergesToFlowRateExpectation)
{
    // Jittered injection and spread droplets sample the uniform spray: mean within 3 SE.
    const FiberCircle fiber = fiberOf(setting, 5e-4);
    SprayDefinition spray = polydisperseSpray(setting, setting.fig9Streams);
    const double truth = analyticCollisionMass(SprayStreams(spray), fiber);
    spray.jitter = true;
    const MeanAndError fine
        = geometricMass(spray, fiber, DropletPlacement::Spread, setting.fineSeeds, setting.fineSteps / 4);
    EXPECT_GT(fine.standardError, 0.0);
    EXPECT_LT(std::abs(fine.mean - truth), 3.0 * fine.standardError + 1e-4 * truth);
}

// --- polydisperse: the radius question -------------------------------------------------------

TEST(Polydisperse, MassWeightedRadiusMatchesFineGeometricReference)
{
    const Table radius = radiusStudy(setting);
    for (std::size_t row = 0; row < radius.rows.size(); ++row)
    {
        const double fine = radius.value(row, "fine"), se = radius.value(row, "fineSE");
        const double tolerance = se + 0.01 * fine;
        const double rF = radius.value(row, "fiberRadius");
        // The default mean radius (mass-weighted) with the spray's density, and on the grid.
        EXPECT_LT(std::abs(radius.value(row, "formulaMass") - fine), tolerance) << "r_F = " << rF;
        EXPECT_LT(std::abs(radius.value(row, "gridMass") - fine), tolerance) << "r_F = " << rF;
        // The paper's number-weighted mean misses by more where r_F is a few droplet radii.
        if (rF <= 5e-5)
        {
            EXPECT_GT(std::abs(radius.value(row, "formulaNumber") - fine), tolerance) << "r_F = " << rF;
        }
        RecordProperty("massOverFine_" + std::to_string(row),
                       std::to_string(radius.value(row, "formulaMass") / fine));
        RecordProperty("numberOverFine_" + std::to_string(row),
                       std::to_string(radius.value(row, "formulaNumber") / fine));
    }
    EXPECT_EQ(CollisionOptions{}.radiusAverage, RadiusAverage::Mass);
}
