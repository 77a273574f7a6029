// KernelBuild: the one switch between the two implementations of the deposit's node loop.
//
// Default (portable x86-64 and every other target): DensityGrid::deposit evaluates
// PathWeight::omegaFromOffset node by node; the batched code is not compiled.
//
// Built for AVX2 + FMA (the compiler defines __AVX2__ and __FMA__ for -march=x86-64-v3,
// -march=native on such a CPU; CMake option DROPLETFIBER_MARCH, wmake variable
// DROPLETFIBER_MARCH_FLAGS): the deposit evaluates the common regime of eq. 23 four nodes
// at a time without data-dependent branches (PathWeightBatch). Why opt-in only: with
// SSE2's two lanes the branch-free form is slower than the per-node code (it needs 3
// exponentials per node instead of ~2 plus selects, docs/performance.md); with four lanes
// it is ~1.5x faster on 2D reach-3 h parcels. Its inline exp and erfc agree with libm and
// the per-node code to ~1 ulp, not to the bit, so results differ from the default build
// at round-off.
#pragma once

#if defined(__AVX2__) && defined(__FMA__)
#define DROPLETFIBER_BATCHED_KERNEL 1
#else
#define DROPLETFIBER_BATCHED_KERNEL 0
#endif

namespace dropletFiber
{

constexpr bool batchedDepositKernel = DROPLETFIBER_BATCHED_KERNEL != 0;

} // namespace dropletFiber
