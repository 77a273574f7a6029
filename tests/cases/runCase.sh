#!/usr/bin/env bash
#------------------------------------------------------------------------------
# runCase.sh - run an OpenFOAM test case in a scratch copy, then check it.
#
# Usage: runCase.sh CASE_DIR WORK_DIR serial|parallel|parallelN [CHECK_COMMAND ...]
#   parallelN: the case's decomposeParDict set to N subdomains, (N 1 1)
#   The case is copied to WORK_DIR (replaced if present), its Allrun is run
#   (with -parallel for parallel), and CHECK_COMMAND is run with the copy's
#   path appended. A failed step prints the tail of the case's logs; a run
#   without the dropletFiberCollision function object (library not loaded) fails
#   (bin/checkFunctionObjectRan).
#------------------------------------------------------------------------------
set -euo pipefail
caseDir="$1"; workDir="$2"; mode="$3"; shift 3
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
# shellcheck disable=SC1091
. "$here/lib/caseRun.sh"
loadFoamEnvironment

rm -rf "$workDir"
mkdir -p "$(dirname "$workDir")"
cp -r "$caseDir" "$workDir"

args=()
case "$mode" in
    parallel) args=(-parallel) ;;
    parallel[0-9]*)
        # decomposed along x into N (more ranks than cores: oversubscribed)
        ranks="${mode#parallel}"
        foamDictionary "$workDir/system/decomposeParDict" -entry numberOfSubdomains \
            -set "$ranks" > /dev/null
        foamDictionary "$workDir/system/decomposeParDict" -entry coeffs/n \
            -set "($ranks 1 1)" > /dev/null
        export OMPI_MCA_rmaps_base_oversubscribe=1
        args=(-parallel)
        ;;
esac
if ! "$workDir/Allrun" "${args[@]}"; then
    showLogs "$workDir"
    die "Allrun of $workDir failed"
fi
checkRanClean "$workDir"
if [ "$#" -gt 0 ]; then
    "$@" "$workDir"
fi
