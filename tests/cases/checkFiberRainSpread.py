"""The rain laid with its populations spread (fibers.laydown populations spread, P59).

Usage: checkFiberRainSpread.py CASE (fiberRain run to 0.5 s with spread populations)

Each computed fiber (N = 1000) lays its own line and its 999 others over the hat of its
population's level (laydown.dat's spread > 0, the same for all: one level in still air).
The hat conserves the glass (folded at the belt's edges): the map's glass = the table's
(1e-12). Along, the rain is a comb of 1 mm period; a complete row of 10 mm integrates the
hat over whole periods, and the fold keeps the width's total: every complete row holds
the 100 fibers' glass of the uniform rain, its mean area weight G = m_dot / (W V) to
1e-12, as does the log's mat (to its 12 digits). The complete rows start later than on
the line by the hat's half-width (the footprints' reach).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkFiberRainFiles import laid, mat, write_reports  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

case = sys.argv[1]
G = 2500 * math.pi * 5e-6 ** 2 * 0.008 * 1000 * 10 / 0.01 ** 2 * 1000  # g/m2
h = 0.01
table = laid(case)
spreads = {r["spread"] for r in table}
H = min(spreads)
check(len(spreads) == 1 and H > 0, "laydown.dat: every fiber's population spread by one hat, %s m" % sorted(spreads))
a = mat(os.path.join(case, "postProcessing", "dropletFiber", "0", "mat_0.5.vti"))
glass = sum(a["arrays"]["areaWeight"]) * h * h / 1000
tableGlass = sum(r["represents"] * r["glassMass"] for r in table)
check(abs(glass - tableGlass) <= 1e-12 * tableGlass, "the map's glass the table's (%.3g)" % (glass / tableGlass - 1))
logMat = write_reports(os.path.join(case, "log.pimpleFoam")).get("0.5", {}).get("mat")
check(logMat is not None, "the log has complete rows at 0.5 s")
if logMat:
    r0 = int(round(a["origin"][1] / h - 0.5))
    nx = a["shape"][0]
    first, last = logMat["rows"]
    reach = 0.004 + H
    V, firstTime, foot = 0.256, 0.068359375, -0.000125
    check((first, last) == (math.ceil((V * firstTime - foot + reach) / h - 1e-9),
                            math.floor((V * 0.5 - foot - reach) / h + 1e-9) - 1),
          "the complete rows %s: held back by the hat's half-width %.4g m" % (logMat["rows"], H))
    worst = 0.0
    for row in range(first, last + 1):
        values = a["arrays"]["areaWeight"][(row - r0) * nx:(row - r0 + 1) * nx]
        worst = max(worst, abs(sum(values) / nx - G) / G)
    check(worst <= 1e-12, "every complete row's mean area weight G = %.12g g/m2 (largest %.3g)" % (G, worst))
    check(abs(logMat["areaWeight"] - G) <= 1e-11 * G, "the log's mat %.12g g/m2 = G" % logMat["areaWeight"])
finish()
