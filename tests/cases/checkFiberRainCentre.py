"""The rain laid with fibers.laydown footprint centre: the map as before P58.

Usage: checkFiberRainCentre.py CASE (fiberRain run to 0.5 s with footprint centre)

Every laid fiber whole in the cell of its centre's foot: each cell of mat_0.5.vti holds
the glass and fibers of laydown.dat's rows whose (across, along) fall in it, N times (to
1e-12 of the complete rows' G, as the map was checked before P58); the complete rows
without the footprints' reach (P48: the rows that entered the zone after the first fiber
and left it), every cell of them G = m_dot / (W V).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkFiberRainFiles import ACROSS_MIN, laid, mat, write_reports  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

case = sys.argv[1]
G = 2500 * math.pi * 5e-6 ** 2 * 0.008 * 1000 * 10 / 0.01 ** 2 * 1000  # g/m2
h, V = 0.01, 0.256
table = laid(case)
cells = {}
for r in table:
    key = (int(math.floor((r["across"] - ACROSS_MIN) / h)), int(math.floor(r["along"] / h)))
    cells[key] = cells.get(key, 0.0) + r["represents"] * r["glassMass"]
a = mat(os.path.join(case, "postProcessing", "dropletFiber", "0", "mat_0.5.vti"))
nx, ny = a["shape"][:2]
r0 = int(round(a["origin"][1] / h - 0.5))
worst = max(abs(a["arrays"]["areaWeight"][j * nx + i] - 1000 * cells.get((i, r0 + j), 0.0) / h ** 2) / G
            for j in range(ny) for i in range(nx))
check(worst <= 1e-12, "every cell the glass of the fibers whose centres fall in it (largest %.3g of G)" % worst)
logMat = write_reports(os.path.join(case, "log.pimpleFoam")).get("0.5", {}).get("mat")
first = min(r["Time"] for r in table)
feet = [V * r["Time"] - r["along"] for r in table]
rows = (math.ceil((V * first - min(feet)) / h - 1e-9), math.floor((V * 0.5 - max(feet)) / h + 1e-9) - 1)
check(logMat is not None and logMat["rows"] == rows, "the complete rows %s without a reach: %s"
      % (logMat and logMat["rows"], rows))
complete = [a["arrays"]["areaWeight"][(row - r0) * nx + i] for row in range(rows[0], rows[1] + 1) for i in range(nx)]
check(complete and max(abs(v - G) / G for v in complete) <= 1e-12,
      "every complete cell G = %.12g g/m2 (1e-12)" % G)
finish()
