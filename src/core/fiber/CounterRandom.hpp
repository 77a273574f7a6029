// CounterRandom: random numbers as a pure function of a key, for the turbulent air of
// docs/model.md sec. 8. A counter-based generator has no state to carry, split or
// restore: the draw for (seed, fiber id, point, step) is the same whichever processor
// computes it, in whichever order, before or after a restart.
//
// Philox4x32-10 (Salmon, Moraes, Dror, Shaw, "Parallel random numbers: as easy as 1, 2,
// 3", SC'11, 2011; the reference implementation is Random123): a 128-bit counter and a
// 64-bit key give 128 random bits. Checked against Random123's published known-answer
// vectors (tests/unit/fiber/CounterRandomTest.cpp).
//
// Gaussians: each pair of 32-bit words gives a uniform u in (0, 1) (never 0 or 1) and
// Box-Muller turns two uniforms into two independent standard normals; the 32-bit
// resolution bounds |xi| by sqrt(-2 ln 2^-33) = 6.8, far beyond what the statistics
// here can resolve.
#pragma once

#include <array>
#include <cstdint>

namespace dropletFiber
{

using PhiloxCounter = std::array<std::uint32_t, 4>;
using PhiloxKey = std::array<std::uint32_t, 2>;

// The ten-round Philox 4x32 bijection of counter under key.
PhiloxCounter philox4x32_10(PhiloxCounter counter, PhiloxKey key);

// (bits + 1/2) / 2^32: a uniform on (0, 1) that is never 0 or 1.
double uniformOpen(std::uint32_t bits);

// Four independent standard normal numbers from one Philox block (Box-Muller on the
// pairs of words 0,1 and 2,3).
std::array<double, 4> gaussianQuadruple(const PhiloxCounter& counter, const PhiloxKey& key);

// The key layout of the turbulent air: counter (point, low and high word of step,
// low word of fiber id), key (seed, high word of fiber id). Distinct (fiber id, point,
// step) give distinct counters, so their draws are independent.
std::array<double, 4> fiberPointGaussians(std::uint32_t seed, std::uint64_t fiberId, std::uint32_t point,
                                          std::uint64_t step);

} // namespace dropletFiber
