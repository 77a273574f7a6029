// branchFreeExp(x) = e^x without branches or calls, for V = double or Lanes (Lanes.hpp),
// so that the deposit's node loop, which needs three exponentials per node, runs without
// data-dependent jumps and four nodes per instruction. Why not std::exp: the libm call is
// opaque (no lanes) and its range checks are branches.
//
// Method (Cody-Waite): x = n ln2 + r with n = round(x / ln2), |r| <= ln2 / 2; ln2 is split
// into a high part with 21 trailing zero bits (n ln2_high is exact for |n| < 2^21) and a low
// part. e^r = 1 + r + r^2 P(r), P the Taylor polynomial up to r^13 / 13! (coefficients 1/k!,
// no fitted constants; truncation error < r^14/14! < 5e-18 relative). 2^n is built in the
// exponent bits as two factors 2^n1 2^n2, so that results below DBL_MIN come out as
// correctly rounded subnormals (gradual underflow, like std::exp).
//
// Accuracy (BranchFreeKernelTest, against long double expl): within 1 ulp (1.006 seen with
// GCC's FMA contraction; compiled for AVX2 + FMA, KernelBuild.hpp) for
// -708.39 <= x <= 709 (ln DBL_MIN .. near overflow); subnormal results within one unit of
// the smallest subnormal; 0 for x <= -746. Domain: x <= 709 (callers use x <= 0.25). The
// arguments are clamped at -746 so that no lane overflows or produces NaN (Lanes.hpp).
#pragma once

#include "grid/Lanes.hpp"

#include <cstdint> // before the AVX2 region (KernelBuild.hpp)

DROPLETFIBER_AVX2_BEGIN

namespace dropletFiber::avx2
{

template <class V>
inline V branchFreeExp(V x)
{
    constexpr double log2e = 1.4426950408889634074;        // 1 / ln 2
    constexpr double ln2High = 6.93147180369123816490e-01; // bits 0x3FE62E42FEE00000
    constexpr double ln2Low = 1.90821492927058770002e-10;  // ln 2 - ln2High
    // Adding 1.5 * 2^52 rounds to an integer (to nearest) and leaves it in the low bits of
    // the sum: bits(shifter + n) = bits(shifter) + n for |n| < 2^51.
    constexpr double shifter = 6755399441055744.0;
    constexpr std::uint64_t shifterBits = 0x4338000000000000ull;
    const V xc = maximum(x, splat<V>(-746.0)); // below, e^x rounds to 0 anyway
    const V shifted = xc * log2e + shifter;
    const V n = shifted - shifter;
    const V r = (xc - n * ln2High) - n * ln2Low;

    // e^r = 1 + r + r^2 P(r), P(r) = 1/2! + r/3! + ... + r^11/13!, by Estrin's scheme (pairs,
    // then pairs of pairs): a dependency chain of 5 steps instead of Horner's 11, so that
    // the processor overlaps more evaluations.
    const V r2 = r * r;
    const V r4 = r2 * r2;
    const V r8 = r4 * r4;
    const V a0 = 1.0 / 2.0 + r * (1.0 / 6.0);
    const V a1 = 1.0 / 24.0 + r * (1.0 / 120.0);
    const V a2 = 1.0 / 720.0 + r * (1.0 / 5040.0);
    const V a3 = 1.0 / 40320.0 + r * (1.0 / 362880.0);
    const V a4 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0);
    const V a5 = 1.0 / 479001600.0 + r * (1.0 / 6227020800.0);
    const V p = ((a0 + r2 * a1) + r4 * (a2 + r2 * a3)) + r8 * (a4 + r2 * a5);
    const V expR = 1.0 + (r + r2 * p);

    // 2^n, n in [-1077, 1023], as 2^n1 2^n2 with both factors normal numbers:
    // biased = n + 1077 in [0, 2100], n1 = floor(biased / 2) - 538, n2 = n - n1.
    const auto biased = bitsOf(shifted) - (shifterBits - 1077u);
    const auto half = biased >> 1;
    const auto scale1 = fromBits((half + (1023u - 538u)) << 52);          // 2^n1
    const auto scale2 = fromBits((biased - half + (1023u - 539u)) << 52); // 2^n2
    return expR * scale1 * scale2;
}

} // namespace dropletFiber::avx2

DROPLETFIBER_AVX2_END
