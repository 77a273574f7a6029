// CodyErfcRationals: the three rational functions of Cody's erf/erfc approximation, each as
// numerator and denominator polynomials, written once for both evaluations of the scaled
// erfc: ScaledErfc.hpp (scalar, with branches: the per-node code) and BranchFreeErfc.hpp
// (V = double or SIMD lanes, no branches: the batched code, compiled for AVX2 + FMA). V is
// any type with +, * and scalar double operands.
//
// Default target, always inlined, V by reference (KernelBuild.hpp, point 3): the AVX2 code
// gets these polynomials inlined and compiled for AVX2, and never calls a default-target
// copy with a lane vector (whose calling convention differs between the two targets). For
// the per-node code nothing changes: inlined or not, the same operations in the same order.
//
// Method: W. J. Cody, "Rational Chebyshev approximations for the error function",
// Math. Comp. 23 (1969) 631-637, coefficients of his public-domain SPECFUN routine CALERF.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define DROPLETFIBER_ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define DROPLETFIBER_ALWAYS_INLINE inline
#endif

namespace dropletFiber
{

template <class V>
struct PolynomialPair
{
    V p;
    V q;
};

// Horner forms laid out by hand, one polynomial per line pair (clang-format would split
// every product onto a line of its own)
// clang-format off
// [0, 0.46875]: erf(x) = x P(z) / Q(z), z = x^2.
template <class V>
DROPLETFIBER_ALWAYS_INLINE PolynomialPair<V> codyErfSmall(const V& z)
{
    return {(((0.185777706184603153 * z + 3.16112374387056560) * z + 113.864154151050156) * z
             + 377.485237685302021) * z + 3209.37758913846947,
            (((z + 23.6012909523441209) * z + 244.024637934444173) * z + 1282.61652607737228) * z
                + 2844.23683343917062};
}

// [0.46875, 4]: erfc(x) exp(x^2) = P(x) / Q(x).
template <class V>
DROPLETFIBER_ALWAYS_INLINE PolynomialPair<V> codyErfcMiddle(const V& x)
{
    return {(((((((2.15311535474403846e-8 * x + 0.564188496988670089) * x + 8.88314979438837594) * x
                 + 66.1191906371416295) * x + 298.635138197400131) * x + 881.952221241769090) * x
              + 1712.04761263407058) * x + 2051.07837782607147) * x + 1230.33935479799725,
            (((((((x + 15.7449261107098347) * x + 117.693950891312499) * x + 537.181101862009858) * x
                + 1621.38957456669019) * x + 3290.79923573345963) * x + 4362.61909014324716) * x
             + 3439.36767414372164) * x + 1230.33935480374942};
}

// x > 4: erfc(x) exp(x^2) = (1/sqrt(pi) - z P(z) / Q(z)) / x, z = 1/x^2.
template <class V>
DROPLETFIBER_ALWAYS_INLINE PolynomialPair<V> codyErfcLarge(const V& z)
{
    return {((((0.0163153871373020978 * z + 0.305326634961232344) * z + 0.360344899949804439) * z
              + 0.125781726111229246) * z + 0.0160837851487422766) * z + 6.58749161529837803e-4,
            ((((z + 2.56852019228982242) * z + 1.87295284992346047) * z + 0.527905102951428412) * z
             + 0.0605183413124413191) * z + 0.00233520497626869185};
}

// clang-format on

} // namespace dropletFiber
