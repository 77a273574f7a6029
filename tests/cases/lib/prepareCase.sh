# shellcheck shell=bash
# prepareCaseCopy CASE_DIR WORK_DIR: load OpenFOAM, copy the case to WORK_DIR
# (replacing it), restore 0/ and make the mesh; leaves the shell in WORK_DIR.
# For checks that run the solver themselves (sourced, not run).
prepareCaseCopy() {
    local caseDir="$1" work="$2" here
    here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
    # shellcheck disable=SC1091
    . "$here/../../../bin/functions.sh"
    loadFoamEnvironment
    rm -rf "$work"; mkdir -p "$(dirname "$work")"; cp -r "$caseDir" "$work"
    cd "$work" || exit 1
    set +u  # RunFunctions is not written for set -u
    # shellcheck disable=SC1091
    . "$WM_PROJECT_DIR/bin/tools/RunFunctions"
    restore0Dir > /dev/null
    blockMesh > log.blockMesh 2>&1 || { echo "FAILED: blockMesh"; exit 1; }
}
