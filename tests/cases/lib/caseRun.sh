# shellcheck shell=bash
# What every case test asks of a finished run (sourced; needs bin/functions.sh's die).
#
# checkRanClean RUN: no log of RUN shows a fatal error or a crash (RunFunctions do not
#   stop on a failed application), and the dropletFiberCollision function object ran
#   (OpenFOAM v1912 runs on, exit 0, without a function object it cannot load); the
#   logs' tails are printed where one failed.

caseRunTools="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../../bin" && pwd)"

showLogs() {
    for log in "$1"/log.*; do
        [ -f "$log" ] || continue
        echo "==== tail of $log"
        tail -25 "$log"
    done
}

checkRanClean() {
    local log
    for log in "$1"/log.*; do
        if grep -q -E "FOAM FATAL|FOAM exiting|Segmentation fault" "$log"; then
            showLogs "$1"
            die "$log shows a fatal error"
        fi
    done
    "$caseRunTools/checkFunctionObjectRan" "$1" \
        || die "the run of $1 went on without the function object"
}
