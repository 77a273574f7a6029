#!/usr/bin/env python3
"""The fibers' turbulent air (docs/model.md sec. 8) in a case run.

Usage:
  checkTurbulentFibers.py case K CASE_DIR
      the log says the model is on and why; the fiber VTK files hold
      turbulentVelocity; fiberDispersion.dat: the rms of u' per component,
      squared and averaged over the rows after the first T_L, equals 2K/3
      within 10 % (hundreds of fiber points over some 30 time scales: the
      statistical error is a few per cent), and the spread of the fiber
      centres is positive across the stream.
  checkTurbulentFibers.py same STATE STATE_OR_DIR...
      u' of every fiber in STATE equals, character for character (the
      state's full precision: to the bit), u' of the same fiber in the
      other states (the union of a parallel run's processor states).
Exit 1 on a failure.
"""
import glob
import math
import os
import re
import sys

FIBER = re.compile(r"^\s*(fiber\d+)\s*$")
TURBULENT = re.compile(r"^\s*turbulentVelocity\s+(.*);\s*$")


def turbulent_velocities(path):
    """{fiber name: text of its turbulentVelocity list}."""
    found, fiber = {}, None
    for line in open(path):
        m = FIBER.match(line)
        if m:
            fiber = m.group(1)
            continue
        m = TURBULENT.match(line)
        if m and fiber:
            found[fiber] = m.group(1).strip()
    return found


def check_same(reference, others):
    a = turbulent_velocities(reference)
    b = {}
    for path in others:
        b.update(turbulent_velocities(path))
    failures = []
    if not a:
        failures.append("%s holds no turbulentVelocity" % reference)
    if sorted(a) != sorted(b):
        failures.append("different fibers: %s" % sorted(set(a) ^ set(b)))
    failures += ["%s: u' differs" % f for f in sorted(a) if f in b and a[f] != b[f]]
    print("%d fibers' u' compared" % len(a))
    return failures


def table(path):
    rows = [l.split() for l in open(path) if not l.startswith("#")]
    header = [l for l in open(path) if l.startswith("# Time")][0].split()[1:]
    return header, [[float(v) for v in r] for r in rows]


def check_case(case, k):
    failures = []
    log = glob.glob(os.path.join(case, "log.*Foam"))[0]
    text = open(log).read()
    if not re.search(r"fibers\.turbulence: ornsteinUhlenbeck \(default with the case's "
                     r"turbulence model 'RAS'\)", text):
        failures.append("%s: no log line saying the turbulent air is on by default" % log)
    out = os.path.join(case, "postProcessing/dropletFiber/0")
    # serial: fibers_<time>.vtp; parallel: the .pvtp and its pieces
    vtps = glob.glob(os.path.join(out, "fibers_*.vtp")) + glob.glob(os.path.join(out, "fibers_*.pvtp")) \
        + glob.glob(os.path.join(out, "fibers_*/processor*.vtp"))
    if not vtps or not all('Name="turbulentVelocity"' in open(p).read() for p in vtps):
        failures.append("fiber VTK files without turbulentVelocity")
    header, rows = table(os.path.join(case, "postProcessing/dropletFiber/0/fiberDispersion.dat"))
    col = {name: i for i, name in enumerate(header)}
    kept = [r for r in rows if r[col["Time"]] > 0.05]
    for name in ("uTurbRmsX", "uTurbRmsY", "uTurbRmsZ"):
        variance = sum(r[col[name]] ** 2 for r in kept) / len(kept)
        print("%s: mean square %.4g, 2k/3 = %.4g" % (name, variance, 2 * k / 3))
        if abs(variance / (2 * k / 3) - 1) > 0.10:
            failures.append("%s: mean square %.4g is not 2k/3 = %.4g within 10 %%"
                            % (name, variance, 2 * k / 3))
    spread = rows[-1][col["spreadY"]]
    print("spread of the fiber centres across the stream at the end: %.3g m" % spread)
    if not spread > 0:
        failures.append("no spread of the fiber centres")
    return failures


def main():
    if len(sys.argv) >= 4 and sys.argv[1] == "case":
        failures = check_case(sys.argv[3], float(sys.argv[2]))
    elif len(sys.argv) >= 4 and sys.argv[1] == "same":
        others = []
        for p in sys.argv[3:]:
            others += sorted(glob.glob(p)) if any(c in p for c in "*?[") else [p]
        failures = check_same(sys.argv[2], others)
    else:
        print(__doc__)
        return 2
    for f in failures:
        print("FAILED:", f)
    print("%s" % ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
