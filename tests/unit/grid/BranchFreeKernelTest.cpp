// The inline exp and scaled erfc of the batched deposit (compiled for AVX2 + FMA in every
// x86-64 build, KernelBuild.hpp) against long double expl and erfcl (an independent
// implementation with 11 more bits), and their four-lane form against their scalar form (the
// same formulas; GCC may contract a * b + c into FMA differently in the two, so they agree to
// an ulp or two, not to the bit). On a CPU without AVX2 + FMA (or a build without the batched
// code) the tests report a skip.
#include "grid/KernelBuild.hpp"
#include "grid/PathWeightBatch.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#if DROPLETFIBER_BATCHED_KERNEL
#include "grid/BranchFreeErfc.hpp"
#include "grid/BranchFreeExp.hpp"
#include "grid/Lanes.hpp"

// The four-lane forms for the tests, from and to arrays: code of the default target (the
// tests) must not pass lane vectors by value to AVX2 code (KernelBuild.hpp, points 3 and 5).
DROPLETFIBER_AVX2_BEGIN
namespace dropletFiber::avx2
{
namespace
{
void branchFreeExpFourLanes(const double* x, double* result)
{
    storeLanes(result, branchFreeExp(loadLanes(x)));
}

void erfcScaledPartsFourLanes(const double* x, double* numerator, double* denominator)
{
    const FractionOf<Lanes> parts = erfcScaledParts(loadLanes(x));
    storeLanes(numerator, parts.numerator);
    storeLanes(denominator, parts.denominator);
}

// As the deposit: each of four arguments with the one interval that erfcScaledInterval
// chooses for it (PathWeightBatch), and all three selected (erfcScaledParts).
void erfcScaledPartsOneIntervalFourLanes(const double* x, double* numerator, double* denominator)
{
    const Lanes v = loadLanes(x);
    const FractionOf<Lanes> parts[3]
        = {erfcScaledPartsSmall(v), erfcScaledPartsMiddle(v), erfcScaledPartsLarge(v)};
    for (int lane = 0; lane < laneCount; ++lane)
    {
        const int interval = erfcScaledInterval(x[lane]);
        numerator[lane] = parts[interval].numerator[lane];
        denominator[lane] = parts[interval].denominator[lane];
    }
}
} // namespace
} // namespace dropletFiber::avx2
DROPLETFIBER_AVX2_END
#endif

using namespace dropletFiber;

#define SKIP_UNLESS_BATCHED()                                                                                \
    if (!PathWeightBatch::cpuSupported())                                                                    \
    {                                                                                                        \
        GTEST_SKIP() << "this CPU has no AVX2 + FMA (or this build no batched kernel): nothing to test";     \
    }

#if DROPLETFIBER_BATCHED_KERNEL
using namespace dropletFiber::avx2;

namespace
{

// |got - reference| in units of the double ulp at the reference (normal range).
double ulps(double got, long double reference)
{
    const double rounded = static_cast<double>(reference);
    const double ulp = std::nextafter(std::abs(rounded), INFINITY) - std::abs(rounded);
    return static_cast<double>(std::abs(static_cast<long double>(got) - reference) / ulp);
}

} // namespace
#endif

TEST(BranchFreeKernel, ExpWithinOneUlpOfExpl)
{
    SKIP_UNLESS_BATCHED();
#if DROPLETFIBER_BATCHED_KERNEL
    std::mt19937_64 random(20261123);
    std::uniform_real_distribution<double> wide(-708.39, 709.0);
    std::uniform_real_distribution<double> narrow(-60.0, 0.25); // what the deposit passes
    // 1 ulp for the method (the Taylor truncation is < 5e-18 relative), plus a little for
    // GCC's contraction of a * b + c into FMA for the AVX2 + FMA target (-ffp-contract=fast),
    // which rounds the polynomial differently: worst seen 1.006 ulp.
    constexpr double maxExpUlps = 1.02;
    double worst = 0.0;
    for (int i = 0; i < 2000000; ++i)
    {
        const double x = (i % 2 == 0) ? wide(random) : narrow(random);
        const double error = ulps(branchFreeExp(x), std::exp(static_cast<long double>(x)));
        worst = std::max(worst, error);
        ASSERT_LE(error, maxExpUlps) << "x = " << x;
    }
    for (double x :
         {0.0, -0.0, 1e-300, -1e-300, 1e-17, -1e-17, 0.5 * M_LN2, -0.5 * M_LN2, M_LN2, -M_LN2, 1.0, -1.0})
    {
        ASSERT_LE(ulps(branchFreeExp(x), std::exp(static_cast<long double>(x))), maxExpUlps) << x;
    }
    EXPECT_EQ(branchFreeExp(0.0), 1.0);
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", worst);
    RecordProperty("worstUlps", text);
    // Gradual underflow: subnormal results within one unit of the smallest subnormal; 0 far below.
    std::uniform_real_distribution<double> subnormal(-745.2, -708.4);
    for (int i = 0; i < 100000; ++i)
    {
        const double x = subnormal(random);
        const long double reference = std::exp(static_cast<long double>(x));
        ASSERT_LE(std::abs(static_cast<long double>(branchFreeExp(x)) - reference),
                  static_cast<long double>(std::numeric_limits<double>::denorm_min()))
            << x;
    }
    for (double x : {-746.0, -800.0, -1e5, -1e300, -DBL_MAX})
    {
        EXPECT_EQ(branchFreeExp(x), 0.0) << x;
    }
#endif
}

TEST(BranchFreeKernel, ErfcScaledMatchesLongDoubleReference)
{
    SKIP_UNLESS_BATCHED();
#if DROPLETFIBER_BATCHED_KERNEL
    double worst = 0.0;
    for (int i = 0; i <= 300000; ++i)
    {
        const double x = 1e-4 * i; // 0 .. 30, all three intervals of the approximation
        const long double xl = x;
        const long double reference = std::erfc(xl) * std::exp(xl * xl);
        // Below erfcScaledSmallEnd the parts leave out the factor exp(x^2) (gaussianErfcScaled).
        const FractionOf<double> parts = erfcScaledParts(x);
        const long double factor = x <= erfcScaledSmallEnd ? std::exp(xl * xl) : 1.0L;
        const long double got = factor * parts.numerator / parts.denominator;
        const double error = static_cast<double>(std::abs((got - reference) / reference));
        worst = std::max(worst, error);
        ASSERT_LT(error, 2e-15) << "x = " << x;
        // The deposit evaluates one interval per end, chosen by erfcScaledInterval, in lanes:
        // the same bits as all three selected, in lanes.
        const double arguments[laneCount] = {x, x + 0.5e-4, 2.0 * x, 0.5 * x};
        double numerators[laneCount], denominators[laneCount], singleNumerators[laneCount],
            singleDenominators[laneCount];
        erfcScaledPartsFourLanes(arguments, numerators, denominators);
        erfcScaledPartsOneIntervalFourLanes(arguments, singleNumerators, singleDenominators);
        for (int lane = 0; lane < laneCount; ++lane)
        {
            ASSERT_EQ(singleNumerators[lane], numerators[lane]) << arguments[lane];
            ASSERT_EQ(singleDenominators[lane], denominators[lane]) << arguments[lane];
        }
        // g erfcScaled(x) with g = exp(-x^2) and gAtZero = 1: erfc(x) itself.
        const FractionOf<double> product
            = gaussianErfcScaled(x, parts, static_cast<double>(std::exp(-xl * xl)), 1.0);
        const long double erfcReference = std::erfc(xl);
        if (erfcReference > 1e-290L)
        {
            ASSERT_LT(
                std::abs((static_cast<long double>(product.numerator) / product.denominator - erfcReference)
                         / erfcReference),
                4e-15L)
                << x;
        }
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3e", worst);
    RecordProperty("worstRelativeError", text);
    for (double x : {50.0, 1e3, 1e5, 1e8}) // far tail: 1 / (x sqrt(pi)) (1 - 1/(2x^2) + ...)
    {
        const FractionOf<double> parts = erfcScaledParts(x);
        const double z = 1.0 / (2.0 * x * x);
        const double asymptotic
            = (1.0 - z + 3.0 * z * z - 15.0 * z * z * z + 105.0 * z * z * z * z) / (x * std::sqrt(M_PI));
        EXPECT_NEAR(parts.numerator / parts.denominator / asymptotic, 1.0, 1e-14) << x;
    }
#endif
}

TEST(BranchFreeKernel, FourLanesAgreeWithScalar)
{
    SKIP_UNLESS_BATCHED();
#if DROPLETFIBER_BATCHED_KERNEL
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> exponent(-700.0, 1.0);
    std::uniform_real_distribution<double> argument(0.0, 12.0);
    const auto relative = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
    for (int i = 0; i < 100000; ++i)
    {
        double e[laneCount], x[laneCount], expLanes[laneCount], numerators[laneCount],
            denominators[laneCount];
        for (int lane = 0; lane < laneCount; ++lane)
        {
            e[lane] = exponent(random);
            x[lane] = argument(random);
        }
        branchFreeExpFourLanes(e, expLanes);
        erfcScaledPartsFourLanes(x, numerators, denominators);
        for (int lane = 0; lane < laneCount; ++lane)
        {
            ASSERT_LE(relative(expLanes[lane], branchFreeExp(e[lane])), 5e-16) << e[lane];
            const FractionOf<double> scalar = erfcScaledParts(x[lane]);
            ASSERT_LE(relative(numerators[lane] / denominators[lane], scalar.numerator / scalar.denominator),
                      5e-16)
                << x[lane];
        }
    }
#endif
}
