#!/usr/bin/env bash
#------------------------------------------------------------------------------
# bench/run.sh - build and run all benchmarks of docs/performance.md, one after
# the other, and keep their output. Measurements, not tests: nothing here
# passes or fails on a timing.
#
# Usage: bench/run.sh [-quick] [-no-tutorial] [-out DIR]
#   -quick        smaller runs (deposition up to 1e5 parcels, fibers up to 1000,
#                 60 steps in the paper setting, tutorial -short): ~5 min
#   -no-tutorial  skip the channelSpray runs (tutorial share, its spray's traffic)
#   -out DIR      where the outputs go (default build-bench/bench-results/<date>)
# Full run: ~12 min on 2 cores (the tutorial serial + 2 ranks included).
#
# Builds in build-bench (Release, the project's flags). The OpenFOAM part needs
# the library built with ./Allwmake.
#------------------------------------------------------------------------------
set -euo pipefail
root="$(cd "${0%/*}/.." && pwd)"
quick=false
tutorial=true
out=""
while [ $# -gt 0 ]; do
    case "$1" in
        -quick) quick=true ;;
        -no-tutorial) tutorial=false ;;
        -out) out="$2"; shift ;;
        *) echo "usage: $0 [-quick] [-no-tutorial] [-out DIR]" >&2; exit 2 ;;
    esac
    shift
done
build="$root/build-bench"
out="${out:-$build/bench-results/$(date +%Y%m%d-%H%M%S)}"
mkdir -p "$out"
echo "bench/run.sh: outputs in $out"

targets="depositionBench collisionBench fiberStepBench fiberScalingBench fiberTutorialBench paperSettingBench gridTrafficBench wideKernelBench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > "$out/cmake.log"
# shellcheck disable=SC2086
cmake --build "$build" -j2 --target $targets >> "$out/cmake.log" 2>&1
bin="$build/bench"

{
    echo "date: $(date -Is)"
    echo "host: $(uname -srm)"
    lscpu | grep -E "Model name|^CPU\(s\)|Thread|Core|Socket|MHz|L1d|L2|L3|Hypervisor|Flags" | sed 's/^Flags:.*avx512f.*/Flags: ... avx2 fma avx512f ... (see lscpu)/'
    grep -m3 -E "^cpu family|^model\s|^cpu MHz" /proc/cpuinfo
    getconf -a | grep -E "LEVEL[123]_D?CACHE_SIZE"
    free -g | head -2
    echo "compiler: $(c++ --version | head -1)"
    echo "CMAKE_CXX_FLAGS_RELEASE: $(grep CMAKE_CXX_FLAGS_RELEASE: "$build/CMakeCache.txt" | cut -d= -f2-) (std=c++17, no -march)"
    echo "core at commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)$(git -C "$root" diff --quiet HEAD -- src/core 2>/dev/null || echo ' (src/core modified)')"
    echo "clock: thread CPU time (BENCH_CLOCK=wall for wall-clock time)"
    echo "load average at start: $(cat /proc/loadavg)"
} > "$out/machine.txt"
cat "$out/machine.txt"

run() {
    local name="$1"; shift
    echo
    echo "=== $name: $*"
    local start=$SECONDS
    "$@" 2>&1 | tee "$out/$name.txt"
    echo "($name: $((SECONDS - start)) s, load average $(cut -d' ' -f1-3 /proc/loadavg))" | tee -a "$out/$name.txt"
}

if $quick; then
    run deposition "$bin/depositionBench" --quick
    run collision "$bin/collisionBench" --repeats 3
    run fiberScaling "$bin/fiberScalingBench" --max-fibers 1000
    run fiberTutorial "$bin/fiberTutorialBench" --repeats 3
    run paperSetting "$bin/paperSettingBench" --quick
    run wideKernel "$bin/wideKernelBench" --repeats 1 --seconds 0.05
else
    run deposition "$bin/depositionBench" --budget 60 --repeats 3
    run collision "$bin/collisionBench" --repeats 5
    run fiberStep "$bin/fiberStepBench"
    run fiberScaling "$bin/fiberScalingBench" --max-fibers 10000
    run fiberTutorial "$bin/fiberTutorialBench"
    run paperSetting "$bin/paperSettingBench" --steps 200
    run wideKernel "$bin/wideKernelBench" --repeats 3
fi
run gridTraffic3D "$bin/gridTrafficBench" --synthetic3d

if $tutorial; then
    short=""
    $quick && short="-short"
    # shellcheck disable=SC2086
    run tutorialShare "$root/bench/tutorialShare.sh" $short -keep "$out/tutorial"
    # the tutorial's own spray: per-rank boxes of the 2-rank run at its last write time
    case_dir="$out/tutorial/parallel/channelSpray"
    last=$(find "$case_dir/processor0" -mindepth 1 -maxdepth 1 -type d -name '[0-9]*' -printf '%f\n' | sort -g | tail -1)
    python3 "$root/bench/foamParcels.py" "$case_dir" "$last" "$out/tutorialParcels_rank" > "$out/tutorialParcels.txt"
    run gridTrafficTutorial "$bin/gridTrafficBench" --parcels "$out/tutorialParcels_rank" 2 \
        --lower 0 0 0 --upper 0.05 0.15 0.01 --spacing 1e-3 --flat 2 --cap 6e-3 --cic 0.5 --dt 5e-4 \
        --label "channelSpray t=$last, 2 ranks"
fi
echo
echo "bench/run.sh: done; outputs in $out"
