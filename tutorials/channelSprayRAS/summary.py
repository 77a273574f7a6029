"""Summary of the channel-spray tutorial, printed at the end of Allrun.

Usage: python3 summary.py [CASE_DIR] [LOG]
Fibers, captured binder mass, and the conservation checks: captured binder at
most the binder sprayed (mass introduced by the cloud's injectors), parcel mass =
on the grid + outside it, and fiber mass = added + captured - removed. With
depletion (the table's removedStep column) also the binder balance
    sprayed = airborne + left the domain + captured
from the cloud's own last report in the log (mass introduced by its injectors,
current mass in the system, and the mass of the parcels that escaped or stuck at
each patch: "left") and the captured total of the table, to 1e-6 of the sprayed
mass (the cloud prints 8 digits); the binder efficiency is captured / sprayed.
Exits non-zero when a check fails.
"""
import os
import re
import sys

case = sys.argv[1] if len(sys.argv) > 1 else "."
log = sys.argv[2] if len(sys.argv) > 2 else os.path.join(case, "log.pimpleFoam")
table = os.path.join(case, "postProcessing/dropletFiber/0/dropletFiber.dat")
if not os.path.isfile(table):
    # OpenFOAM v1912 runs a case on, exit 0, without a function object it cannot load
    sys.exit("summary.py: no table %s: the dropletFiberCollision function object did not run.\n"
             "    Look in %s for 'Unknown function type dropletFiberCollision' or\n"
             "    'Could not load \"libdropletFiber.so\"': the library is then neither in\n"
             "    $FOAM_USER_LIBBIN nor on LD_LIBRARY_PATH of the environment the case ran in\n"
             "    (build it there with ./Allwmake, or load the environment it was built in)."
             % (table, log))
rows = []
names = None
for line in open(table):
    if line.startswith("#"):
        names = [c.strip() for c in line[1:].split("\t") if c.strip()]
    elif line.strip():
        rows.append(dict(zip(names, map(float, line.split()))))
last = rows[-1]
text = open(log).read()
# last report of the cloud: mass introduced by every injector
report = text[text.rfind("Cloud: kinematicCloud\n"):]
sprayed = sum(float(m) for m in re.findall(r"mass introduced\s*=\s*(\S+)", report))
airborne = float(re.search(r"Current mass in system\s*=\s*(\S+)", report).group(1))
# escape and stick at every patch (the "system" lines are their sums): parcels that
# left the domain
left = sum(float(m) for block in re.findall(r"Parcel fate: patch[^\n]*\n((?:\s+- [^\n]*\n)+)", report)
           for m in re.findall(r"- (?:escape|stick)\s*=\s*\S+,\s*(\S+)", block))
depletion = "removedStep" in last
balances = re.findall(r"\(balance (\S+) kg\)", text)[-2:]

ok = True
print("channelSprayRAS summary at t = %g s" % last["Time"])
print("  fibers in the channel        %d" % last["fibers"])
print("  parcels in the channel       %d" % last["parcels"])
print("  binder sprayed               %.4g kg" % sprayed)
print("  binder captured by fibers    %.4g kg (binder efficiency captured / sprayed %.3g %%)"
      % (last["capturedTotal"], 100 * last["capturedTotal"] / sprayed))
balance = sprayed - (airborne + left + last["capturedTotal"])
print("  binder balance: sprayed %.7g = airborne %.7g + left the domain %.7g + captured %.4g kg"
      " (balance %.3g kg, %.2g of the sprayed)" % (sprayed, airborne, left, last["capturedTotal"],
                                                  balance, balance / sprayed))
if depletion:
    good = abs(balance) <= 1e-6 * sprayed
    ok = ok and good
    print("  conservation: %-40s %s" % ("sprayed = airborne + left + captured", "ok" if good else "FAILED"))
else:
    print("  (collision.depletion false: the captured droplets also fly on, counted twice)")
print("  fiber mass now               %.4g kg" % last["fiberMass"])
if not last["capturedTotal"] <= sprayed:
    ok = False
    print("  FAILED: captured more binder than sprayed")
for what, value in zip(("parcel mass = grid + outside", "fiber mass = added + captured - removed"), balances):
    scale = max(last["capturedTotal"], 1e-30)
    good = abs(float(value)) <= 1e-9 * max(scale, sprayed)
    ok = ok and good
    print("  conservation: %-40s balance %s kg %s" % (what, value, "ok" if good else "FAILED"))
sys.exit(0 if ok else 1)
