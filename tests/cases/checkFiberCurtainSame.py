"""Two runs of the fiberCurtain case give the same per-step tables: the fibers' drag
(fiberDrag.dat) and the air's (the momentum integrals, the wall forces, the probes).

Usage: checkFiberCurtainSame.py [--after T] RUN_A RUN_B REL_TOL
  Every table of RUN_A (postProcessing/<name>/0) against RUN_B's, row by row, a value
  agreeing when it differs by at most REL_TOL times its column's largest magnitude in
  RUN_A (at least a thousandth of the table's largest). --after T: RUN_B restarted at the write time T (its tables in
  postProcessing/<name>/T), against RUN_A's rows after T. Prints the largest
  difference per table; exit 1 on a failure. The fiber states are compared by
  compareFiberUnion.py (parallel) or cmp (restart).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkFiberCurtainFiles import entry, table  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

args = sys.argv[1:]
after = None
if args[0] == "--after":
    after, args = args[1], args[2:]
a, b, tol = args[0], args[1], float(args[2])
dt = entry(os.path.join(a, "system", "controlDict"), "deltaT")
skip = int(round(float(after) / dt)) if after else 0

for fo, name in (("dropletFiber", "fiberDrag.dat"), ("airMomentum", "volFieldValue.dat"),
                 ("airBeforeFibers", "volFieldValue.dat"), ("airAfterFibers", "volFieldValue.dat"),
                 ("wallForces", "force.dat"), ("airProbes", "U")):
    ta = table(a, fo, name)[skip:]
    tb = table(b, fo, name, after or "0")
    if len(ta) != len(tb) or not ta:
        check(False, "%s/%s: %d rows against %d" % (fo, name, len(ta), len(tb)))
        continue
    if any(len(r) != len(ta[0]) for r in ta + tb):
        check(False, "%s/%s: the runs' columns differ" % (fo, name))
        continue
    # The time, then the values; a column of round-off around zero (the air's z in
    # this 2-D case) is judged against a thousandth of the table's largest value
    largest = max(abs(v) for r in ta for v in r[1:]) or 1.0
    worst = 0.0
    for col in range(len(ta[0])):
        scale = max([abs(r[col]) for r in ta] + [1e-3 * largest])
        worst = max([worst] + [abs(ra[col] - rb[col]) / scale for ra, rb in zip(ta, tb)])
    check(worst <= tol, "%s/%s: %d rows, largest difference %.3g of a column's largest value"
          " (tolerance %g)" % (fo, name, len(ta), worst, tol))
finish()
