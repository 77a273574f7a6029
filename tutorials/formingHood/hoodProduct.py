#!/usr/bin/env python3
"""The forming hood's product: binder efficiency, binder content (LOI), where the
rest of the binder goes, the spray across the veil and the binder on the fibers.

From a finished run (serial or 2 ranks): the function object's per-step table
(sprayedMass, capturedTotal, captured_<species>), binderDistribution.dat, the
coupling grid's droplet mass density rho (grid VTK files), the solver log (the
glass flow of the weighted fibers, the cloud's fates via hoodBalance.py) and
constant/sprayCloudProperties (the resin's mass fraction, the nozzles).

- Binder efficiency, captured / sprayed: over the run, and in windows of WINDOW s
  from FROM s on (the rates once the spray and the veil are established); their
  mean and spread (standard deviation over the windows, and of their mean).
- Binder content of the product (LOI): captured resin / (glass + captured resin),
  the rates in the same windows; glass: the injectors' physical flow.
- The spray along the nozzles' axes: rho on the coupling grid, averaged over the
  eight nozzles and the write times from FROM on; with a second case (the same
  run with Allrun -noDepletion) both, and their ratio: the depletion across the
  veil.

- The work balance over the processors (parallelStatistics.dat): each stage's
  max / mean, summed over the run's steps.

The tables, the grid files and the cloud's report are read by the project's report
package (caseOutputs, vtkFiles, solverLog; found by reportPackage.py).

Usage: hoodProduct.py CASE [NO_DEPLETION_CASE] [-from T] [-window W]
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hoodBalance  # noqa: E402  (puts the report's modules on the import path)
import caseOutputs  # noqa: E402
import vtkFiles  # noqa: E402

RESIN = "C16H34"  # the resin's stand-in (constant/sprayCloudProperties)
NAME = "dropletFiber"  # the function object's name (system/controlDict)


def table(case, file_name):
    """The function object's table file_name as {column: array} (None: no such table)."""
    found = caseOutputs.read_table(case, NAME, file_name)
    return None if found is None else {n: np.array(found.column(n)) for n in found.names}


def resin_fraction(case):
    text = open(os.path.join(case, "constant", "sprayCloudProperties")).read()
    return float(re.search(r"\b%s\s+([0-9.eE+-]+)\s*;" % RESIN, text).group(1))


def nozzles(case):
    """(position, unit axis) of each nozzle of positionAxis."""
    text = open(os.path.join(case, "constant", "sprayCloudProperties")).read()
    block = text[text.index("positionAxis"):]
    block = block[:block.index(");")]
    number = r"\s*([-+0-9.eE]+)"
    found = re.findall(r"\(\(" + number * 3 + r"\s*\)\s*\(" + number * 3 + r"\s*\)\)", block)
    out = []
    for v in found:
        p, a = np.array(v[:3], dtype=float), np.array(v[3:], dtype=float)
        out.append((p, a / np.linalg.norm(a)))
    return out


def glass_flow(log):
    """The injectors' glass flow (kg/s) as the log's weighted-fibers report gives it."""
    found = re.findall(r"injector (\S+): \S+ computed fibers/s, each represents \S+: \S+ "
                       r"physical fibers/s, glass (\S+) kg/s", open(log).read())
    return sum(float(f) for f in dict(found).values()) if found else None


def physical_fibers(log):
    found = re.findall(r"injector (\S+): (\S+) computed fibers/s, each represents (\S+): (\S+) "
                       r"physical fibers/s", open(log).read())
    seen = {}
    for name, rate, n, physical in found:
        seen.setdefault(name, (float(rate), float(n), float(physical)))
    return seen


def grid_rho(path):
    """rho [k, j, i] of a grid .vti or .pvti, with its first node's position and spacing."""
    grid = vtkFiles.Grid(None, path)
    return grid.fields["rho"], grid.origin + grid.spacing * grid.start, grid.spacing


def interpolate(rho, origin, spacing, x):
    f = (x - origin) / spacing  # (i, j, k)
    i0 = np.floor(f).astype(int)
    if np.any(i0 < 0) or np.any(i0 + 1 >= np.array(rho.shape[::-1])):
        return np.nan
    w = f - i0
    value = 0.0
    for di in (0, 1):
        for dj in (0, 1):
            for dk in (0, 1):
                c = (w[0] if di else 1 - w[0]) * (w[1] if dj else 1 - w[1]) * (w[2] if dk else 1 - w[2])
                value += c * rho[i0[2] + dk, i0[1] + dj, i0[0] + di]
    return value


def axis_profile(case, start, distances):
    """rho along the nozzles' axes, mean over the nozzles and the grid files from start on."""
    folder = caseOutputs.start_folders(case, NAME)[0]
    used = [(t, p) for t, p in vtkFiles.series(folder, "grid.vti") if t >= start - 1e-9]
    profile = np.zeros(len(distances))
    for _, path in used:
        rho, origin, spacing = grid_rho(path)
        for p, a in nozzles(case):
            profile += [interpolate(rho, origin, spacing, p + s * a) for s in distances]
    return profile / (len(used) * len(nozzles(case))), [t for t, _ in used]


def windows(t, columns, start, width, end):
    """Per window [a, a + width) from start to end: the increments of each column."""
    edges = np.arange(start, end + 1e-9, width)
    at = [np.interp(e, t, t) for e in edges]
    out = []
    for a, b in zip(at[:-1], at[1:]):
        out.append({k: np.interp(b, t, c) - np.interp(a, t, c) for k, c in columns.items()})
    return edges, out


def spread(values):
    values = np.array(values)
    sd = values.std(ddof=1) if len(values) > 1 else float("nan")
    return values.mean(), sd, sd / np.sqrt(len(values))


def main():
    args = sys.argv[1:]
    start, width = 0.3, 0.05
    if "-from" in args:
        i = args.index("-from"); start = float(args[i + 1]); del args[i:i + 2]
    if "-window" in args:
        i = args.index("-window"); width = float(args[i + 1]); del args[i:i + 2]
    case = args[0]
    other = args[1] if len(args) > 1 else None
    log = os.path.join(case, "log.sprayFoam")
    d = table(case, "dropletFiber.dat")
    t = d["Time"]
    end = t[-1]
    if end < start + width:  # a short run: its last third
        start = round(t[0] + 2 * (end - t[0]) / 3, 3)
        width = (end - start) / 2
    y = resin_fraction(case)
    glass = glass_flow(log)
    print("Product of the forming hood at t = %g s (windows of %g s from %g s)" % (end, width, start))
    for name, (rate, n, physical) in sorted(physical_fibers(log).items())[:1]:
        print("    fibers: %g computed/s per stream, each represents %.4g physical" % (rate, n))
    if glass:
        print("    glass injected: %.6g kg/s (%.1f kg/h)" % (glass, 3600 * glass))

    if "sprayedMass" not in d:
        print("    (no depletion: the table has no sprayed and per-species columns)")
    else:
        sprayed, captured, resin = d["sprayedMass"], d["capturedTotal"], d["captured_" + RESIN]
        print("    resin (binder solids) in the sprayed liquid: %.3g" % y)
        print("Over the run: sprayed %.4e kg, captured %.4e kg: binder efficiency %.4f"
              % (sprayed[-1], captured[-1], captured[-1] / sprayed[-1]))
        print("    resin sprayed %.4e kg, captured %.4e kg: resin efficiency %.4f"
              % (y * sprayed[-1], resin[-1], resin[-1] / (y * sprayed[-1])))
        # where the rest goes: the cloud's fates (hoodBalance.py), shares of the sprayed
        r = hoodBalance.last_cloud_report(log)
        evaporated, walls, out = hoodBalance.fates(r)
        cap = hoodBalance.captured_total(case, r["time"])
        print("Where the binder sprayed by t = %s s is (share of the sprayed mass):" % r["timeName"])
        for label, v in [("captured by the fibers", cap), ("evaporated (water)", evaporated),
                         ("through the outlet", out), ("on the hood walls", walls),
                         ("airborne", r["inSystem"])]:
            print("    %-24s %.4e kg  %7.3f %%" % (label, v, 100 * v / r["introduced"]))

        edges, per = windows(t, {"sprayed": sprayed, "captured": captured, "resin": resin},
                             start, width, end)
        eff = [w["captured"] / w["sprayed"] for w in per]
        reff = [w["resin"] / (y * w["sprayed"]) for w in per]
        print("Windows (rates once established): t, binder efficiency, resin efficiency, LOI")
        lois = []
        for a, w, e, re_ in zip(edges, per, eff, reff):
            resin_rate = w["resin"] / width
            loi = resin_rate / (glass + resin_rate) if glass else float("nan")
            lois.append(loi)
            print("    %.3f-%.3f  %.4f  %.4f  %.4f" % (a, a + width, e, re_, loi))
        for label, v in [("binder efficiency (captured/sprayed)", eff),
                         ("resin efficiency", reff), ("binder content (LOI)", lois)]:
            m, sd, se = spread(v)
            print("    %-38s mean %.4f, sd over windows %.4f, sd of the mean %.4f" % (label, m, sd, se))

    b = table(case, "binderDistribution.dat")
    if b is not None:
        print("Binder on the fibers at t = %g s: %.4g m of fiber (computed), bare %.3f, "
              "mean sigma %.4g kg/m, CoV %.3f, %.4g hits/m; expected mode: bare %.3f, CoV %.3f"
              % (b["Time"][-1], b["fiberLength"][-1], b["bareFraction"][-1], b["meanSigma"][-1],
                 b["sigmaCoV"][-1], b["hitsPerLength"][-1], b["expectedBareFraction"][-1],
                 b["expectedSigmaCoV"][-1]))

    p = table(case, "parallelStatistics.dat")
    if p is not None:
        print("Work balance over the processors, the run's steps summed (max / mean; 1 is even):")
        print("    " + ", ".join(
            "%s %.3f" % (stage, p[stage + "Max"].sum() / p[stage + "Mean"].sum())
            for stage in ("cpuDeposit", "cpuCollision", "cpuFibers", "parcels", "nodeWeights",
                          "collisionSamples", "fiberPoints") if p[stage + "Mean"].sum() > 0))

    distances = np.arange(0.0, 0.4501, 0.05)  # to the spinner's axis (s = 0.42 m)
    profile, times = axis_profile(case, start, distances)
    header = "Droplet mass density rho (kg/m3) along the nozzles' axes (mean of 8 nozzles, times %s)" \
        % " ".join("%g" % x for x in times)
    p0, a0 = nozzles(case)[0]
    if other:
        second, _ = axis_profile(other, start, distances)
        print(header + ", with depletion (%s) and without (%s):" % (case, other))
        print("    %6s %6s %6s  %11s %11s %7s" % ("s [m]", "y [m]", "r [m]", "depletion", "none", "ratio"))
    else:
        print(header + ":")
        print("    %6s %6s %6s  %11s" % ("s [m]", "y [m]", "r [m]", "rho"))
    for i, s in enumerate(distances):
        x = p0 + s * a0
        r = np.hypot(x[0], x[2])
        if other:
            ratio = profile[i] / second[i] if second[i] > 0 else float("nan")
            print("    %6.3f %6.3f %6.3f  %11.4e %11.4e %7.3f" % (s, x[1], r, profile[i], second[i], ratio))
        else:
            print("    %6.3f %6.3f %6.3f  %11.4e" % (s, x[1], r, profile[i]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
