"""A run's maxSegmentLengthError stays below 1e-10.

Usage: checkSegmentLengthError.py TABLE.dat [LABEL]

maxSegmentLengthError (the largest deviation of a segment's length from its rest
length, relative) is round-off by nature, ~1e-14: a continued or regression run's
may differ from another run's in its last digits, so the comparisons of tables
leave it out and this check bounds it instead. Prints the largest value (after
LABEL) and exits 1 when it is 1e-10 or more, or when the table has no rows.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402

LIMIT = 1e-10
rows = read_table(sys.argv[1])
label = sys.argv[2] + ": " if len(sys.argv) > 2 else ""
if not rows:
    print("%s%s has no rows" % (label, sys.argv[1]))
    sys.exit(1)
worst = max(r["maxSegmentLengthError"] for r in rows)
print("%slargest segment-length error %.3g (must stay < %g)" % (label, worst, LIMIT))
sys.exit(0 if worst < LIMIT else 1)
