#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkOldStateRestart.sh - a restart state written before the population
# counted the fibers the belt took still restarts, and continues as if never
# stopped.
#
# Usage: checkOldStateRestart.sh CASE_DIR FULL_RUN WORK_DIR STATE_ARCHIVE
#   CASE_DIR: tests/cases/fiberRain; FULL_RUN: its run 0 -> 0.5 without a stop
#   (the fixture's run); STATE_ARCHIVE: the time folder 0.25 of that case as
#   the library wrote it before (tests/cases/references/fiberRainState0.25.tar.xz:
#   the laid fibers' totals in the mat's entry only). The copy restarts from it
#   (startFrom latestTime) to 0.5: the log says where the laid totals came
#   from, and its laydown.dat rows and log figures at 0.375 and 0.5 are the
#   uninterrupted run's to the bit, its glass balance closed. That version laid
#   each fiber whole in its centre's cell with no error sums: the log warns that
#   the cells laid before carry none, and the maps hold the same glass and
#   fibers (checkFiberRainSame.py --after --olderMat).
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "${0%/*}" && pwd)"
archive="$(cd "$(dirname "$4")" && pwd)/$(basename "$4")"
set -- "$1" "$2" "$3" serial
# shellcheck disable=SC1091
. "$here/lib/restartAgainst.sh"
restart=0.25; last=0.5

splitCopy
rm -rf 0 && cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1 || { tail -20 log.blockMesh; die "blockMesh failed"; }
tar xJf "$archive"
check "[ -f $restart/uniform/dropletFiber/dropletFiber ] && ! grep -q fibersLaid $restart/uniform/dropletFiber/dropletFiber" \
    "the archive's state is not one without the population's laid totals"
setEnd "$last"
# log.restart, as checkFiberRainSame.py reads it; the solver's log is that one
"$app" > log.restart 2>&1 || { tail -20 log.restart; die "the restart from the older state failed"; }
ln -sf log.restart "log.$app"
checkRanClean "$work/split"
check "grep -q 'restarted from' log.restart" "the restarted run did not read the restart state"
check "grep -q \"the fibers laid in the mat's totals only: taken from there\" log.restart" \
    "the log does not say that the laid totals came from the mat's"
check "grep -q fibersLaid $last/uniform/dropletFiber/dropletFiber" \
    "the state written after the restart has no fibersLaid"
check "grep -q 'has no error sums of the mat' log.restart" \
    "the log does not warn that the older mat's cells carry no errors"
check "'$PY' '$here/checkFiberRainSame.py' --after $restart --olderMat '$full' '$work/split'" \
    "the run restarted from the older state differs from the uninterrupted run"

checkSummary || exit 1
