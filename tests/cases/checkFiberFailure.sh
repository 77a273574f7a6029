#!/usr/bin/env bash
# A fiber that cannot be advanced (a limp, fast fiber with one sub-step allowed)
# stops the run with an OpenFOAM error giving the reason, not a crash, and the
# per-step table written so far stays. In parallel each processor advances its
# share of the fibers, so the failure happens on one processor: all of them
# must stop with the reason, none may hang in the state exchange.
# Usage: checkFiberFailure.sh CASE_DIR WORK_DIR [serial|parallel]
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"
fo=functions/dropletFiber/fibers
foamDictionary system/controlDict -entry $fo/maxSubSteps -set 1 > /dev/null
foamDictionary system/controlDict -entry $fo/youngsModulus -set 0 > /dev/null
foamDictionary system/controlDict -entry $fo/injectors/spinner/velocity -set "(30 -20 0)" > /dev/null
app="$(foamDictionary -entry application -value system/controlDict)"
if [ "${3:-serial}" = parallel ]; then
    decomposePar > log.decomposePar 2>&1 || { echo "FAILED: decomposePar"; exit 1; }
    # a hang in a collective would run into the test's timeout
    timeout 120 mpirun -np 2 "$app" -parallel > log.fail 2>&1
else
    "$app" > log.fail 2>&1
fi
status=$?
check "[ $status -ne 124 ]" "the run hung (killed by the timeout)"
check "[ $status -ne 0 ]" "solver exited with $status, expected a failure"
check 'grep -q "FOAM FATAL ERROR" log.fail' "no OpenFOAM fatal error in the log"
check 'grep -q "fiber step failed at time .*did not converge" log.fail' "the error does not give the reason"
check '! grep -q -i "segmentation\|terminate called" log.fail' "the run crashed"
rows=$(grep -vc "^#" postProcessing/dropletFiber/0/dropletFiber.dat)
check "[ ${rows:-0} -ge 1 ]" "the table written before the failure is gone"
grep -A2 "FOAM FATAL ERROR" log.fail | head -3
checkSummary
