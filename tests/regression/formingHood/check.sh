#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Regression run of the forming-hood tutorial: the shortened run (Allrun -short,
# 150 time steps on 2 processors: the fibers meet the spray from 0.1 s) in a
# scratch copy. Checked:
# - the function object ran, the fibers' turbulent air was on (the tutorial asks
#   for ornsteinUhlenbeck with the case's k-epsilon), depletion was on;
# - the tutorial's own balance (hoodBalance.py, called by Allrun) closed to 1e-9
#   of the binder sprayed, and the water evaporated (phase change > 0);
# - the per-step table equals the stored reference to 1e-6 of each column's
#   scale: the run is deterministic on a fixed decomposition (same seeds, same
#   order of operations), so a larger difference is a change of behaviour, while
#   round-off from another compiler or library stays far below it;
#   maxSegmentLengthError is round-off by nature and is checked to stay < 1e-10;
# - the picture was written.
#
# Usage: check.sh WORK_DIR [--update]
#   --update  store this run's table as the new reference (after a deliberate
#             change of results; say why in the commit message)
#------------------------------------------------------------------------------
set -euo pipefail
work="$1"; update="${2:-}"
here="$(cd "${0%/*}" && pwd)"
root="$(cd "$here/../../.." && pwd)"
. "$root/bin/functions.sh"
loadFoamEnvironment
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

rm -rf "$work"; mkdir -p "$(dirname "$work")"
cp -r "$root/tutorials/formingHood" "$work"
(cd "$work" && ./Allclean > /dev/null)
if ! (cd "$work" && DROPLETFIBER_DIR="$root" ./Allrun -short > log.Allrun 2>&1); then
    tail -n 30 "$work"/log.* ; die "Allrun -short failed"
fi
cat "$work/log.Allrun"
"$root/bin/checkFunctionObjectRan" "$work" || die "the run of $work went on without the function object"
log="$work/log.sprayFoam"
grep -q "Balance closed" "$work/log.Allrun" || die "the binder balance did not close"
grep -q "fibers.turbulence: ornsteinUhlenbeck" "$log" || die "the fibers' turbulent air is not on"
grep -q "Selecting dispersion model stochasticDispersionRAS" "$log" || die "the droplets do not disperse"
[ -f "$work/formingHood.png" ] || die "no picture"
table="$work/postProcessing/dropletFiber/0/dropletFiber.dat"
reference="$here/reference.parallel.dat"
if [ "$update" = --update ]; then
    cp "$table" "$reference"
    info "stored $reference"
    exit 0
fi
"$PY" "$root/tests/cases/compareTables.py" --skip maxSegmentLengthError "$reference" "$table" 1e-6
"$PY" - "$table" "$log" <<'PYEOF'
import re, sys
lines = [l for l in open(sys.argv[1]) if l.strip()]
names = [h.strip() for h in [l for l in lines if l.startswith("# Time")][-1][1:].split("\t")]
rows = [dict(zip(names, map(float, l.split()))) for l in lines if not l.startswith("#")]
worst = max(r["maxSegmentLengthError"] for r in rows)
evaporated = [float(x) for x in re.findall(r"Mass transfer phase change\s+=\s+(\S+)", open(sys.argv[2]).read())]
print("largest segment-length error %.3g (must stay < 1e-10); water evaporated %.3g kg (must be > 0);"
      " captured %.3g kg (must be > 0)" % (worst, evaporated[-1], rows[-1]["capturedTotal"]))
sys.exit(0 if worst < 1e-10 and evaporated[-1] > 0 and rows[-1]["capturedTotal"] > 0 else 1)
PYEOF
