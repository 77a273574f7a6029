# shellcheck shell=bash
# Helpers of the case checks that run the solver themselves (sourced, not run).
# Sourcing sets PY (python3).
#
# prepareCaseCopy CASE_DIR WORK_DIR: load OpenFOAM, copy the case to WORK_DIR
# (replacing it), restore 0/ and make the mesh; leaves the shell in WORK_DIR.

PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

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

# check CONDITION MESSAGE: evaluate a shell condition, count it as passed or
# failed (printing MESSAGE when it fails); checkSummary prints the counts in
# the `N passed, N failed` form and returns non-zero when any failed.
checksPassed=0
checksFailed=0
check() {
    if eval "$1"; then
        checksPassed=$((checksPassed + 1))
    else
        checksFailed=$((checksFailed + 1))
        echo "FAILED: $2"
    fi
}
checkSummary() {
    echo "$checksPassed passed, $checksFailed failed"
    [ "$checksFailed" -eq 0 ]
}

# expectFatalIOError STATUS LOG PATTERN WHAT: the run of WHAT (its exit STATUS, its
# LOG) stopped with a FatalIOError saying PATTERN (an extended regular expression),
# counted as a check; prints the error's line, or the log's error when it failed
expectFatalIOError() {
    local status="$1" log="$2" pattern="$3" what="$4"
    if [ "$status" -ne 0 ] && grep -q "FOAM FATAL IO ERROR" "$log" \
        && grep -q -E -- "$pattern" "$log"; then
        checksPassed=$((checksPassed + 1))
        echo "ok: $what -> $(grep -A1 'FOAM FATAL IO ERROR' "$log" | tail -1)"
    else
        checksFailed=$((checksFailed + 1))
        echo "FAILED: $what (exit $status); log:"
        grep -A4 "FOAM FATAL" "$log" || tail -5 "$log"
    fi
}
