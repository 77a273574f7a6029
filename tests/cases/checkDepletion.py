"""Depletion's binder balance in a finished case (docs/model.md sec. 7).

Usage: checkDepletion.py [--limited STREAMS] [--hitsCut] CASE

Every step, the mass the fibers captured (capturedStep) must equal the mass taken
from the parcels (removedStep) to 1e-12 relative, and the parcel mass flying on
(airborneMass) must be the parcel mass gathered (parcelMass) less what was removed,
to 1e-12 of it; the fibers must have captured something. With --limited STREAMS
(the fixedFiber case with fibers far thicker than the grid spacing, every parcel
cloud-in-cell): the limit binds (demandedStep > capturedStep, and the log says so
once), and the parcels of the STREAMS streams that cross the fibers lose all their
droplets and leave the cloud: the injection gives 50 parcels per step (one per
stream, checkCapture.py) and none reaches the outlet, so without removal the table
would count 50 (n - 1) parcels at step n; with it, at least STREAMS fewer once a
stream's parcels have crossed. With --hitsCut (collision mode discrete where the
hits ask more of some parcels than they hold, P33): the log says once that the hits
were cut, and captured = removed holds in those steps as in all others.
"""
import glob
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402
from checks import check, failures, finish  # noqa: E402

args = sys.argv[1:]
streams = None
hitsCut = False
while args and args[0].startswith("--"):
    if args[0] == "--limited":
        streams = int(args[1])
        args = args[2:]
    elif args[0] == "--hitsCut":
        hitsCut = True
        args = args[1:]
    else:
        sys.exit("checkDepletion.py: unknown option %s" % args[0])
case = args[0]
rows = read_table(os.path.join(case, "postProcessing/dropletFiber/0/dropletFiber.dat"))



check(rows and "removedStep" in rows[0] and "airborneMass" in rows[0],
      "the table has the depletion columns removedStep and airborneMass")
if failures():
    sys.exit(1)
worst = max([abs(r["capturedStep"] - r["removedStep"]) / r["capturedStep"]
             for r in rows if r["capturedStep"] > 0] + [0.0])
check(rows[-1]["capturedTotal"] > 0, "the fibers captured %.6g kg" % rows[-1]["capturedTotal"])
check(worst <= 1e-12, "captured = removed every step (worst relative difference %.3g)" % worst)
worstAir = max(abs(r["airborneMass"] - (r["parcelMass"] - r["removedStep"])) / max(r["parcelMass"], 1e-300)
               for r in rows)
check(worstAir <= 1e-12, "airborne = parcel mass - removed every step (worst %.3g of the parcel mass)" % worstAir)
if streams is not None:
    dt = rows[1]["Time"] - rows[0]["Time"]
    limited = [r for r in rows if r["demandedStep"] > r["capturedStep"] * (1 + 1e-9)]
    check(len(limited) > 0, "the limit binds at %d steps" % len(limited))
    logs = glob.glob(os.path.join(case, "log.*Foam"))
    text = "".join(open(log).read() for log in logs)
    check(text.count("capture is limited to what the nodes hold") == 1, "the log says so once")
    last = rows[-1]
    injected = 50 * (round(last["Time"] / dt) - 1)
    check(last["parcels"] <= injected - streams,
          "parcels emptied are removed: %d parcels, %d injected (at least %d fewer expected)"
          % (last["parcels"], injected, streams))
if hitsCut:
    text = "".join(open(log).read() for log in glob.glob(os.path.join(case, "log.*Foam")))
    check(text.count("discrete hits asked more of some parcels than they held") == 1,
          "the log says once that parcels fell short and the hits were cut")
finish()
