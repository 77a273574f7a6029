"""A heavily weighted random mat on three grids (docs/model.md sec. 12, spread populations;
checkWeightedMat.sh --spacings runs it).

Usage: checkWeightedSpacings.py --dropletDiameter D CASE... -- CASE_WITHOUT_SPREAD

The cases hold the same mat (M fibers of weight N, makeMat.py's seed) on grids a factor 2
apart. Its penetration (fiberMats.penetration, outlet and capture over the last 10 ms)
against exp(-S), S from the fibers written (fiberMats.depth, each fiber N times). Checked:
- the spread runs agree with each other within 2 % (the populations' levels are set by
  the fibers, not by the grid; what differs is the lines' own resolution and the
  parcels' kernels);
- each within 3 % of exp(-S) (issue's target for such mats; this mat's own clustering at
  the kernel's scale is in it);
- the run without spread (P40 alone) at the finest grid off the spread runs' mean by more
  than 10 % (the fault the populations remove; the check can fail).
"""
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402
import fiberMats  # noqa: E402

W, D = 0.02, 0.001
tMeasured = 0.02

args = sys.argv[1:]
if len(args) < 4 or args[0] != "--dropletDiameter" or "--" not in args:
    sys.exit(__doc__)
rp = 0.5 * float(args[1])
split = args.index("--")
spread, without = args[2:split], args[split + 1:]


def ratio(case):
    fibers = fiberMats.mat(case)
    S = fiberMats.depth(fibers, rp, W, D)
    byOutlet, byCapture = fiberMats.penetration(case, tMeasured)
    return fibers, S, byOutlet / math.exp(-S), byCapture / math.exp(-S)


ratios = []
for case in spread:
    fibers, S, outlet, captured = ratio(case)
    print("%s: S %.4f, %d fibers of weight %g: P / exp(-S) %.4f (outlet) %.4f (captured)"
          % (case, S, len(fibers), fibers[0][3], outlet, captured))
    ratios.append(outlet)
mean = statistics.mean(ratios)
print("spread runs: mean %.4f, range %.4f" % (mean, max(ratios) - min(ratios)))
check(max(ratios) - min(ratios) < 0.02, "the three grids the same penetration within 2 %")
for case, r in zip(spread, ratios):
    check(abs(r - 1) < 0.03, "%s within 3 %% of exp(-S) (%+.2f %%)" % (case, 100 * (r - 1)))
for case in without:
    fibers, S, outlet, captured = ratio(case)
    print("%s (P40 alone): P / exp(-S) %.4f" % (case, outlet))
    check(abs(outlet / mean - 1) > 0.1, "without spread the finest grid is off by more than 10 %% (%+.1f %%)"
          % (100 * (outlet / mean - 1)))
finish()
