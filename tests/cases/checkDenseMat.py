"""Penetration of a random fixed-fiber mat through the function object (case denseMat;
docs/model.md sec. 7, P15; docs/validation.md, dense mats).

Usage: checkDenseMat.py [--tolerance TOL] [--csv FILE] CASE...

For each finished case (makeMat.py's mat, run by its Allrun): the mat's interception
depth is derived here from the fibers' points in system/matFibers and the case's
sizes, independently of the library,
    S = sum over fibers of 2 (r_F + r_p) L_f / (W D)     (fibers along z, normal to the flow)
and its geometric penetration (P15, straight paths) is exp(-S). The measured
penetration is from the function object's table over the last 10 ms (10 mm of travel,
the spray has crossed the duct and the mat long before): the parcel mass that left
through the outlet over the mass sprayed, escapedMass / sprayedMass (their increments),
and 1 - capturedStep / sprayedMass for the same steps (the two differ by the change of
the airborne mass, zero in a steady stream). Checked: both within TOL of exp(-S).

And the model's own value for this mat (docs/model.md sec. 7, thick fibers, P21): the
lanes' field, computed here from the fibers' positions: the mean over the parcels' lanes
(y = (j/4 + 1/8) mm) of exp(-S_I(y)), S_I the piecewise-linear interpolant across the
flow of the nodes' depths, each fiber's strip 2 (r_F + r_p) spread over its two node
columns by the hat weights of its y (phi_n) and scaled by its self-shadow, 1 + <f>_n / 2
(<f>_n the mean over column n's hat of the fiber's own lane depth f = sum_m phi_m hat_m,
integrated numerically here). It holds the mat's clustering at the grid's scale, which
exp(-S) does not. Checked: the measured penetration within 1 % of it at every step (the
depths are the lanes' whatever the step). Printed beside it: the lanes' field without
the self-shadow (P20's excess).
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402
import fiberMats  # noqa: E402

W, D, h = 0.02, 0.001, 0.001
rF, rp = 5e-5, 2e-5
tMeasured = 0.02

args = sys.argv[1:]
tolerance, csv = 0.03, None
while args and args[0].startswith("--"):
    if args[0] == "--tolerance":
        tolerance = float(args[1])
    elif args[0] == "--csv":
        csv = args[1]
    else:
        sys.exit("checkDenseMat.py: unknown option %s" % args[0])
    args = args[2:]


def travelOf(case):
    text = open(os.path.join(case, "system/matTime")).read()
    return float(re.search(r"deltaT\s+([-+0-9.eE]+)", text).group(1)) / h


lines = []
for case in args:
    placed = fiberMats.mat(case, rF)
    S = fiberMats.depth(placed, rp, W, D)
    expected = math.exp(-S)
    byOutlet, byCapture = fiberMats.penetration(case, tMeasured)
    lane, unshadowed = fiberMats.laneFields(placed, rp, W, D, h)
    travel = travelOf(case)
    lines.append((S, travel, byOutlet, byCapture, expected, lane, unshadowed))
    print("S %.4f (%d fibers), %.3g spacing per step: penetration %.5f (outlet) %.5f "
          "(captured) against exp(-S) %.5f: %+.2f %% %+.2f %%; lanes' field %.5f (%+.2f %%), "
          "without the self-shadow %.5f (%+.2f %%)"
          % (S, len(placed), travel, byOutlet, byCapture, expected,
             100 * (byOutlet / expected - 1), 100 * (byCapture / expected - 1),
             lane, 100 * (lane / expected - 1), unshadowed, 100 * (unshadowed / expected - 1)))
    check(abs(byOutlet / expected - 1) < tolerance and abs(byCapture / expected - 1) < tolerance,
          "S %.3f, %.3g spacing per step: within %.3g %% of exp(-S)"
          % (S, travel, 100 * tolerance))
    check(abs(byOutlet / lane - 1) < 0.01,
          "S %.3f, %.3g spacing per step: within 1 %% of the mat's lanes' field" % (S, travel))

if csv:
    with open(csv, "w") as out:
        out.write("S,travel,outlet,captured,expMinusS,lanesField,lanesFieldUnshadowed\n")
        for line in lines:
            out.write(",".join("%.10g" % v for v in line) + "\n")
finish()
