#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkDiscreteHits.sh - collision mode discrete in the fiberStream case
# (docs/model.md sec. 3 and 7, eqs. P30-P32; docs/validation.md, discrete hits).
#
# Usage: checkDiscreteHits.sh CASE_DIR WORK_DIR
#   The case with collision { mode discrete; seed 3; } is run 0 -> 0.2 and
#   0 -> 0.1 -> restart -> 0.2 (checkRestart.sh: the state at 0.2, segmentHits
#   included, to 1e-12; the binder table's row at 0.2 too), and on 2 and 3
#   ranks. Checked:
#   - every step the binder balance closes (capturedStep = removedStep to
#     1e-12, checkDepletion.py), serial and on 2 ranks;
#   - the fibers' hit counts are whole numbers and the fibers caught some;
#   - the 2 ranks' state equals the serial one to the bit at 0.05, before the
#     spray reaches the processors' cut (the function object's sums do not
#     depend on the decomposition, docs/model.md sec. 4); at 0.2, and on 3
#     ranks, to 1e-12: OpenFOAM's tracking gives parcels that differ in the
#     last bit once they near a cut, and its air next to one;
#   - binderDistribution.dat has a row per write time, hits per length equal
#     to the state's hits over the fiber length.
#------------------------------------------------------------------------------
set -euo pipefail
caseDir="$1"; work="$2"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

rm -rf "$work"; mkdir -p "$work"
cp -r "$caseDir" "$work/case"
foamDictionary "$work/case/system/controlDict" -entry functions/dropletFiber/collision \
    -add "{ mode discrete; seed 3; }" > /dev/null || die "cannot set collision.mode"
# 1e-12, not 0: OpenFOAM restarts its time from the folder's name (0.1), the continuous
# run has 0.10000000000000007, and its injection places the later parcels by it (last
# bit); the function object's own clock and sums restart exactly (docs/model.md sec. 4)
"$here/checkRestart.sh" "$work/case" "$work/restart" 0.1 0.2 serial 1e-12 \
    maxSegmentLengthError
"$PY" "$here/compareTables.py" --after 0.1 \
    "$work/restart/full/postProcessing/dropletFiber/0/binderDistribution.dat" \
    "$work/restart/split/postProcessing/dropletFiber/0.1/binderDistribution.dat" 1e-10
"$here/runCase.sh" "$work/case" "$work/parallel" parallel
"$here/runCase.sh" "$work/case" "$work/parallel3" parallel3
serial="$work/restart/full"
grep -q "mode discrete" "$serial"/log.* || die "the log does not name collision mode discrete"
"$PY" "$here/checkDepletion.py" "$serial"
"$PY" "$here/checkDepletion.py" "$work/parallel"
"$PY" "$here/checkDepletion.py" "$work/parallel3"
state=0.2/uniform/dropletFiber/dropletFiber
"$PY" "$here/compareFiberUnion.py" "$serial/$state" "$work/parallel" "$state" 1e-12
"$PY" "$here/compareFiberUnion.py" "$serial/$state" "$work/parallel3" "$state" 1e-12
early=0.05/uniform/dropletFiber/dropletFiber
"$PY" "$here/compareFiberUnion.py" "$serial/$early" "$work/parallel" "$early" 0
"$PY" "$here/compareBlockWindows.py" "$serial/$early" "$work/parallel" "$early" 0
"$PY" - "$serial" <<'PYEOF'
import os, re, sys
case = sys.argv[1]
text = open(os.path.join(case, "0.2/uniform/dropletFiber/dropletFiber")).read()
def numbers(key):
    """Every fiber's list `key`, one after another."""
    values = []
    for m in re.finditer(key + r"\s+(\d+)\s*(?:\(([^)]*)\)|\{\s*([^}\s]+)\s*\})", text):
        if m.group(2) is not None:
            values += [float(x) for x in m.group(2).split()]
        else:
            values += [float(m.group(3))] * int(m.group(1))
    if not values:
        raise SystemExit("FAILED: no entry %s in the state" % key)
    return values
hits = numbers("segmentHits")
lengths = numbers("restLengths")
if len(hits) != len(lengths):
    raise SystemExit("FAILED: %d hit counts for %d segments" % (len(hits), len(lengths)))
if any(h != int(h) or h < 0 for h in hits):
    raise SystemExit("FAILED: segmentHits are not whole numbers: %s" % hits)
if sum(hits) == 0:
    raise SystemExit("FAILED: the fiber caught no droplet")
rows = [l.split() for l in open(os.path.join(case, "postProcessing/dropletFiber/0/binderDistribution.dat"))
        if l.strip() and not l.startswith("#")]
times = [float(r[0]) for r in rows]
if times != [0.05, 0.1, 0.15, 0.2]:
    raise SystemExit("FAILED: binderDistribution.dat rows at %s, expected the write times" % times)
per_length = float(rows[-1][6])
expected = sum(hits) / sum(lengths)
if abs(per_length - expected) > 1e-9 * expected:
    raise SystemExit("FAILED: hitsPerLength %g, the state gives %g" % (per_length, expected))
print("discrete hits: %d hits on %d segments, per length %g /m, bareFraction %s" %
      (sum(hits), len(hits), per_length, rows[-1][3]))
PYEOF
echo "discrete hits: balance, whole counts, serial = 2 ranks, restart: passed"
