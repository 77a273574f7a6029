"""Depletion of a solver's cloud against the cloud's own mass report.

Usage: checkCloudBalance.py CLOUD [NONVOLATILE Y0] CASE

The solver prints the cloud's report after its step (KinematicCloud::info and the
submodels': mass in system, mass introduced per injector, escaped mass, mass
transfer by phase change, devolatilisation, surface reaction). The cloud does not
know of the function object's removal, so the mass taken from it is

    taken = introduced - escaped - transferred - in system

which at the report of time t must equal the fibers' capturedTotal of the
function object's table at the time step before t (the function object runs
between the solver's steps, at the start of the next one). Checked at every
report, to the precision the cloud prints (the case's writePrecision: N
significant digits give each of the four terms a rounding error of at most
5 10^-N of its value, 2 10^(1-N) of the introduced mass together). Also: the fibers captured something, the cloud's
parcels lost mass to phase change when it has such a model (evaporation
reported), and the log has no warning that the captured mass is counted twice.

The table's binder balance: sprayedMass = airborneMass + evaporatedMass +
escapedMass + capturedTotal at every row (to the table's 12 digits), its three
cloud figures equal the cloud's report at the same time (sprayed = introduced,
evaporated = phase change, escaped = escape; print precision), and the captured
mass per liquid species (captured_<species>) sums to capturedTotal. With a
non-volatile species NONVOLATILE injected at mass fraction Y0 (it neither
evaporates nor, in a closed box, escapes), its captured mass is what was
injected of it less what the parcels hold of it, independently of the function
object: at every time the cloud was written (before the function object's
removal of that time), captured_NONVOLATILE of the row before = Y0 sprayedMass
- sum over the written parcels of nParticle rho pi d^3/6 Y_NONVOLATILE.
"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import cloud_species_mass, read_table  # noqa: E402

NUMBER = r"([-+0-9.eE]+)"


def cloud_reports(text, cloud):
    """{time: {inSystem, introduced, escaped, transferred, phaseChange}} of CLOUD."""
    reports = {}
    time = None
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        m = re.match(r"^Time = " + NUMBER + r"\s*$", line)
        if m:
            time = float(m.group(1))
        if line.strip() == "Cloud: " + cloud and time is not None:
            r = {"inSystem": None, "introduced": 0.0, "escaped": 0.0,
                 "transferred": 0.0, "phaseChange": None}
            j = i + 1
            while j < len(lines) and lines[j].startswith(("    ", "   |")):
                s = lines[j].strip()
                m = re.match(r"Current mass in system\s*= " + NUMBER, s)
                if m:
                    r["inSystem"] = float(m.group(1))
                    mantissa = m.group(1).lower().split("e")[0].lstrip("-+0.")
                    r["digits"] = len(mantissa.replace(".", ""))
                m = re.match(r"- mass introduced\s*= " + NUMBER, s)
                if m:
                    r["introduced"] += float(m.group(1))
                if s.startswith("Parcel fate: system"):
                    m = re.match(r"- escape\s*= " + NUMBER + ", " + NUMBER, lines[j + 1].strip())
                    r["escaped"] += float(m.group(2))
                m = re.match(r"Mass transfer ([a-z ]+?)\s*= " + NUMBER, s)
                if m:
                    r["transferred"] += float(m.group(2))
                    if m.group(1) == "phase change":
                        r["phaseChange"] = float(m.group(2))
                j += 1
            reports[time] = r
            i = j
            continue
        i += 1
    return reports


def check_four_terms(rows, reports, digits, check):
    """sprayed = airborne + evaporated + escaped + captured in the table, and
    the table's cloud figures against the cloud's own report."""
    if not check("sprayedMass" in rows[0], "the table has the binder balance columns"):
        return
    worst = 0.0
    for r in rows:
        accounted = r["airborneMass"] + r["evaporatedMass"] + r["escapedMass"] + r["capturedTotal"]
        worst = max(worst, abs(r["sprayedMass"] - accounted) / max(r["sprayedMass"], 1e-300))
    last = rows[-1]
    check(worst <= 1e-10,
          "sprayed = airborne + evaporated + escaped + captured at %d rows, worst %.3g"
          " relative; last: %.6g = %.6g + %.6g + %.6g + %.6g kg"
          % (len(rows), worst, last["sprayedMass"], last["airborneMass"],
             last["evaporatedMass"], last["escapedMass"], last["capturedTotal"]))
    # the report's rounding (digits significant) and the table's (13)
    tolerance = 10.0 ** (1 - digits)
    worst = 0.0
    compared = 0
    for r in rows:
        rep = next((v for t, v in reports.items() if abs(t - r["Time"]) <= 1e-9 * t), None)
        if rep is None:
            continue
        compared += 1
        scale = max(rep["introduced"], 1e-300)
        for column, key in (("sprayedMass", "introduced"), ("escapedMass", "escaped"),
                            ("evaporatedMass", "phaseChange")):
            worst = max(worst, abs(r[column] - (rep[key] or 0.0)) / scale)
    check(compared > 10 and worst <= tolerance,
          "the table's sprayed, evaporated and escaped mass = the cloud's report at %d"
          " times, worst %.3g of the introduced mass (tolerance %.3g)"
          % (compared, worst, tolerance))


def check_species(rows, case, cloud, nonvolatile, check):
    """The captured mass per liquid species: its sum, and a non-volatile
    species against the parcels the cloud wrote."""
    species = [c for c in rows[0] if c.startswith("captured_")]
    if not species:
        return
    worst = max(abs(sum(r[c] for c in species) - r["capturedTotal"]) / max(r["capturedTotal"], 1e-300)
                for r in rows if r["capturedTotal"] > 0)
    check(worst <= 1e-10, "the captured mass per species (%s) sums to capturedTotal, worst"
          " %.3g relative" % (", ".join(species), worst))
    if not nonvolatile:
        return
    name, y0 = nonvolatile[0], float(nonvolatile[1])
    column = "captured_" + name
    times = [r["Time"] for r in rows]
    roots = [d for d in os.listdir(case) if d.startswith("processor")] or ["."]
    written = sorted({t for root in roots for t in os.listdir(os.path.join(case, root))
                      if os.path.isdir(os.path.join(case, root, t, "lagrangian", cloud))},
                     key=float)
    compared = 0
    worst = 0.0
    for name_t in written:
        t = float(name_t)
        now = [k for k, tt in enumerate(times) if abs(tt - t) <= 1e-9 * t]
        before = [k for k, tt in enumerate(times) if tt < t * (1 - 1e-9)]
        if not now or not before or rows[now[0]]["escapedMass"] != 0:
            continue
        injected = y0 * rows[now[0]]["sprayedMass"]
        held = cloud_species_mass(case, name_t, cloud, name)
        expected = injected - held
        got = rows[before[-1]][column]
        worst = max(worst, abs(got - expected) / injected)
        compared += 1
        share = got / max(rows[before[-1]]["capturedTotal"], 1e-300)
    check(compared > 0 and worst <= 1e-8,
          "%s (non-volatile) captured = injected - held by the parcels at %d written times,"
          " worst %.3g of the injected %s" % (column, compared, worst, name))
    if compared:
        check(share >= y0 * (1 - 1e-9),
              "%s's share of the captured mass %.6g >= its share %.3g in the injected"
              " droplets (the water evaporated before capture)" % (name, share, y0))


def main():
    cloud, case = sys.argv[1], sys.argv[-1]
    nonvolatile = sys.argv[2:-1]
    rows = read_table(os.path.join(case, "postProcessing/dropletFiber/0/dropletFiber.dat"))
    logs = sorted(glob.glob(os.path.join(case, "log.*Foam")))
    text = "".join(open(log).read() for log in logs)
    reports = cloud_reports(text, cloud)
    passed = failed = 0

    def check(ok, what):
        nonlocal passed, failed
        passed += bool(ok)
        failed += not ok
        print(("ok: " if ok else "FAILED: ") + what)
        return ok

    check(len(reports) > 10, "the log has %d reports of cloud %s" % (len(reports), cloud))
    check("counted twice" not in text, "no warning that the captured mass is counted twice")
    check(rows and rows[-1]["capturedTotal"] > 0,
          "the fibers captured %.6g kg" % (rows[-1]["capturedTotal"] if rows else 0))
    if failed:
        print("%d passed, %d failed" % (passed, failed))
        sys.exit(1)
    times = [r["Time"] for r in rows]
    worst = 0.0
    compared = 0
    last = None
    for t, r in sorted(reports.items()):
        before = [k for k, tt in enumerate(times) if tt < t * (1 - 1e-9)]
        captured = rows[before[-1]]["capturedTotal"] if before else 0.0
        taken = r["introduced"] - r["escaped"] - r["transferred"] - r["inSystem"]
        scale = max(r["introduced"], 1e-300)
        worst = max(worst, abs(taken - captured) / scale)
        compared += 1
        last = (t, taken, captured, r)
    t, taken, captured, r = last
    digits = max(rep.get("digits", 0) for rep in reports.values())
    tolerance = 2 * 10.0 ** (1 - digits)
    check(digits >= 6, "the cloud prints %d significant digits" % digits)
    check(worst <= tolerance,
          "taken from the cloud (introduced - escaped - transferred - in system) = captured"
          " at %d reports, worst %.3g of the introduced mass; at t = %g: taken %.6g kg,"
          " captured %.6g kg (tolerance %.3g)" % (compared, worst, t, taken, captured, tolerance))
    check(captured > 10 * tolerance * r["introduced"],
          "the captured mass (%.3g of the introduced) is above the report's precision"
          % (captured / r["introduced"]))
    if r["phaseChange"] is not None:
        check(r["phaseChange"] > 0, "the droplets evaporate: phase change %.6g kg" % r["phaseChange"])
    check_four_terms(rows, reports, digits, check)
    check_species(rows, case, cloud, nonvolatile, check)
    print("%d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
