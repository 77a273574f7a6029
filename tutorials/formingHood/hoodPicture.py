#!/usr/bin/env python3
"""The README's picture of the forming hood at its last write time: the binder
parcels (OpenFOAM's vtkCloud files) and the fibers (the function object's VTK
files, serial or one piece per processor) projected on a vertical plane (front
view) and on the horizontal plane (top view); fibers coloured by the binder
they carry per length (sigma, the
mass per length, less the bare glass fiber's; grey: none), parcels by their
droplets' diameter.

The VTK files are read by the project's report package (vtkFiles, caseOutputs;
found by reportPackage.py).

Usage: hoodPicture.py CASE OUTPUT.png
"""
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reportPackage  # noqa: E402,F401  (the report's modules on the import path)
import caseOutputs  # noqa: E402
import vtkFiles  # noqa: E402


def fibers(case):
    """The fibers of the last write (serial, or one piece per processor) and the time
    as its file names it."""
    notes = []
    for folder in reversed(caseOutputs.start_folders(case, "dropletFiber")):
        found = vtkFiles.last_readable(folder, "fibers.vtp", vtkFiles.Fibers, notes)
        if found is not None:
            for note in notes:  # a last file cut short (a run stopped while writing it)
                print("hoodPicture: " + note)
            return found, re.sub(r"\.p?vtp$", "", os.path.basename(found.path)).split("_")[-1]
    sys.exit("hoodPicture: no fibers VTK files in %s" % os.path.join(case, "postProcessing", "dropletFiber"))


def bare_fiber_sigma(case):
    """Mass per length of a fiber without binder, pi r^2 rho_F, from the fibers'
    radius and density in system/controlDict (sigma in the VTK files includes it)."""
    text = open(os.path.join(case, "system", "controlDict")).read()
    fibers_block = text[text.index("fibers"):]
    radius = float(re.search(r"\bradius\s+([0-9.eE+-]+);", fibers_block).group(1))
    density = float(re.search(r"\bdensity\s+([0-9.eE+-]+);", fibers_block).group(1))
    return np.pi * radius ** 2 * density


def parcels(case):
    """Positions and diameters of the parcels at the last write (vtkCloud's files)."""
    found = vtkFiles.series(os.path.join(case, "postProcessing", "parcels"), "sprayCloud.vtp")
    if not found:
        return np.zeros((0, 3)), np.zeros(0)
    cloud = vtkFiles.PolyData(*found[-1])
    return cloud.points, cloud.point_data.get("d", np.zeros(len(cloud.points)))


def main():
    case, output = sys.argv[1], sys.argv[2]
    fiber, name = fibers(case)
    count = len(set(fiber.point_data["fiberId"].tolist()))
    bare = bare_fiber_sigma(case)
    sigma = np.maximum(fiber.point_data["sigma"] - bare, 0.0)
    p, d = parcels(case)
    # colour scale to the 98th percentile of the binder-carrying segment ends: a few
    # fibers that crossed a nozzle's core would otherwise leave the rest pale
    ends = sigma[fiber.segments.ravel()]
    carrying = ends[ends > 0]
    sigma_max = np.percentile(carrying, 98) if len(carrying) else 1.0
    fig, axes = plt.subplots(1, 2, figsize=(10, 6))
    views = [(0, 1, "front view: x (m)", "height y (m)", (0, 1.5)),
             (0, 2, "top view: x (m)", "z (m)", (-0.5, 0.5))]
    for ax, (i, j, xlabel, ylabel, ylim) in zip(axes, views):
        ax.scatter(p[:, i], p[:, j], s=2, c=d * 1e6, cmap="Blues", vmin=0, vmax=120,
                   alpha=0.5, linewidths=0)
        segments = fiber.points[fiber.segments][:, :, [i, j]]
        colours = 0.5 * (sigma[fiber.segments[:, 0]] + sigma[fiber.segments[:, 1]])
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
                 % (name, count, len(p)))
    fig.savefig(output, dpi=110)
    print("hoodPicture: wrote %s" % output)


if __name__ == "__main__":
    main()
