"""A weighted mat restarted (checkWeightedMat.sh --restart; docs/model.md sec. 9): the
restart state holds every fiber's weight, the table goes on with the same physical
fibers, and once the parcels flying at the restart have passed the mat the capture is the
uninterrupted run's.

Usage: checkWeightedRestart.py WHOLE RESTARTED TIME
  WHOLE: the run without a stop; RESTARTED: the run stopped at TIME and restarted (its
  log.restart). The mat's weights are read from the case's system/matFibers.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402
from checks import check, finish  # noqa: E402
import fiberMats  # noqa: E402

whole, restarted, stop = sys.argv[1], sys.argv[2], sys.argv[3]
fibers = fiberMats.mat(restarted)
physical = sum(n for _, _, _, n in fibers)

state = open(os.path.join(restarted, stop, "uniform/dropletFiber/dropletFiber")).read()
# The fibers' part of the state (the sources' copy of the dictionary follows it)
fiberPart = state[state.index("\nfibers"):state.index("\ninjectors")]
weights = [float(v) for v in re.findall(r"\brepresents\s+([-+0-9.eE]+)\s*;", fiberPart)]
check(len(weights) == len(fibers) and all(w == fibers[0][3] for w in weights),
      "the state at %s holds the weight %g of each of the %d fibers (found %d)"
      % (stop, fibers[0][3], len(fibers), len(weights)))
log = open(os.path.join(restarted, "log.restart")).read()
check("weighted fibers" in log, "the restarted run says its fibers are weighted")

table = "postProcessing/dropletFiber/0/dropletFiber.dat"
# The restarted run's table: its own start time's folder (postProcessing/<name>/<start>)
after = [r for r in read_table(os.path.join(restarted, "postProcessing/dropletFiber", stop,
                                            "dropletFiber.dat"))]
check(len(after) > 0 and all(r["fibersRepresented"] == physical for r in after),
      "every row after the restart: fibersRepresented %g" % physical)


# The case's cloud (a function object's) moves its flying parcels one step less after a
# restart (docs/userGuide.md, restart): once the parcels flying at the restart have left
# the mat (6 mm at 1 mm/ms: from 10 ms after it), the capture is the uninterrupted run's
def capturedLate(rows):
    return sum(r["capturedStep"] for r in rows if r["Time"] > float(stop) + 0.012 - 1e-12)


cWhole = capturedLate(read_table(os.path.join(whole, table)))
cRestarted = capturedLate(after)
check(abs(cRestarted / cWhole - 1) < 0.002,
      "captured from 12 ms after the restart on %.6g kg, without a stop %.6g kg (within 0.2 %%)"
      % (cRestarted, cWhole))
# The report (dropletFiberReport.txt) from the fibers' VTK, each segment times its fiber's
# array represents, against the binder table and the per-step table (C++ sums)
report = open(os.path.join(restarted, "dropletFiberReport.txt")).read()
binder = read_table(os.path.join(restarted, "postProcessing/dropletFiber", stop,
                                 "binderDistribution.dat"))[-1]
fromVtk = float(re.search(r"captured binder per length mean ([-+0-9.eE]+)", report).group(1))
massFromVtk = float(re.search(r"fiber mass from sigma ([-+0-9.eE]+)", report).group(1))
check(abs(fromVtk / binder["meanSigma"] - 1) < 1e-3,
      "binder per length from the weighted VTK %.4g = binder table's %.4g" % (fromVtk, binder["meanSigma"]))
check(abs(massFromVtk / after[-1]["fiberMass"] - 1) < 1e-6,
      "fiber mass from the weighted VTK %.7g = the table's %.7g" % (massFromVtk, after[-1]["fiberMass"]))
check(re.search(r"fibers\s+%d computed, representing %g physical" % (len(fibers), physical), report) is not None,
      "the report says %d computed fibers represent %g" % (len(fibers), physical))
finish()
