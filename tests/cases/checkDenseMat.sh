#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkDenseMat.sh - a random fixed-fiber mat through the function object, the
# table S x travel per step (docs/model.md sec. 7; docs/validation.md, dense mats).
#
# Usage: checkDenseMat.sh [--parallel] CASE_DIR WORK_DIR TOLERANCE [S ... -- TRAVEL ...]
#   (defaults: S 1, ln 10, 4.6; travel 1, 1/2, 1/4 grid spacings per step)
#   For every cell of the table a copy of the denseMat case gets its mat
#   (makeMat.py: seed 1, the same fiber positions' draws for every travel) and
#   is run serially by its Allrun (pimpleFoam, default grid settings);
#   checkDenseMat.py then compares every penetration with exp(-S) from the
#   fibers placed, within TOLERANCE, and writes the table (WORK_DIR/denseMat.csv).
#   --parallel: every run on 2 ranks (the case's decomposeParDict, cut across
#   the mat at x = 8 mm).
#------------------------------------------------------------------------------
set -euo pipefail
allrunArgs=()
if [ "${1:-}" = "--parallel" ]; then
    allrunArgs=(-parallel)
    shift
fi
caseDir="$1"; work="$2"; tolerance="$3"; shift 3
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
# shellcheck disable=SC1091
. "$here/lib/caseRun.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

depths=(1 2.302585092994046 4.6)
travels=(1 0.5 0.25)
if [ "$#" -gt 0 ]; then
    depths=(); travels=()
    while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do depths+=("$1"); shift; done
    [ "$#" -gt 0 ] && shift
    while [ "$#" -gt 0 ]; do travels+=("$1"); shift; done
fi

rm -rf "$work"; mkdir -p "$work"
cases=()
for S in "${depths[@]}"; do
    for travel in "${travels[@]}"; do
        run="$work/S${S:0:4}_travel$travel"
        cp -r "$caseDir" "$run"
        "$PY" "$run/makeMat.py" "$run" "$S" "$travel" 1
        "$run/Allrun" "${allrunArgs[@]}" > /dev/null
        checkRanClean "$run"
        cases+=("$run")
    done
done
"$PY" "$here/checkDenseMat.py" --tolerance "$tolerance" --csv "$work/denseMat.csv" "${cases[@]}"
