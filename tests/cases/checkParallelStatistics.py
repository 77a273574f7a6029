"""The work columns of parallelStatistics.dat add up (case fixedFiber).

Usage: checkParallelStatistics.py SERIAL_RUN PARALLEL_RUN PROCESSORS

Each step's work is spread over the processors, so its mean over them times their
number is the serial run's figure:
  - parcels deposited: the parcel count of the serial run's own table (the cloud's
    parcels, dropletFiber.dat), each parcel deposited by one processor;
  - fiber points stepped: the case's one fixed fiber of 7 points (its controlDict),
    held by one processor (the maximum is all of it);
  - collision samples: the serial run's count (each segment sampled by its holder).
A serial run deposits no copies; thread CPU times are not negative, a maximum is not
below its mean, and the deposit takes some CPU time over the run.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402
from checks import check as counted, finish  # noqa: E402


def check(ok, what):
    """Failures only: a row of checks per time"""
    counted(ok, what, quiet=True)


serial_run, parallel_run, processors = sys.argv[1], sys.argv[2], int(sys.argv[3])
OUT = "postProcessing/dropletFiber/0"
FIBER_POINTS = 7
table = {round(r["Time"], 9): r for r in read_table(os.path.join(serial_run, OUT, "dropletFiber.dat"))}
serial = read_table(os.path.join(serial_run, OUT, "parallelStatistics.dat"))
parallel = {round(r["Time"], 9): r for r in read_table(os.path.join(parallel_run, OUT, "parallelStatistics.dat"))}



def close(a, b):
    # Means are written with the table's precision (6 digits at least)
    return abs(a - b) <= 1e-5 * max(abs(a), abs(b), 1.0)


check(len(serial) == len(table) and len(parallel) == len(table),
      "rows: serial statistics %d, parallel %d, table %d" % (len(serial), len(parallel), len(table)))
for s in serial:
    t = round(s["Time"], 9)
    p = parallel.get(t)
    if p is None or t not in table:
        check(False, "time %g missing" % t)
        continue
    check(s["parcelsMax"] == table[t]["parcels"], "t=%g serial parcels %g, table %g"
          % (t, s["parcelsMax"], table[t]["parcels"]))
    check(close(processors * p["parcelsMean"], table[t]["parcels"]),
          "t=%g parallel parcels %g x %d, serial table %g" % (t, p["parcelsMean"], processors, table[t]["parcels"]))
    check(s["parcelCopiesMax"] == 0, "t=%g serial copies %g" % (t, s["parcelCopiesMax"]))
    check(s["fiberPointsMax"] == FIBER_POINTS and p["fiberPointsMax"] == FIBER_POINTS
          and close(processors * p["fiberPointsMean"], FIBER_POINTS),
          "t=%g fiber points serial %g, parallel max %g mean %g" % (t, s["fiberPointsMax"], p["fiberPointsMax"],
                                                                  p["fiberPointsMean"]))
    check(close(processors * p["collisionSamplesMean"], s["collisionSamplesMax"]),
          "t=%g collision samples parallel %g x %d, serial %g"
          % (t, p["collisionSamplesMean"], processors, s["collisionSamplesMax"]))
    for stage in ("cpuDeposit", "cpuCollision", "cpuFibers"):
        for row in (s, p):
            check(row[stage + "Mean"] >= 0 and row[stage + "Max"] >= row[stage + "Mean"] * (1 - 1e-5),
                  "t=%g %s max %g mean %g" % (t, stage, row[stage + "Max"], row[stage + "Mean"]))
for name, rows in (("serial", serial), ("parallel", list(parallel.values()))):
    check(sum(r["cpuDepositMax"] for r in rows) > 0, name + ": no deposit CPU time over the run")
finish()
