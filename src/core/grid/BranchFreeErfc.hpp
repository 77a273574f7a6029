// Branch-free scaled erfc for the batched deposit (PathWeightBatch): erfcScaled(x) =
// exp(x^2) erfc(x) for x >= 0, for V = double or Lanes. Compiled for AVX2 + FMA
// (namespace avx2, KernelBuild.hpp); the per-node code uses ScaledErfc.hpp (same
// coefficients, with branches).
//
// Why separate from ScaledErfc.hpp: the per-node code stays exactly as it is; this variant
// evaluates each of Cody's three rational functions on its argument clamped into its own
// interval (so that no lane overflows) and selects the one for x, or
// evaluates one interval for a list of ends sorted by interval (the deposit); no
// data-dependent branch (the range choice was the most mispredicted branch of the
// deposit). The factor exp(x^2) of the first interval is not computed here: the path
// weight has it times its Gaussian already (gaussianErfcScaled).
//
// Method: W. J. Cody's rational functions (CodyErfcRationals.hpp, shared with
// ScaledErfc.hpp): erf on [0, 0.46875], erfc exp(x^2) on [0.46875, 4] and x > 4. Relative
// accuracy ~1e-16 (BranchFreeKernelTest, against long double erfcl and expl).
#pragma once

// CodyErfcRationals.hpp before the AVX2 region: its templates keep the default target and
// are always inlined (KernelBuild.hpp, point 3).
#include "grid/CodyErfcRationals.hpp"
#include "grid/Lanes.hpp"

DROPLETFIBER_AVX2_BEGIN

namespace dropletFiber::avx2
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

constexpr double erfcScaledLargeStart = 4.0; // start of the third

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
    const PolynomialPair<V> r = codyErfSmall(xs * xs);
    return {r.q - xs * r.p, r.q};
}

template <class V>
inline FractionOf<V> erfcScaledPartsMiddle(V x)
{
    // [0.46875, 4]: erfc(x) exp(x^2) = P(x) / Q(x).
    const V xm = minimum(maximum(x, splat<V>(erfcScaledSmallEnd)), splat<V>(erfcScaledLargeStart));
    const PolynomialPair<V> r = codyErfcMiddle(xm);
    return {r.p, r.q};
}

template <class V>
inline FractionOf<V> erfcScaledPartsLarge(V x)
{
    // x > 4: erfc(x) exp(x^2) = (1/sqrt(pi) - z R(z)) / x, z = 1/x^2.
    constexpr double inverseSqrtPi = 0.56418958354775628695;
    const V xl = maximum(x, splat<V>(erfcScaledLargeStart));
    const V zl = 1.0 / (xl * xl);
    const PolynomialPair<V> r = codyErfcLarge(zl);
    return {inverseSqrtPi * r.q - zl * r.p, r.q * xl};
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

} // namespace dropletFiber::avx2

DROPLETFIBER_AVX2_END
