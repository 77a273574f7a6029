#!/usr/bin/env bash
# A restart whose dictionary differs from the restart state's sources warns, naming what
# differs and which one is used, and runs on: a fixed fiber moved (the state's is used:
# its points at 0.15 are those at 0.1), an injector's rate (the dictionary's from now
# on), a grid entry (this run's grid); the same dictionary says nothing; on 2 ranks the
# grid's warning once. Usage: checkRestartSources.sh CASE_DIR WORK_DIR (fiberStream:
# writes at 0.05, 0.1, 0.15; fixed fiber 'across' held fixed, injector 'spinner')
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/restartCopies.sh"
work="$2"
prepareCaseCopy "$1" "$work/good"
runTo 0.1
fo=functions/dropletFiber
set() { echo "foamDictionary system/controlDict -entry $fo/$1 -set '$2' > /dev/null"; }
state=uniform/dropletFiber/dropletFiber
positions() { grep -m1 -A0 "positions" "$1" | tr -s ' '; }

restartCopy same "" 0.11
expectRuns same "restarted from"
check "! grep -q 'restart state .* against this run' '$work/same/log.restart'" "same: warned of a difference"

restartCopy fixedMoved "$(set fibers/fixed/across/points '((0.06 0.01 0.005) (0.06 0.04 0.005))')" 0.15
expectRuns fixedMoved "fixed fiber 'across' differs in 1\(points\) \(the restart state .*0.1/$state\"? against this run's dictionary\): the restart state's fibers are used"
check "[ \"\$(positions '$work/fixedMoved/0.1/$state')\" = \"\$(positions '$work/fixedMoved/0.15/$state')\" ]" \
    "fixedMoved: the fixed fiber is not the state's at 0.15"

restartCopy injectorRate "$(set fibers/injectors/spinner/rate 200)" 0.11
expectRuns injectorRate "injector 'spinner' differs in 1\(rate\) .*: the dictionary's injectors give the fibers from now on"

restartCopy gridBeta "$(set grid/beta 0.05)" 0.11
expectRuns gridBeta "grid entries 1\(beta\) differ between the restart state .*: this run's grid is used"

rm -rf "${work:?}/good"/{0.05,0.1,postProcessing,log.*}
(cd "$work/good" && runTo 0.1 parallel) || exit 1
restartCopy gridBeta.parallel "$(set grid/beta 0.05)" 0.11 parallel
expectRuns gridBeta.parallel "grid entries 1\(beta\) differ"
check "[ \"\$(grep -c 'grid entries 1(beta) differ' '$work/gridBeta.parallel/log.restart')\" = 1 ]" \
    "gridBeta.parallel: not warned exactly once"
checkSummary
