// PathIntegralClosedForm: int phi dlambda along the path for one node (or four, V = Lanes)
// in the common case, the closed form of eq. 23 with scaled erfc ("regime C" of
// PathWeight.cpp), without data-dependent branches; compiled for AVX2 + FMA (namespace avx2,
// KernelBuild.hpp).
// Nodes that need one of the two rare regimes (A: the path only grazes the edge of the
// support; B: a short interval, Taylor series) are flagged in needsExact and left to
// PathWeight::integralAlongPath (the per-node code); nodes out of reach, and nodes whose
// reach circle misses the path, give 0.
//
// Why branch-free: in the deposit the regime choices (one- or two-sided interval, clipped
// ends, erfc range) depend on the node and were mispredicted ~2.7 times per node, a third
// of the time (docs/performance.md). Here every lane evaluates every candidate and selects.
//
// Formulas (docs/model.md eqs. 19-23; see PathWeight.hpp for lambda, lambda_m, d_0): the node is
// within reach for lambda in (lambda_m - h, lambda_m + h), h^2 = reach^2 - d_0^2; the
// interval [lambda_1, lambda_2] is that chord clipped to the path [0, L]; u_i = lambda_i -
// lambda_m, x_i = sqrt(gamma) u_i, g_i = exp(-gamma (d_0^2 + u_i^2)) (the kernel's Gaussian at
// the interval's ends, exp(-a) where the end is on the reach circle), g_0 = exp(-gamma d_0^2):
//   int_{x1}^{x2} exp(-gamma d0^2 - x^2) dx = sqrt(pi)/2 [s_1 g_1 E(|x_1|) + s_2 g_2 E(|x_2|)]
//                                             + (x_1 < 0 < x_2 ? sqrt(pi) g_0 : 0),
// E = erfcScaled, s_1 = +1 if x_1 >= 0 else -1, s_2 = +1 if x_2 <= 0 else -1 (this covers the
// one-sided cases 0 <= x_1 < x_2 and x_1 < x_2 <= 0, and the two-sided x_1 < 0 < x_2). Outside
// regime B the two terms differ by a factor >~ 1.5 (no cancellation). The result is that
// integral / sqrt(gamma) - exp(-a) (lambda_2 - lambda_1).
//
// Every candidate is finite for every input (clamped arguments), so discarded lanes raise no
// floating-point exception (Lanes.hpp).
#pragma once

#include "grid/BranchFreeExp.hpp"
#include "grid/Lanes.hpp"
#include "grid/BranchFreeErfc.hpp"

DROPLETFIBER_AVX2_BEGIN

namespace dropletFiber::avx2
{

struct PathIntegralClosedForm
{
    double length = 0.0; // L = |v dt|
    double reachSquared = 0.0;
    double gamma = 0.0;
    double sqrtGamma = 0.0;
    double inverseSqrtGamma = 0.0;
    double edgeExponent = 0.0; // a = gamma reach^2
    double edgeValue = 0.0;    // exp(-a), the kernel's Gaussian at the reach

    // Regimes A and B, left to the exact code: the largest q = gamma (h^2 - u^2) on the
    // interval below this (the Gaussian and the constant of eq. 12 nearly cancel)...
    static constexpr double grazingQ = 0.25;
    // ...or the interval's half-width in x times (1 + |centre|) at most this.
    static constexpr double shortInterval = 0.5;

    // What a node's interval leaves for the other stages. status: 1 closed form,
    // 0 no weight (out of reach, or the chord misses the path), -1 regime A or B.
    template <class V>
    struct Interval
    {
        V x1, x2;                          // sqrt(gamma) u_i
        V exponent0, exponent1, exponent2; // g_i = exp(exponent_i)
        V width;                           // lambda_2 - lambda_1
        V status;
    };

    // The whole closed form for one node (V = double) or four (V = Lanes): the stages in
    // sequence. The deposit runs the same stages as loops over many nodes
    // (PathWeightBatch::omegas); both the same formulas. needsExact: regime A or B (result 0).
    template <class V>
    V operator()(V lambdaM, V d0Squared, MaskOf<V>& needsExact) const
    {
        const Interval<V> ends = interval(lambdaM, d0Squared);
        needsExact = ends.status < 0.0;
        return integral(ends, branchFreeExp(ends.exponent0), branchFreeExp(ends.exponent1),
                        branchFreeExp(ends.exponent2), erfcScaledParts(magnitude(ends.x1)),
                        erfcScaledParts(magnitude(ends.x2)));
    }

    // Stage 1: the interval [lambda_1, lambda_2] and the regime.
    template <class V>
    Interval<V> interval(V lambdaM, V d0Squared) const
    {
        const V zero = splat<V>(0.0);
        const V halfChordSquared = reachSquared - d0Squared;
        const V halfChord = squareRoot(maximum(halfChordSquared, zero));
        const V toEnd = length - lambdaM;
        const MaskOf<V> inReach = d0Squared < reachSquared;
        // An end of the path lies outside the reach circle iff its offset from lambda_m is
        // at least h (compared squared); then the interval ends on the circle if the
        // circle's end lies inside the path (clipped).
        const MaskOf<V> startOutside = lambdaM * lambdaM >= halfChordSquared;
        const MaskOf<V> endOutside = toEnd * toEnd >= halfChordSquared;
        const MaskOf<V> clipped1 = startOutside & (lambdaM - halfChord > 0.0);
        const MaskOf<V> clipped2 = endOutside & (lambdaM + halfChord < length);
        const V lambda1 = select(clipped1, lambdaM - halfChord, zero);
        const V lambda2 = select(clipped2, lambdaM + halfChord, splat<V>(length));
        const MaskOf<V> weighted = inReach & (lambda2 > lambda1);
        const V width = lambda2 - lambda1;
        const V u1 = select(clipped1, -halfChord, -lambdaM);
        const V u2 = select(clipped2, halfChord, toEnd);

        const V uNearest = select((u1 <= 0.0) & (u2 >= 0.0), zero, minimum(magnitude(u1), magnitude(u2)));
        const V qMax = gamma * (halfChordSquared - uNearest * uNearest);
        const V xCentre = sqrtGamma * (0.5 * (lambda1 + lambda2) - lambdaM);
        const V xHalf = sqrtGamma * 0.5 * width;
        const MaskOf<V> needsExact
            = weighted & ((qMax < grazingQ) | (xHalf * (1.0 + magnitude(xCentre)) <= shortInterval));

        Interval<V> ends;
        ends.x1 = sqrtGamma * u1;
        ends.x2 = sqrtGamma * u2;
        // An end on the reach circle has the Gaussian exp(-a) (d_0^2 + h^2 = reach^2).
        ends.exponent0 = -gamma * d0Squared;
        ends.exponent1 = select(clipped1, splat<V>(-edgeExponent), -gamma * (d0Squared + u1 * u1));
        ends.exponent2 = select(clipped2, splat<V>(-edgeExponent), -gamma * (d0Squared + u2 * u2));
        ends.width = width;
        ends.status = select(needsExact, splat<V>(-1.0), select(weighted, splat<V>(1.0), zero));
        return ends;
    }

    // Last stage: the formula above from the interval, the Gaussians g_i = exp(exponent_i)
    // and erfcScaledParts(|x_i|).
    template <class V>
    V integral(const Interval<V>& ends, V g0, V g1, V g2, const FractionOf<V>& parts1,
               const FractionOf<V>& parts2) const
    {
        constexpr double halfSqrtPi = 0.88622692545275801365; // sqrt(pi) / 2
        const V zero = splat<V>(0.0);
        const FractionOf<V> end1 = gaussianErfcScaled(magnitude(ends.x1), parts1, g1, g0);
        const FractionOf<V> end2 = gaussianErfcScaled(magnitude(ends.x2), parts2, g2, g0);
        const V signed1 = select(ends.x1 >= 0.0, end1.numerator, -end1.numerator);
        const V signed2 = select(ends.x2 <= 0.0, end2.numerator, -end2.numerator);
        const V twoSided = select((ends.x1 < 0.0) & (ends.x2 > 0.0), 2.0 * halfSqrtPi * g0, zero);
        const V gaussian = twoSided
            + halfSqrtPi * (signed1 * end2.denominator + signed2 * end1.denominator)
                / (end1.denominator * end2.denominator);
        const V integral = gaussian * inverseSqrtGamma - edgeValue * ends.width;
        return select(ends.status > 0.0, integral, zero);
    }
};

} // namespace dropletFiber::avx2

DROPLETFIBER_AVX2_END
