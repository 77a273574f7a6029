"""The report's one PNG: binder over time, the balance, fibers and parcels over time,
the fibers over the droplet mass density (one projection for a 2D case, x-y and x-z
for a 3D one), sigma along each fiber (2D), the distribution of sigma over the fiber
length, and where the case has them the fibers' turbulent dispersion and the binder
distribution table."""
import math
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

import fiberDispersion  # noqa: E402
from fiberLoad import fiber_load  # noqa: E402
from solverLog import sprayed_at  # noqa: E402

AXES = "xyz"


def _binder_over_time(ax, r):
    t = r.table.column("Time")
    ax.plot(t, r.table.column("capturedTotal"), label="captured by the fibers")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("captured binder [kg]")
    ax.set_title("Binder captured and binder efficiency")
    if r.log is not None and r.log.history:
        sprayed = [sprayed_at(r.log.history, time) for time in t]
        efficiency = [100 * c / s if s > 0 else float("nan") for c, s in zip(r.table.column("capturedTotal"), sprayed)]
        twin = ax.twinx()
        twin.plot(t, efficiency, color="tab:red", lw=0.9, label="efficiency captured / sprayed")
        twin.set_ylabel("binder efficiency [%]", color="tab:red")
        twin.legend(loc="lower right", fontsize=8)
    ax.legend(loc="upper left", fontsize=8)


def _balance(ax, r):
    b = r.balance()
    ax.set_title("Binder balance at t = %g s" % (b["time"] if b else r.table.last()["Time"]))
    if b is None:
        ax.text(0.5, 0.5, "no cloud report in the log", ha="center", transform=ax.transAxes)
        return
    parts = [("sprayed", b["sprayed"]), ("airborne", b["airborne"]), ("left the domain", b["left"])]
    if b["evaporated"] is not None:
        parts.append(("evaporated", b["evaporated"]))
    if b["otherTransfer"]:
        parts.append(("other transfers", b["otherTransfer"]))
    parts.append(("captured", b["captured"]))
    for species, (value, _, _) in sorted(r.species()["captured"].items()):
        parts.append(("captured " + species, value))
    names = [p[0] for p in parts]
    values = [max(p[1], 1e-300) for p in parts]
    ax.barh(names, values, color=["grey"] + ["tab:blue"] * (len(parts) - 1))
    ax.set_xscale("log")
    low = min(v for v in values if v > 1e-299) if any(v > 1e-299 for v in values) else 1e-12
    ax.set_xlim(low / 10, max(values) * 10)
    for y, v in enumerate(values):
        ax.text(max(v, low / 10), y, " %.3g" % v if v > 1e-299 else " 0", va="center", fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("mass [kg]")


def _counts(ax, r):
    t = r.table.column("Time")
    ax.plot(t, r.table.column("fibers"), color="tab:green", label="fibers")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("fibers", color="tab:green")
    twin = ax.twinx()
    twin.plot(t, r.table.column("parcels"), color="tab:purple", label="parcels")
    twin.set_ylabel("parcels", color="tab:purple")
    ax.set_title("Fibers and parcels")


def _fiber_view(fig, ax, r, a, b):
    grid, fibers = r.grid, r.fibers
    if grid is not None and "rho" in grid.fields:
        rho = grid.fields["rho"]
        other = 3 - a - b  # the axis projected out: mean over it ([k, j, i] = z, y, x)
        image = rho.mean(axis=2 - other)
        if a > b:
            image = image.T
        lower = grid.origin
        upper = grid.origin + grid.spacing * (np.array(grid.shape[::-1]) - 1)
        im = ax.imshow(image, origin="lower", cmap="Blues", aspect="equal",
                       extent=[lower[a], upper[a], lower[b], upper[b]])
        fig.colorbar(im, ax=ax, orientation="horizontal", fraction=0.05, pad=0.12,
                     label="droplet mass density [kg/m³]" + (" (mean over %s)" % AXES[other] if grid.shape[0] > 1 else ""))
    if fibers is not None and len(fibers.segments) and "sigma" in fibers.point_data:
        p = fibers.points
        segments = np.stack([p[fibers.segments[:, 0]][:, [a, b]], p[fibers.segments[:, 1]][:, [a, b]]], axis=1)
        lines = LineCollection(segments, array=1e6 * fibers.segment_mean("sigma"), cmap="autumn_r", linewidths=2)
        ax.add_collection(lines)
        ax.autoscale_view()
        fig.colorbar(lines, ax=ax, fraction=0.08, pad=0.03, label="σ [mg/m]")
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("%s [m]" % AXES[a])
    ax.set_ylabel("%s [m]" % AXES[b])
    time = fibers.time if fibers is not None else (grid.time if grid is not None else float("nan"))
    ax.set_title("Fibers and droplets at t = %g s (%s-%s)" % (time, AXES[a], AXES[b]))


def _sigma_along(ax, r):
    fibers = r.fibers
    ax.set_title("σ along each fiber")
    ids = fibers.point_data.get("fiberId") if fibers is not None else None
    if ids is None:
        ax.text(0.5, 0.5, "no fibers file", ha="center", transform=ax.transAxes)
        return
    for f in np.unique(ids):
        points = fibers.points[ids == f]
        arc = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))))
        ax.plot(arc, 1e6 * fibers.point_data["sigma"][ids == f], lw=1)
    ax.set_xlabel("arc length along the fiber [m]")
    ax.set_ylabel("σ [mg/m]")
    ax.set_title("σ along each fiber at t = %g s" % fibers.time)


def _sigma_distribution(ax, r):
    load = fiber_load(r.fibers)
    ax.set_title("Distribution of σ over the fiber length")
    if load is None:
        ax.text(0.5, 0.5, "no fibers file", ha="center", transform=ax.transAxes)
        return
    lengths, edges = load["histogram"]
    ax.bar(1e6 * edges[:-1], lengths, width=1e6 * np.diff(edges), align="edge", color="tab:orange")
    ax.set_xlabel("σ, fiber mass per length [mg/m]")
    ax.set_ylabel("fiber length [m]")
    text = "t = %g s, %.4g m of fiber\nmean %.4g mg/m, CoV %.3g" % (
        load["time"], load["length"], 1e6 * load["sigmaMean"], load["sigmaCoV"])
    if "bareFraction" in load:
        text += "\nlength without captured binder %.3g %%" % (100 * load["bareFraction"])
    ax.text(0.97, 0.95, text, ha="right", va="top", transform=ax.transAxes, fontsize=8)


def _dispersion(ax, r, points):
    ax.set_title("Fibers' dispersion")
    if not points:
        ax.text(0.5, 0.5, "every fiber written at one time only", ha="center", transform=ax.transAxes)
        return
    ax.scatter([a for _, a in points], [f for f, _ in points], s=8)
    ax.axvline(0.0, color="k", lw=0.8, ls="--")
    ax.invert_yaxis()
    ax.set_xlabel("fiber centre across the fibers' mean drift, from its first write [m]")
    ax.set_ylabel("distance travelled along the drift since [m]")
    table = r.siblings.get("fiberDispersion.dat")
    rms = fiberDispersion.rms_beyond(points)
    title = "Fibers' dispersion across their drift"
    if table is not None and all(table.has(c) for c in ("uTurbRmsX", "uTurbRmsY", "uTurbRmsZ")):
        last = table.last()
        title += "\nrms u' %.3g m/s" % math.sqrt(sum(last[c] ** 2 for c in ("uTurbRmsX", "uTurbRmsY", "uTurbRmsZ")) / 3)
    if rms is not None:
        title += ("," if "\n" in title else "\n") + " rms %.3g m beyond %.3g m of travel" % (rms[0], rms[2])
    ax.set_title(title, fontsize=10)


def expected_partner(table, name):
    """The expected mode's column next to one of the run's own (bareFraction ->
    expectedBareFraction), or None where the table has none."""
    partner = "expected" + name[:1].upper() + name[1:]
    return partner if table.has(partner) else None


def _binder_distribution(ax, r):
    """Bare fraction and CoV of sigma over time: the run's own (solid) and, where the
    table has them, the expected mode's on the same fibers (dashed, the same colour)."""
    table = r.siblings["binderDistribution.dat"]
    t = table.column("Time")
    for name in table.names:
        if name == "Time" or name.startswith("expected") or not re.search(r"fraction|cov|coefficient", name, re.I):
            continue
        line, = ax.plot(t, table.column(name), label=name + " (this run)")
        partner = expected_partner(table, name)
        if partner is not None:
            ax.plot(t, table.column(partner), "--", color=line.get_color(), label=name + " (expected mode)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("fraction / coefficient of variation")
    ax.set_title("Binder distribution (binderDistribution.dat)")
    ax.legend(fontsize=8)


def _laid(r):
    """Across, along [m] and the glass and binder [kg] each laid row stands for."""
    t = r.siblings["laydown.dat"]
    n = np.array(t.column("represents"))
    return (np.array(t.column("across")), np.array(t.column("along")),
            n * np.array(t.column("glassMass")), n * np.array(t.column("binderMass")))


def _complete_rows(r):
    """(along from, along to) of the complete rows in the latest mat profile, or None."""
    note = r.mat_profile["notes"][0] if r.mat_profile else ""
    m = re.search(r"\(along (\S+) to (\S+) m\)", note)
    return (float(m.group(1)), float(m.group(2))) if m else None


def _mat_map(ax, r):
    """The mat on the belt: the function object's latest map (mat_<time>.vti: each fiber
    along its length), the complete rows between the dashed lines; without it the glass
    laid (laydown.dat) binned by the fibers' centres."""
    across, along, glass, binder = _laid(r)
    total = glass.sum() + binder.sum()
    if r.mat is not None:
        m = r.mat
        h = m.spacing[:2]
        x0 = m.origin[0] + h[0] * (m.start[0] - 0.5)
        y0 = m.origin[1] + h[1] * (m.start[1] - 0.5)
        values = m.fields["areaWeight"][0]
        xe = x0 + h[0] * np.arange(values.shape[1] + 1)
        ye = y0 + h[1] * np.arange(values.shape[0] + 1)
        mesh = ax.pcolormesh(xe, ye, values, cmap="viridis")
        rows = _complete_rows(r)
        for y in rows or ():
            ax.axhline(y, color="w", ls="--", lw=1)
        source = "mat_%g.vti%s" % (m.time, ", complete rows dashed" if rows else ", no complete row yet")
    else:
        counts, xe, ye = np.histogram2d(across, along, bins=30, weights=glass)
        area = (xe[1] - xe[0]) * (ye[1] - ye[0])
        mesh = ax.pcolormesh(xe, ye, 1000 * counts.T / area, cmap="viridis")
        source = "laydown.dat, by centres"
    plt.colorbar(mesh, ax=ax, label="glass area weight [g/m²]")
    ax.set_xlabel("across the belt [m]")
    ax.set_ylabel("along the belt [m]")
    ax.set_title("The mat (%s): %d fibers laid, LOI %.2f %%"
                 % (source, len(glass), 100 * binder.sum() / total if total else 0), fontsize=10)


def _mat_profile(ax, r):
    """Across the belt over the complete rows: glass area weight and LOI with their
    one-sigma error bands (matProfile_<time>.dat), the CoV split into counting noise and
    the mat's own."""
    p = r.mat_profile
    if p is None:
        ax.text(0.5, 0.5, "no complete row of the mat yet:\nthe belt has not carried a row\n"
                "across the whole laying zone\n(run longer: the hood's Allrun -steady)",
                ha="center", va="center", transform=ax.transAxes)
        ax.set_title("Across the width", fontsize=10)
        return
    x = np.array(p["across"])
    g, ge = np.array(p["areaWeight"]), np.array(p["areaWeightError"])
    loi, le = np.array(p["LOI"]), np.array(p["LOIError"])
    ax.fill_between(x, g - ge, g + ge, color="C0", alpha=0.3)
    ax.plot(x, g, "o-", color="C0", label="glass area weight")
    ax.set_xlabel("across the belt [m]")
    ax.set_ylabel("glass area weight [g/m²] (blue)")
    right = ax.twinx()
    right.fill_between(x, loi - le, loi + le, color="C3", alpha=0.25)
    right.plot(x, loi, "s-", color="C3", label="LOI")
    right.set_ylabel("LOI [%] (red)")
    m = re.search(r"CoV (\S+): counting noise (\S+), the mat's own (\S+) \(two-sigma bound (\S+)\)",
                  " ".join(p["notes"]))
    split = ("CoV %s: counting noise %s, the mat's own %s (< %s)"
             % tuple("%.3g" % float(v) for v in m.groups())
             if m else "")
    ax.set_title("Across, complete rows at t = %g s (bands: one sigma)\n%s" % (p["time"], split), fontsize=10)


def _mat_orientation(ax, r):
    """The laid fibers' orientation in the belt's plane (laydown.dat): the glass-weighted
    distribution of the angle to the belt's motion, and the order <cos 2 theta>."""
    t = r.siblings["laydown.dat"]
    across, along = np.array(t.column("orientation_across")), np.array(t.column("orientation_along"))
    weight = np.array(t.column("represents")) * np.array(t.column("glassMass"))
    inPlane = across ** 2 + along ** 2 > 0
    theta = np.degrees(np.arctan2(np.abs(across[inPlane]), np.abs(along[inPlane])))
    ax.hist(theta, bins=18, range=(0, 90), weights=weight[inPlane] / weight[inPlane].sum(), color="C2")
    c2 = np.cos(np.radians(2 * theta))
    order = (weight[inPlane] * c2).sum() / weight[inPlane].sum() if inPlane.any() else 0.0
    ax.set_xlabel("angle to the belt's motion [deg] (0 along, 90 across)")
    ax.set_ylabel("share of the glass")
    ax.set_title("Orientation in the mat: <cos 2θ> = %.3f (1 along, -1 across, 0 random)" % order,
                 fontsize=10)


def write_png(r, path, planar, points):
    """Every panel the case has data for, three to a row."""
    panels = [_binder_over_time, _balance, _counts, ("view", 0, 1)]
    panels.append(_sigma_along if planar else ("view", 0, 2))
    panels.append(_sigma_distribution)
    if "fiberDispersion.dat" in r.siblings:
        panels.append("dispersion")
    if "binderDistribution.dat" in r.siblings:
        panels.append(_binder_distribution)
    if "laydown.dat" in r.siblings:
        panels += [_mat_map, _mat_profile, _mat_orientation]
    rows = (len(panels) + 2) // 3
    fig, axes = plt.subplots(rows, 3, figsize=(19, 6 * rows), squeeze=False)
    fig.subplots_adjust(left=0.05, right=0.95, bottom=0.06, top=1 - 0.8 / (6 * rows), wspace=0.5, hspace=0.45)
    for ax, panel in zip(axes.flat, panels):
        if isinstance(panel, tuple):
            _fiber_view(fig, ax, r, panel[1], panel[2])
        elif panel == "dispersion":
            _dispersion(ax, r, points)
        else:
            panel(ax, r)
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    fig.suptitle("%s: dropletFiber report (function object %s)" % (r.case_name(), r.name))
    fig.savefig(path, dpi=90)
    plt.close(fig)
