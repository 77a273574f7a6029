#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkWeightedMat.sh - weighted fibers through the function object (docs/model.md
# sec. 9; docs/validation.md, weighted fibers): random fixed-fiber mats of M fibers
# of weight N against M N fibers of weight 1, drawn from the same distribution.
#
# Usage: checkWeightedMat.sh [--parallel | --restart] CASE_DIR WORK_DIR [S ...]
#   (default S: 1, ln 10, 4.6)
#   For every S two copies of the denseMat case get their mats (makeMat.py, seed 1:
#   thin fibers r_F 2 um, droplets 6 um; weight 5 and weight 1) on a 2 mm grid, a
#   quarter spacing per step, and run serially; checkWeightedMat.py checks both
#   against exp(-S) within 3 % and against each other within the sampling error.
#   --parallel: the weighted mat at the first S also on 2 ranks (cut across the mat),
#   its table the serial run's to 1e-8; with 40 um droplets (6 um ones follow the air,
#   whose parallel solution differs from the serial one at the solver's tolerance).
#   --spacings: the first S with weight 100 (46 fibers) on grids of 2, 1 and 0.5 mm and,
#   for contrast, at 0.5 mm with collision.spread off (P40 alone); checkWeightedSpacings.py
#   checks the three spread runs the same penetration within 2 % and each within 3 % of
#   exp(-S), and the run without spread off them by more than 10 %.
#   --restart: the weighted mat at the first S run to 15 ms, restarted to the end:
#   its state holds the weights, the table goes on with the same physical fibers,
#   and the capture, once the parcels flying at the restart passed the mat, is the
#   uninterrupted run's to 0.2 % (the case's cloud, a function object's, moves those
#   parcels one step less at a restart: not to the bit); the report reads the fibers'
#   VTK with their weights as the binder table and the per-step table count them.
#------------------------------------------------------------------------------
set -euo pipefail
mode=serial
case "${1:-}" in
    --parallel) mode=parallel; shift ;;
    --restart) mode=restart; shift ;;
    --spacings) mode=spacings; shift ;;
esac
caseDir="$1"; work="$2"; shift 2
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
# shellcheck disable=SC1091
. "$here/lib/caseRun.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
depths=("$@"); [ "${#depths[@]}" -gt 0 ] || depths=(1 2.302585092994046 4.6)
matOptions=(--fiberRadius 2e-6 --dropletDiameter 6e-6)

# prepare NAME S WEIGHT [NODES]: a copy of the case with its mat, on the 2 mm grid (or
# the grid NODES)
prepare() {
    local run="$work/$1"
    cp -r "$caseDir" "$run"
    "$PY" "$run/makeMat.py" "$run" "$2" 0.5 1 --represents "$3" "${matOptions[@]}"
    foamDictionary -entry functions/dropletFiber/grid/nodes -set "${4:-(9 11 1)}" \
        "$run/system/controlDict" > /dev/null
    echo "$run"
}

rm -rf "$work"; mkdir -p "$work"
table=postProcessing/dropletFiber/0/dropletFiber.dat
case "$mode" in
serial)
    cases=()
    for S in "${depths[@]}"; do
        for weight in 5 1; do
            run=$(prepare "S${S:0:4}_weight$weight" "$S" "$weight")
            "$run/Allrun" > /dev/null
            checkRanClean "$run"
            cases+=("$run")
        done
    done
    "$PY" "$here/checkWeightedMat.py" --spacing 2e-3 --dropletDiameter 6e-6 "${cases[@]}"
    ;;
parallel)
    matOptions=(--fiberRadius 2e-6 --dropletDiameter 4e-5)
    serial=$(prepare serial "${depths[0]}" 5)
    parallel=$(prepare parallel "${depths[0]}" 5)
    "$serial/Allrun" > /dev/null; checkRanClean "$serial"
    "$parallel/Allrun" -parallel > /dev/null; checkRanClean "$parallel"
    "$PY" "$here/compareTables.py" "$serial/$table" "$parallel/$table" 1e-8
    ;;
spacings)
    cases=()
    for nodes in "(9 11 1)" "(17 21 1)" "(33 41 1)"; do
        run=$(prepare "h${nodes//[^0-9]/_}" "${depths[0]}" 100 "$nodes")
        "$run/Allrun" > /dev/null; checkRanClean "$run"
        cases+=("$run")
    done
    run=$(prepare withoutSpread "${depths[0]}" 100 "(33 41 1)")
    foamDictionary -entry functions/dropletFiber/collision -add "{ spread { active false; } }" \
        "$run/system/controlDict" > /dev/null
    grep -q "active *false" "$run/system/controlDict" || die "collision.spread not switched off"
    "$run/Allrun" > /dev/null; checkRanClean "$run"
    "$PY" "$here/checkWeightedSpacings.py" --dropletDiameter 6e-6 "${cases[@]}" -- "$run"
    ;;
restart)
    whole=$(prepare whole "${depths[0]}" 5)
    "$whole/Allrun" > /dev/null; checkRanClean "$whole"
    run=$(prepare restarted "${depths[0]}" 5)
    (
        cd "$run"
        # (foamDictionary writes the included matTime's entries into controlDict)
        foamDictionary -entry writeInterval -set 0.015 system/controlDict > /dev/null
        foamDictionary -entry endTime -set 0.015 system/controlDict > /dev/null
        ./Allrun > /dev/null
        foamDictionary -entry endTime -set 0.03 system/controlDict > /dev/null
        pimpleFoam > log.restart 2>&1
    )
    checkRanClean "$run"
    "$here/../../bin/dropletFiberReport" "$run" > /dev/null
    "$PY" "$here/checkWeightedRestart.py" "$whole" "$run" 0.015
    ;;
esac
