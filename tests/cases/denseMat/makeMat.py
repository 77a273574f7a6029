#!/usr/bin/env python3
"""Writes the denseMat case's mat, time step and injection (tests/cases/denseMat).

Usage: makeMat.py CASE [S [TRAVEL [SEED]]] [--represents N] [--fiberRadius R]
                  [--dropletDiameter D]   (defaults: ln 10, 1, 1; 1, 50 um, 40 um)

The mat: N fixed fibers along z (the duct's depth, 1 mm, less 1 um at each face so
that every point is inside the mesh), each at an (x, y) drawn uniformly in the slab
4 mm <= x <= 10 mm (6 grid spacings) across the duct's width 0 <= y <= 20 mm, with
Python's Mersenne Twister seeded by SEED. N is the count whose interception depth
    S = N 2 (r_F + r_p) L / (W D)
(L the fiber length, W D the duct's cross-section, r_F = 50 um, r_p = 20 um) is
closest to the S asked; the checker (checkDenseMat.py) derives S again from the
points written. TRAVEL is the droplets' path per time step in grid spacings
(1 mm at 1 m/s): deltaT = TRAVEL * 1e-3 s. The run lasts 30 mm of travel, the
last 10 mm measured (checkDenseMat.py), whatever the step.

Weighted mats (docs/model.md sec. 9; checkWeightedMat.sh): with --represents N each
fiber written stands for N physical ones (entry represents), and N is in the count's
S = N count 2 (r_F + r_p) L / (W D); --fiberRadius and --dropletDiameter set r_F (each
fiber's entry radius) and the droplets' diameter 2 r_p.
"""
import random
import sys

options = {"--represents": 1.0, "--fiberRadius": 5e-5, "--dropletDiameter": 4e-5}
positional = []
arguments = sys.argv[1:]
while arguments:
    if arguments[0] in options:
        options[arguments[0]] = float(arguments[1])
        arguments = arguments[2:]
    else:
        positional.append(arguments.pop(0))
case = positional[0]
S = float(positional[1]) if len(positional) > 1 else 2.302585092994046
travel = float(positional[2]) if len(positional) > 2 else 1.0
seed = int(positional[3]) if len(positional) > 3 else 1
weight = options["--represents"]

W, D, h, U = 0.02, 0.001, 0.001, 1.0
rF, rp = options["--fiberRadius"], 0.5 * options["--dropletDiameter"]
z0, z1 = 1e-6, D - 1e-6
count = int(round(S * W * D / (weight * 2.0 * (rF + rp) * (z1 - z0))))
rng = random.Random(seed)
extra = "" if rF == 5e-5 else " radius %.17g;" % rF
if weight != 1.0:
    extra += " represents %.17g;" % weight
with open(case + "/system/matFibers", "w") as out:
    out.write("// makeMat.py: S %.17g, seed %d, %d fibers\n" % (S, seed, count))
    for n in range(count):
        x = 0.004 + 0.006 * rng.random()
        y = W * rng.random()
        out.write("f%d { points ((%.17g %.17g %.17g) (%.17g %.17g %.17g)); hold fixed;%s }\n"
                  % (n, x, y, z0, x, y, z1, extra))

dt = travel * h / U
with open(case + "/system/matTime", "w") as out:
    out.write("deltaT %.17g;\nendTime %.17g;\n" % (dt, 0.03 / U))
with open(case + "/constant/matInjection", "w") as out:
    out.write("parcelsPerSecond %.17g;\n" % (1.01 / dt))
with open(case + "/constant/parcelInjectionProperties", "w") as out:
    out.write("FoamFile { version 2.0; format ascii; "
              "class GlobalIOList<kinematicParcelInjectionData>; "
              "object parcelInjectionProperties; }\n(\n")
    for j in range(80):
        out.write("    (0.0005 %.17g 0.0005) (1 0 0) %r 1000 1\n"
                  % ((0.25 * j + 0.125) * h, 2.0 * rp))
    out.write(");\n")
