#!/usr/bin/env python3
"""The binder balance of a formingHood run, from the solver log's last cloud
report (sprayFoam's sprayCloud: introduced, in the air, evaporated, escaped
through the walls and, counted as leaving the "system", through the outlet) and the function object's table (captured in total).

The cloud does not know of the droplets the fibers took (depletion), so its own
report closes as introduced - escaped - phase change - in system = captured:
the difference is the check. Without depletion (Allrun -noDepletion: the log says
that the spray keeps every droplet) the fibers' capture is not taken from the spray:
sprayed = airborne + evaporated + walls + outlet, the captured printed beside it.
The cloud's report and the table are read by the project's report package
(solverLog, caseOutputs; found by reportPackage.py).
Usage: hoodBalance.py CASE LOG [TOLERANCE]
(relative to the mass sprayed; default 1e-9). Exit 1 when it does not close.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reportPackage  # noqa: E402,F401  (the report's modules on the import path)
import caseOutputs  # noqa: E402
from solverLog import SolverLog  # noqa: E402

CLOUD = "sprayCloud"


def last_cloud_report(log):
    """The last report of the spray's cloud (solverLog): introduced, inSystem,
    phaseChange, escapedPatches, escapedSystem (parcels through the outlet, counted by
    the cloud as leaving the "system"), time and timeName."""
    report = SolverLog(log).clouds.get(CLOUD)
    if report is None:
        sys.exit("hoodBalance: no cloud report with injected mass in %s" % log)
    return report


def fates(report):
    """(evaporated, on the walls, through the outlet) of a cloud report."""
    escaped = report["escapedPatches"]
    outlet = sum(v for k, v in escaped.items() if k != "walls") + report["escapedSystem"]
    evaporated = report["phaseChange"] if report["phaseChange"] is not None else 0.0
    return evaporated, escaped.get("walls", 0.0), outlet


def captured_total(case, time):
    """capturedTotal of the step before the cloud report's time: the cloud reports
    while the solver moves it, before the function object of that step removes
    the droplets the fibers capture."""
    table = caseOutputs.read_table(case, "dropletFiber", "dropletFiber.dat")
    if table is None:
        sys.exit("hoodBalance: no postProcessing/dropletFiber/*/dropletFiber.dat in %s" % case)
    before = [row for row in table.rows if row["Time"] < time - 1e-9]
    if not before:
        return 0.0  # the report of the first step
    return before[-1]["capturedTotal"]


def laid_binder(log):
    """The captured binder on airborne fibers, laid in the mat and on lost fibers, and the
    balance, from the function object's last laydown report (None without a belt)."""
    number = r"([-+0-9.eE]+)"
    found = re.findall(r"binder: captured " + number + " kg = on airborne fibers " + number
                       + r" \+ laid " + number + r" \+ on lost fibers " + number + r" \(balance "
                       + number, open(log).read())
    if not found:
        return None
    captured, on_air, in_mat, lost, balance = (float(v) for v in found[-1])
    return on_air, in_mat, lost, balance


def main():
    case, log = sys.argv[1], sys.argv[2]
    tolerance = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-9
    log = log if os.path.isabs(log) else os.path.join(case, log)
    r = last_cloud_report(log)
    captured = captured_total(case, r["time"])
    depletion = "the spray keeps every droplet" not in open(log).read()
    evaporated, walls, out = fates(r)
    rest = r["introduced"] - r["inSystem"] - evaporated - walls - out \
        - (captured if depletion else 0.0)
    sprayed = r["introduced"]
    print("Binder balance at t = %s s (kg, and share of the binder sprayed):" % r["timeName"])
    for name, value in [("sprayed", sprayed), ("airborne", r["inSystem"]),
                        ("evaporated (water)", evaporated), ("on the hood walls", walls),
                        ("through the outlet", out)] + (
                            [("captured by the fibers", captured)] if depletion else []):
        print("    %-24s %.6e  %8.4f %%" % (name, value, 100 * value / sprayed if sprayed else 0))
    relative = abs(rest) / sprayed if sprayed else 0.0
    print("    %-24s %.3e  (relative %.2e, allowed %.0e)" % ("not accounted for", rest, relative,
                                                          tolerance))
    if not depletion:
        print("    %-24s %.6e  (depletion off: not taken from the spray)"
              % ("captured by the fibers", captured))
    laid = laid_binder(log)
    if laid is not None:
        # The captured binder's whereabouts (fibers.laydown): the function object's balance
        on_air, in_mat, lost, balance = laid
        for name, value in [("  on fibers in the air", on_air), ("  laid in the mat", in_mat),
                            ("  on fibers lost", lost)]:
            print("    %-24s %.6e  %8.4f %%" % (name, value, 100 * value / sprayed if sprayed else 0))
    if relative > tolerance:
        print("hoodBalance: the balance does not close")
        return 1
    print("Balance closed: sprayed = airborne + evaporated + walls + outlet"
          + (" + captured" if depletion else " (depletion off)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
