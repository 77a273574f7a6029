// erfcScaled(x) = exp(x^2) erfc(x) against long double erfc and exp (an independent
// implementation with 11 more bits), over the whole range the path weight uses.
#include "grid/ScaledErfc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dropletFiber;

TEST(ScaledErfc, MatchesLongDoubleReference)
{
    double worst = 0.0;
    for (int i = 0; i <= 200000; ++i)
    {
        const double x = 1e-4 * i; // 0 .. 20, all three intervals of the approximation
        const long double reference
            = std::erfc(static_cast<long double>(x)) * std::exp(static_cast<long double>(x) * x);
        const double got = erfcScaled(x);
        const double error = std::abs(static_cast<double>((got - reference) / reference));
        worst = std::max(worst, error);
        ASSERT_LT(error, 2e-15) << "x = " << x;
        const Fraction f = erfcScaledFraction(x);
        ASSERT_LT(std::abs(static_cast<double>((f.numerator / f.denominator - reference) / reference)),
                  2e-15);
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3e", worst);
    RecordProperty("worstRelativeError", text);
    // Far tail: erfc underflows long before x = 1e5, the scaled function does not.
    for (double x : {50.0, 1e3, 1e5, 1e8})
    {
        // Asymptotic series sum (-1)^n (2n-1)!! / (2 x^2)^n, five terms (error < 1e-15 for x >= 50).
        const double z = 1.0 / (2.0 * x * x);
        const double series = 1.0 - z + 3.0 * z * z - 15.0 * z * z * z + 105.0 * z * z * z * z;
        const double asymptotic = series / (x * std::sqrt(3.14159265358979323846));
        EXPECT_NEAR(erfcScaled(x) / asymptotic, 1.0, 1e-14) << x;
    }
    EXPECT_EQ(erfcScaled(0.0), 1.0);
}
