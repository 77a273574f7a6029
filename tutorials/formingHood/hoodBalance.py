#!/usr/bin/env python3
"""The binder balance of a formingHood run, from the solver log's last cloud
report (sprayFoam's sprayCloud: introduced, in the air, evaporated, escaped
through the walls and, counted as leaving the "system", through the outlet) and the function object's table (captured in total).

The cloud does not know of the droplets the fibers took (depletion), so its own
report closes as introduced - escaped - phase change - in system = captured:
the difference is the check. Without depletion (Allrun -noDepletion: the log says
that the spray keeps every droplet) the fibers' capture is not taken from the spray:
sprayed = airborne + evaporated + walls + outlet, the captured printed beside it.
Usage: hoodBalance.py CASE LOG [TOLERANCE]
(relative to the mass sprayed; default 1e-9). Exit 1 when it does not close.
"""
import glob
import os
import re
import sys


def last_cloud_report(log):
    """Figures of the last 'Cloud: sprayCloud' report with a mass introduced."""
    text = open(log).read()
    blocks = text.split("Cloud: sprayCloud\n")
    for block in reversed(blocks[1:]):
        introduced = re.findall(r"- mass introduced\s+=\s+(\S+)", block)
        if not introduced:
            continue
        # a block ends where the solver goes on (the next blank line after the fates)
        body = block.split("Mass transfer phase change")[0]
        phase = re.search(r"Mass transfer phase change\s+=\s+(\S+)", block)
        escaped = {}
        for patch, part in re.findall(r"Parcel fate: patch \(number, mass\) (\S+)\n"
                                      r"((?:\s+- \w+\s+=\s+\S+, \S+\n)+)", body):
            escaped[patch] = sum(float(m) for m in re.findall(r"- escape\s+=\s+\S+, (\S+)", part))
        # parcels leaving through a patch that is not a wall (the outlet) are
        # counted by the cloud as escaped from the "system"
        system = re.search(r"Parcel fate: system \(number, mass\)\n\s+- escape\s+=\s+\S+, (\S+)", body)
        escaped["system"] = float(system.group(1)) if system else 0.0
        return {
            "introduced": sum(float(m) for m in introduced),
            "inSystem": float(re.search(r"Current mass in system\s+=\s+(\S+)", body).group(1)),
            "evaporated": float(phase.group(1)) if phase else 0.0,
            "escaped": escaped,
            "time": re.findall(r"^Time = (\S+)", text[:text.rfind(block)], re.M)[-1],
        }
    sys.exit("hoodBalance: no cloud report with injected mass in %s" % log)


def captured_total(case, time):
    """capturedTotal of the step before the cloud report's time: the cloud reports
    while the solver moves it, before the function object of that step removes
    the droplets the fibers capture."""
    tables = glob.glob(os.path.join(case, "postProcessing", "dropletFiber", "*",
                                           "dropletFiber*.dat"))
    if not tables:
        sys.exit("hoodBalance: no postProcessing/dropletFiber/*/dropletFiber.dat in %s" % case)
    value, latest = None, -1.0
    for table in tables:
        lines = open(table).read().splitlines()
        names = [n.strip() for n in [l for l in lines if l.startswith("# Time")][-1][1:].split("\t")]
        col = names.index("capturedTotal")
        for line in lines:
            if line.strip() and not line.startswith("#"):
                cells = line.split()
                if latest < float(cells[0]) < float(time) - 1e-9:
                    value, latest = float(cells[col]), float(cells[0])
    if value is None:
        return 0.0  # the report of the first step
    return value


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
    walls = r["escaped"].get("walls", 0.0)
    out = sum(v for k, v in r["escaped"].items() if k != "walls")
    rest = r["introduced"] - r["inSystem"] - r["evaporated"] - walls - out \
        - (captured if depletion else 0.0)
    sprayed = r["introduced"]
    print("Binder balance at t = %s s (kg, and share of the binder sprayed):" % r["time"])
    for name, value in [("sprayed", sprayed), ("airborne", r["inSystem"]),
                        ("evaporated (water)", r["evaporated"]), ("on the hood walls", walls),
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
