#!/usr/bin/env bash
# The portable build must run on any x86-64 CPU, so AVX instructions may appear only in the
# batched deposit kernel, which runs only on CPUs with AVX2 + FMA (src/core/grid/KernelBuild.hpp:
# everything compiled for AVX2 lives in namespace dropletFiber::avx2). An AVX2 copy of a
# shared inline function picked by the linker would crash other CPUs with SIGILL; this test
# finds such a copy in the built files: it disassembles them (objdump) and fails on any
# function outside dropletFiber::avx2 that holds a VEX/EVEX instruction (mnemonics v...,
# ymm/zmm registers). Each file must also hold some dropletFiber::avx2 code, so that the
# check is known to see the kernel.
# Exit 77 (CTest: skipped) when the build has no batched kernel (not x86-64).
# Usage: checkAvx2Isolation.sh FILE... (static libraries, executables, shared libraries)
set -uo pipefail
if [ $# -eq 0 ]; then
    echo "usage: $0 FILE..." >&2
    exit 2
fi
if [ "$(uname -m)" != "x86_64" ]; then
    echo "not x86-64: the build has no AVX2 kernel to check"
    exit 77
fi
failed=0
for file in "$@"; do
    if [ ! -f "$file" ]; then
        echo "FAILED: $file does not exist (not built?)"
        failed=1
        continue
    fi
    # Mangled names (no -C): dropletFiber::avx2 functions, members and templates all start
    # with _ZN12dropletFiber4avx2 (const members: _ZNK...).
    report=$(objdump -d --no-show-raw-insn "$file" | awk '
        /^[0-9a-f]+ <.*>:$/ { name = substr($2, 2, length($2) - 3); next }
        /^ +[0-9a-f]+:\t/ {
            split($0, field, "\t")
            if (field[2] ~ /^v[a-z]/ || $0 ~ /%[yz]mm/) { avx[name]++ }
        }
        END {
            for (n in avx) {
                if (n ~ /^_ZNK?12dropletFiber4avx2/) { kernel++ } else { print "outside " n " (" avx[n] " AVX instructions)" }
            }
            print "kernel " kernel + 0
        }')
    outside=$(echo "$report" | grep "^outside " || true)
    kernel=$(echo "$report" | sed -n 's/^kernel //p')
    if [ -n "$outside" ]; then
        echo "FAILED: $file has AVX instructions outside dropletFiber::avx2:"
        echo "$outside" | c++filt | head -20
        failed=1
    elif [ "$kernel" -eq 0 ]; then
        echo "FAILED: $file has no dropletFiber::avx2 code: the check does not see the kernel"
        failed=1
    else
        echo "ok: $file: AVX instructions only in $kernel function(s) of dropletFiber::avx2"
    fi
done
exit $failed
