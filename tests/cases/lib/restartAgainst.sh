# shellcheck shell=bash
# The set-up of a check that restarts a case in the middle and compares it with the
# uninterrupted run (sourced by checkFiberCurtainRestart.sh, checkFiberRainRestart.sh,
# with their arguments CASE_DIR FULL_RUN WORK_DIR [parallel]): caseDir, full, work and
# mode from them, the checks' helpers and OpenFOAM's environment, the case's
# application app, its arguments args and launcher np for the mode, the processor
# folders procs (. in serial), setEnd END (the copy's endTime) and splitCopy (a fresh
# copy of the case in $work/split, entered).
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
# A fresh copy of the case in $work/split, entered; work and full made absolute
splitCopy() {
    rm -rf "$work"; mkdir -p "$work"
    work="$(cd "$work" && pwd)"; full="$(cd "$full" && pwd)"
    cp -r "$caseDir" "$work/split"
    cd "$work/split"
}
