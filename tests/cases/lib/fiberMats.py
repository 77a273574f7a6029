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
- laneFields(fibers, rp, W, D, h): the model's own value for the mat, (with, without the
  self-shadow of P21): the mean over the parcels' lanes (y = (j/4 + 1/8) mm) of
  exp(-S_I(y)), S_I the piecewise-linear interpolant across the flow of the nodes'
  depths, each fiber's strip 2 (r_F + r_p) (times N) spread over its two node columns
  by the hat weights of its y. It holds the mat's clustering at the grid's scale, which
  exp(-S) does not.
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


def hatMean(n, phi, columns, pieces=200):
    """The mean over node n's hat (within the duct) of f = sum_m phi[m] hat_m."""
    lo, hi = max(0, n - 1), min(columns, n + 1)
    weighted = weights = 0.0
    for k in range(pieces):
        y = lo + (hi - lo) * (k + 0.5) / pieces
        f = sum(value * hat(y - m) for m, value in phi.items())
        weighted += hat(y - n) * f
        weights += hat(y - n)
    return weighted / weights


def laneFields(fibers, rp, W, D, h):
    """(shadowed, unshadowed) lanes' fields of the mat: each fiber's strip over its two node
    columns (phi_n, by the hat weights of its y), scaled by its self-shadow 1 + <f>_n / 2
    (<f>_n the mean over column n's hat of the fiber's own lane depth f = sum_m phi_m hat_m,
    docs/model.md sec. 7, P21), times the physical fibers it stands for (sec. 9)."""
    columns = int(round(W / h))
    plain = [0.0] * (columns + 1)
    shadowed = [0.0] * (columns + 1)
    for a, b, rF, n in fibers:
        u = a[1] / h
        lower = min(int(math.floor(u)), columns - 1)
        phi = {}
        for c in (lower, lower + 1):
            dual = 0.5 if c in (0, columns) else 1.0
            phi[c] = 2.0 * (rF + rp) * math.dist(a, b) / (h * D) * hat(u - c) / dual
        for c, value in phi.items():
            plain[c] += n * value
            shadowed[c] += n * value * (1.0 + 0.5 * hatMean(c, phi, columns))
    lanes = [(0.25 * j + 0.125) * 1e-3 / h for j in range(int(round(4 * W / 1e-3)))]

    def field(depth):
        return sum(math.exp(-sum(depth[c] * hat(y - c) for c in range(columns + 1)))
                   for y in lanes) / len(lanes)
    return field(shadowed), field(plain)
