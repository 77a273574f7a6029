#!/usr/bin/env bash
# The averaging window right after a restart, to the bit: restored from the parcels of
# its steps (deposited again, DepositLog) and restored from its node values. A run to
# T_HALF writes its state with the parcels (windowState parcels) and the node values beside
# (writeWindowValues); a copy of it gets the node values as its state (the layout earlier
# versions wrote). Both restart for one step, writing then: the node values written must
# be identical (cmp). A dropped parcel, or the parcels
# replayed in another order, make them differ (checked by a build that did either).
# Usage: checkWindowReplay.sh CASE_DIR WORK_DIR T_HALF (fiberStream: dt 0.002, W = 5)
set -uo pipefail
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
work="$2"; half="$3"
state=uniform/dropletFiber/dropletFiber
prepareCaseCopy "$1" "$work/parcels"
app="$(foamDictionary -entry application -value system/controlDict)"
foamDictionary system/controlDict -entry functions/dropletFiber/windowState -set parcels > /dev/null
foamDictionary system/controlDict -entry functions/dropletFiber/writeWindowValues -set yes > /dev/null
sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
"$app" > "log.$app" 2>&1 || { tail -20 "log.$app"; echo "FAILED: the run to $half"; exit 1; }
grep -q -E "gridWindowCounters +[0-9]+ *\( *3 " "$half/$state" || { echo "FAILED: no deposit log at $half"; exit 1; }
dt="$(foamDictionary -entry deltaT -value system/controlDict)"
next="$("$PY" -c "print(round($half + $dt, 12))")"
sed -i "s/^endTime .*/endTime         $next;/" system/controlDict
foamDictionary system/controlDict -entry writeInterval -set 1 > /dev/null

# The copy whose state holds the node values instead
rm -rf "${work:?}/values"; cp -r "$work/parcels" "$work/values"
"$PY" - "$work/values/$half/$state" <<'PY'
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
for copy in parcels values; do
    (cd "$work/$copy" && "$app" > log.restart 2>&1) || { tail -20 "$work/$copy/log.restart"; echo "FAILED: the restart of $copy"; exit 1; }
    check "grep -q 'restarted from' '$work/$copy/log.restart'" "$copy: the state was not read"
    check "[ -f '$work/$copy/$next/$state.gridWindowValues' ]" "$copy: no window written at $next"
done
check "grep -q -E 'gridWindowCounters +[0-9]+ *\\( *1 ' '$work/values/$half/$state'" "values: the state at $half is not node values"
check "cmp '$work/parcels/$next/$state.gridWindowValues' '$work/values/$next/$state.gridWindowValues'" \
    "the window after the restart from the parcels differs from the one from the node values"
"$PY" "$here/compareWindow.py" "$work/parcels/$next/$state.gridWindowValues" "$work/values/$next/$state.gridWindowValues" 0
checkSummary
