#!/usr/bin/env python3
"""The README's picture of the forming hood at its last write time: the binder
parcels (OpenFOAM's vtkCloud files) and the fibers (the function object's VTK
files, serial or one piece per processor) projected on a vertical plane (front
view) and on the horizontal plane (top view); fibers coloured by the binder
they carry per length (sigma, the
mass per length, less the bare glass fiber's; grey: none), parcels by their
droplets' diameter.

Usage: hoodPicture.py CASE OUTPUT.png
"""
import glob
import os
import re
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def arrays(path):
    """Points and named point-data arrays of an ASCII VTK PolyData piece; lines
    as lists of point indices."""
    piece = ET.parse(path).getroot().find("PolyData/Piece")
    def values(node):
        return np.array(node.text.split(), dtype=float) if node is not None and node.text else np.zeros(0)
    points = values(piece.find("Points/DataArray")).reshape(-1, 3)
    data = {a.get("Name"): values(a) for a in piece.findall("PointData/DataArray")}
    lines = []
    conn = piece.find("Lines/DataArray[@Name='connectivity']")
    offs = piece.find("Lines/DataArray[@Name='offsets']")
    if conn is not None:
        c, start = values(conn).astype(int), 0
        for end in values(offs).astype(int):
            lines.append(c[start:end])
            start = end
    return points, data, lines


def latest(pattern):
    """The file (or piece folder) of the latest time among the matches."""
    def time_of(p):
        stem = os.path.basename(p).split("_")[-1]
        return float(stem.split(".vt")[0].split(".pvt")[0])
    files = glob.glob(pattern)
    return max(files, key=time_of) if files else None


def fibers(case):
    """Polylines (list of n x 3 arrays) and their sigma per point, last write."""
    base = os.path.join(case, "postProcessing", "dropletFiber")
    serial = latest(os.path.join(base, "*", "fibers_*.vtp"))
    folder = latest(os.path.join(base, "*", "fibers_*[0-9]"))
    pieces = [serial] if serial else sorted(glob.glob(os.path.join(folder or "", "processor*.vtp")))
    if not pieces:
        sys.exit("hoodPicture: no fibers VTK files in %s" % base)
    polylines, sigmas, ids = [], [], set()
    for piece in pieces:
        points, data, lines = arrays(piece)
        ids.update(data["fiberId"].tolist())
        for line in lines:
            polylines.append(points[line])
            sigmas.append(data["sigma"][line])
    return polylines, sigmas, len(ids), os.path.basename(pieces[0] if serial else folder)


def bare_fiber_sigma(case):
    """Mass per length of a fiber without binder, pi r^2 rho_F, from the fibers'
    radius and density in system/controlDict (sigma in the VTK files includes it)."""
    text = open(os.path.join(case, "system", "controlDict")).read()
    fibers_block = text[text.index("fibers"):]
    radius = float(re.search(r"\bradius\s+([0-9.eE+-]+);", fibers_block).group(1))
    density = float(re.search(r"\bdensity\s+([0-9.eE+-]+);", fibers_block).group(1))
    return np.pi * radius ** 2 * density


def parcels(case):
    path = latest(os.path.join(case, "postProcessing", "parcels", "sprayCloud_*.vtp"))
    if path is None:
        return np.zeros((0, 3)), np.zeros(0)
    points, data, _ = arrays(path)
    return points, data.get("d", np.zeros(len(points)))


def main():
    case, output = sys.argv[1], sys.argv[2]
    polylines, sigmas, count, name = fibers(case)
    bare = bare_fiber_sigma(case)
    sigmas = [np.maximum(s - bare, 0.0) for s in sigmas]
    p, d = parcels(case)
    # colour scale to the 98th percentile of the binder-carrying points: a few
    # fibers that crossed a nozzle's core would otherwise leave the rest pale
    carrying = np.concatenate([s[s > 0] for s in sigmas] + [np.zeros(0)])
    sigma_max = np.percentile(carrying, 98) if len(carrying) else 1.0
    fig, axes = plt.subplots(1, 2, figsize=(10, 6))
    views = [(0, 1, "front view: x (m)", "height y (m)", (0, 1.5)),
             (0, 2, "top view: x (m)", "z (m)", (-0.5, 0.5))]
    for ax, (i, j, xlabel, ylabel, ylim) in zip(axes, views):
        ax.scatter(p[:, i], p[:, j], s=2, c=d * 1e6, cmap="Blues", vmin=0, vmax=120,
                   alpha=0.5, linewidths=0)
        segments, colours = [], []
        for line, s in zip(polylines, sigmas):
            for a in range(len(line) - 1):
                segments.append(line[a:a + 2][:, [i, j]])
                colours.append(0.5 * (s[a] + s[a + 1]))
        cmap = matplotlib.colormaps["inferno_r"].copy()
        cmap.set_under("0.55")  # fibers without binder: grey
        lc = LineCollection(segments, cmap=cmap, linewidths=1.5)
        lc.set_array(np.array(colours) * 1e9)
        lc.set_clim(1e-3 * sigma_max * 1e9, sigma_max * 1e9)
        ax.add_collection(lc)
        ax.set_xlim(-0.5, 0.5)
        ax.set_ylim(*ylim)
        ax.set_aspect("equal")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
    fig.colorbar(lc, ax=axes, shrink=0.6, label="binder on the fibers (ug per m of fiber)", extend="both")
    fig.suptitle("formingHood at %s s: %d fibers, %d binder parcels (blue: diameter up to 120 um)"
                 % (name.split("_")[-1].replace(".vtp", ""), count, len(p)))
    fig.savefig(output, dpi=110)
    print("hoodPicture: wrote %s" % output)


if __name__ == "__main__":
    main()
