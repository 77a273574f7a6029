#!/usr/bin/env bash
# fibers.coupled true without an active fvOption fiberDragSource: the air feels
# nothing, and the log says so with a warning at the start and again at the end of
# the run (not one line of the settings only). Both ways of missing it: the
# fvOption switched off (active false) and no fvOptions file at all.
# Usage: checkCoupledWithoutSource.sh CASE_DIR WORK_DIR (the fiber curtain; runs copies)
set -uo pipefail
here="$(cd "${0%/*}" && pwd)"
caseDir="$(cd "$1" && pwd)"; mkdir -p "$2"; work="$(cd "$2" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"

# runWithout HOW: a few steps of a copy whose fvOption is missing HOW
runWithout() {
    local how="$1"
    prepareCaseCopy "$caseDir" "$work/$how"
    if [ "$how" = inactive ]; then
        foamDictionary constant/fvOptions -entry fiberDrag/active -add false > /dev/null
    else
        rm -f constant/fvOptions
    fi
    foamDictionary system/controlDict -entry endTime -set 0.0048828125 > /dev/null
    local log=log.pimpleFoam
    pimpleFoam > $log 2>&1
    check "tail -n 3 $log | grep -q '^End'" "$how: the run did not end"
    check "grep -c 'fibers.coupled is true, but no active fvOption fiberDragSource is listed' $log | grep -qx 2" \
        "$how: not warned twice (start and end) that no active fiberDragSource is listed"
    check "grep -q 'the fields fiberDragForce and fiberDragCoeff are written, the air feels nothing' $log" \
        "$how: the start's warning does not say the air feels nothing"
    check "tail -n 40 $log | grep -q 'the air felt nothing of the fibers. drag during this run'" \
        "$how: the end of the run does not repeat that the air felt nothing"
}
runWithout inactive
runWithout absent
checkSummary || exit 1
