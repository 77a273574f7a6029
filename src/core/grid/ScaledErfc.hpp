// erfcScaled(x) = exp(x^2) erfc(x) for x >= 0, without exponentials for x > 0.46875.
//
// Why: the path weight (eq. 23) needs exp(-E) erfc(x) where exp(-E - x^2) is a Gaussian
// the caller already has (the kernel at an end of the path). With the scaled function the
// per-node cost is one rational function instead of erfc's two exponentials, and
// nothing underflows before the product does.
//
// Method: W. J. Cody, "Rational Chebyshev approximations for the error function",
// Math. Comp. 23 (1969) 631-637, with the coefficients of his public-domain SPECFUN
// routine CALERF: erf on [0, 0.46875], erfc exp(x^2) on [0.46875, 4] and x > 4.
// Relative accuracy ~1e-16 (checked against long double erfc in ScaledErfcTest).
#pragma once

#include "grid/CodyErfcRationals.hpp"

#include <cmath>

namespace dropletFiber
{

// erfcScaled(x) as numerator / denominator, so that a caller combining two of them
// needs one division instead of two (division latency dominates the path weight).
struct Fraction
{
    double numerator;
    double denominator;
};

inline Fraction erfcScaledFraction(double x)
{
    constexpr double inverseSqrtPi = 0.56418958354775628695;
    if (x <= 0.46875)
    {
        // erf(x) = x P(x^2) / Q(x^2); erfc = 1 - erf >= 0.5 here (no cancellation).
        const double z = x * x;
        const PolynomialPair<double> r = codyErfSmall(z);
        return {std::exp(z) * (r.q - x * r.p), r.q};
    }
    if (x <= 4.0)
    {
        const PolynomialPair<double> r = codyErfcMiddle(x);
        return {r.p, r.q};
    }
    // x > 4: erfc(x) exp(x^2) = (1/sqrt(pi) - z R(z)) / x, z = 1/x^2.
    const double z = 1.0 / (x * x);
    const PolynomialPair<double> r = codyErfcLarge(z);
    return {inverseSqrtPi * r.q - z * r.p, r.q * x};
}

inline double erfcScaled(double x)
{
    const Fraction f = erfcScaledFraction(x);
    return f.numerator / f.denominator;
}

} // namespace dropletFiber
