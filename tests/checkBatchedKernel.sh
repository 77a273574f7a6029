#!/usr/bin/env bash
# The opt-in AVX2 deposition kernel (src/core/grid/KernelBuild.hpp) is compiled
# only with -march=x86-64-v3 or newer, so the default build never runs its tests
# (they skip). This test builds the grid's unit tests that way in a folder of
# its own and runs them, so both code paths are tested on every CI run.
# Exit 77 (CTest: skipped) on a CPU without AVX2 and FMA.
# Usage: checkBatchedKernel.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
source="$1"
build="$2"
if ! grep -qw avx2 /proc/cpuinfo || ! grep -qw fma /proc/cpuinfo; then
    echo "this CPU has no AVX2/FMA: the batched kernel cannot run here"
    exit 77
fi
log="$build.log"
if ! cmake -S "$source" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDROPLETFIBER_MARCH=x86-64-v3 > "$log" 2>&1 \
   || ! cmake --build "$build" --target gridUnitTests -j2 >> "$log" 2>&1; then
    tail -40 "$log"
    echo "FAILED: building the grid unit tests with -march=x86-64-v3 ($log)"
    exit 1
fi
output=$("$build/tests/gridUnitTests" --gtest_brief=1 2>&1)
status=$?
echo "$output" | tail -20
if [ $status -ne 0 ]; then
    echo "FAILED: grid unit tests with the batched kernel"
    exit 1
fi
# The batched kernel's own tests skip when it is not compiled in: here it must be.
if echo "$output" | grep -q "SKIPPED"; then
    echo "FAILED: tests skipped although the batched kernel should be compiled in"
    exit 1
fi
echo "grid unit tests passed with the batched AVX2 kernel"
