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
# - the spread populations' resolution in the log and in the report;
# - the picture was written.
#
# Usage: check.sh WORK_DIR [--update]
#   --update  store this run's table as the new reference (after a deliberate
#             change of results; say why in the commit message)
#------------------------------------------------------------------------------
set -euo pipefail
work="$1"; update="${2:-}"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../cases/lib/tutorialRun.sh"

runTutorialCopy formingHood "$work" -short
log="$work/log.sprayFoam"
grep -q "Balance closed" "$work/log.Allrun" || die "the binder balance did not close"
grep -q "fibers.turbulence: ornsteinUhlenbeck" "$log" || die "the fibers' turbulent air is not on"
grep -q "Selecting dispersion model stochasticDispersionRAS" "$log" || die "the droplets do not disperse"
[ -f "$work/formingHood.png" ] || die "no picture"
# The weighted fibers' spread populations (docs/model.md sec. 12): the log's resolution
# lines at write times, and the report's summary of them
grep -q "spread populations at time 0.15 " "$log" || die "no spread populations' line at 0.15 s"
grep -q "spread populations (t = 0.15 s)" "$work/dropletFiberReport.txt" || die "the report does not say how the populations spread"
table="$work/postProcessing/dropletFiber/0/dropletFiber.dat"
compareWithReference "$table" "$here/reference.parallel.dat" "$update"
"$PY" - "$table" "$log" <<'PYEOF'
import re, sys
lines = [l for l in open(sys.argv[1]) if l.strip()]
names = [h.strip() for h in [l for l in lines if l.startswith("# Time")][-1][1:].split("\t")]
rows = [dict(zip(names, map(float, l.split()))) for l in lines if not l.startswith("#")]
evaporated = [float(x) for x in re.findall(r"Mass transfer phase change\s+=\s+(\S+)", open(sys.argv[2]).read())]
print("water evaporated %.3g kg (must be > 0); captured %.3g kg (must be > 0)"
      % (evaporated[-1], rows[-1]["capturedTotal"]))
sys.exit(0 if evaporated[-1] > 0 and rows[-1]["capturedTotal"] > 0 else 1)
PYEOF
