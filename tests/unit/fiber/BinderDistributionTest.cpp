// BinderDistribution: the binder table's figures for two fibers set by hand, against the
// same figures worked out on paper (docs/model.md sec. 3, discrete hits).
#include "fiber/BinderDistribution.hpp"

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
