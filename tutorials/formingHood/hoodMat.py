#!/usr/bin/env python3
"""The forming hood's product: the primary mat on the conveyor under the hood, from the
fibers the function object laid on it (fibers.laydown; laydown.dat, one row per fiber).

The product is the mat's complete rows (Allrun -steady: rows that crossed the whole
laying zone, the outlet's 1 m along the belt, 5 s at 0.2 m/s, after the laying became
steady at steadyFrom): the function object's last matProfile_<time>.dat gives their glass
area weight and binder content with their standard errors and the across-width CoV split
into counting noise and the mat's own (docs/model.md sec. 11, P60, P61). The binder the
fibers carry is resin and the water not yet evaporated; the product's LOI is the resin's
(water gone), at the resin's share of the binder captured. Beside it, the second route
to the binder content, the capture balance over the steady window: the binder and glass
the log's balances put into the mat between the write times at steadyFrom and at the
end (binder captured less what the airborne and the lost fibers carry), with the counting
noise of the fibers laid in the window; the two must agree within their errors. (Resin
captured over glass laid does not: it counts the binder of the fibers lost to the walls.)

A run without complete rows (the default 0.6 s) takes the product from the laying rate
once it is established (from FROM s on): the glass and binder laid per second in each
column across the belt, carried away at the belt speed V, give the steady mat's area
weight per column

    G_c = (glass laid per s in column c) / (h V)       (h: the column's width)

and likewise the binder's; LOI = binder / (glass + binder); the across-width coefficient
of variation of G (the figure a plant quotes for uniformity); the binder efficiency into
the product = binder laid / binder sprayed (the table's sprayedMass) over the same window.
The belt's speed, width and cells come from the solver log's settings line. Writes
hoodMat.png: the laying rate over the outlet and the product across the belt.

The tables are read by the project's report package (caseOutputs, through
hoodProduct.py's table).

Usage: hoodMat.py CASE [-from T] [-png FILE]
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hoodProduct  # noqa: E402

NUMBER = r"([-+0-9.eE]+)"


def belt(log):
    """(speed, across min, across max, cell) from the log's laydown settings line."""
    m = re.search(r"laydown: belt through .* velocity \(" + NUMBER + " " + NUMBER + " " + NUMBER
                  + r"\) m/s, across " + NUMBER + " to " + NUMBER + " m, map cells " + NUMBER,
                  open(log).read())
    if not m:
        return None
    v = np.array([float(m.group(i)) for i in (1, 2, 3)])
    return np.linalg.norm(v), float(m.group(4)), float(m.group(5)), float(m.group(6))


def steady_from(log):
    """steadyFrom [s] from the log's laydown settings line (None when not given)."""
    m = re.search(r"complete rows entered the laying zone after steadyFrom " + NUMBER + " s",
                  open(log).read())
    return float(m.group(1)) if m else None


def laid_by_time(log):
    """{write time: (glass laid, binder laid) [kg]} from the log's balances."""
    out, now, glass = {}, None, None
    for line in open(log):
        m = re.search(r"laydown at time " + NUMBER + ":", line)
        if m:
            now = float(m.group(1))
        m = re.match(r"^    glass: injected \S+ kg = in the air \S+ \+ laid " + NUMBER, line)
        if m and now is not None:
            glass = float(m.group(1))
        m = re.match(r"^    binder: captured \S+ kg = on airborne fibers \S+ \+ laid " + NUMBER, line)
        if m and now is not None and glass is not None:
            out[now] = (glass, float(m.group(1)))
    return out


def lost_share(log):
    """The share of the binder captured that the lost fibers carry, at the last write."""
    found = re.findall(r"binder: captured " + NUMBER + r" kg = on airborne fibers \S+ \+ laid \S+ \+ on lost"
                       r" fibers " + NUMBER, open(log).read())
    return float(found[-1][1]) / float(found[-1][0]) if found else 0.0


def mat_profile(case):
    """The last matProfile_<time>.dat (the report package's reader): (time, its comment
    lines) or None."""
    p = hoodProduct.caseOutputs.latest_mat_profile(case, hoodProduct.NAME)
    return None if p is None else (p["time"], p["notes"])


def resin_share(table):
    """The resin's share of all binder captured so far (the fibers carry one binder mass)."""
    column = "captured_" + hoodProduct.RESIN
    if column in table and table["capturedTotal"][-1] > 0:
        return table[column][-1] / table["capturedTotal"][-1]
    return 1.0


def product(case, log, table):
    """The product from the complete rows and the capture balance beside it, and whether
    they agree within two standard errors of their difference (printed)."""
    time, notes = mat_profile(case)
    m = re.search(r"glass area weight " + NUMBER + r" \+- " + NUMBER + r" g/m2, LOI " + NUMBER + r" \+- "
                  + NUMBER + r" %, across-width CoV " + NUMBER + r": counting noise " + NUMBER
                  + r", the mat's own " + NUMBER + r" \(two-sigma bound " + NUMBER, notes[1])
    G, dG, loi, dloi, cov, noise, own, bound = (float(v) for v in m.groups())
    share = resin_share(table)
    # Resin over glass + resin from binder over glass + binder: L_r = s L / (1 - L + s L)
    L = loi / 100
    resinLoi = share * L / (1 - L + share * L)
    dResin = dloi / 100 * share / (1 - L + share * L) ** 2
    print("The product: the mat's complete rows at %g s (%s)" % (time, notes[0].split("over its ")[1]))
    print("    glass area weight %.1f +- %.1f g/m2; binder content (resin and water) %.2f +- %.2f %%;"
          % (G, dG, loi, dloi))
    print("    LOI (resin, %.1f %% of the binder captured) %.2f +- %.2f %%" % (100 * share, 100 * resinLoi,
                                                                         100 * dResin))
    print("    across-width CoV %.3f: counting noise %.3f, the mat's own %.3f (two-sigma bound %.3f)"
          % (cov, noise, own, bound))
    # The capture balance over the steady window: the binder and glass the log's balances
    # put into the mat between the write times at steadyFrom and at the end
    start = steady_from(log) or 0.0
    laidAt = laid_by_time(log)
    t0 = min(laidAt, key=lambda w: abs(w - start))
    t1 = max(laidAt)
    glass = laidAt[t1][0] - laidAt[t0][0]
    binder = laidAt[t1][1] - laidAt[t0][1]
    L2 = binder / (glass + binder)
    balance = share * L2 / (1 - L2 + share * L2)
    # Its counting noise: the fibers laid in the window as independent draws
    laid = hoodProduct.table(case, "laydown.dat")
    use = (laid["Time"] > t0) & (laid["Time"] <= t1)
    n = laid["represents"][use]
    g, b = n * laid["glassMass"][use], n * laid["binderMass"][use]
    dL2 = L2 * (1 - L2) * np.sqrt((g ** 2).sum() / g.sum() ** 2 + (b ** 2).sum() / b.sum() ** 2
                                  - 2 * (g * b).sum() / (g.sum() * b.sum()))
    dBalance = dL2 * share / (1 - L2 + share * L2) ** 2
    print("The capture balance, %g to %g s (the log's binder and glass laid): binder %.4g kg on glass"
          " %.4g kg, LOI (resin) %.2f +- %.2f %%" % (t0, t1, binder, glass, 100 * balance, 100 * dBalance))
    sigma = abs(resinLoi - balance) / np.hypot(dResin, dBalance)
    print("    the two routes %s: they differ by %.2f standard errors; the product's figure is the"
          " complete rows'" % ("agree" if sigma <= 2 else "DISAGREE", sigma))
    # The binder captured in the window includes what the fibers that are lost carry
    t = table["Time"]
    resin = np.interp(t1, t, table["captured_" + hoodProduct.RESIN]) - np.interp(
        t0, t, table["captured_" + hoodProduct.RESIN])
    print("    (resin captured over glass laid, %.2f %%, counts the binder of the fibers lost to the"
          " walls, %.0f %% of the binder captured by %g s: not the product's)"
          % (100 * resin / (glass + resin), 100 * lost_share(log), t1))
    return 0


def main():
    args = sys.argv[1:]
    start, png = 0.3, "hoodMat.png"
    for flag in ("-from", "-png"):
        if flag in args:
            i = args.index(flag)
            value = args[i + 1]
            del args[i:i + 2]
            if flag == "-from":
                start = float(value)
            else:
                png = value
    if len(args) != 1:
        print(__doc__)
        return 1
    case = args[0]
    log = os.path.join(case, "log.sprayFoam")
    settings = belt(log) if os.path.isfile(log) else None
    laid = hoodProduct.table(case, "laydown.dat")
    if settings is None:
        print("hoodMat: no belt in %s (fibers.laydown not given)" % case)
        return 1
    if laid is None or len(laid["Time"]) == 0:
        print("hoodMat: no fiber has reached the belt yet")
        return 0
    speed, lo, hi, h = settings
    t = laid["Time"]
    table = hoodProduct.table(case, "dropletFiber.dat")
    if mat_profile(case) is not None:
        return product(case, log, table)
    print("hoodMat: no complete row of the mat (run ./Allrun -steady): the product from the laying rate")
    end = float(table["Time"][-1])
    if end - start <= 0 or not (t >= start - 1e-9).any():
        # A short run: from the first fiber laid (not yet an established rate)
        start = float(t.min())
        print("hoodMat: the run ends before %g s: the mat from the first fiber laid, at %g s" % (end, start))
    window = max(end - start, 1e-12)
    use = t >= start - 1e-9
    n = laid["represents"][use]
    glass, binder = n * laid["glassMass"][use], n * laid["binderMass"][use]
    columns = int(round((hi - lo) / h))
    column = np.clip(np.floor((laid["across"][use] - lo) / h).astype(int), 0, columns - 1)
    g = np.bincount(column, glass, columns) / window / (h * speed)
    b = np.bincount(column, binder, columns) / window / (h * speed)
    sprayed = np.interp(end, table["Time"], table["sprayedMass"]) - np.interp(start, table["Time"],
                                                                             table["sprayedMass"])
    print("The mat on the belt (laydown.dat, %g-%g s: %d computed fibers laid, %.3g physical),"
          % (start, end, int(use.sum()), n.sum()))
    print("    belt %.3g m/s, %.3g m wide, %d columns of %.3g m" % (speed, hi - lo, columns, h))
    print("    glass laid %.4g kg/s, binder %.4g kg/s" % (glass.sum() / window, binder.sum() / window))
    print("    area weight (mean over the width): glass %.1f g/m2, binder %.2f g/m2, LOI %.2f %%"
          % (1000 * g.mean(), 1000 * b.mean(), 100 * b.sum() / (g.sum() + b.sum())))
    print("    across-width CoV: glass area weight %.3f, LOI %.3f"
          % (g.std() / g.mean(), np.std(b / (g + b)) / np.mean(b / (g + b))))
    print("    binder efficiency into the product: laid %.4g / sprayed %.4g kg = %.3f"
          % (binder.sum(), sprayed, binder.sum() / sprayed if sprayed > 0 else 0))
    # The fibers carry their binder as one mass (not per species): the laid binder's resin
    # taken at the resin's share of all binder captured so far
    resinColumn = "captured_" + hoodProduct.RESIN
    share = 1.0
    if resinColumn in table and table["capturedTotal"][-1] > 0:
        share = table[resinColumn][-1] / table["capturedTotal"][-1]
        r = share * b
        print("    resin (%.1f %% of the binder captured): %.2f g/m2, the product's LOI (water gone) %.2f %%"
              % (100 * share, 1000 * r.mean(), 100 * r.sum() / (g.sum() + r.sum())))
    draw(png, laid, use, speed, lo, hi, h, g, share * b, window)
    print("hoodMat: wrote %s" % png)
    return 0


def draw(png, laid, use, speed, lo, hi, h, g, resin, window):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5))
    n = laid["represents"][use]
    foot = speed * laid["Time"][use] - laid["along"][use]  # along the motion, fixed frame
    edges = np.arange(lo, hi + h / 2, h)
    counts, xe, ye = np.histogram2d(laid["across"][use], foot, bins=[edges, edges - (lo + hi) / 2],
                                    weights=n * laid["glassMass"][use])
    mesh = left.pcolormesh(xe, ye, 1000 * counts.T / (h * h * window), cmap="viridis")
    plt.colorbar(mesh, ax=left, label="glass laid [g/(m² s)]")
    left.set_xlabel("across the belt [m]")
    left.set_ylabel("along the belt's motion [m] (fixed frame)")
    left.set_title("Where the fibers land on the belt")
    centres = 0.5 * (edges[1:] + edges[:-1])
    right.plot(centres, 1000 * g, "o-", label="glass [g/m²]")
    right.set_xlabel("across the belt [m]")
    right.set_ylabel("the mat's glass area weight [g/m²] (blue)")
    other = right.twinx()
    loi = np.divide(100 * resin, g + resin, out=np.zeros_like(g), where=g + resin > 0)
    other.plot(centres, loi, "s--", color="tab:red", label="LOI [%]")
    other.set_ylabel("LOI, resin / (glass + resin) [%] (red)")
    right.set_title("The product across the belt: CoV %.3f" % (g.std() / g.mean()))
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
