#!/usr/bin/env bash
# A controlDict naming a cloud that does not exist must stop the run (non-zero
# exit, FatalIOError) with a message naming the cloud and listing the clouds
# that exist, and saying what to check (the cloud's own loading, its files,
# reconstructPar's loss of collision records). Usage: checkMissingCloud.sh CASE_DIR WORK_DIR
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"
# only the first clouds entry: ours (cloudInfo has one too)
sed -i "0,/clouds          (kinematicCloud);/s//clouds          (noSuchCloud);/" system/controlDict
grep -q "noSuchCloud" system/controlDict || { echo "FAILED: could not edit controlDict"; exit 1; }
pimpleFoam > log.missingCloud 2>&1
status=$?
check "[ $status -ne 0 ]" "pimpleFoam exited with $status, expected a failure"
check 'grep -q "FOAM FATAL IO ERROR" log.missingCloud' "no FatalIOError in the log"
check 'grep -q "Cloud .noSuchCloud. named in entry .clouds." log.missingCloud' "error does not name the cloud and the entry"
check 'grep -A1 "Clouds that exist" log.missingCloud | grep -q kinematicCloud' "error does not list the existing cloud"
check 'grep -q "a warning or error of the cloud.s own loading above in the log" log.missingCloud' "error does not point at the cloud's own loading"
check 'grep -q "its files in 0/lagrangian/noSuchCloud" log.missingCloud' "error does not name the cloud's files of the start time"
check 'grep -q "reconstructPar does not carry over a colliding cloud.s collision records" log.missingCloud' "error does not mention reconstructPar's loss of collision records"
check '! grep -q "^Time = 0.004" log.missingCloud' "run went on after the error"
grep -A6 "FOAM FATAL IO ERROR" log.missingCloud | head -8
checkSummary
