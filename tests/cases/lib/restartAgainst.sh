# shellcheck shell=bash
# The set-up of a check that restarts a case in the middle and compares it with the
# uninterrupted run (sourced by checkFiberCurtainRestart.sh, checkFiberRainRestart.sh,
# with their arguments CASE_DIR FULL_RUN WORK_DIR [parallel]): caseDir, full, work and
# mode from them, the checks' helpers and OpenFOAM's environment, the case's
# application app, its arguments args and launcher np for the mode, the processor
# folders procs (. in serial), and setEnd END (the copy's endTime).
caseDir="$1"; full="$2"; work="$3"; mode="${4:-serial}"
libDir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck disable=SC1091
. "$libDir/prepareCase.sh"
# shellcheck disable=SC1091
. "$libDir/caseRun.sh"
# shellcheck disable=SC1091
. "$libDir/../../../bin/functions.sh"
loadFoamEnvironment

app="$(foamDictionary -entry application -value "$caseDir/system/controlDict")"
args=(); np=(); procs=(.)
if [ "$mode" = parallel ]; then
    args=(-parallel); np=(mpirun -np 2); procs=(processor0 processor1)
fi
setEnd() { sed -i "s/^endTime .*/endTime         $1;/" system/controlDict; }
