#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkFiberRainRestart.sh - the fiber rain restarted at a middle write time
# continues the mat on the belt without duplicates and without losses.
#
# Usage: checkFiberRainRestart.sh CASE_DIR FULL_RUN WORK_DIR [parallel]
#   FULL_RUN: the case run 0 -> 0.5 without a stop (the fixture's run).
#   The case is run 0 -> 0.25 (470 fibers laid, 170 in the air, the injectors at
#   work), then restarted (startFrom latestTime) to 0.5, serial or on 2 ranks. The
#   restarted run writes postProcessing/dropletFiber/0.25/: its laydown.dat holds
#   exactly the uninterrupted run's rows after 0.25, to the bit (none twice, none
#   lost), and its mat_0.375.vti, mat_0.5.vti and the restart state's `laydown`
#   entry at 0.375 and 0.5 are the uninterrupted run's byte for byte, and so are
#   the restarted log's laydown, mat, glass, binder and fiber-mass lines at those
#   times, every figure as printed (checkFiberRainSame.py --after).
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/restartAgainst.sh"
restart=0.25; last=0.5

splitCopy
setEnd "$restart"
./Allrun "${args[@]}" > /dev/null
checkRanClean "$work/split"
setEnd "$last"
"${np[@]}" "$app" "${args[@]}" > log.restart 2>&1 || { tail -20 log.restart; die "the restart failed"; }
checkRanClean "$work/split"
check "grep -q 'restarted from' log.restart" "the restarted run did not read the restart state"
check "[ -f postProcessing/dropletFiber/$restart/laydown.dat ]" \
    "the restarted run wrote no postProcessing/dropletFiber/$restart/laydown.dat"

check "'$PY' '$here/checkFiberRainSame.py' --after $restart '$full' '$work/split'" \
    "the restarted run's mat differs from the uninterrupted run's"

checkSummary || exit 1
echo "restart at $restart ($mode), compared at 0.375 and $last: to the bit"
