#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkDiscreteHits.sh - collision mode discrete in the fixedFiber case
# (docs/model.md sec. 3 and 7, eqs. P30-P32; docs/validation.md, discrete hits).
#
# Usage: checkDiscreteHits.sh CASE_DIR WORK_DIR
#   The case with collision { mode discrete; seed 3; } is run serial 0 -> 0.2
#   and 0 -> 0.1 -> restart -> 0.2 (checkRestart.sh: the state at 0.2 to 1e-12,
#   its segmentHits included), and on 2 ranks. Checked:
#   - every step the binder balance closes (capturedStep = removedStep to
#     1e-12, checkDepletion.py), serial and on 2 ranks;
#   - the fibers' hit counts are whole numbers and the fibers caught some;
#   - the 2 ranks' fibers equal the serial ones (hits included) to 1e-12;
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
"$here/checkRestart.sh" "$work/case" "$work/restart" 0.1 0.2 serial 1e-12
"$here/runCase.sh" "$work/case" "$work/parallel" parallel
serial="$work/restart/full"
grep -q "mode discrete" "$serial/log.pimpleFoam" || die "the log does not name collision mode discrete"
"$PY" "$here/checkDepletion.py" "$serial"
"$PY" "$here/checkDepletion.py" "$work/parallel"
state=0.2/uniform/dropletFiber/dropletFiber
"$PY" "$here/compareFiberUnion.py" "$serial/$state" "$work/parallel" "$state" 1e-12
"$PY" - "$serial" <<'PYEOF'
import os, re, sys
case = sys.argv[1]
text = open(os.path.join(case, "0.2/uniform/dropletFiber/dropletFiber")).read()
def numbers(key):
    m = re.search(key + r"\s+(?:List<scalar>\s+)?\d+\s*\(([^)]*)\)", text)
    if not m:
        m = re.search(key + r"\s+(\d+)\s*\{\s*([^}\s]+)\s*\}", text)
        if not m:
            raise SystemExit("FAILED: no entry %s in the state" % key)
        return [float(m.group(2))] * int(m.group(1))
    return [float(x) for x in m.group(1).split()]
hits = numbers("segmentHits")
lengths = numbers("restLengths")
if any(h != int(h) or h < 0 for h in hits):
    raise SystemExit("FAILED: segmentHits are not whole numbers: %s" % hits)
if sum(hits) == 0:
    raise SystemExit("FAILED: the fiber caught no droplet")
rows = [l.split() for l in open(os.path.join(case, "postProcessing/dropletFiber/0/binderDistribution.dat"))
        if l.strip() and not l.startswith("#")]
times = [float(r[0]) for r in rows]
if times != [0.1, 0.2]:
    raise SystemExit("FAILED: binderDistribution.dat rows at %s, expected 0.1 and 0.2" % times)
per_length = float(rows[-1][6])
expected = sum(hits) / sum(lengths)
if abs(per_length - expected) > 1e-9 * expected:
    raise SystemExit("FAILED: hitsPerLength %g, the state gives %g" % (per_length, expected))
print("discrete hits: %d hits on %d segments, per length %g /m, bareFraction %s" %
      (sum(hits), len(hits), per_length, rows[-1][3]))
PYEOF
echo "discrete hits: balance, whole counts, serial = 2 ranks, restart: passed"
