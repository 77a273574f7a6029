// Lanes: four doubles that one AVX2 instruction processes together, for the branch-free
// node loop of the deposit (PathWeightBatch). Written with the GCC/Clang vector extension
// (__attribute__((vector_size))). Compiled for AVX2 + FMA in every x86-64 build, used only
// on CPUs that have them (KernelBuild.hpp): with two SSE2 lanes the branch-free loop is
// slower than the per-node code. Everything here is in namespace dropletFiber::avx2 and
// inside DROPLETFIBER_AVX2_BEGIN/END (KernelBuild.hpp: why, and what else that needs).
//
// Why explicit lanes and not a plain loop for the auto-vectoriser: with the default
// -ftrapping-math GCC does not if-convert floating-point operations that it has moved
// into a conditional branch, and std::sqrt carries an errno branch, so the plain loop
// stays scalar and full of branches. Here every lane computes every candidate value and
// `select` picks one by a bit mask: no data-dependent jumps.
//
// The kernels that use lanes are templates on V = double or V = Lanes, written with the
// helpers below: the scalar instantiation (tests) and the lane instantiation evaluate the
// same formulas (GCC may contract a * b + c into FMA differently in the two, so they agree
// to an ulp, not always to the bit). Candidates computed in a lane and then discarded must
// not raise divide-by-zero, invalid or overflow (OpenFOAM may trap them, FOAM_SIGFPE):
// callers clamp their arguments so that every candidate is finite.
#pragma once

#include "grid/KernelBuild.hpp"

#if !DROPLETFIBER_BATCHED_KERNEL
#error "Lanes.hpp needs the batched kernel's build (x86-64, GCC or Clang; KernelBuild.hpp)"
#endif

// Before the AVX2 region: their inline functions keep the default target (KernelBuild.hpp).
#include <immintrin.h>

#include <cmath>
#include <cstdint>
#include <cstring>

DROPLETFIBER_AVX2_BEGIN

namespace dropletFiber::avx2
{

constexpr int laneCount = 4;
using Lanes = double __attribute__((vector_size(laneCount * sizeof(double))));
using LaneMask = std::int64_t __attribute__((vector_size(laneCount * sizeof(double)))); // all bits set = true
using LaneBits = std::uint64_t __attribute__((vector_size(laneCount * sizeof(double))));

// The mask type of V: bool for double, LaneMask for Lanes.
template <class V>
using MaskOf = decltype(V{} < V{});

// V filled with c.
template <class V>
inline V splat(double c);
template <>
inline double splat<double>(double c)
{
    return c;
}
template <>
inline Lanes splat<Lanes>(double c)
{
    return Lanes{c, c, c, c};
}

// condition ? ifTrue : ifFalse, per lane.
inline double select(bool condition, double ifTrue, double ifFalse)
{
    return condition ? ifTrue : ifFalse;
}
inline LaneBits bitsOf(Lanes a);
inline Lanes fromBits(LaneBits bits);
inline Lanes select(LaneMask condition, Lanes ifTrue, Lanes ifFalse)
{
    LaneBits mask; // true lanes have all bits set
    std::memcpy(&mask, &condition, sizeof mask);
    return fromBits((bitsOf(ifTrue) & mask) | (bitsOf(ifFalse) & ~mask));
}

// a and not b, per lane (for bool, ~ would not do: ~true is -2).
inline bool andNot(bool a, bool b)
{
    return a && !b;
}
inline LaneMask andNot(LaneMask a, LaneMask b)
{
    return a & ~b;
}

// std::min / std::max semantics ((b < a) ? b : a), std::abs, std::sqrt, per lane.
template <class V>
inline V minimum(V a, V b)
{
    return select(b < a, b, a);
}
template <class V>
inline V maximum(V a, V b)
{
    return select(a < b, b, a);
}
inline double magnitude(double a)
{
    return std::abs(a);
}
inline Lanes magnitude(Lanes a)
{
    return fromBits(bitsOf(a) & (~std::uint64_t(0) >> 1));
}
inline double squareRoot(double a)
{
    return std::sqrt(a);
}
inline Lanes squareRoot(Lanes a)
{
    // One vsqrtpd: correctly rounded like the scalar sqrt (std::sqrt per lane would keep
    // its errno branch). Callers pass a >= 0.
    return _mm256_sqrt_pd(a);
}

// The IEEE bit pattern of each lane and back (for exponent arithmetic).
template <class To, class From>
inline To bitCast(const From& a)
{
    static_assert(sizeof(To) == sizeof(From), "bitCast: sizes differ");
    To b;
    std::memcpy(&b, &a, sizeof b);
    return b;
}
inline std::uint64_t bitsOf(double a)
{
    return bitCast<std::uint64_t>(a);
}
inline LaneBits bitsOf(Lanes a)
{
    return bitCast<LaneBits>(a);
}
inline double fromBits(std::uint64_t bits)
{
    return bitCast<double>(bits);
}
inline Lanes fromBits(LaneBits bits)
{
    return bitCast<Lanes>(bits);
}

inline Lanes loadLanes(const double* values)
{
    Lanes a;
    std::memcpy(&a, values, sizeof a);
    return a;
}
inline void storeLanes(double* values, Lanes a)
{
    std::memcpy(values, &a, sizeof a);
}

} // namespace dropletFiber::avx2

DROPLETFIBER_AVX2_END
