"""Check that dropletFiberCollision sees the parcels OpenFOAM has.

Usage: checkParcelTotals.py CLOUD CASE

1. Every step: parcels and droplet mass in our table equal OpenFOAM's own
   cloudInfo (kinematicCloud::nParcels, massInSystem) at the same time.
2. Every write time: they equal the totals computed here from the cloud files
   OpenFOAM wrote (d, nParticle, rho; all processor folders).
Prints `N passed, N failed` and exits non-zero on a failure.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import cloud_totals, read_table  # noqa: E402
from checks import check as counted, finish  # noqa: E402


def check(ok, what):
    """Failures only: a row of checks per time"""
    counted(ok, what, quiet=True)


cloud, case = sys.argv[1], sys.argv[2]
ours = read_table(os.path.join(case, "postProcessing/dropletFiber/0/dropletFiber.dat"))
info = read_table(os.path.join(case, "postProcessing/cloudInfo/0/%s.dat" % cloud))



def close(a, b, rel=1e-10):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


check(len(ours) > 10, "table has %d rows" % len(ours))
# cloudInfo is listed with ours before the cloud's function object, so both see
# the same parcels at every step (OpenFOAM runs each function object's execute()
# and write() in list order).
check(len(ours) == len(info), "rows: ours %d, cloudInfo %d" % (len(ours), len(info)))
for row, ref in zip(ours, info):
    check(abs(row["Time"] - ref["Time"]) < 1e-9, "times %g, %g" % (row["Time"], ref["Time"]))
    check(row["parcels"] == ref["nParcels"],
          "t=%g parcels %d vs cloudInfo %d" % (row["Time"], row["parcels"], ref["nParcels"]))
    check(close(row["parcelMass"], ref["mass"]),
          "t=%g mass %.12g vs cloudInfo %.12g" % (row["Time"], row["parcelMass"], ref["mass"]))

ours_by_time = {round(r["Time"], 9): r for r in ours}
root = os.path.join(case, "processor0") if os.path.isdir(os.path.join(case, "processor0")) else case
times = sorted((d for d in os.listdir(root) if d.replace(".", "").isdigit() and float(d) > 0),
               key=float)
check(len(times) > 0, "no written times")
for t in times:
    parcels, droplets, mass = cloud_totals(case, t, cloud)
    row = ours_by_time.get(round(float(t), 9))
    check(row is not None, "time %s missing in our table" % t)
    if row is None:
        continue
    check(parcels == row["parcels"], "t=%s parcels %d vs written %d" % (t, row["parcels"], parcels))
    check(close(droplets, row["droplets"]), "t=%s droplets %g vs written %g" % (t, row["droplets"], droplets))
    check(close(mass, row["parcelMass"], 1e-9),
          "t=%s mass %.12g vs written %.12g" % (t, row["parcelMass"], mass))
    print("t=%s: %d parcels, %.6g droplets, %.6g kg (ours and OpenFOAM's)" % (t, parcels, droplets, mass))

finish()
