#!/usr/bin/env bash
# A restart whose state is missing stops instead of starting the coupling anew (the
# fibers and the captured mass would be lost): the time folder written by a run
# without uniform/dropletFiber, a time folder copied into a case without its uniform/
# (the case's earlier times say it is a restart), and on 2 ranks; 'restart fresh;'
# starts anew on purpose, saying so, as does a restart before the function object's
# timeStart. Usage: checkRestartWithoutState.sh CASE_DIR WORK_DIR
# (fiberStream: writes at 0.1)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/restartCopies.sh"
work="$2"
prepareCaseCopy "$1" "$work/good"
runTo 0.1
state=0.1/uniform/dropletFiber

restartCopy stateRemoved "rm -rf $state" 0.11
expectStop stateRemoved "Restart state .*$state/dropletFiber\"? is missing: this run restarts at time 0.1 \(time index 50, written by a run; the case holds 2 earlier time\(s\), the first 0, the last 0.05\)" \
    "would start anew" "set 'restart fresh;'"

# A copied time folder without its uniform/ (no time index): the earlier times say it
restartCopy uniformRemoved "rm -rf 0.1/uniform 0.05" 0.11
expectStop uniformRemoved "this run restarts at time 0.1 \(the case holds 1 earlier time\(s\), the first 0, the last 0\)"

# Asked for: runs, saying what it does
restartCopy fresh "rm -rf $state; foamDictionary system/controlDict -entry functions/dropletFiber/restart -add fresh > /dev/null" 0.11
expectRuns fresh "restart fresh: starting from the dictionary's fibers"

# Before the function object's timeStart it has not run: nothing to lose, it starts
restartCopy beforeTimeStart "rm -rf $state; foamDictionary system/controlDict -entry functions/dropletFiber/timeStart -add 0.105 > /dev/null" 0.11
expectRuns beforeTimeStart "no restart state .*0.1/uniform/dropletFiber/dropletFiber"

# The first time of a case: starts, without a word of a restart
check "grep -q \"no restart state .* (the case's first time\" '$work/good/log.icoUncoupledKinematicParcelFoam'" \
    "the first run does not say that it starts from the dictionary"

# 2 ranks: processor1's state missing, every rank stops naming it
rm -rf "${work:?}/good"/{0.05,0.1,postProcessing,log.*}
(cd "$work/good" && runTo 0.1 parallel) || exit 1
restartCopy stateRemoved.parallel "rm -rf processor1/$state" 0.11 parallel
expectStop stateRemoved.parallel "^processor 1: Restart state .*processor1/$state/dropletFiber\"? is missing: this run restarts at time 0.1" \
    "set 'restart fresh;'"
restartCopy stateRemovedAll.parallel "rm -rf processor*/$state" 0.11 parallel
expectStop stateRemovedAll.parallel "^processor 0: Restart state .*processor0/$state/dropletFiber\"? is missing"
checkSummary
