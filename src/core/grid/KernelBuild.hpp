// KernelBuild: which implementations of the deposit's node loop a build contains, and how
// the AVX2 + FMA code is compiled inside a portable build.
//
// Two implementations (DensityGrid::deposit):
//  - per node: PathWeight::omegaFromOffset node by node; every build, every CPU;
//  - batched: the common regime of eq. 23 four nodes at a time without data-dependent
//    branches (PathWeightBatch), ~1.6x faster on 2D reach-3 h parcels. It needs AVX2 and
//    FMA: with SSE2's two lanes the branch-free form is slower than the per-node code (3
//    exponentials per node instead of ~2 plus selects, docs/performance.md).
//
// DROPLETFIBER_BATCHED_KERNEL = 1 (x86-64 with GCC or Clang): the batched code is compiled
// into every build, for AVX2 + FMA only (DROPLETFIBER_AVX2_BEGIN/END below), whatever
// -march says; the rest of the build keeps the compiler's target (portable x86-64 by
// default). Which code a grid runs is decided at run time: batched when
// KernelSettings::vectorised is true and PathWeightBatch::cpuSupported() (this CPU has AVX2
// and FMA, asked once). Elsewhere (other architectures or compilers, or defined 0 on the
// command line) the batched code is left out and every grid runs the per-node code.
// The two agree to ~1 ulp of exp/erfc (node weights to ~1e-15 of the parcel's largest),
// not to the bit: KernelSettings::vectorised = false gives the portable results anywhere.
//
// Why not `#if __AVX2__`: #pragma GCC target does not define __AVX2__ / __FMA__ for the
// preprocessor, and the portable build must contain the code anyway.
//
// No AVX instruction outside the batched code (a portable build must run on any x86-64;
// an AVX2 copy of a shared inline function picked by the linker would crash a CPU without
// AVX2 with SIGILL). How this is ensured:
//  1. Everything compiled for AVX2 is defined between DROPLETFIBER_AVX2_BEGIN and
//     DROPLETFIBER_AVX2_END, in namespace dropletFiber::avx2 (the kernel's own helpers
//     also in an anonymous namespace), and nothing of that namespace is defined outside
//     such a region: no inline or template function exists in both an AVX2 and a
//     default-target version, so the linker cannot mix them up (ODR).
//  2. Headers of the standard library, Eigen and the project's default-target code are
//     included before the region. GCC and Clang compile an inline or template function
//     with the target of its definition, not of its caller, so std functions called from
//     AVX2 code are inlined from, or call, their default-target definitions.
//  3. Default-target helpers that AVX2 code calls with lane vectors (CodyErfcRationals.hpp)
//     are always_inline and take them by reference: no call crosses the two targets with
//     a 32-byte vector argument, whose calling convention differs between them.
//  4. No lambdas inside a region (GCC does not give them the region's target).
//  5. Default-target code calls into dropletFiber::avx2 only after cpuSupported() (the
//     grid's choice, tests skip otherwise), passing pointers and doubles only.
// Checked by CTest build.avx2CodeIsolated (tests/checkAvx2Isolation.sh): objdump of the
// grid library, the test and bench programs and the OpenFOAM library finds AVX
// instructions only in functions of dropletFiber::avx2.
#pragma once

#ifndef DROPLETFIBER_BATCHED_KERNEL
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define DROPLETFIBER_BATCHED_KERNEL 1
#else
#define DROPLETFIBER_BATCHED_KERNEL 0
#endif
#endif

#if DROPLETFIBER_BATCHED_KERNEL
// The region compiled for AVX2 + FMA: function definitions between BEGIN and END get
// target("avx2,fma") (Clang: its attribute pragma; GCC: push_options / target).
#if defined(__clang__)
#define DROPLETFIBER_AVX2_BEGIN                                                                              \
    _Pragma("clang attribute push(__attribute__((target(\"avx2,fma\"))), apply_to = function)")
#define DROPLETFIBER_AVX2_END _Pragma("clang attribute pop")
#else
#define DROPLETFIBER_AVX2_BEGIN _Pragma("GCC push_options") _Pragma("GCC target(\"avx2,fma\")")
#define DROPLETFIBER_AVX2_END _Pragma("GCC pop_options")
#endif
#endif
