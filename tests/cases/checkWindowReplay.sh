#!/usr/bin/env bash
# The averaging window right after a restart, to the bit: restored from the parcels of
# its steps (deposited again, DepositLog) and restored from its node values. A run to
# T_HALF writes its state with the parcels (windowState parcels) and the node values beside
# (writeWindowValues); a copy of it gets the node values as its state (the layout earlier
# versions wrote). Both restart for one step, writing then: the node values written must
# be identical (cmp). A dropped parcel, or the parcels
# replayed in another order, make them differ (checked by a build that did either).
# MODE parallel: the same on 2 ranks (each processor's block, its own parcels and the
# copies it got); decomposed: a serial run's state decomposed onto 2 ranks (each processor
# replays the serial run's parcels that reach its block, or cuts its part out of the node
# values).
# Usage: checkWindowReplay.sh CASE_DIR WORK_DIR T_HALF [serial|parallel|decomposed]
#   (fiberStream: dt 0.002, W = 5)
set -uo pipefail
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
work="$2"; half="$3"; mode="${4:-serial}"
state=uniform/dropletFiber/dropletFiber
run=(); dirs=(.)
if [ "$mode" != serial ]; then
    run=(mpirun -np 2); dirs=(processor0 processor1)
fi
prepareCaseCopy "$1" "$work/parcels"
app="$(foamDictionary -entry application -value system/controlDict)"
foamDictionary system/controlDict -entry functions/dropletFiber/windowState -set parcels > /dev/null
foamDictionary system/controlDict -entry functions/dropletFiber/writeWindowValues -set yes > /dev/null
sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
if [ "$mode" = parallel ]; then
    decomposePar -time 0 > log.decomposePar 2>&1 || { echo "FAILED: decomposePar"; exit 1; }
    "${run[@]}" "$app" -parallel > "log.$app" 2>&1 || { tail -20 "log.$app"; echo "FAILED: the run to $half"; exit 1; }
else
    "$app" > "log.$app" 2>&1 || { tail -20 "log.$app"; echo "FAILED: the run to $half"; exit 1; }
fi
saved=(.); [ "$mode" = parallel ] && saved=(processor0 processor1)
for dir in "${saved[@]}"; do
    grep -q -E "gridWindowCounters +[0-9]+ *\( *[34] " "$dir/$half/$state" \
        || { echo "FAILED: no deposit log at $dir/$half"; exit 1; }
done
dt="$(foamDictionary -entry deltaT -value system/controlDict)"
next="$("$PY" -c "print(round($half + $dt, 12))")"
sed -i "s/^endTime .*/endTime         $next;/" system/controlDict
foamDictionary system/controlDict -entry writeInterval -set 1 > /dev/null

# The copy whose state holds the node values instead
rm -rf "${work:?}/values"; cp -r "$work/parcels" "$work/values"
for dir in "${saved[@]}"; do
"$PY" - "$work/values/$dir/$half/$state" <<'PY'
import re, sys
path = sys.argv[1]
text = open(path).read()
values = re.search(r"^gridWindowValuesCounters\s+(\d+\s*\([^)]*\))", text, re.M).group(1)
text = re.sub(r"^gridWindowCounters\s+\d+\s*\([^)]*\)", "gridWindowCounters " + values, text, count=1, flags=re.M)
data = open(path + ".gridWindowValues", "rb").read()
count = int(re.match(rb"\s*(\d+)", data).group(1))
text = re.sub(r"^gridWindowValueCount\s+\d+;", "gridWindowValueCount %d;" % count, text, count=1, flags=re.M)
open(path, "w").write(text)
open(path + ".gridWindow", "wb").write(data)
PY
done
for copy in parcels values; do
    (
        cd "$work/$copy" || exit 1
        if [ "$mode" = decomposed ]; then
            rm -rf processor*
            decomposePar -time "$half" > log.decomposePar 2>&1 || exit 1
        fi
        if [ "$mode" = serial ]; then
            "$app" > log.restart 2>&1
        else
            "${run[@]}" "$app" -parallel > log.restart 2>&1
        fi
    ) || { tail -20 "$work/$copy/log.restart"; echo "FAILED: the restart of $copy"; exit 1; }
    check "grep -q 'restarted from' '$work/$copy/log.restart'" "$copy: the state was not read"
done
check "grep -q -E 'gridWindowCounters +[0-9]+ *\\( *[12] ' '$work/values/${saved[0]}/$half/$state'" \
    "values: the state at $half is not node values"
# sameSlots A B: the windows' slots equal node by node, to the bit (a node outside a
# slot's box is 0 there: a block replaying a serial run's parcels may store a slot over a
# smaller box than the one cut out of the serial slot)
sameSlots() {
    "$PY" - "$1" "$2" <<'PY'
import os, re, sys
sys.path.insert(0, os.environ["HERE"])
from compareWindow import counters_of, read
def slots(path):
    c, v = counters_of(path), read(path)
    header = 14 if c[0] == 2 else 8
    nodes, position = {}, 0
    for s in range(c[6]):
        lo, hi = c[header + 6 * s:header + 6 * s + 3], c[header + 6 * s + 3:header + 6 * s + 6]
        for k in range(lo[2], hi[2] + 1):
            for j in range(lo[1], hi[1] + 1):
                for i in range(lo[0], hi[0] + 1):
                    values = tuple(v[position:position + 7])
                    if any(values):
                        nodes[(s, i, j, k)] = values
                    position += 7
    return c[6], c[7], nodes
a, b = slots(sys.argv[1]), slots(sys.argv[2])
print("window slots: %d steps, %d committed, %d non-zero nodes; %s" % (a[0], a[1], len(a[2]), "equal" if a == b else "DIFFER"))
sys.exit(0 if a == b else 1)
PY
}
export HERE="$here"
for dir in "${dirs[@]}"; do
    a="$work/parcels/$dir/$next/$state.gridWindowValues"; b="$work/values/$dir/$next/$state.gridWindowValues"
    check "[ -f '$a' ] && [ -f '$b' ]" "$dir: no window written at $next"
    check "sameSlots '$a' '$b'" "$dir: the window after the restart from the parcels differs from the one from the node values"
    if [ "$mode" != decomposed ]; then
        check "cmp '$a' '$b'" "$dir: the window's values as written differ"
    fi
done
checkSummary
