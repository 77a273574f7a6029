#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkRestartToTheBit.sh - a restart continues to the bit when the time
# folders' names give back OpenFOAM's time (docs/userGuide.md, what restarts
# to the bit; docs/model.md sec. 4, what is exact). A solver with its own cloud
# (the case's icoUncoupledKinematicParcelFoam): the icoUncoupledKinematicCloud
# function object does not restart its cloud to the bit (the user guide says why).
#
# Usage: checkRestartToTheBit.sh CASE_DIR WORK_DIR
#   The case with timePrecision 17, writePrecision 17 (the clouds' injected mass
#   is kept in an ASCII dictionary) and collision { mode discrete; seed 3; }
#   (the draws keyed by the time index: a last-bit difference in the spray
#   could change a count) is run 0 -> 0.2 and 0 -> 0.1 -> restart -> 0.2.
#   OpenFOAM restarts its time from the folder's name: with 17 digits the name
#   is the continuous run's time (0.10000000000000007), and so are its
#   injection and tracking. Checked at the last time, byte for byte: the
#   function object's state (fibers, hits, totals), its averaging window, the
#   parcels and the air; and the table rows after the restart to tolerance 0.
#   (With fewer digits the restart differs in the last bits: checkRestart.sh.)
#------------------------------------------------------------------------------
set -euo pipefail
caseDir="$1"; work="$2"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
loadFoamEnvironment

rm -rf "$work"; mkdir -p "$work"
for run in full split; do
    cp -r "$caseDir" "$work/$run"
    sed -i -e 's/^timePrecision .*/timePrecision   17;/' \
        -e 's/^writePrecision .*/writePrecision  17;/' "$work/$run/system/controlDict"
    foamDictionary "$work/$run/system/controlDict" -entry functions/dropletFiber/collision \
        -add "{ mode discrete; seed 3; }" > /dev/null || die "cannot set collision.mode"
done
app="$(foamDictionary -entry application -value "$caseDir/system/controlDict")"
(cd "$work/full" && ./Allrun > /dev/null)
(
    cd "$work/split"
    sed -i "s/^endTime .*/endTime         0.1;/" system/controlDict
    ./Allrun > /dev/null
    sed -i "s/^endTime .*/endTime         0.2;/" system/controlDict
    "$app" > log.restart 2>&1
)
grep -q "restarted from" "$work/split/log.restart" || die "the restarted run did not read the restart state"
last="$(foamListTimes -case "$work/full" -latestTime 2>/dev/null | tail -1)"
restart="$(foamListTimes -case "$work/split" 2>/dev/null | grep '^0\.1' | head -1)"
[ -n "$last" ] && [ "$restart" = 0.10000000000000007 ] \
    || die "time folders $last / $restart: expected 17-digit names (0.10000000000000007)"
state=uniform/dropletFiber/dropletFiber
for file in "$state" "$state.gridWindow" lagrangian/kinematicCloud/positions \
            lagrangian/kinematicCloud/U lagrangian/kinematicCloud/nParticle U; do
    check "cmp -s '$work/full/$last/$file' '$work/split/$last/$file'" \
        "$last/$file differs between the continuous and the restarted run"
done
for table in dropletFiber.dat binderDistribution.dat; do
    check "'$PY' '$here/compareTables.py' --after 0.1 \
        '$work/full/postProcessing/dropletFiber/0/$table' \
        '$work/split/postProcessing/dropletFiber/$restart/$table' 0 > /dev/null" \
        "$table: the restarted run's rows differ from the continuous run's"
done
checkSummary || exit 1
echo "restart at $restart, compared at $last: to the bit"
