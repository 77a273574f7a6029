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
        const double p = (((0.185777706184603153 * z + 3.16112374387056560) * z + 113.864154151050156) * z
                          + 377.485237685302021) * z + 3209.37758913846947;
        const double q = (((z + 23.6012909523441209) * z + 244.024637934444173) * z + 1282.61652607737228) * z
            + 2844.23683343917062;
        return {std::exp(z) * (q - x * p), q};
    }
    if (x <= 4.0)
    {
        const double p = (((((((2.15311535474403846e-8 * x + 0.564188496988670089) * x + 8.88314979438837594) * x
                               + 66.1191906371416295) * x + 298.635138197400131) * x + 881.952221241769090) * x
                            + 1712.04761263407058) * x + 2051.07837782607147) * x + 1230.33935479799725;
        const double q = (((((((x + 15.7449261107098347) * x + 117.693950891312499) * x + 537.181101862009858) * x
                             + 1621.38957456669019) * x + 3290.79923573345963) * x + 4362.61909014324716) * x
                          + 3439.36767414372164) * x + 1230.33935480374942;
        return {p, q};
    }
    // x > 4: erfc(x) exp(x^2) = (1/sqrt(pi) - z R(z)) / x, z = 1/x^2.
    const double z = 1.0 / (x * x);
    const double p = ((((0.0163153871373020978 * z + 0.305326634961232344) * z + 0.360344899949804439) * z
                       + 0.125781726111229246) * z + 0.0160837851487422766) * z + 6.58749161529837803e-4;
    const double q = ((((z + 2.56852019228982242) * z + 1.87295284992346047) * z + 0.527905102951428412) * z
                      + 0.0605183413124413191) * z + 0.00233520497626869185;
    return {inverseSqrtPi * q - z * p, q * x};
}

inline double erfcScaled(double x)
{
    const Fraction f = erfcScaledFraction(x);
    return f.numerator / f.denominator;
}

} // namespace dropletFiber
