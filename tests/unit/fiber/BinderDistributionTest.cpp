// BinderDistribution: the binder table's figures for two fibers set by hand, against the
// same figures worked out on paper (docs/model.md sec. 3, discrete hits).
#include "fiber/BinderDistribution.hpp"
#include "fiber/FiberSolver.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dropletFiber;

namespace
{

Fiber straightFiber(const std::vector<double>& segmentLengths)
{
    Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Zero(3, Eigen::Index(segmentLengths.size() + 1));
    for (std::size_t j = 0; j < segmentLengths.size(); ++j)
    {
        points(0, Eigen::Index(j + 1)) = points(0, Eigen::Index(j)) + segmentLengths[j];
    }
    FiberMaterial material;
    material.radius = 1e-5;
    material.density = 1000.0;
    return Fiber::immobileFiber(points, material);
}

} // namespace

// Fiber A: segments 1, 1, 2 mm with 0, 2, 4 ug (sigma 0, 2, 2 mg/m) and 0, 3, 5 hits;
// fiber B: one 4 mm segment with 4 ug (sigma 1 mg/m), 7 hits. L = 8 mm, bare 1 mm,
// mass 10 ug: mean 1.25 mg/m; sum l sigma^2 = (1 x 4 + 2 x 4 + 4 x 1) mm (mg/m)^2 = 16,
// over L: 2 (mg/m)^2, variance 2 - 1.5625 = 0.4375, CoV sqrt(0.4375) / 1.25 = 0.52915;
// hits 15 over 8 mm: 1875 per m.
TEST(BinderDistribution, FiguresOfTwoFibersByHand)
{
    Fiber a = straightFiber({1e-3, 1e-3, 2e-3});
    a.mutableState().segmentCapturedMass << 0.0, 2e-9, 4e-9;
    a.mutableState().segmentHits << 0.0, 3.0, 5.0;
    Fiber b = straightFiber({4e-3});
    b.mutableState().segmentCapturedMass << 4e-9;
    b.mutableState().segmentHits << 7.0;
    BinderSums sums;
    sums.add(a);
    BinderSums other;
    other.add(b);
    sums += other; // as the processors' sums add up
    const BinderFigures f = binderFigures(sums);
    EXPECT_NEAR(f.length, 8e-3, 1e-15);
    EXPECT_NEAR(f.bareFraction, 0.125, 1e-12);
    EXPECT_NEAR(f.meanSigma, 1.25e-6, 1e-18);
    EXPECT_NEAR(f.sigmaVariation, std::sqrt(0.4375) / 1.25, 1e-9);
    EXPECT_NEAR(f.hitsPerLength, 1875.0, 1e-9);
    EXPECT_EQ(binderFigures(BinderSums{}).length, 0.0);
}

// The expected mode's columns on the same fibers: A's expected masses 0, 1, 3 ug (sigma 0,
// 1, 1.5 mg/m), B's 6 ug (sigma 1.5 mg/m). Bare 1 mm of 8: 0.125; mean 10 ug / 8 mm = 1.25
// mg/m; sum l sigma^2 = 1 x 1 + 2 x 2.25 + 4 x 2.25 = 14.5, over L 1.8125, variance
// 1.8125 - 1.5625 = 0.25, CoV 0.5 / 1.25 = 0.4. A state without the expected masses reads
// them as its captured masses (the expected mode's history).
TEST(BinderDistribution, ExpectedModeFiguresByHand)
{
    Fiber a = straightFiber({1e-3, 1e-3, 2e-3});
    a.mutableState().segmentCapturedMass << 0.0, 2e-9, 4e-9;
    a.mutableState().segmentExpectedMass << 0.0, 1e-9, 3e-9;
    Fiber b = straightFiber({4e-3});
    b.mutableState().segmentExpectedMass << 6e-9;
    BinderSums sums;
    sums.add(a);
    sums.add(b);
    const BinderFigures f = binderFigures(sums);
    EXPECT_NEAR(f.expectedBareFraction, 0.125, 1e-12);
    EXPECT_NEAR(f.expectedMeanSigma, 1.25e-6, 1e-18);
    EXPECT_NEAR(f.expectedSigmaVariation, 0.4, 1e-9);
    // B caught nothing itself: 5 of 8 mm bare in the captured columns
    EXPECT_NEAR(f.bareFraction, 0.625, 1e-12);

    FiberState old = a.state();
    old.segmentExpectedMass.resize(0);
    const Fiber restarted(old);
    EXPECT_EQ(restarted.state().segmentExpectedMass, a.state().segmentCapturedMass);
}

// A step's capture adds each segment's expected mass next to its caught mass and hits.
TEST(BinderDistribution, CaptureAddsTheExpectedMass)
{
    Fiber a = straightFiber({1e-3, 2e-3});
    std::vector<SegmentSource> sources(2);
    sources[0].mass = 2e-9; // two droplets where 0.7 were expected
    sources[0].hits = 2.0;
    sources[0].expectedMass = 0.7e-9;
    sources[1].expectedMass = 0.4e-9; // none caught
    applyCapture(a, sources);
    applyCapture(a, sources);
    EXPECT_DOUBLE_EQ(a.state().segmentExpectedMass(0), 1.4e-9);
    EXPECT_DOUBLE_EQ(a.state().segmentExpectedMass(1), 0.8e-9);
    EXPECT_DOUBLE_EQ(a.state().segmentCapturedMass(0), 4e-9);
    EXPECT_EQ(a.state().segmentCapturedMass(1), 0.0);
}

// A computed fiber standing for N physical ones counts as N copies of itself (its
// segments once: the resolution): fiber A of weight 3 with fiber B of weight 1 gives the
// figures of three A's and one B, worked out as above. L = 3 x 4 + 4 = 16 mm, bare 3 mm,
// mass 3 x 6 + 4 = 22 ug: mean 1.375 mg/m; sum l sigma^2 = 3 x 12 + 4 = 40 mm (mg/m)^2,
// over L 2.5, variance 2.5 - 1.890625 = 0.609375, CoV 0.780625 / 1.375 = 0.567727;
// hits 3 x 8 + 7 = 31 over 16 mm: 1937.5 per m.
TEST(BinderDistribution, AWeightedFiberCountsAsItsPhysicalFibers)
{
    Fiber a = straightFiber({1e-3, 1e-3, 2e-3});
    a.mutableState().segmentCapturedMass << 0.0, 2e-9, 4e-9;
    a.mutableState().segmentHits << 0.0, 3.0, 5.0;
    a.setRepresents(3.0);
    Fiber b = straightFiber({4e-3});
    b.mutableState().segmentCapturedMass << 4e-9;
    b.mutableState().segmentHits << 7.0;
    BinderSums sums;
    sums.add(a);
    sums.add(b);
    const BinderFigures f = binderFigures(sums);
    EXPECT_NEAR(f.length, 16e-3, 1e-15);
    EXPECT_NEAR(f.bareFraction, 3.0 / 16.0, 1e-12);
    EXPECT_NEAR(f.meanSigma, 1.375e-6, 1e-15);
    EXPECT_NEAR(f.sigmaVariation, std::sqrt(0.609375) / 1.375, 1e-9);
    EXPECT_NEAR(f.hitsPerLength, 1937.5, 1e-9);
    EXPECT_EQ(sums.values[5], 4.0); // segments computed
    EXPECT_THROW(a.setRepresents(0.0), std::invalid_argument);
}
