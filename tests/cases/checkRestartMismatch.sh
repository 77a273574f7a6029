#!/usr/bin/env bash
# A restart state that disagrees with the run stops naming the file, the entry and
# both values: a state of another time or time index, one with fewer fibers than its
# count, an injector count its rate cannot give; on 2 ranks (each processor's own
# state) processor 1's fibers short of its count. Usage: checkRestartMismatch.sh
# CASE_DIR WORK_DIR (fiberStream: writes at 0.05 and 0.1, injector 'spinner', 100/s)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/restartCopies.sh"
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/editFile.sh"
work="$2"
prepareCaseCopy "$1" "$work/good"
runTo 0.1
state=0.1/uniform/dropletFiber/dropletFiber

# The state of 0.05 in the folder of 0.1 (its window is of the same grid)
restartCopy otherTime "cp 0.05/uniform/dropletFiber/* 0.1/uniform/dropletFiber/" 0.11
expectStop otherTime "Restart state .*$state\"?: entry 'time' is 0.05, the run restarts at time 0.1 "

restartCopy otherIndex "edit $state 'timeIndex +50;' 'timeIndex 49;'" 0.11
expectStop otherIndex "entry 'timeIndex' is 49, the run restarts at time index 50 "

# A fiber fewer than the count (fiber1's dictionary removed)
restartCopy fiberMissing "edit $state '\\n    fiber1\\n    [{].*?\\n    [}]' ''" 0.11
expectStop fiberMissing "entry 'fiberCount' is 12, its dictionary 'fibers' holds 11 fibers"

restartCopy injectorCount "edit $state 'spinner +[0-9]+;' 'spinner 1000000000;'" 0.11
expectStop injectorCount "Entry 'spinner' is 1000000000: injector 'spinner' \(rate 100, startTime 0, endTime 0.15\) has given at most 11 fibers by time 0.1"

# 2 ranks: processor 1's state short of a fiber; every rank stops naming it
rm -rf "${work:?}/good"/{0.05,0.1,postProcessing,log.*}
(cd "$work/good" && runTo 0.1 parallel) || exit 1
restartCopy fiberMissing.parallel "edit processor1/$state 'fiberCount +[0-9]+;' 'fiberCount 99;'" 0.11 parallel
expectStop fiberMissing.parallel "^processor 1: Restart state .*processor1/$state\"?: entry 'fiberCount' is 99, its dictionary 'fibers' holds"
checkSummary
