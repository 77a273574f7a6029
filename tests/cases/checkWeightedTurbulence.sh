#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkWeightedTurbulence.sh - M computed fibers of weight N against M N of weight 1,
# moving in turbulent air through a spray (docs/model.md sec. 12, spread populations;
# docs/validation.md "A converged veil"): the fiber stream of fiberStreamRAS (frozen
# homogeneous k-epsilon air, depletion on) at rate R with represents 1, and at R / N with
# represents N, the same physical fibers per second. Each run's captured total over the
# run (the per-step table's capturedTotal: every physical fiber's) is a sample of the
# stream's random paths (u' keyed by fibers.turbulence.seed); several seeds of each give
# the mean and its sampling error, and the two means must agree within three combined
# standard errors (checkWeightedTurbulence.py).
#
# Usage: checkWeightedTurbulence.sh CASE_DIR WORK_DIR [SEEDS]   (default 4 seeds)
#------------------------------------------------------------------------------
set -euo pipefail
caseDir="$1"; work="$2"; seeds="${3:-4}"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
# shellcheck disable=SC1091
. "$here/lib/caseRun.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
rate=1000
weight=10

# run NAME RATE REPRESENTS SEED: a copy of the case, its fixed fiber gone (the stream
# only), run serially
run() {
    local dir="$work/$1"
    cp -r "$caseDir" "$dir"
    local dict="$dir/system/controlDict"
    foamDictionary "$dict" -entry functions/dropletFiber/fibers/fixed -remove > /dev/null
    foamDictionary "$dict" -entry functions/dropletFiber/fibers/injectors/spinner/rate -set "$2" > /dev/null
    foamDictionary "$dict" -entry functions/dropletFiber/fibers/injectors/spinner/represents -add "$3" > /dev/null
    foamDictionary "$dict" -entry functions/dropletFiber/fibers/turbulence -add "{ seed $4; }" > /dev/null
    "$dir/Allrun" > /dev/null
    checkRanClean "$dir"
    echo "$dir"
}

rm -rf "$work"; mkdir -p "$work"
unweighted=(); weighted=()
for seed in $(seq 1 "$seeds"); do
    unweighted+=("$(run "weight1_seed$seed" "$rate" 1 "$seed")")
    weighted+=("$(run "weight${weight}_seed$seed" "$((rate / weight))" "$weight" "$seed")")
done
"$PY" "$here/checkWeightedTurbulence.py" --weight "$weight" "${unweighted[@]}" -- "${weighted[@]}"
