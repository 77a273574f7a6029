"""Compare two postProcessing .dat tables column by column.

Usage: compareTables.py [--after T] A.dat B.dat REL_TOL
Same rows and columns (with --after, only the rows of A after time T, against
all rows of B: a restarted run's table); every value within REL_TOL relative (absolute for values
below 1e-300). Prints `N passed, N failed`.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402

args = sys.argv[1:]
after = None
if args[0] == "--after":
    after, args = float(args[1]), args[2:]
a, b, tol = read_table(args[0]), read_table(args[1]), float(args[2])
if after is not None:
    a = [r for r in a if r["Time"] > after + 1e-9]
passed = failed = 0
if len(a) != len(b) or not a:
    print("FAILED: %d rows vs %d rows" % (len(a), len(b)))
    failed += 1
for ra, rb in zip(a, b):
    for key in ra:
        if key.startswith("wallTime"):
            continue  # timings differ by nature
        va, vb = ra[key], rb.get(key)
        if vb is not None and abs(va - vb) <= tol * max(abs(va), abs(vb), 1e-300):
            passed += 1
        else:
            failed += 1
            print("FAILED: t=%g %s: %r vs %r" % (ra.get("Time", 0), key, va, vb))
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
