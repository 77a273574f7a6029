// Branch-free scaled erfc for the batched deposit (PathWeightBatch): erfcScaled(x) =
// exp(x^2) erfc(x) for x >= 0, for V = double or Lanes. AVX2 + FMA build only
// (KernelBuild.hpp); the default build uses ScaledErfc.hpp (same coefficients, with
// branches).
//
// Why separate from ScaledErfc.hpp: the per-node code of the default build stays exactly
// as it is; this variant evaluates each of Cody's three rational functions on its argument
// clamped into its own interval (so that no lane overflows) and selects the one for x, or
// evaluates one interval for a list of ends sorted by interval (the deposit); no
// data-dependent branch (the range choice was the most mispredicted branch of the
// deposit). The factor exp(x^2) of the first interval is not computed here: the path
// weight has it times its Gaussian already (gaussianErfcScaled).
//
// Method: W. J. Cody, "Rational Chebyshev approximations for the error function",
// Math. Comp. 23 (1969) 631-637, coefficients of SPECFUN's CALERF: erf on [0, 0.46875],
// erfc exp(x^2) on [0.46875, 4] and x > 4. Relative accuracy ~1e-16 (BranchFreeKernelTest,
// against long double erfcl and expl).
#pragma once

#include "grid/Lanes.hpp"

namespace dropletFiber
{

// A value as numerator / denominator, so that a caller combining two of them needs one
// division instead of two.
template <class V>
struct FractionOf
{
    V numerator;
    V denominator;
};

constexpr double erfcScaledSmallEnd = 0.46875; // end of Cody's first interval

constexpr double erfcScaledLargeStart = 4.0;   // start of the third

// erfcScaled(x) for x >= 0 in parts: numerator / denominator, times exp(x^2) when
// x <= erfcScaledSmallEnd (where the formula is exp(x^2) erfc(x); the path weight has that
// factor times its Gaussian without another exponential, see gaussianErfcScaled).
// The three intervals also separately (each clamps x into its interval, so that a lane
// outside stays finite): the deposit sorts the ends by interval and evaluates one each.
template <class V>
inline FractionOf<V> erfcScaledPartsSmall(V x)
{
    // [0, 0.46875]: erf(x) = x P(x^2) / Q(x^2); erfc = 1 - erf >= 0.5 (no cancellation).
    const V xs = minimum(x, splat<V>(erfcScaledSmallEnd));
    const V zs = xs * xs;
    const V ps = (((0.185777706184603153 * zs + 3.16112374387056560) * zs + 113.864154151050156) * zs
                  + 377.485237685302021) * zs + 3209.37758913846947;
    const V qs = (((zs + 23.6012909523441209) * zs + 244.024637934444173) * zs + 1282.61652607737228) * zs
        + 2844.23683343917062;
    return {qs - xs * ps, qs};
}

template <class V>
inline FractionOf<V> erfcScaledPartsMiddle(V x)
{
    // [0.46875, 4]: erfc(x) exp(x^2) = P(x) / Q(x).
    const V xm = minimum(maximum(x, splat<V>(erfcScaledSmallEnd)), splat<V>(erfcScaledLargeStart));
    const V pm = (((((((2.15311535474403846e-8 * xm + 0.564188496988670089) * xm + 8.88314979438837594) * xm
                       + 66.1191906371416295) * xm + 298.635138197400131) * xm + 881.952221241769090) * xm
                    + 1712.04761263407058) * xm + 2051.07837782607147) * xm + 1230.33935479799725;
    const V qm = (((((((xm + 15.7449261107098347) * xm + 117.693950891312499) * xm + 537.181101862009858) * xm
                     + 1621.38957456669019) * xm + 3290.79923573345963) * xm + 4362.61909014324716) * xm
                  + 3439.36767414372164) * xm + 1230.33935480374942;
    return {pm, qm};
}

template <class V>
inline FractionOf<V> erfcScaledPartsLarge(V x)
{
    // x > 4: erfc(x) exp(x^2) = (1/sqrt(pi) - z R(z)) / x, z = 1/x^2.
    constexpr double inverseSqrtPi = 0.56418958354775628695;
    const V xl = maximum(x, splat<V>(erfcScaledLargeStart));
    const V zl = 1.0 / (xl * xl);
    const V pl = ((((0.0163153871373020978 * zl + 0.305326634961232344) * zl + 0.360344899949804439) * zl
                   + 0.125781726111229246) * zl + 0.0160837851487422766) * zl + 6.58749161529837803e-4;
    const V ql = ((((zl + 2.56852019228982242) * zl + 1.87295284992346047) * zl + 0.527905102951428412) * zl
                  + 0.0605183413124413191) * zl + 0.00233520497626869185;
    return {inverseSqrtPi * ql - zl * pl, ql * xl};
}

// Which of the three: 0 small, 1 middle, 2 large.
inline int erfcScaledInterval(double x)
{
    return (x > erfcScaledSmallEnd ? 1 : 0) + (x > erfcScaledLargeStart ? 1 : 0);
}

template <class V>
inline FractionOf<V> erfcScaledParts(V x)
{
    const FractionOf<V> small = erfcScaledPartsSmall(x);
    const FractionOf<V> middle = erfcScaledPartsMiddle(x);
    const FractionOf<V> large = erfcScaledPartsLarge(x);
    const MaskOf<V> isSmall = x <= erfcScaledSmallEnd;
    const MaskOf<V> isMiddle = x <= erfcScaledLargeStart;
    return {select(isSmall, small.numerator, select(isMiddle, middle.numerator, large.numerator)),
            select(isSmall, small.denominator, select(isMiddle, middle.denominator, large.denominator))};
}

// g erfcScaled(x) for x >= 0 from erfcScaledParts(x), given g and gAtZero = g exp(x^2) (the
// same Gaussian at x = 0).
template <class V>
inline FractionOf<V> gaussianErfcScaled(V x, const FractionOf<V>& parts, V g, V gAtZero)
{
    return {select(x <= erfcScaledSmallEnd, gAtZero, g) * parts.numerator, parts.denominator};
}

} // namespace dropletFiber
