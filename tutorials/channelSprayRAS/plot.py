"""Plot the channel-spray tutorial in turbulent air: captured binder mass over time,
the fibers in the spray at the end (coloured by sigma, mass per length, over the
droplet mass density of the grid), sigma along every fiber, and the fibers'
turbulent dispersion: the fiber centres at every write time against the distance
they have fallen, across the channel from their injector's (the rms turbulent
velocity u' at the fiber points from fiberDispersion.dat).

Usage: /usr/bin/python3 plot.py [CASE_DIR] [OUTPUT_PNG]
Reads postProcessing/dropletFiber/0/{dropletFiber.dat, the last fibers_*.vtp (a
parallel run: fibers_*.pvtp and its pieces) and grid_*.vti} (XML, the grid's arrays
in VTK's base64 binary form; read with the standard library).
"""
import base64
import json
import math
import os
import struct
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

case = sys.argv[1] if len(sys.argv) > 1 else "."
png = sys.argv[2] if len(sys.argv) > 2 else os.path.join(case, "channelSprayRAS.png")
out = os.path.join(case, "postProcessing", "dropletFiber", "0")


def table(path):
    names, rows = None, []
    for line in open(path):
        if line.startswith("#"):
            names = [c.strip() for c in line[1:].split("\t") if c.strip()]
        elif line.strip():
            rows.append(dict(zip(names, map(float, line.split()))))
    return rows


def last_file(series):
    return os.path.join(out, json.load(open(os.path.join(out, series)))["files"][-1]["name"])


def array_values(da):
    """ASCII numbers, or VTK's inline binary form (the grid's arrays): base64 of a
    UInt64 byte count followed by the little-endian doubles."""
    if da.get("format") != "binary":
        return [float(v) for v in (da.text or "").split()]
    raw = base64.b64decode("".join((da.text or "").split()))
    (count,) = struct.unpack("<Q", raw[:8])
    return list(struct.unpack("<%dd" % (count // 8), raw[8:8 + count]))


def data_arrays(block):
    return {da.get("Name"): array_values(da) for da in block}


rows = table(os.path.join(out, "dropletFiber.dat"))
t = [r["Time"] for r in rows]

def fiber_pieces(path):
    """The pieces of a .vtp, or of the .pvtp of a parallel run (one per processor)."""
    root = ET.parse(path).getroot()
    if root.get("type") != "PPolyData":
        return [root.find("PolyData/Piece")]
    folder = os.path.dirname(path)
    return [ET.parse(os.path.join(folder, piece.get("Source"))).getroot().find("PolyData/Piece")
            for piece in root.findall("PPolyData/Piece")]


# fibers at the end
points, sigma, fiber_id = [], [], []
for piece in fiber_pieces(last_file("fibers.vtp.series")):
    p = [float(v) for v in (piece.find("Points/DataArray").text or "").split()]
    points += [(p[3 * i], p[3 * i + 1]) for i in range(len(p) // 3)]
    point_data = data_arrays(piece.find("PointData"))
    sigma += point_data["sigma"]
    fiber_id += point_data["fiberId"]

# grid at the end: one .vti (serial), or a .pvti listing a piece per processor
grid_file = last_file("grid.vti.series")
root = ET.parse(grid_file).getroot()
image = root.find("ImageData") if root.find("ImageData") is not None else root.find("PImageData")
ext = [int(v) for v in image.get("WholeExtent").split()]
origin = [float(v) for v in image.get("Origin").split()]
spacing = [float(v) for v in image.get("Spacing").split()]
nx, ny = ext[1] + 1, ext[3] + 1
rho_map = [[0.0] * nx for _ in range(ny)]
pieces = [(grid_file, image.find("Piece"))] if image.tag == "ImageData" else [
    (os.path.join(os.path.dirname(grid_file), p.get("Source")), None) for p in image.findall("Piece")]
for path, piece in pieces:
    piece = piece if piece is not None else ET.parse(path).getroot().find("ImageData/Piece")
    e = [int(v) for v in piece.get("Extent").split()]
    rho = data_arrays(piece.find("PointData"))["rho"]
    for j in range(e[2], e[3] + 1):
        for i in range(e[0], e[1] + 1):
            rho_map[j][i] = rho[(i - e[0]) + (e[1] - e[0] + 1) * (j - e[2])]

fig, axes = plt.subplots(1, 4, figsize=(21, 6), gridspec_kw={"width_ratios": [1.2, 1.0, 1.2, 1.2]})

ax = axes[0]
ax.plot(t, [1e9 * r["capturedTotal"] for r in rows], label="captured binder, total")
ax.set_xlabel("time [s]")
ax.set_ylabel("captured binder mass [µg]")
ax2 = ax.twinx()
ax2.plot(t, [r["fibers"] for r in rows], color="grey", lw=0.8, label="fibers in the channel")
ax2.set_ylabel("fibers in the channel", color="grey")
ax.set_title("Binder captured by the fibers")
ax.legend(loc="upper left")

ax = axes[1]
extent = [origin[0] * 100, (origin[0] + spacing[0] * (nx - 1)) * 100,
          origin[1] * 100, (origin[1] + spacing[1] * (ny - 1)) * 100]
im = ax.imshow(rho_map, origin="lower", extent=extent, cmap="Blues", aspect="equal")
fig.colorbar(im, ax=ax, orientation="horizontal", fraction=0.05, pad=0.1,
             label="droplet mass density [kg/m³]")
segments, colours = [], []
for i in range(len(points) - 1):
    if fiber_id[i] == fiber_id[i + 1]:
        a, b = points[i], points[i + 1]
        segments.append([(100 * a[0], 100 * a[1]), (100 * b[0], 100 * b[1])])
        colours.append(1e6 * 0.5 * (sigma[i] + sigma[i + 1]))
lines = LineCollection(segments, array=colours, cmap="autumn_r", linewidths=2.5)
ax.add_collection(lines)
fig.colorbar(lines, ax=ax, fraction=0.1, pad=0.03, label="σ, fiber mass per length [mg/m]")
ax.set_xlabel("x [cm]")
ax.set_ylabel("y [cm]")
ax.set_title("Spray and fibers at t = %.2f s" % t[-1])

ax = axes[2]
base = None
for f in sorted(set(fiber_id)):
    idx = [i for i, v in enumerate(fiber_id) if v == f]
    s, arc = [0.0], [sigma[idx[0]]]
    for k in range(1, len(idx)):
        s.append(s[-1] + math.dist(points[idx[k - 1]], points[idx[k]]))
        arc.append(sigma[idx[k]])
    ax.plot([1000 * v for v in s], [1e6 * v for v in arc], lw=1)
# bare glass fiber: rho_F pi r_F^2 (2500 kg/m3, r_F = 3 um)
ax.axhline(1e6 * 2500 * math.pi * 3e-6 ** 2, color="k", ls="--", lw=0.8, label="bare glass fiber")
ax.set_xlabel("arc length along the fiber [mm]")
ax.set_ylabel("σ [mg/m]")
ax.set_title("σ along each fiber at t = %.2f s" % t[-1])
ax.legend()

ax = axes[3]
# Turbulent dispersion: the centre of every fiber at every write time, against the
# distance it has fallen; the injectors start their fibers in turn, so fiber id mod 3
# is its injector. In laminar air the centres of one injector stay on one vertical line
# (the air comes straight down); their spread across is the turbulent dispersion.
births, centres = {}, {}
for entry in json.load(open(os.path.join(out, "fibers.vtp.series")))["files"]:
    for piece in fiber_pieces(os.path.join(out, entry["name"])):
        p = [float(v) for v in (piece.find("Points/DataArray").text or "").split()]
        ids = data_arrays(piece.find("PointData"))["fiberId"]
        for f in sorted(set(ids)):
            idx = [i for i, v in enumerate(ids) if v == f]
            c = (sum(p[3 * i] for i in idx) / len(idx), sum(p[3 * i + 1] for i in idx) / len(idx))
            centres.setdefault(int(f), []).append(c)
top = 0.147  # the injectors' height
for injector, colour in zip(range(3), ("tab:blue", "tab:orange", "tab:green")):
    mine = [c for f, cs in centres.items() if f % 3 == injector for c in cs]
    newborn = [c[0] for c in mine if top - c[1] < 0.002]
    x0 = sum(newborn) / len(newborn) if newborn else sum(c[0] for c in mine) / len(mine)
    fallen = [c for c in mine if top - c[1] > 0.05]
    rms = math.sqrt(sum((c[0] - x0) ** 2 for c in fallen) / len(fallen)) if fallen else 0.0
    ax.scatter([1000 * (c[0] - x0) for c in mine], [100 * (top - c[1]) for c in mine], s=12, color=colour,
               label="injector %d: rms %.1f mm below 5 cm" % (injector + 1, 1000 * rms))
ax.axvline(0.0, color="k", lw=0.8, ls="--", label="laminar air: straight down")
ax.invert_yaxis()
ax.set_xlabel("fiber centre across the channel, from its injector's [mm]")
ax.set_ylabel("distance fallen [cm]")
last = table(os.path.join(out, "fiberDispersion.dat"))[-1]
u_rms = math.sqrt(sum(last[c] ** 2 for c in ("uTurbRmsX", "uTurbRmsY", "uTurbRmsZ")) / 3)
ax.set_title("Turbulent dispersion of the fibers (rms u' %.2f m/s)" % u_rms)
ax.legend(loc="lower left", fontsize=8)

fig.tight_layout()
fig.savefig(png, dpi=110)
print("wrote", png)
