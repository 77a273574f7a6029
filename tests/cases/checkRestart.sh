#!/usr/bin/env bash
# Restart: run 0 -> T equals run 0 -> T/2, then restart from T/2 -> T.
# Usage: checkRestart.sh CASE_DIR WORK_DIR T_HALF T [parallel|serial [TOL [SKIP]]]
# Compares the restart state written at T (fibers, injector counters, totals,
# averaging window) to TOL relative (default 1e-10), and the per-step table rows
# after T/2 (maxSegmentLengthError apart, below; SKIP: more table columns left
# out, compareTables.py --skip); parallel: both runs on 2 ranks (RESTART_RANKS, as the
# case's decomposeParDict says), each processor's state compared.
set -euo pipefail
caseDir="$1"; work="$2"; half="$3"; end="$4"; mode="${5:-serial}"; tol="${6:-1e-10}"
skip="maxSegmentLengthError${7:+,$7}"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

rm -rf "$work"; mkdir -p "$work"
cp -r "$caseDir" "$work/full"
cp -r "$caseDir" "$work/split"
allrunArgs=(); mpi=()
if [ "$mode" = parallel ]; then
    allrunArgs=(-parallel); mpi=(mpirun -np "${RESTART_RANKS:-2}")
fi
(cd "$work/full" && ./Allrun "${allrunArgs[@]}" > /dev/null)
(
    cd "$work/split"
    sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
    ./Allrun "${allrunArgs[@]}" > /dev/null
    sed -i "s/^endTime .*/endTime         $end;/" system/controlDict
    app="$(foamDictionary -entry application -value system/controlDict)"
    if [ "$mode" = parallel ]; then
        "${mpi[@]}" "$app" -parallel > log.restart 2>&1
    else
        "$app" > log.restart 2>&1
    fi
)
app="$(foamDictionary -entry application -value "$caseDir/system/controlDict")"
for log in "$work/full/log.$app" "$work/split/log.$app" "$work/split/log.restart"; do
    tail -n 3 "$log" | grep -q "^End" || { tail -n 30 "$log"; die "$log did not end"; }
    "$here/../../bin/checkFunctionObjectRan" "$log" || die "$log: run without the function object"
done
grep -q "restarted from" "$work/split/log.restart" || die "the restarted run did not read the restart state"
state=uniform/dropletFiber/dropletFiber
dirs=(.)
[ "$mode" = parallel ] && mapfile -t dirs < <(seq -f "processor%g" 0 $(( ${RESTART_RANKS:-2} - 1 )))
for dir in "${dirs[@]}"; do
    "$PY" "$here/compareState.py" "$work/full/$dir/$end/$state" "$work/split/$dir/$end/$state" "$tol"
    # the averaging window (binary list), value by value. Not bit for bit: OpenFOAM's own
    # time value after a restart differs from the continuous run's in the last bits
    # (0.20000000000000009 against ...15 here), and with it the parcels at round-off
    "$PY" "$here/compareWindow.py" "$work/full/$dir/$end/$state.gridWindow" \
        "$work/split/$dir/$end/$state.gridWindow" "$tol"
    # ...and its node values (the state holds the parcels deposited, written with
    # writeWindowValues)
    if [ -f "$work/full/$dir/$end/$state.gridWindowValues" ]; then
        "$PY" "$here/compareWindow.py" "$work/full/$dir/$end/$state.gridWindowValues" \
            "$work/split/$dir/$end/$state.gridWindowValues" "$tol"
    fi
done
# maxSegmentLengthError is round-off by nature (~1e-14: the largest deviation of a
# segment's length): the continued run's may differ from the first's in its last digits
# (the parcels' positions read back move the capture by round-off); it must stay < 1e-10
"$PY" "$here/compareTables.py" --after "$half" --skip "$skip" \
    "$work/full/postProcessing/dropletFiber/0/dropletFiber.dat" \
    "$work/split/postProcessing/dropletFiber/$half/dropletFiber.dat" "$tol"
"$PY" "$here/checkSegmentLengthError.py" \
    "$work/split/postProcessing/dropletFiber/$half/dropletFiber.dat" "continued run"
