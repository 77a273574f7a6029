# shellcheck shell=bash
# Helpers of the restart checks (sourced; sources prepareCase.sh): a run of the
# case copy to a time, copies of it changed and restarted, and what their logs
# must say.
#
# runTo END [parallel]: run the case in the current directory to END (on 2 ranks:
#   decomposed first); endTime is left at END
# restartCopy NAME SETUP END [parallel]: copy $work/${good:-good} to $work/NAME, run
#   the shell commands SETUP in it, restart it to END (log.restart); exit status
#   in $status
# expectStop NAME PATTERN...: the restart NAME stopped with a FatalIOError saying
#   every PATTERN (extended regular expressions), without crash and without a step
# expectRuns NAME PATTERN...: the restart NAME ran to its end, its log saying
#   every PATTERN

# shellcheck disable=SC1091
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/prepareCase.sh"

setEndTime() { sed -i "s/^endTime .*/endTime         $1;/" system/controlDict; }

runTo() {
    local end="$1" mode="${2:-serial}" app
    app="$(foamDictionary -entry application -value system/controlDict)"
    setEndTime "$end"
    if [ "$mode" = parallel ]; then
        [ -d processor0 ] || decomposePar -time 0 > log.decomposePar 2>&1 \
            || { echo "FAILED: decomposePar"; exit 1; }
        mpirun -np 2 "$app" -parallel > "log.$app" 2>&1
    else
        "$app" > "log.$app" 2>&1
    fi || { tail -20 "log.$app"; echo "FAILED: the run to $end"; exit 1; }
}

restartCopy() {
    local name="$1" setup="$2" end="$3" mode="${4:-serial}" app
    rm -rf "${work:?}/$name"; cp -r "$work/${good:-good}" "$work/$name"
    (
        cd "$work/$name" || exit 1
        eval "$setup"
        setEndTime "$end"
        app="$(foamDictionary -entry application -value system/controlDict)"
        if [ "$mode" = parallel ]; then
            timeout 120 mpirun -np 2 "$app" -parallel > log.restart 2>&1
        else
            timeout 120 "$app" > log.restart 2>&1
        fi
    )
    status=$?
}

expectStop() {
    local name="$1" log="$work/$1/log.restart" pattern
    shift
    check "[ $status -ne 0 ] && [ $status -ne 124 ]" "$name: exit $status (0: ran on, 124: hung)"
    check "grep -q 'FOAM FATAL IO ERROR' '$log'" "$name: no FatalIOError"
    for pattern in "$@"; do
        check 'grep -q -E -- "$pattern" "$log"' "$name: the log does not say: $pattern"
    done
    check "! grep -q -E 'printStack|terminate called|Segmentation fault|core dumped' '$log'" \
        "$name: crashed"
    echo "$name: $(grep -m1 -E -- "$1" "$log")"
}

expectRuns() {
    local name="$1" log="$work/$1/log.restart" pattern
    shift
    check "[ $status -eq 0 ] && tail -n 3 '$log' | grep -q '^End'" "$name: exit $status, did not end"
    for pattern in "$@"; do
        check 'grep -q -E -- "$pattern" "$log"' "$name: the log does not say: $pattern"
    done
    [ "$#" -gt 0 ] && echo "$name: $(grep -m1 -E -- "$1" "$log")"
    return 0
}
