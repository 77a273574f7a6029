#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The turbulent-air tutorial runs: tutorials/channelSprayRAS, Allrun -short, in a
# scratch copy. Checked: the function object ran; the log says the fibers'
# turbulent air is on by default with the k-epsilon model and the droplets
# disperse with stochasticDispersionRAS; the report's checks (mass balances)
# passes; fiberDispersion.dat has a row per step with a turbulent velocity at the
# fiber points of the order of the inlet's sqrt(2k/3) = 0.1 m/s (0.05-0.2 m/s:
# k decays along the channel and grows at the walls); the plot is written.
#
# Usage: check.sh WORK_DIR
#------------------------------------------------------------------------------
set -euo pipefail
work="$1"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../cases/lib/tutorialRun.sh"

runTutorialCopy channelSprayRAS "$work" -short
log="$work/log.pimpleFoam"
grep -q "fibers.turbulence: ornsteinUhlenbeck (default with the case's turbulence model 'RAS')" "$log" \
    || die "the log does not say the fibers' turbulent air is on by default"
grep -q "Selecting dispersion model stochasticDispersionRAS" "$log" || die "the droplets do not disperse"
[ -f "$work/channelSprayRAS.png" ] || die "no plot"
"$PY" - "$work/postProcessing/dropletFiber/0/fiberDispersion.dat" <<'PYEOF'
import math, sys
lines = open(sys.argv[1]).read().splitlines()
names = [l for l in lines if l.startswith("# Time")][0][1:].split()
rows = [dict(zip(names, map(float, l.split()))) for l in lines if l.strip() and not l.startswith("#")]
u = [math.sqrt(sum(r[c] ** 2 for c in ("uTurbRmsX", "uTurbRmsY", "uTurbRmsZ")) / 3) for r in rows]
mean = sum(u) / len(u)
print("%d rows, rms u' at the fiber points %.3f m/s on average (must be 0.05-0.2)" % (len(rows), mean))
sys.exit(0 if len(rows) == 80 and 0.05 < mean < 0.2 else 1)
PYEOF
