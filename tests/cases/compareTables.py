"""Compare two postProcessing .dat tables column by column.

Usage: compareTables.py [--after T] [--skip COL,COL] A.dat B.dat REL_TOL

Same rows and columns (with --after, only the rows of A after time T, against
all rows of B: a restarted run's table). A value agrees when it differs by at
most REL_TOL times the largest magnitude of its column in A (so that a column
that passes through zero is judged on its own scale). Wall-time columns are
never compared (timings differ by nature); --skip names more columns to leave
out. Prints the largest difference per column and `N passed, N failed`.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402

args = sys.argv[1:]
after, skip = None, set()
while args and args[0].startswith("--"):
    if args[0] == "--after":
        after = float(args[1])
    elif args[0] == "--skip":
        skip = set(args[1].split(","))
    args = args[2:]
a, b, tol = read_table(args[0]), read_table(args[1]), float(args[2])
if after is not None:
    a = [r for r in a if r["Time"] > after + 1e-9]
passed = failed = 0
if len(a) != len(b) or not a:
    print("FAILED: %d rows vs %d rows" % (len(a), len(b)))
    failed += 1
columns = [k for k in (a[0] if a else {}) if not k.startswith("wallTime") and k not in skip]
for key in columns:
    scale = max([abs(r[key]) for r in a] + [1e-300])
    worst, bad = 0.0, 0
    for ra, rb in zip(a, b):
        if key not in rb:
            bad += 1
            continue
        diff = abs(ra[key] - rb[key]) / scale
        worst = max(worst, diff)
        if diff > tol:
            bad += 1
            if bad <= 3:
                print("FAILED: t=%g %s: %r vs %r" % (ra["Time"], key, ra[key], rb[key]))
    passed += len(a) - bad
    failed += bad
    print("%-22s largest difference %.3g of the column's scale" % (key, worst))
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
