// Eqs. 12-18: the figure-4 check values of the paper (docs/model.md sec. 4), and the defining
// identities of r_min (packing, eqs. 14-15) and alpha (inflection point, eqs. 16-17)
// checked from their definitions rather than from the formulas the code uses.
#include "grid/ParcelKernel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dropletFiber;

namespace
{
constexpr double pi = 3.14159265358979323846;

KernelSettings settings2D()
{
    KernelSettings s;
    s.dimension = KernelDimension::TwoD;
    return s;
}
} // namespace

TEST(ParcelKernel, Figure4CheckValues)
{
    // Paper, figure 4: n = 1000, r_p = 1e-5 m, 2D, beta = 2.5 %. Values as printed
    // (docs/model.md sec. 4): r_max = 1e-2 m, r_min = 3.32e-4 m, alpha = 151.9, phi(0) = 1,
    // phi(1 mm) = 0.219, phi(2 mm) = 0.0023. Tolerances = half a unit of the last digit.
    const ParcelKernel kernel(1e-5, 1000.0, settings2D(), 2);
    EXPECT_NEAR(kernel.rMax(), 1e-2, 1e-15);
    EXPECT_NEAR(kernel.rMin(), 3.32e-4, 0.005e-4);
    EXPECT_NEAR(kernel.alpha(), 151.9, 0.05);
    EXPECT_NEAR(kernel.phi(0.0), 1.0, 1e-12);
    EXPECT_NEAR(kernel.phi(1e-3), 0.219, 0.0005);
    EXPECT_NEAR(kernel.phi(2e-3), 0.0023, 0.00005);
    EXPECT_EQ(kernel.phi(1e-2), 0.0);
    EXPECT_EQ(kernel.phi(2e-2), 0.0);
    EXPECT_FALSE(kernel.capped());
}

TEST(ParcelKernel, MinimumRadiusIsDensestPacking)
{
    // Eq. 14: n discs of radius r_p fill the fraction pi/(2 sqrt 3) of a disc of radius r_min;
    // 3D: n spheres fill pi/sqrt(18) of a sphere of radius r_min.
    for (double n : {1.0, 7.0, 1000.0, 123456.0})
    {
        const double rp = 3e-5;
        const double r2 = influenceRadiusMin(rp, n, 2);
        EXPECT_NEAR(n * pi * rp * rp / (pi * r2 * r2), pi / (2.0 * std::sqrt(3.0)), 1e-13);
        const double r3 = influenceRadiusMin(rp, n, 3);
        EXPECT_NEAR(n * rp * rp * rp / (r3 * r3 * r3), pi / std::sqrt(18.0), 1e-13);
    }
}

TEST(ParcelKernel, AlphaPutsInflectionPointBetweenMinAndMaxRadius)
{
    // Eqs. 16-17: d^2/dd^2 exp(-alpha d^2 / r_max^2) vanishes at beta r_max + (1 - beta) r_min.
    // Checked with a central finite difference of the Gaussian itself.
    for (double beta : {0.025, 0.1, 0.5})
    {
        for (double n : {2.0, 50.0, 1000.0, 1e5})
        {
            KernelSettings s;
            s.beta = beta;
            const ParcelKernel k(1e-5, n, s, 3);
            const double dInflection = beta * k.rMax() + (1.0 - beta) * k.rMin();
            auto g = [&](double d) { return std::exp(-k.alpha() * d * d / (k.rMax() * k.rMax())); };
            auto second = [&](double d)
            {
                const double h = 1e-4 * dInflection;
                return (g(d + h) - 2.0 * g(d) + g(d - h)) / (h * h);
            };
            // Sign change across the inflection point (second derivative < 0 inside, > 0 outside).
            EXPECT_LT(second(0.99 * dInflection), 0.0) << "beta " << beta << " n " << n;
            EXPECT_GT(second(1.01 * dInflection), 0.0) << "beta " << beta << " n " << n;
        }
    }
}

TEST(ParcelKernel, SingleDropletParcelHasBroadKernel)
{
    // n = 1: r_min (packing radius of one disc) exceeds r_max = r_p; eq. 18 then gives a
    // small alpha and phi stays a positive, decreasing function on [0, r_max).
    const ParcelKernel k(1e-4, 1.0, settings2D(), 2);
    EXPECT_GT(k.rMin(), k.rMax());
    EXPECT_LT(k.alpha(), 1.0);
    EXPECT_GT(k.phi(0.0), k.phi(0.5e-4));
    EXPECT_GT(k.phi(0.99e-4), 0.0);
    EXPECT_EQ(k.phi(1e-4), 0.0);
}

TEST(ParcelKernel, CapTruncatesSupportAndKeepsShape)
{
    KernelSettings s = settings2D();
    s.rMaxCap = 2e-3;
    const ParcelKernel capped(1e-5, 1000.0, s, 2);
    const ParcelKernel free(1e-5, 1000.0, settings2D(), 2);
    EXPECT_TRUE(capped.capped());
    EXPECT_EQ(capped.reach(), 2e-3);
    EXPECT_EQ(capped.alpha(), free.alpha());
    // Same Gaussian, different constant: phi_capped(d) - phi_free(d) = exp(-alpha) - exp(-alpha (cap/r_max)^2).
    const double shift = std::exp(-free.alpha()) - std::exp(-free.alpha() * 0.04);
    EXPECT_NEAR(capped.phi(1e-3) - free.phi(1e-3), shift, 1e-15);
    EXPECT_EQ(capped.phi(2e-3), 0.0);
    EXPECT_GT(free.phi(2e-3), 0.0);
}

TEST(ParcelKernel, PhiAccurateNearEdgeOfSupport)
{
    // Reference in long double: the double formula exp(-a s) - exp(-a) would lose all
    // digits here. What remains is the rounding of d^2 itself (relative error of
    // reach^2 - d^2 about 1e-16 / gap), the conditioning of phi at the rim.
    const ParcelKernel k = ParcelKernel::fromShape(150.0, 1.0);
    for (double gap : {1e-3, 1e-6, 1e-9})
    {
        const double d = 1.0 - gap;
        const long double dl = d;
        const long double ref = std::exp(-150.0L * dl * dl) - std::exp(-150.0L);
        EXPECT_NEAR(k.phi(d) / static_cast<double>(ref), 1.0, 4e-16 / gap + 1e-13) << gap;
    }
}

TEST(ParcelKernel, RejectsInvalidSettings)
{
    KernelSettings s;
    s.beta = 0.0;
    EXPECT_THROW(s.validate(), std::invalid_argument);
    s.beta = 1.5;
    EXPECT_THROW(s.validate(), std::invalid_argument);
    EXPECT_THROW(ParcelKernel(-1e-5, 10.0, KernelSettings{}, 2), std::invalid_argument);
    EXPECT_THROW(ParcelKernel(1e-5, 0.0, KernelSettings{}, 2), std::invalid_argument);
    KernelSettings cut;
    EXPECT_EQ(cut.negligibleWeight, 1e-8);
    cut.negligibleWeight = 0.0; // exact tails
    EXPECT_NO_THROW(cut.validate());
    cut.negligibleWeight = 1e-6;
    EXPECT_NO_THROW(cut.validate());
    for (double bad : {-1e-17, 2e-6, 0.5, std::nan(""), HUGE_VAL})
    {
        cut.negligibleWeight = bad;
        EXPECT_THROW(cut.validate(), std::invalid_argument) << bad;
    }
}
