#!/usr/bin/env bash
# The two routes that gather parcels give the same parcels: the case is run with
# 'gather writeObjects;' (every cloud through cloud::writeObjects, the generic
# route), and its table must equal, to the last digit written, the table of the
# default run ('gather direct;': the stock solvers' parcel types read directly);
# each run's log names the route its cloud was read by.
# Usage: checkGenericGather.sh CASE_DIR WORK_DIR DEFAULT_RUN_TABLE
set -uo pipefail
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
defaultTable="$3"
prepareCaseCopy "$1" "$2"
foamDictionary system/controlDict -entry functions/dropletFiber/gather -add writeObjects > /dev/null
"$(foamDictionary -entry application -value system/controlDict)" > log.generic 2>&1
status=$?
check "[ $status -eq 0 ]" "the run with 'gather writeObjects' failed ($status), see $2/log.generic"
check '"$here/../../bin/checkFunctionObjectRan" log.generic' "the run went on without the function object"
check 'grep -q "gather writeObjects: every cloud through" log.generic' \
    "the entry did not take effect (no generic-route line in the log)"
app="$(foamDictionary -entry application -value system/controlDict)"
cloudName="$(sed -n "s/^.*cloud '\([^']*\)' (type [^)]*) read through cloud::writeObjects (entry gather writeObjects).*$/\1/p" log.generic | head -1)"
check '[ -n "$cloudName" ]' "the generic run does not log the cloud's route"
check 'grep -q "gather direct: the stock solvers'"'"' parcel types read directly" "$(dirname "$defaultTable")/../../../log.$app"' \
    "the default run's settings line does not name the direct route"
check "grep -q \"cloud '$cloudName' (type [^)]*) read parcel by parcel\" \"\$(dirname \"\$defaultTable\")/../../../log.$app\"" \
    "the default run did not read the parcels directly"
python3 "$here/compareTables.py" "$defaultTable" postProcessing/dropletFiber/0/dropletFiber.dat 0
check "[ $? -eq 0 ]" "the tables of the two routes differ"
# The averaging window of the last write time, every value in binary: the
# parcels' positions, velocities, sizes and numbers must agree to the bit
defaultRun="$(cd "$(dirname "$defaultTable")/../../.." && pwd)"
last="$(foamListTimes -latestTime -case "$defaultRun" 2>/dev/null | tail -1)"
window="$last/uniform/dropletFiber/dropletFiber.gridWindow"
check '[ -n "$last" ] && [ -f "$defaultRun/$window" ] && [ -f "$window" ]' "no grid window at the last write time '$last'"
check 'cmp -s "$defaultRun/$window" "$window"' "the grid windows of the two routes differ (at $last)"
checkSummary
