#!/usr/bin/env bash
# A damaged restart state stops the restart with a FatalIOError that names
# the file and the entry (no SIGFPE, no std::terminate, no run on with it).
# Each damage is made in a copy of a run to 0.1, then restarted; the last one
# on 2 ranks (a 2-rank run to 0.1), with only processor1's state damaged.
# Usage: checkDamagedState.sh CASE_DIR WORK_DIR (fiberStream: writes at 0.1)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/editFile.sh"
work="$2"
prepareCaseCopy "$1" "$work/good"
app="$(foamDictionary -entry application -value system/controlDict)"
sed -i "s/^endTime .*/endTime         0.1;/" system/controlDict
"$app" > "log.$app" 2>&1 || { tail -20 "log.$app"; echo "FAILED: the run to 0.1"; exit 1; }
sed -i "s/^endTime .*/endTime         0.11;/" system/controlDict
state=0.1/uniform/dropletFiber/dropletFiber

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

# setLogDiameter STATE VALUE: the diameter of the first parcel of the oldest step in
# the deposit log STATE.gridWindow (its layout from STATE's gridWindowCounters)
setLogDiameter() {
    "$PY" - "$@" <<'PY'
import re, struct, sys
path, value = sys.argv[1], float(sys.argv[2])
text = open(path).read()
c = [int(float(v)) for v in re.search(r"gridWindowCounters\s+\d+\s*\(([^)]*)\)", text).group(1).split()]
assert c[0] in (3, 4) and c[6] > 0, "no deposit log"
header = 14 if c[0] == 4 else 8
parcels, runs = c[header], c[header + 1]
assert parcels > 0, "no parcel in the oldest step"
index = 2 * runs + 6
data = bytearray(open(path + ".gridWindow", "rb").read())
start = re.match(rb"\s*\d+\s*\(", data).end() + 8 * index
data[start:start + 8] = struct.pack("<d", value)
open(path + ".gridWindow", "wb").write(bytes(data))
print(index)
PY
}

# expectStop NAME FILE PATTERN [parallel]: restart a damaged copy (prepared by
# the commands in $damage, run in it), expect a FatalIOError naming FILE and
# matching PATTERN
expectStop() {
    local name="$1" file="$2" pattern="$3" mode="${4:-serial}"
    rm -rf "${work:?}/$name"; cp -r "$work/${good:-good}" "$work/$name"
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

# The window's state is the deposit log of its steps (the parcels, replayed)
damage="setWindowValue $state.gridWindow 700 nan"
expectStop windowNaN "$state.gridWindow" "value 700 is nan"

damage="setLogDiameter $state -1e-05 > /dev/null"
expectStop logDiameterNegative "$state.gridWindow" "\(step 1 of 5, parcel 1, diameter\) is -1.0000000000000001e-05: allowed are finite values >= 0"

damage="edit $state 'capturedMass +1 \( [^ ]+' 'capturedMass    1 ( -2e-07'"
expectStop capturedNegative "$state.fibers.fiber0" "Entry 'capturedMass': value 0 is -2e-07"

damage="edit $state 'captured +[^;]+;' 'captured -1e-06;'"
expectStop totalCapturedNegative "$state.totals" "Entry 'captured' is -1e-06"

damage="edit $state 'spinner +[0-9]+;' 'spinner -3;'"
expectStop injectorNegative "$state.injectors" "Entry 'spinner' is -3"

damage="edit $state 'velocities +6 \{ 0 \}' 'velocities 5 ( 0 0 0 0 0 )'"
expectStop velocitiesSize "$state.fibers.fiber0" "Entry 'velocities' has 5 values: expected 6"

damage="edit $state 'gridWindowCounters +([0-9]+) \( 3 101' 'gridWindowCounters \\1 ( 3 100'"
expectStop windowGridSize "$state" "saved for a grid of 100x26x1 nodes, this grid has 101x26x1"

damage="edit $state 'gridWindowValueCount +[0-9]+' 'gridWindowValueCount 12'"
expectStop windowValueCount "$state.gridWindow" "entry 'gridWindowValueCount' says 12"

# The window stored as node values (windowState nodeValues; the format earlier versions
# wrote, read as before)
rm -rf "$work/goodValues"; cp -r "$work/good" "$work/goodValues"
(
    cd "$work/goodValues" || exit 1
    rm -rf 0.1
    foamDictionary system/controlDict -entry functions/dropletFiber/windowState -set nodeValues > /dev/null
    sed -i "s/^endTime .*/endTime         0.1;/" system/controlDict
    "$app" > "log.$app" 2>&1 || exit 1
    sed -i "s/^endTime .*/endTime         0.11;/" system/controlDict
    grep -q -E "gridWindowCounters +[0-9]+ *\( *1 " 0.1/uniform/dropletFiber/dropletFiber
) || { echo "FAILED: the run to 0.1 with the window's node values"; exit 1; }
good=goodValues
damage="setWindowValue $state.gridWindow 700 nan"
expectStop valuesNaN "$state.gridWindow" "value 700 \(quantity 0 of 7\) is nan"
damage="setWindowValue $state.gridWindow 701 -1"
expectStop valuesNegativeCount "$state.gridWindow" "value 701 \(quantity 1 of 7\) is -1"
good=good

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
expectStop windowNaN.parallel "processor1/$state.gridWindow" "value 700 is nan" parallel
check "grep -q '^processor 1: Restart state' '$work/windowNaN.parallel/log.restart'" \
    "windowNaN.parallel: the error does not name processor 1"
checkSummary
