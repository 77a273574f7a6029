#!/usr/bin/env bash
# Limits that used to crash or pass in silence, on the fiberStream case:
#  - an injector rate above ~9,000 per second without an endTime injects every
#    fiber (it was an integer overflow: SIGFPE, or no fibers at all);
#  - a grid that cannot fit in memory (a spacing typo) stops before allocating,
#    naming spacing and the estimate; so does one above the user's maxMemory;
#  - non-finite air at a fiber stops with the time, fiber, point and field
#    (it was a SIGFPE inside the fiber solver);
#  - a grid box, a fixed fiber or an injector outside the mesh is warned about.
# Usage: checkLimits.sh CASE_DIR WORK_DIR [serial|parallel]
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"
mode="${3:-serial}"
fo=functions/dropletFiber
foamDictionary system/controlDict -entry endTime -set 0.004 > /dev/null
cp system/controlDict system/controlDict.good
# 0/Ubad: 0/U with nan in every cell, in binary (OpenFOAM reads no nan in ascii)
python3 - <<'PYTHON'
import re, struct
cells = int(re.search(rb"nCells:\s*(\d+)", open("constant/polyMesh/owner", "rb").read()).group(1))
text = open("0/U").read().replace("format      ascii;", "format      binary;")
text = text.replace("object      U;", "object      Ubad;")
head, tail = text.split("internalField   uniform (1 0 0);")
values = struct.pack("<%dd" % (3 * cells), *([float("nan"), 0.0, 0.0] * cells))
with open("0/Ubad", "wb") as f:
    f.write(head.encode())
    f.write(b"internalField   nonuniform List<vector> %d(" % cells + values + b");")
    f.write(tail.encode())
PYTHON
if [ "$mode" = parallel ]; then
    # no trapping: decomposePar compares the nan values of 0/Ubad while writing
    FOAM_SIGFPE=false decomposePar > log.decomposePar 2>&1 || { echo "FAILED: decomposePar"; exit 1; }
fi

# run LOG: the case's solver, serial or on 2 ranks; returns its exit status
run() {
    if [ "$mode" = parallel ]; then
        mpirun -np 2 icoUncoupledKinematicParcelFoam -parallel > "$1" 2>&1
    else
        icoUncoupledKinematicParcelFoam > "$1" 2>&1
    fi
}

# mutate ENTRY VALUE...: in a fresh copy of the good controlDict (REMOVE removes it)
mutate() {
    cp system/controlDict.good system/controlDict
    while [ "$#" -ge 2 ]; do
        if [ "$2" = REMOVE ]; then
            foamDictionary system/controlDict -entry "$fo/$1" -remove > /dev/null
        else
            foamDictionary system/controlDict -entry "$fo/$1" -set "$2" > /dev/null
        fi
        shift 2
    done
}

noCrash() {
    ! grep -q -E "sigFpe::sigHandler|^Floating point exception|new cannot satisfy|terminate called|Segmentation fault" "$1"
}

# runStops LOG WHAT: the run (log LOG) stops with a FatalIOError, without a crash
runStops() {
    run "$1"
    local status=$?
    check "[ $status -ne 0 ] && noCrash $1 && grep -q 'FOAM FATAL IO ERROR' $1" \
        "$2: exit $status, no FatalIOError, or a crash"
}

# --- Overflow: 20,000 fibers per second, no endTime. Births at k * 50 us:
# 41 by t = 0.002 (k = 0..40), 81 by t = 0.004; with the fixed fiber 82.
mutate fibers/injectors/spinner/rate 20000 fibers/injectors/spinner/endTime REMOVE
run log.highRate
status=$?
check "[ $status -eq 0 ] && noCrash log.highRate" "rate 20000 without endTime: exit $status or a crash"
check 'grep -q "dropletFiber: parcels [0-9]*, fibers 42," log.highRate' "rate 20000: not 41 injected fibers (and the fixed one) at t = 0.002"
check 'grep -q "dropletFiber: parcels [0-9]*, fibers 82," log.highRate' "rate 20000: not 81 injected fibers (and the fixed one) at t = 0.004"
check '! grep -q "outside the mesh" log.highRate' "a good case warned about something outside the mesh"
if [ "$mode" = parallel ]; then
    # each processor holds its block: 2626 nodes split in two (at most 2626/2 + a row)
    held=$(sed -n 's/.*memory per processor (estimate): grid [0-9.]* MB (largest block: \([0-9]*\) of 2626 nodes.*/\1/p' log.highRate | head -1)
    check '[ -n "$held" ] && [ "$held" -lt 1500 ] && [ "$held" -ge 1313 ]' "memory estimate not printed with the settings, or not of the largest block (got '$held')"
else
    check 'grep -q "memory per processor (estimate): grid 1.05 MB (2626 nodes" log.highRate' "memory estimate not printed with the settings"
fi
grep -m1 "memory per processor" log.highRate

# A rate no memory holds (2e9 fibers of 11 points per step of 0.002 s) stops
# at the start, naming the rate
mutate fibers/injectors/spinner/rate 1e12 fibers/injectors/spinner/endTime REMOVE
runStops log.hugeRate "rate 1e12"
check "grep -q \"Entry 'rate' 1e+12 of injector 'spinner': the fibers injected in one step of 0.002 s need an estimated 8.8e+06 MB\" log.hugeRate" "rate 1e12: message does not name the rate and the estimate"
grep -A2 "FOAM FATAL IO ERROR" log.hugeRate | tail -2

# --- Memory: a spacing typo (1e-9 m: 1e16 nodes) stops, naming spacing and the estimate
mutate grid/nodes REMOVE grid/spacing 1e-9
runStops log.tinySpacing "spacing 1e-9"
check "grep -q \"Entry 'spacing' 1e-09 gives nodes (200000001 50000001 1), 1.000000025e+16 nodes in all: the grid would need an estimated 6.8e+12 MB in all (averagingSteps 5)\" log.tinySpacing" "spacing 1e-9: message without the node counts and the estimate"
grep -A2 "FOAM FATAL IO ERROR" log.tinySpacing | tail -2

# 2.5e9 nodes, within the grid's index range, but not in this machine's memory
mutate grid/nodes REMOVE grid/spacing 2e-6
runStops log.smallSpacing "spacing 2e-6"
# (W + 2) x 56 + 8 = 400 bytes per node, W = 5: 2500125001 nodes 1.0e+06 MB held, plus
# 5 x 56 per node while writing: 1.7e+06 MB; in parallel the largest of the two blocks
# (at least half the nodes)
if [ "$mode" = parallel ]; then
    needs="The grid needs an estimated [0-9.]*e+0[56] MB on the processor with the largest block ([0-9]* of 2500125001 nodes, averagingSteps 5"
else
    needs="The grid needs an estimated 1.7e+06 MB (2500125001 nodes, averagingSteps 5"
fi
check "grep -q '$needs' log.smallSpacing && grep -q \"Allowed: a coarser 'spacing', fewer 'averagingSteps'\" log.smallSpacing && grep -q 'MemAvailable' log.smallSpacing" "spacing 2e-6: message without the estimate, MemAvailable, spacing and averagingSteps"
grep -A3 "FOAM FATAL IO ERROR" log.smallSpacing | tail -3

# The user's limit below the need (1.79 MB: 1.05 held + 0.74 while writing)
mutate grid/maxMemory 0.5
run log.maxMemory
status=$?
check "[ $status -ne 0 ] && grep -q 'FOAM FATAL IO ERROR' log.maxMemory" "maxMemory 0.5: exit $status or no FatalIOError"
check "grep -q 'more than the 0.5 MB allowed (the limit grid.maxMemory)' log.maxMemory && grep -q \"or a larger 'maxMemory'\" log.maxMemory" "maxMemory 0.5: message does not name the limit"
mutate grid/maxMemory -1
run log.maxMemoryNegative
check "grep -q \"Entry 'maxMemory' is -1\" log.maxMemoryNegative" "maxMemory -1 not rejected"

# --- Non-finite air: a velocity field holding nan where the fibers are
# (0/Ubad, read by readFields, so that the cloud's own flow stays clean)
mutate air "{ U Ubad; rho rho; mu mu; }"
# readFields before the coupling: its field must exist when the coupling starts
sed -i '/^functions/{n;s/^{/{\n    readUbad { type readFields; libs ("libfieldFunctionObjects.so"); fields (Ubad); }/}' system/controlDict
run log.nanAir
status=$?
check "[ $status -ne 0 ] && noCrash log.nanAir && grep -q 'FOAM FATAL ERROR' log.nanAir" "nan air: exit $status, no FatalError, or a crash (SIGFPE)"
check "grep -q \"the air velocity (field Ubad) is not finite at time 0.002 at point 0 (0.021 0.044 0.005) of fiber 1 (from 'spinner')\" log.nanAir" "nan air: message without time, point, fiber and field"
grep -A2 "FOAM FATAL ERROR" log.nanAir | tail -2

# --- Placed outside: the grid box, a fixed fiber's point, the injector
mutate grid/lower "(1 1 0)" grid/upper "(2 2 0.01)" \
    fibers/fixed/across/points "((0.05 0.01 0.005) (0.05 0.2 0.005))" \
    fibers/injectors/spinner/position "(0.5 0.045 0.005)"
foamDictionary system/controlDict -entry endTime -set 0.002 > /dev/null
run log.outside
status=$?
check "[ $status -eq 0 ]" "placed outside: exit $status, expected a run with warnings"
check "grep -q 'the grid box, lower (1 1 0) upper (2 2 0.01), lies entirely outside the mesh bounds (0 0 0) (0.2 0.05 0.01)' log.outside" "grid outside the mesh: no warning"
check "grep -q \"fixed fiber 'across': points 1 of its 2 lie outside the mesh (the first at (0.05 0.2 0.005))\" log.outside" "fixed fiber point outside the mesh: no warning"
check "grep -q \"injector 'spinner': position (0.5 0.045 0.005) lies outside the mesh\" log.outside" "injector outside the mesh: no warning"
check "[ \"\$(grep -c 'outside the mesh' log.outside)\" -eq 3 ]" "placed outside: not warned once each"
grep -A1 "outside the mesh" log.outside | grep -v "^--" | head -6

cp system/controlDict.good system/controlDict
checkSummary
