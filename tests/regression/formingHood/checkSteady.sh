#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The forming hood's steady product (Allrun -steady) on a belt at 1 m/s with
# 200 computed fibers per second and stream: endTime 2 s, the laying steady
# from 0.5 s, a row crosses the 1 m in 1 s, so the rows that entered after 0.5 s
# and left by 2 s are complete. Checked:
# - the log's mat over complete rows at 2 s, with its errors and CoV split,
#   and matProfile_2.dat;
# - one binder content: the product's LOI (the complete rows' resin) and the
#   capture balance's over the steady window agree within two standard errors
#   of their difference (hoodMat.py, called by Allrun);
# - dropletFiberFormingLine -hoods 2 builds the line of two from the state: its
#   area weight twice the hood's (1e-9), its LOI the hood's;
# - the report's picture was written.
#
# Usage: checkSteady.sh WORK_DIR
#------------------------------------------------------------------------------
set -euo pipefail
work="$1"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../cases/lib/tutorialRun.sh"

runTutorialCopy formingHood "$work" -steady -beltSpeed 1 -fiberRate 200
log="$work/log.sprayFoam"
grep -q "^endTime 2$" "$work/log.Allrun" || die "-steady -beltSpeed 1 did not set endTime 2"
grep -q -E "^    mat \(rows [0-9]+ to [0-9]+, .*\): glass area weight \S+ \+- \S+ g/m2, LOI" "$log" \
    || die "no complete rows with errors in the log"
grep -q "mat's across-width CoV: counting noise" "$log" || die "no CoV split in the log"
[ -f "$work/postProcessing/dropletFiber/0/matProfile_2.dat" ] || die "no matProfile_2.dat"
grep -q "the two routes agree" "$work/log.Allrun" \
    || die "the product's LOI and the capture balance's disagree (log.Allrun: hoodMat.py)"
(cd "$work" && dropletFiberFormingLine -hoods 2 > log.formingLine 2>&1) \
    || { tail -20 "$work/log.formingLine"; die "dropletFiberFormingLine failed"; }
"$PY" - "$work/log.formingLine" <<'PYEOF'
import re, sys
text = open(sys.argv[1]).read()
f = {w: (float(g), float(l)) for w, g, l in
     re.findall(r"^    (one hood|the line of 2): glass area weight (\S+) \+- \S+ g/m2, LOI (\S+)", text, re.M)}
hood, line = f.get("one hood"), f.get("the line of 2")
ok = hood and line and abs(line[0] - 2 * hood[0]) <= 1e-9 * hood[0] and abs(line[1] - hood[1]) <= 1e-9
print("forming line of 2: %s g/m2 (hood %s), LOI %s %% (hood %s)" % (line and line[0], hood and hood[0],
                                                                  line and line[1], hood and hood[1]))
sys.exit(0 if ok else 1)
PYEOF
[ -f "$work/dropletFiberReport.png" ] || die "no report picture"
echo "formingHood steady: passed"
