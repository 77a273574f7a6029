"""M computed fibers of weight N against M N of weight 1 in turbulent air (docs/model.md
sec. 12; checkWeightedTurbulence.sh runs them).

Usage: checkWeightedTurbulence.py --weight N UNWEIGHTED_CASE... -- WEIGHTED_CASE...

Each case's captured total at its last step (the per-step table's capturedTotal, every
physical fiber's capture) is one draw of the stream's random paths. Checked:
- the weighted runs' fibers stand for N each (fibersRepresented / fibers), the unweighted
  for 1;
- the means of the two sets agree within three combined standard errors of the mean
  (the spread over each set's seeds), and the weighted set's standard error is not so
  large that the check could not fail (below 10 % of the mean).
"""
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

TABLE = "postProcessing/dropletFiber/0/dropletFiber.dat"


def lastRow(case):
    """The table's last row as a dict of its columns"""
    header, row = None, None
    with open(os.path.join(case, TABLE)) as f:
        for line in f:
            if line.startswith("# Time"):
                header = [c.strip() for c in line[1:].split("\t")]
            elif line.strip() and not line.startswith("#"):
                row = line.split()
    return dict(zip(header, (float(v) for v in row)))


args = sys.argv[1:]
if len(args) < 2 or args[0] != "--weight" or "--" not in args:
    sys.exit(__doc__)
weight = float(args[1])
split = args.index("--")
unweighted, weighted = args[2:split], args[split + 1:]

sets = {}
for name, cases, n in (("weight 1", unweighted, 1.0), ("weight %g" % weight, weighted, weight)):
    captured = []
    for case in cases:
        row = lastRow(case)
        # without weights the table has no fibersRepresented column: each stands for 1
        represents = row.get("fibersRepresented", row["fibers"]) / row["fibers"] if row["fibers"] > 0 else n
        check(abs(represents - n) < 1e-9 * n, "%s: its fibers stand for %g each (%g)" % (case, n, represents))
        captured.append(row["capturedTotal"])
    mean = statistics.mean(captured)
    error = statistics.stdev(captured) / math.sqrt(len(captured)) if len(captured) > 1 else 0.0
    print("%s: captured %s kg, mean %.6e, standard error %.2e (%.2f %%)"
          % (name, " ".join("%.6e" % c for c in captured), mean, error, 100 * error / mean))
    sets[name] = (mean, error)

(m1, e1), (mN, eN) = sets["weight 1"], sets["weight %g" % weight]
combined = math.sqrt(e1 * e1 + eN * eN)
print("difference %.3e kg (%.2f %%), %.2f combined standard errors"
      % (mN - m1, 100 * (mN - m1) / m1, abs(mN - m1) / combined if combined > 0 else float("inf")))
check(m1 > 0 and mN > 0, "both sets captured droplets")
check(eN < 0.1 * mN, "the weighted set's sampling error is below 10 % of its mean (the check can fail)")
check(abs(mN - m1) <= 3 * combined, "the means agree within three combined standard errors")
finish()
