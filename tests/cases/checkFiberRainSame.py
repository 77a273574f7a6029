"""Two runs of the fiberRain case lay the same mat: serial against 2 ranks, or an
uninterrupted run against one restarted at a write time.

Usage: checkFiberRainSame.py RUN_A RUN_B            (RUN_B on 2 ranks)
       checkFiberRainSame.py --after T RUN_A RUN_B  (RUN_B restarted at T)
       checkFiberRainSame.py --after T --olderMat RUN_A RUN_B
           (RUN_B restarted at T from a state whose mat an earlier version laid: each fiber
           whole in its centre's cell, no error sums. Its maps and the log's mat differ
           from RUN_A's by the fibers laid before T; the rest as below, and the maps'
           totals, glass and fibers, RUN_A's to 1e-12)

Both: the step table dropletFiber.dat (the restarted run's after T) the other's, every
column to the bit but the wall times and, on 2 ranks, the fiber mass in the air (1e-13:
a sum over the processors; measured 4e-16), laidGlass and laidBinder included.

Serial against 2 ranks: laydown.dat holds the same fibers in the same order (the laid
fibers are gathered each step and added in birth-id order), every column to the bit but
`across`, which may differ by 1e-15 m (measured 1.4e-17): the belt's point is the patch's
area-weighted centre, a sum over the processors' faces in another order; every
mat_<time>.vti's arrays to the bit and its origin across to 1e-15 m; the series alike;
the restart state's `laydown` entry at every write time the same text.

Restarted at T: its postProcessing/dropletFiber/T/laydown.dat holds exactly the
uninterrupted run's rows after T, to the bit, in order: no row twice, none lost, the
header once; its mat_<time>.vti after T and the state's `laydown` entry at every write
time after T (every processor's) are the uninterrupted run's byte for byte, and its
series lists those maps only; the restarted log (RUN_B/log.restart) says at every write
time after T what the uninterrupted one (RUN_A/log.pimpleFoam) says: laid fibers, mat,
glass, binder and fiber-mass balances, every figure as printed.
"""
import filecmp
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkFiberCurtainFiles import columns, table  # noqa: E402
from checkFiberRainFiles import laid, laid_lines, mat, series, state_laydown, write_reports  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

args = sys.argv[1:]
after = None
if args[0] == "--after":
    after, args = args[1], args[2:]
olderMat = args[0] == "--olderMat"
if olderMat:
    args = args[1:]
a, b = args
start = after or "0"


def out(case, name, folder="0"):
    return os.path.join(case, "postProcessing", "dropletFiber", folder, name)


def states(case, time):
    """Each processor's `laydown` entry at the time: its text without the belt's edges
    across, which are kept as numbers (acrossMin, acrossMax: from the patch's points
    relative to its centre, a sum over the processors' faces, 1e-15 m apart)."""
    procs = sorted(d for d in os.listdir(case) if d.startswith("processor")) or ["."]
    out = []
    for p in procs:
        text, values = state_laydown(os.path.join(case, p, time, "uniform", "dropletFiber", "dropletFiber"))
        if text is not None:
            text = "\n".join(line for line in text.split("\n")
                             if not line.strip().startswith(("acrossMin", "acrossMax")))
            text = (text, values["acrossMin"], values["acrossMax"])
        out.append(text)
    return out


def same_state(sa, sb):
    return (sa[0] == sb[0] and abs(sa[1] - sb[1]) <= 1e-15 and abs(sa[2] - sb[2]) <= 1e-15)


filesB = series(b, start)
timesA = [(f, t) for f, t in series(a) if after is None or t > float(after) + 1e-12]
check(filesB == timesA and filesB, "mat.vti.series of %s: %s" % (b, [f for f, _ in filesB]))

# The step table dropletFiber.dat (the restarted run's rows after T): every column to the
# bit but the wall times and, on 2 ranks, the fiber mass (a sum over the processors: 1e-13)
names = columns(a, "dropletFiber", "dropletFiber.dat")
stepsB = table(b, "dropletFiber", "dropletFiber.dat", start)
stepsA = table(a, "dropletFiber", "dropletFiber.dat")[-len(stepsB):] if stepsB else []
worst, same = 0.0, names == columns(b, "dropletFiber", "dropletFiber.dat", start)
for ra, rb in zip(stepsA, stepsB):
    for name, va, vb in zip(names, ra, rb):
        if name == "fiberMass" and after is None:
            worst = max(worst, abs(va - vb) / max(abs(va), 1e-300))
        elif not name.startswith("wallTime"):
            same = same and va == vb
check(stepsB and len(stepsA) == len(stepsB) and same and worst <= 1e-13,
      "dropletFiber.dat: %d steps, every column to the bit but the wall times%s (laidGlass, laidBinder"
      " included)" % (len(stepsB), "" if after else ", fiberMass to 1e-13 (%.3g)" % worst))

if after is not None:
    T = float(after)
    linesA = [line for line in laid_lines(a) if float(line.split()[0]) > T + 1e-12]
    linesB = laid_lines(b, after)
    ids = [int(float(line.split()[1])) for line in linesB]
    check(linesB == linesA and len(set(ids)) == len(ids),
          "laydown.dat after %s: %d rows, the uninterrupted run's %d rows after it to the bit"
          " (ids %s to %s, none twice)" % (after, len(linesB), len(linesA), ids[:1], ids[-1:]))
    header = [line for line in open(out(b, "laydown.dat", after)) if line.startswith("# Time")]
    check(len(header) == 1, "the restarted laydown.dat has its header once (%d)" % len(header))
    logA = write_reports(os.path.join(a, "log.pimpleFoam"))
    logB = write_reports(os.path.join(b, "log.restart"))
    for f, t in filesB:
        name = "%g" % t
        if olderMat:
            ra, rb = (dict((k, v) for k, v in (log.get(name) or {}).items() if k != "mat")
                      for log in (logA, logB))
            check(ra == rb and ra, "%s: the restarted log's laid fibers and balances the uninterrupted"
                  " run's, every figure as printed (the mat's rows laid before %s differ)" % (name, after))
            ma, mb = mat(out(a, f)), mat(out(b, f, after))
            worst = max(abs(sum(ma["arrays"][k]) - sum(mb["arrays"][k])) / sum(ma["arrays"][k])
                        for k in ("areaWeight", "fibersPerArea"))
            check(worst <= 1e-12, "%s of the restarted run: its glass and fibers the uninterrupted run's"
                  " to 1e-12 (%.3g)" % (f, worst))
            continue
        check(logB.get(name) == logA.get(name) and logA.get(name),
              "%s: the restarted log's laydown report the uninterrupted run's, every figure as"
              " printed" % name)
        check(filecmp.cmp(out(a, f), out(b, f, after), shallow=False),
              "%s of the restarted run: the uninterrupted run's byte for byte" % f)
        sa, sb = states(a, name), states(b, name)
        check(sa == sb and sa[0] is not None,
              "%s: the state's laydown entry the uninterrupted run's (%d processor(s))" % (name, len(sa)))
else:
    ta, tb = laid(a), laid(b)
    check([r["id"] for r in ta] == [r["id"] for r in tb] and ta,
          "laydown.dat: the same %d fibers in the same order (%d)" % (len(ta), len(tb)))
    worst, same = 0.0, True
    for ra, rb in zip(ta, tb):
        worst = max(worst, abs(ra["across"] - rb["across"]))
        same = same and all(ra[k] == rb[k] for k in ra if k != "across")
    check(same and worst <= 1e-15,
          "laydown.dat: every column to the bit, across to 1e-15 m (largest difference %.3g m)" % worst)
    for f, t in filesB:
        ma, mb = mat(out(a, f)), mat(out(b, f))
        d = abs(ma["origin"][0] - mb["origin"][0])
        check(ma["arrays"] == mb["arrays"] and ma["shape"] == mb["shape"] and d <= 1e-15
              and ma["origin"][1:] == mb["origin"][1:] and ma["spacing"] == mb["spacing"],
              "%s: every array to the bit, origin across to 1e-15 m (%.3g)" % (f, d))
        name = "%g" % t
        sa, sb = states(a, name), states(b, name)
        check(sa[0] is not None and all(s is not None and same_state(s, sa[0]) for s in sb),
              "%s: the state's laydown entry the same text on every processor and serial (the belt's"
              " edges across to 1e-15 m)" % name)
finish()
