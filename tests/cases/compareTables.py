"""Compare two postProcessing .dat tables column by column.

Usage: compareTables.py A.dat B.dat REL_TOL
Same rows and columns; every value within REL_TOL relative (absolute for values
below 1e-300). Prints `N passed, N failed`.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402

a, b, tol = read_table(sys.argv[1]), read_table(sys.argv[2]), float(sys.argv[3])
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
