#!/usr/bin/env bash
# A damaged restart state stops the restart with a FatalIOError that names
# the file and the entry (no SIGFPE, no std::terminate, no run on with it).
# Each damage is made in a copy of a run to 0.1, then restarted; the last one
# on 2 ranks (a 2-rank run to 0.1), with only processor1's state damaged.
# Usage: checkDamagedState.sh CASE_DIR WORK_DIR (fiberStream: writes at 0.1)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
work="$2"
prepareCaseCopy "$1" "$work/good"
app="$(foamDictionary -entry application -value system/controlDict)"
sed -i "s/^endTime .*/endTime         0.1;/" system/controlDict
"$app" > "log.$app" 2>&1 || { tail -20 "log.$app"; echo "FAILED: the run to 0.1"; exit 1; }
sed -i "s/^endTime .*/endTime         0.11;/" system/controlDict
state=0.1/uniform/dropletFiber/dropletFiber

# edit FILE PATTERN REPLACEMENT: replace the first match of a Python regex
edit() {
    "$PY" - "$@" <<'PY'
import re, sys
path, pattern, replacement = sys.argv[1:4]
text = open(path).read()
new = re.sub(pattern, replacement, text, count=1, flags=re.S)
assert new != text, "no match for " + pattern
open(path, "w").write(new)
PY
}

# setWindowValue FILE INDEX VALUE: one value of the binary averaging window
setWindowValue() {
    "$PY" - "$@" <<'PY'
import re, struct, sys
path, index, value = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
data = bytearray(open(path, "rb").read())
start = re.match(rb"\s*\d+\s*\(", data).end() + 8 * index
data[start:start + 8] = struct.pack("<d", value)
open(path, "wb").write(bytes(data))
PY
}

# expectStop NAME FILE PATTERN [parallel]: restart a damaged copy (prepared by
# the commands in $damage, run in it), expect a FatalIOError naming FILE and
# matching PATTERN
expectStop() {
    local name="$1" file="$2" pattern="$3" mode="${4:-serial}"
    rm -rf "${work:?}/$name"; cp -r "$work/good" "$work/$name"
    (
        cd "$work/$name" || exit 1
        eval "$damage"
        if [ "$mode" = parallel ]; then
            timeout 120 mpirun -np 2 "$app" -parallel > log.restart 2>&1
        else
            timeout 120 "$app" > log.restart 2>&1
        fi
    )
    local status=$? log="$work/$name/log.restart"
    check "[ $status -ne 0 ] && [ $status -ne 124 ]" "$name: exit $status (0: ran on, 124: hung)"
    check "grep -q 'FOAM FATAL IO ERROR' '$log'" "$name: no FatalIOError"
    check "grep -q -F '$file' '$log'" "$name: the error does not name $file"
    check "grep -q -E \"$pattern\" '$log'" "$name: the error does not say: $pattern"
    check "! grep -q -E 'printStack|terminate called|Segmentation fault|core dumped' '$log'" \
        "$name: crashed"
    check "! grep -q -E '^Time = 0.10[1-9]' '$log'" "$name: ran on"
    echo "$name: $(grep -m1 -E "$pattern" "$log")"
}

damage="setWindowValue $state.gridWindow 700 nan"
expectStop windowNaN "$state.gridWindow" "value 700 \(quantity 0 of 7\) is nan"

damage="edit $state 'capturedMass +1 \( [^ ]+' 'capturedMass    1 ( -2e-07'"
expectStop capturedNegative "$state.fibers.fiber0" "Entry 'capturedMass': value 0 is -2e-07"

damage="edit $state 'captured +[^;]+;' 'captured -1e-06;'"
expectStop totalCapturedNegative "$state.totals" "Entry 'captured' is -1e-06"

damage="edit $state 'spinner +[0-9]+;' 'spinner -3;'"
expectStop injectorNegative "$state.injectors" "Entry 'spinner' is -3"

damage="edit $state 'velocities +6 \{ 0 \}' 'velocities 5 ( 0 0 0 0 0 )'"
expectStop velocitiesSize "$state.fibers.fiber0" "Entry 'velocities' has 5 values: expected 6"

damage="edit $state 'gridWindowCounters +38 \( 1 101' 'gridWindowCounters 38 ( 1 100'"
expectStop windowGridSize "$state" "saved for a grid of 100x26x1 nodes, this grid has 101x26x1"

damage="edit $state 'gridWindowValueCount +[0-9]+' 'gridWindowValueCount 12'"
expectStop windowValueCount "$state.gridWindow" "entry 'gridWindowValueCount' says 12"

# 2 ranks: only processor1's window damaged; every rank stops, naming it. The state
# is a 2-rank run's (each processor keeps the window of its own block of the grid)
rm -rf "$work/good/processor"*
(
    cd "$work/good" || exit 1
    decomposePar -time 0 > log.decomposePar 2>&1 || exit 1
    sed -i "s/^endTime .*/endTime         0.1;/" system/controlDict
    mpirun -np 2 "$app" -parallel > log.parallel 2>&1 || exit 1
    sed -i "s/^endTime .*/endTime         0.11;/" system/controlDict
) || { echo "FAILED: the 2-rank run to 0.1"; exit 1; }
damage="setWindowValue processor1/$state.gridWindow 700 nan"
expectStop windowNaN.parallel "processor1/$state.gridWindow" "value 700 \(quantity 0 of 7\) is nan" parallel
check "grep -q '^processor 1: Restart state' '$work/windowNaN.parallel/log.restart'" \
    "windowNaN.parallel: the error does not name processor 1"
checkSummary
