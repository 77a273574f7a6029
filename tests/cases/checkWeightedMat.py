"""Weighted against unweighted random mats through the function object (case denseMat
with makeMat.py --represents; docs/model.md sec. 9, P40; docs/validation.md, weighted
fibers).

Usage: checkWeightedMat.py --spacing H --dropletDiameter D [--tolerance TOL] CASE...

The cases come in pairs of the same S, each mat drawn from the same distribution: M N
fibers of weight 1 and M of weight N (uniform in the slab, independently). For each
case its S is derived here from the fibers written (fiberMats.depth: each fiber N times)
and its penetration is measured as checkDenseMat.py does (outlet and capture over the
last 10 ms); checked:
- each within TOL of exp(-S) (P15: independently placed fibers, straight paths);
- the two of a pair the same within their sampling error: 3 sqrt(s_w^2 + s_1^2), s the
  spread over 30 other draws of such a mat of the model's lanes' mean field
  (fiberMats.laneFields, computed here from the positions, not by the library):
  a mat of M positions scatters more than one of M N.
"""
import math
import os
import random
import re
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402
import fiberMats  # noqa: E402

W, D = 0.02, 0.001
tMeasured = 0.02

args = sys.argv[1:]
options = {"--spacing": 1e-3, "--dropletDiameter": 4e-5, "--tolerance": 0.03}
while args and args[0].startswith("--"):
    if args[0] not in options:
        sys.exit("checkWeightedMat.py: unknown option %s" % args[0])
    options[args[0]] = float(args[1])
    args = args[2:]
h, rp, tolerance = options["--spacing"], 0.5 * options["--dropletDiameter"], options["--tolerance"]


def drawSpread(count, radius, weight, draws=30):
    """Spread over draws of the lanes' mean field of mats like this one"""
    fields = []
    for seed in range(1000, 1000 + draws):
        rng = random.Random(seed)
        fibers = []
        for _ in range(count):
            x, y = 0.004 + 0.006 * rng.random(), W * rng.random()
            fibers.append(([x, y, 0.0], [x, y, D], radius, weight))
        fields.append(fiberMats.laneFields(fibers, rp, W, D, h)[0])
    return statistics.stdev(fields)


measured = {}
for case in args:
    fibers = fiberMats.mat(case)
    S = fiberMats.depth(fibers, rp, W, D)
    weight = fibers[0][3]
    byOutlet, byCapture = fiberMats.penetration(case, tMeasured)
    expected = math.exp(-S)
    spread = drawSpread(len(fibers), fibers[0][2], weight)
    nominal = float(re.search(r"S ([-+0-9.eE]+)", open(os.path.join(case, "system/matFibers")).readline()).group(1))
    measured.setdefault(round(nominal, 6), []).append((weight, byOutlet, spread, S))
    print("S %.4f, %d fibers of weight %g: penetration %.5f (outlet) %.5f (captured) against "
          "exp(-S) %.5f: %+.2f %%; lanes' field of this draw %.5f, over draws +- %.5f"
          % (S, len(fibers), weight, byOutlet, byCapture, expected, 100 * (byOutlet / expected - 1),
             fiberMats.laneFields(fibers, rp, W, D, h)[0], spread))
    check(abs(byOutlet / expected - 1) < tolerance and abs(byCapture / expected - 1) < tolerance,
          "S %.3f, weight %g: within %.3g %% of exp(-S)" % (S, weight, 100 * tolerance))

for nominal, pair in sorted(measured.items()):
    if len(pair) != 2:
        continue
    (wa, pa, sa, Sa), (wb, pb, sb, Sb) = pair
    # Each against its own exp(-S) (the counts are rounded apart), then the two
    ra, rb = pa / math.exp(-Sa), pb / math.exp(-Sb)
    allowed = 3.0 * math.hypot(sa / math.exp(-Sa), sb / math.exp(-Sb))
    check(abs(ra - rb) <= allowed,
          "S %.3f: weight %g and weight %g the same penetration within the sampling error "
          "(%+.2f %% against %.2f %%)" % (nominal, wa, wb, 100 * (ra - rb), 100 * allowed))
finish()
