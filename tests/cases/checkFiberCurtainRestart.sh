#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkFiberCurtainRestart.sh - the fiber curtain (coupled both ways) restarted
# in the middle of the injection continues the uninterrupted run to the bit, the
# fibers' drag on the air included (docs/model.md sec. 10, timing: the fields
# fiberDragForce and fiberDragCoeff of the written time are the next step's
# source, read at the start).
#
# Usage: checkFiberCurtainRestart.sh CASE_DIR FULL_RUN WORK_DIR [parallel]
#   FULL_RUN: the case run 0 -> 0.15625 without a stop (the fixture's run).
#   The case is run 0 -> 0.03125 (fibers flying, the injectors at work), then
#   restarted (startFrom latestTime) to 0.15625, serial or on 2 ranks. Its time
#   step 2^-10 s makes the write time's name its exact time, and the fields are
#   written binary: checked byte for byte at 0.15625 are the air (U, p, phi), the
#   drag fields and the fibers' state (per processor on 2 ranks), and to the last
#   digit written the per-step tables after the restart (checkFiberCurtainSame.py,
#   tolerance 0). A copy restarted without its fiberDragForce stops naming both
#   fields: the restart must not go on without the drag.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/restartAgainst.sh"
restart=0.03125; last=0.15625

splitCopy
setEnd "$restart"
./Allrun "${args[@]}" > /dev/null
checkRanClean "$work/split"
cp -r "$work/split" "$work/missing"
setEnd "$last"
"${np[@]}" "$app" "${args[@]}" > log.restart 2>&1 || { tail -20 log.restart; die "the restart failed"; }
check "grep -q 'restarted from' log.restart" "the restarted run did not read the restart state"
check "grep -q 'fiberDragSource, which is listed; read at the start time' log.restart" \
    "the restarted run does not say it read the drag fields at the start time"

for p in "${procs[@]}"; do
    for file in U p phi fiberDragForce fiberDragCoeff uniform/dropletFiber/dropletFiber; do
        check "cmp -s '$full/$p/$last/$file' '$work/split/$p/$last/$file'" \
            "$p/$last/$file differs between the uninterrupted and the restarted run"
    done
done
check "'$PY' '$here/checkFiberCurtainSame.py' --after $restart '$full' '$work/split' 0" \
    "the restarted run's tables differ from the uninterrupted run's"

# Without fiberDragForce the restart stops, naming both fields and the time
cd "$work/missing"
rm -f ./"$restart"/fiberDragForce processor*/"$restart"/fiberDragForce
setEnd "$last"
status=0
timeout 120 "${np[@]}" "$app" "${args[@]}" > log.restart 2>&1 || status=$?
expectFatalIOError "$status" log.restart \
    "fiberDragForce and fiberDragCoeff of time $restart are missing" \
    "a restart without its fiberDragForce"
checkSummary || exit 1
echo "restart at $restart ($mode), compared at $last: to the bit"
