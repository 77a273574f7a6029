"""The random fixed-fiber mats of the denseMat case (tests/cases/denseMat/makeMat.py),
read back and modelled independently of the library: the fibers' points, radius and
weight from system/matFibers, the mat's interception depth S and the lanes' mean field.

- mat(case): list of (a, b, radius, represents) per fiber written.
- depth(fibers, rp, W, D): S = sum N 2 (r_F + r_p) L / (W D) (docs/model.md sec. 7, P15;
  sec. 9: each fiber N times).
- penetration(case, after): the measured penetration from the function object's table
  over the steps after the time `after`: the parcel mass that left through the outlet
  over the mass sprayed (escapedMass / sprayedMass, their increments), and 1 -
  capturedStep / sprayedMass for the same steps.
- laneMeanField(fibers, rp, W, D, h): the model's limit for small steps, the mean over
  the parcels' lanes (y = (j/4 + 1/8) mm) of exp(-S_I(y)), S_I the piecewise-linear
  interpolant across the flow of the nodes' depths, each fiber's strip 2 (r_F + r_p)
  (times N) spread over its two node columns by the hat weights of its y.
"""
import math
import os
import re

from foamfiles import read_table

NUMBER = r"([-+0-9.eE]+)"
POINT = r"\(" + r"\s+".join([NUMBER] * 3) + r"\)"


def mat(case, defaultRadius=5e-5):
    found = []
    for line in open(os.path.join(case, "system/matFibers")):
        m = re.search(r"points\s*\(\s*" + POINT + r"\s*" + POINT, line)
        if not m:
            continue
        a = [float(v) for v in m.groups()[:3]]
        b = [float(v) for v in m.groups()[3:]]
        radius = re.search(r"radius\s+" + NUMBER, line)
        weight = re.search(r"represents\s+" + NUMBER, line)
        found.append((a, b, float(radius.group(1)) if radius else defaultRadius,
                      float(weight.group(1)) if weight else 1.0))
    return found


def depth(fibers, rp, W, D):
    return sum(n * 2.0 * (rF + rp) * math.dist(a, b) for a, b, rF, n in fibers) / (W * D)


def penetration(case, after):
    rows = read_table(os.path.join(case, "postProcessing/dropletFiber/0/dropletFiber.dat"))
    start = max((r for r in rows if r["Time"] <= after + 1e-12), key=lambda r: r["Time"])
    last = rows[-1]
    sprayed = last["sprayedMass"] - start["sprayedMass"]
    escaped = last["escapedMass"] - start["escapedMass"]
    captured = sum(r["capturedStep"] for r in rows if r["Time"] > start["Time"] + 1e-12)
    return escaped / sprayed, 1.0 - captured / sprayed


def hat(u):
    return max(0.0, 1.0 - abs(u))


def laneMeanField(fibers, rp, W, D, h):
    columns = int(round(W / h))
    nodeDepth = [0.0] * (columns + 1)
    for a, b, rF, n in fibers:
        u = a[1] / h
        for c in range(columns + 1):
            dual = 0.5 if c in (0, columns) else 1.0
            nodeDepth[c] += n * 2.0 * (rF + rp) * math.dist(a, b) / (h * D) * hat(u - c) / dual
    lanes = [(0.25 * j + 0.125) * 1e-3 for j in range(int(round(4 * W / 1e-3)))]
    return sum(math.exp(-sum(nodeDepth[c] * hat(y / h - c) for c in range(columns + 1)))
               for y in lanes) / len(lanes)
