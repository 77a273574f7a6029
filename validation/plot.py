#!/usr/bin/python3
"""Figures of the validation against Schroeder et al. 2011, sec. 6, in the style of the
paper's figures 7-10: mass hitting the fiber per step and relative error against the
swept parameter, one curve per method. Reads the CSVs written by paperValidation.

    /usr/bin/python3 validation/plot.py CSV_DIR [PNG_DIR]      (PNG_DIR defaults to CSV_DIR)

Relative errors are against the expectation from the flow rate ("truth" column) unless a
panel says otherwise.
"""
import csv
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# One look per method across all figures.
STYLE = OrderedDict(
    [
        ("truth", dict(label="flow-rate expectation", color="black", ls="-", lw=2.2, marker=None)),
        ("formula", dict(label="formula (eq. 9, counted density)", color="tab:gray", ls="--", marker="x")),
        ("geometric", dict(label="geometric (droplets at parcel)", color="tab:red", ls="-", marker="s", ms=3)),
        ("spread", dict(label="geometric, droplets spread in r_min", color="tab:orange", ls=":", marker="v", ms=3)),
        ("fine", dict(label="fine reference (jittered, spread) ± SE", color="tab:brown", ls="-.", marker="D", ms=3)),
        ("grid50_paper", dict(label="grid 50x50, paper deposit", color="tab:purple", ls="--", marker="^", ms=4)),
        ("grid100_paper", dict(label="grid 100x100, paper deposit", color="tab:blue", ls="--", marker="o", ms=4)),
        ("grid250_paper", dict(label="grid 250x250, paper deposit", color="tab:cyan", ls="--", marker="o", ms=3)),
        ("grid50_improved", dict(label="grid 50x50, improved", color="tab:purple", ls="-", marker="^", ms=4, mfc="none")),
        ("grid100_improved", dict(label="grid 100x100, improved", color="tab:green", ls="-", marker="o", ms=4, mfc="none")),
        ("grid250_improved", dict(label="grid 250x250, improved", color="tab:olive", ls="-", marker="o", ms=3, mfc="none")),
    ]
)


def read(directory, name):
    with open(os.path.join(directory, name + ".csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    columns = OrderedDict()
    for key in rows[0].keys():
        if key == "label":
            columns[key] = [r[key] for r in rows]
        else:
            columns[key] = [float(r[key]) for r in rows]
    return columns


def plot_method(ax, x, table, column, relative=None, scale=1.0):
    if column not in table:
        return
    style = dict(STYLE.get(column, dict(label=column)))
    label = style.pop("label")
    y = table[column]
    se = table.get(column + "SE")
    if relative is not None:
        y = [v / r - 1.0 for v, r in zip(y, relative)]
        se = [s / r for s, r in zip(se, relative)] if se else None
    y = [v * scale for v in y]
    if se and column == "fine":
        ax.errorbar(x, y, yerr=[s * scale for s in se], label=label, capsize=2, **style)
    else:
        ax.plot(x, y, label=label, **style)


def finish(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


def two_panel(table, x, xlabel, methods, title, path, reverse=False, logx=False, logy_mass=False):
    fig, (a, b) = plt.subplots(1, 2, figsize=(13, 4.8))
    for m in ["truth"] + methods:
        plot_method(a, x, table, m)
    for m in methods:
        plot_method(b, x, table, m, relative=table["truth"], scale=100.0)
    a.set_ylabel("mass hitting the fiber per step [kg]")
    b.set_ylabel("relative error [%]")
    b.axhline(0.0, color="black", lw=0.8)
    for ax, sub in ((a, "(a) mass hitting the fiber"), (b, "(b) relative error against the flow-rate expectation")):
        ax.set_xlabel(xlabel)
        ax.set_title(sub, fontsize=10)
        ax.grid(alpha=0.3)
        if reverse:
            ax.invert_xaxis()
        if logx:
            ax.set_xscale("log")
    if logy_mass:
        a.set_yscale("log")
    b.legend(fontsize=7, loc="best")
    fig.suptitle(title, fontsize=11)
    finish(fig, path)


def figure7(d, out):
    t = read(d, "figure7")
    methods = ["formula", "geometric", "fine", "grid100_paper", "grid50_paper", "grid100_improved", "grid50_improved"]
    two_panel(t, t["streams"], "number of streams (fixed total flow rate; 1-10 droplets per parcel)", methods,
              "Figure 7: constant flow rate, variable number of streams (r_F = 1 cm)",
              os.path.join(out, "figure7.png"), reverse=True)


def figure8(d, out):
    t = read(d, "figure8")
    methods = ["formula", "geometric", "spread", "fine", "grid100_paper", "grid100_improved", "grid250_paper",
               "grid250_improved"]
    two_panel(t, t["dropletsPerParcel"], "droplets per parcel (log scale)", methods,
              "Figure 8: 100 streams, droplets per parcel varied (r_F = 1 cm)", os.path.join(out, "figure8.png"),
              logx=True, logy_mass=True)


def figure9(d, out):
    t = read(d, "figure9")
    x = [r * 1e3 for r in t["fiberRadius"]]
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(17, 4.8))
    for m in ["truth", "geometric", "fine", "grid100_paper", "grid100_improved"]:
        plot_method(a, x, t, m)
    for m in ["geometric", "fine", "grid100_paper", "grid100_improved"]:
        plot_method(b, x, t, m, relative=t["truth"], scale=100.0)
    b.plot(x, [(v / r - 1) * 100 for v, r in zip(t["formulaNumber"], t["truth"])], color="tab:pink", ls="--",
           label="formula with number-mean radius (eq. 10)")
    # The paper's figure 9(b): grid against the geometric count.
    for m in ["grid100_paper", "grid100_improved"]:
        style = dict(STYLE[m])
        label = style.pop("label")
        c.plot(x, [(g / geo - 1) * 100 for g, geo in zip(t[m], t["geometric"])], label=label + " vs geometric",
               **style)
    a.set_ylabel("mass hitting the fiber per step [kg]")
    b.set_ylabel("relative error [%]")
    c.set_ylabel("relative difference to the geometric count [%]")
    for ax, sub in ((a, "(a) mass hitting the fiber"), (b, "(b) relative error against the flow-rate expectation"),
                    (c, "(c) grid against the geometric count (paper's view)")):
        ax.set_xlabel("fiber radius r_F [mm]")
        ax.set_title(sub, fontsize=10)
        ax.grid(alpha=0.3)
    b.axhline(0.0, color="black", lw=0.8)
    c.axhline(0.0, color="black", lw=0.8)
    b.set_ylim(-25, 25)
    for ax in (a, b, c):
        ax.legend(fontsize=7)
    fig.suptitle("Figure 9: polydisperse spray (6-100 droplets per parcel), 200 streams, grid 100x100", fontsize=11)
    finish(fig, os.path.join(out, "figure9.png"))


def figure10(d, out):
    t = read(d, "figure10")
    x = [r * 1e3 for r in t["fiberRadius"]]
    fig, (a, b) = plt.subplots(1, 2, figsize=(13, 4.8))
    grids = ["grid100_paper", "grid250_paper", "grid100_improved", "grid250_improved"]
    for m in grids:
        style = dict(STYLE[m])
        label = style.pop("label")
        a.plot(x, [(g / geo - 1) * 100 for g, geo in zip(t[m], t["geometric"])], label=label + " vs geometric",
               **style)
    for m in ["geometric", "fine"] + grids:
        plot_method(b, x, t, m, relative=t["truth"], scale=100.0)
    a.set_ylabel("relative difference to the geometric count [%]")
    b.set_ylabel("relative error [%]")
    for ax, sub in ((a, "(a) grid against the geometric count (paper's view)"),
                    (b, "(b) relative error against the flow-rate expectation")):
        ax.set_xlabel("fiber radius r_F [mm]")
        ax.set_title(sub, fontsize=10)
        ax.grid(alpha=0.3)
        ax.axhline(0.0, color="black", lw=0.8)
        ax.legend(fontsize=7)
    fig.suptitle("Figure 10: grids 100x100 and 250x250, polydisperse spray of figure 9, r_F up to 14 mm",
                 fontsize=11)
    finish(fig, os.path.join(out, "figure10.png"))


def radius(d, out):
    t = read(d, "radius")
    x = [r * 1e6 for r in t["fiberRadius"]]
    fine = t["fine"]
    band = [s / f * 100 for s, f in zip(t["fineSE"], fine)]
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.fill_between(x, [-b for b in band], band, color="tab:brown", alpha=0.25, label="fine reference ± 1 SE")
    for col, label, style in (
        ("formulaMass", "eq. 9, mass-weighted mean radius (project default)", dict(color="tab:green", marker="o")),
        ("formulaNumber", "eq. 9, number-weighted mean radius (paper, eq. 10)", dict(color="tab:pink", marker="s")),
        ("gridMass", "grid 100x100 improved, mass-weighted", dict(color="tab:green", ls="--", marker="o", mfc="none")),
        ("gridNumber", "grid 100x100 improved, number-weighted", dict(color="tab:pink", ls="--", marker="s",
                                                                      mfc="none")),
    ):
        ax.plot(x, [(v / f - 1) * 100 for v, f in zip(t[col], fine)], label=label, **style)
    ax.axhline(0.0, color="black", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("fiber radius r_F [um] (droplet radii 6-15.3 um)")
    ax.set_ylabel("relative difference to the fine geometric reference [%]")
    ax.set_title("Which mean radius in eq. 9? Polydisperse spray, 200 streams", fontsize=11)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    finish(fig, os.path.join(out, "radius.png"))


def sawtooth(d, out):
    t = read(d, "sawtooth")
    x = [r * 1e3 for r in t["fiberRadius"]]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for m in ["geometric", "grid100_paper", "grid100_improved"]:
        plot_method(ax, x, t, m, relative=t["truth"], scale=100.0)
    ax.axhline(0.0, color="black", lw=0.8)
    ax.set_xlabel("fiber radius r_F [mm]")
    ax.set_ylabel("relative error [%]")
    ax.set_title("Geometric staircase: 100 streams (spacing 0.498 mm), 10 droplets per parcel", fontsize=11)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    finish(fig, os.path.join(out, "sawtooth.png"))


def accuracy(d, out):
    t = read(d, "accuracy")
    variants = list(OrderedDict.fromkeys(l for l, f in zip(t["label"], t["figure"]) if f in (7.0, 8.0)))
    worst = {7.0: [], 8.0: []}
    for v in variants:
        for fig_number in (7.0, 8.0):
            errors = [abs(e) for l, f, e in zip(t["label"], t["figure"], t["relativeError"])
                      if l == v and f == fig_number]
            worst[fig_number].append(max(errors) * 100)
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(18, 5.2), gridspec_kw=dict(width_ratios=[1.3, 1, 0.8]))
    y = range(len(variants))
    a.barh([i + 0.2 for i in y], worst[7.0], height=0.4, label="figure 7 sweep (50-500 streams)", color="tab:blue")
    a.barh([i - 0.2 for i in y], worst[8.0], height=0.4, label="figure 8 sweep (1-1000 per parcel)",
           color="tab:orange")
    a.set_yticks(list(y))
    a.set_yticklabels(variants, fontsize=8)
    a.invert_yaxis()
    a.axvline(1.0, color="red", lw=1, ls="--", label="1 %")
    a.set_xlabel("largest |relative error| over the sweep [%], grid 100x100")
    a.set_title("(a) what limits the grid method", fontsize=10)
    a.legend(fontsize=8)
    a.grid(alpha=0.3, axis="x")
    for v, style in (("paper", dict(color="tab:blue", marker="o")), ("beta 1", dict(color="tab:purple", marker="^")),
                     ("cloud-in-cell below 0.5 h (improved)", dict(color="tab:green", marker="o", mfc="none"))):
        pts = [(x, e) for l, f, x, e in zip(t["label"], t["figure"], t["x"], t["relativeError"])
               if l == v and f == 8.0]
        b.plot([p[0] for p in pts], [p[1] * 100 for p in pts], label=v, **style)
    b.set_xscale("log")
    b.set_xlabel("droplets per parcel (figure 8 sweep)")
    b.set_ylabel("relative error [%]")
    b.axhline(0.0, color="black", lw=0.8)
    b.set_title("(b) error against kernel size, 100x100", fontsize=10)
    b.grid(alpha=0.3)
    b.legend(fontsize=8)
    pts = [(x, e) for l, f, x, e in zip(t["label"], t["figure"], t["x"], t["relativeError"]) if f == 0.0]
    c.plot([p[0] for p in pts], [p[1] * 100 for p in pts], marker="o", color="tab:green")
    c.set_xscale("log")
    c.set_xlabel("averaging window [steps]")
    c.set_ylabel("relative error [%]")
    c.set_title("(c) window, parcels every 1.37 steps", fontsize=10)
    c.axhline(0.0, color="black", lw=0.8)
    c.grid(alpha=0.3)
    fig.suptitle("Accuracy study of the grid method (figures 7 and 8 settings, r_F = 1 cm)", fontsize=11)
    finish(fig, os.path.join(out, "accuracy.png"))


def depletion(d, out):
    """Depletion (docs/model.md sec. 7): fiber rows and a random mat, from the CSVs the
    depletion unit tests write (validation/run.sh); skipped when they are absent."""
    if not os.path.exists(os.path.join(d, "depletionRows.csv")):
        return
    rows, mat = read(d, "depletionRows"), read(d, "depletionMat")
    dense = read(d, "depletionDenseMat") if os.path.exists(os.path.join(d, "depletionDenseMat.csv")) else None
    fig, axes = plt.subplots(1, 3 if dense else 2, figsize=(19.5 if dense else 13, 4.8))
    a, b = axes[0], axes[1]
    k = rows["rows"]
    a.fill_between(k, rows["oneMinusFToTheK"], rows["onePlusFToTheMinusK"], color="tab:green", alpha=0.2,
                   label="bracket (1-f)^k ... (1+f)^-k")
    a.plot(k, rows["oneMinusFToTheK"], color="black", lw=2.0, label="(1-f)^k, f = 0.05")
    a.plot(k, rows["depleted"], color="tab:green", marker="o", ms=4, label="grid, depletion")
    a.plot(k, rows["notDepleted"], color="tab:red", ls="--", marker="x", label="grid, no depletion (1 - k f)")
    a.set_xlabel("rows of fibers passed, k")
    a.set_ylabel("fraction of the sprayed mass passing")
    a.set_title("Rows of parallel fibers, spacing s, f = 2 (r_F + r_p) / s")
    a.legend(fontsize=8)
    a.grid(alpha=0.3)
    x = mat["alphaTOverDF"]
    b.semilogy(x, mat["theory"], color="black", lw=2.0, label="exp(-4 alpha E t / (pi d_F)) (eq. P15)")
    b.semilogy(x, mat["model"], color="tab:green", marker="o", ms=4, ls="none", label="grid, depletion")
    b.set_xlabel("alpha t / d_F")
    b.set_ylabel("penetration P")
    b.set_title("Random fiber mat, straight paths, E = 1 + d_p / d_F = 5/3")
    b.legend(fontsize=8)
    b.grid(alpha=0.3, which="both")
    if dense:
        dense_mats(axes[2], dense)
    finish(fig, os.path.join(out, "depletion.png"))


def dense_mats(c, dense):
    """Dense mats 6 spacings thick (DenseMatTest): |P_grid / exp(-S) - 1| against the travel per
    step, the per-parcel removal beside a node rule's faces' term P18 (dotted)."""
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
    for colour, S in zip(colours, sorted(set(dense["S"]))):
        pick = [i for i, v in enumerate(dense["S"]) if v == S]
        v = [dense["travel"][i] for i in pick]
        c.loglog(v, [max(abs(dense["relativeError"][i]), 1e-5) for i in pick], color=colour, marker="o", ms=4,
                 label=f"S = {S:.3g}, grid")
        c.loglog(v, [dense["faceErrorLeadingOrder"][i] for i in pick], color=colour, ls=":", lw=1.0)
    c.axhline(0.03, color="black", lw=0.8, ls="--", label="3 %")
    c.set_xlabel("travel per step v dt / h")
    c.set_ylabel("|P_grid / exp(-S) - 1|")
    c.set_title("Dense mats 6 spacings thick (dotted: faces' term P18)")
    c.legend(fontsize=8)
    c.grid(alpha=0.3, which="both")


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    data = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else data
    os.makedirs(out, exist_ok=True)
    for make in (figure7, figure8, figure9, figure10, radius, sawtooth, accuracy, depletion):
        make(data, out)


if __name__ == "__main__":
    main()
