#!/usr/bin/env python3
"""CTest driver for the dropletGrid tool.

Usage: testDropletGrid.py DROPLETGRID CASE WORKDIR
CASE: totals | badInput | segments | large | cloudInCell | depositMethod | negligibleWeight |
vectorised | sameAsDictionary. Expected values are computed here from the
generated input (parcel masses n rho 4/3 pi r^3, eq. 9 from the printed field values),
never taken from the tool's own output. Exits non-zero on a failure.
"""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generateParcels import generate, parcel_mass  # noqa: E402

tool, case, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = []

GRID = ["--lower", "0,0,0", "--upper", "0.05,0.07,0.001", "--nodes", "51,71,1", "--dt", "1e-4"]
NODE_VOLUME = 0.001 * 0.001 * 0.001  # h_x h_y depth, an interior node's volume


def node_volume(row):
    # The node's dual cell (docs/model.md sec. 4, edge nodes): half a cell per active
    # direction in which the node lies on a face of the 51 x 71 grid (z is flat).
    faces = (row["i"] in (0, 50)) + (row["j"] in (0, 70))
    return NODE_VOLUME / 2 ** faces


def check(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b))


def run(args):
    result = subprocess.run([tool] + args, capture_output=True, text=True)
    return result.returncode, result.stdout, result.stderr


def printed(stdout, label):
    match = re.search(r"^\s*" + re.escape(label) + r":\s*([-+0-9.eE]+)", stdout, re.MULTILINE)
    return float(match.group(1)) if match else float("nan")


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
        rows = [dict(zip(header, map(float, line.strip().split(",")))) for line in f if line.strip()]
    return header, rows


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def totals():
    # 400 parcels whose paths lie inside the grid box, 100 far outside it.
    inside = os.path.join(work, "inside.csv")
    mass_inside = generate(inside, 400, seed=3, lower=(0.001, 0.001, 0.0), upper=(0.049, 0.069, 0.001))
    mass_outside = 0.0
    lines = open(inside).read().splitlines()
    for k in range(100):
        d, n, rho = 5e-5, 100.0 + k, 1000.0
        mass_outside += parcel_mass(d, n, rho)
        lines.append("%.17g,%.17g,0.0005,0,-5,0,%.17g,%.17g,%.17g" % (0.08 + 1e-4 * k, 0.03, d, n, rho))
    parcels = write(os.path.join(work, "parcels.csv"), "\n".join(lines) + "\n")
    nodes = os.path.join(work, "nodes.csv")
    code, out, err = run(["--parcels", parcels, "--output", nodes] + GRID)
    print(out, err)
    check(code == 0, "exit code 0")
    check(close(printed(out, "mass in"), mass_inside + mass_outside, 1e-11), "mass in = sum of n rho 4/3 pi r^3")
    check(close(printed(out, "mass on the grid"), mass_inside, 1e-11), "mass on the grid = mass of the inside parcels")
    check(close(printed(out, "mass outside"), mass_outside, 1e-11), "mass outside = mass of the outside parcels")
    check(re.search(r"^\s*time:.*total [0-9.]+ s", out, re.MULTILINE) is not None, "time printed")
    header, rows = read_csv(nodes)
    check(header == "i,j,k,x,y,z,rho,rMeanNumber,rMeanMass,ux,uy,uz".split(","), "node CSV columns")
    check(len(rows) == 51 * 71, "one row per node")
    check(close(sum(r["rho"] * node_volume(r) for r in rows), mass_inside, 1e-11),
          "sum of rho * node volume = mass of the inside parcels")
    check(all(r["rho"] >= 0.0 for r in rows), "rho >= 0 everywhere")
    radii = [r["rMeanMass"] for r in rows if r["rho"] > 0.0]
    check(all(0.5e-5 * (1 - 1e-12) <= r <= 0.5e-4 * (1 + 1e-12) for r in radii),
          "mean radii within the generated range [5, 50] um")


def bad_input():
    good = "x,y,z,ux,uy,uz,d,nParticle,rhoDroplet\n0.01,0.02,0.0005,0,-5,0,2e-5,10,1000\n"
    cases = [
        ("missing column", "x,y,z,ux,uy,uz,d,nParticle\n0.01,0.02,0.0005,0,-5,0,2e-5,10\n", GRID,
         [":1:", "rhoDroplet"]),
        ("non-numeric value", good + "0.01,0.02,0.0005,0,-5,0,2e-5,10,1000\n0.01,0.02,0.0005,0,abc,0,2e-5,10,1000\n",
         GRID, [":4:", "'uy'", "abc"]),
        ("negative diameter", good + "0.01,0.02,0.0005,0,-5,0,-2e-5,10,1000\n", GRID, [":3:", "'d'", "negative"]),
        ("NaN", good + "nan,0.02,0.0005,0,-5,0,2e-5,10,1000\n", GRID, [":3:", "'x'"]),
        ("infinite", good + "0.01,inf,0.0005,0,-5,0,2e-5,10,1000\n", GRID, [":3:", "'y'"]),
        ("missing field", good + "0.01,0.02,0.0005,0,-5,0,2e-5,10\n", GRID, [":3:", "'rhoDroplet'", "missing"]),
        ("empty field", good + "0.01,0.02,0.0005,0,-5,0,2e-5,,1000\n", GRID, [":3:", "'nParticle'", "empty"]),
        ("zero nodes", good, ["--lower", "0,0,0", "--upper", "0.05,0.07,0.001", "--nodes", "0,71,1", "--dt", "1e-4"],
         ["--nodes", ">= 1"]),
        ("all directions flat", good, ["--lower", "0,0,0", "--upper", "0.05,0.07,0.001", "--nodes", "1,1,1",
                                       "--dt", "1e-4"], ["--nodes"]),
        ("upper below lower", good, ["--lower", "0,0,0", "--upper", "0.05,-0.07,0.001", "--nodes", "5,5,1",
                                     "--dt", "1e-4"], ["--upper", "y"]),
        ("bad dt", good, ["--lower", "0,0,0", "--upper", "0.05,0.07,0.001", "--nodes", "5,5,1", "--dt", "0"],
         ["--dt"]),
        ("unknown flag", good, GRID + ["--colour", "red"], ["--colour"]),
    ]
    for name, text, flags, expected in cases:
        path = write(os.path.join(work, name.replace(" ", "_") + ".csv"), text)
        code, out, err = run(["--parcels", path] + flags)
        check(code == 2, "%s: exit code 2 (got %d)" % (name, code))
        check(all(e in err for e in expected), "%s: message names %s: %s" % (name, expected, err.strip()))
    # A bad segments file names its line and field too.
    parcels = write(os.path.join(work, "good.csv"), good)
    segments = write(os.path.join(work, "segments.csv"),
                     "ax,ay,az,bx,by,bz,fiberRadius,ux,uy,uz\n0,0,0,1e-3,0,0,1e-4,0,0,0\n0,0,0,1e-3,0,0,x,0,0,0\n")
    code, out, err = run(["--parcels", parcels, "--segments", segments] + GRID)
    check(code == 2 and "segments.csv:3:" in err and "'fiberRadius'" in err, "segments: line and field named")
    bad_deposit_options(parcels)
    # --help documents every flag.
    code, out, err = run(["--help"])
    flags = ["--parcels", "--lower", "--upper", "--nodes", "--dt", "--output", "--beta", "--rmax-cap",
             "--dimension", "--segments", "--segments-output", "--radius-average", "--samples", "--help",
             "--rMaxCap", "--cloudInCellBelow", "--negligibleWeight", "--depositMethod", "--vectorised"]
    check(code == 0 and all(f in out for f in flags), "--help documents every flag")


# Every bad value of a deposit option: (flag, value, what the message must say is allowed),
# the function object's allowed values (src/openfoam/settings/gridSettings.C).
BAD_DEPOSIT_VALUES = [
    ("--depositMethod", v, ["automatic", "exact"]) for v in ("fast", "Exact", "separable", "")
] + [
    ("--negligibleWeight", v, ["[0, 1e-6]"]) for v in ("2e-6", "1", "-1e-9", "nan", "inf", "1e-8x", "")
] + [
    ("--cloudInCellBelow", v, [">= 0"]) for v in ("-0.5", "-inf", "inf", "nan", "half", "")
] + [
    ("--vectorised", v, ["true", "false"]) for v in ("maybe", "2", "True", "-1", "")
] + [
    ("--beta", v, ["(0, 1]"]) for v in ("0", "1.5", "nan")
] + [
    ("--rmax-cap", "-1e-3", [">= 0"]), ("--rMaxCap", "x", [">= 0"]),
    ("--dimension", "4", ["automatic", "2", "3"]), ("--dimension", "Automatic", ["automatic", "2", "3"]),
]


def bad_deposit_options(parcels):
    for flag, value, allowed in BAD_DEPOSIT_VALUES:
        code, out, err = run(["--parcels", parcels] + GRID + [flag, value])
        what = "%s '%s'" % (flag, value)
        check(code == 2 and out == "", "%s: exit code 2 (got %d), nothing deposited" % (what, code))
        check(err.startswith("dropletGrid: error: " + flag + ":") and ("'%s'" % value) in err
              and all(a in err for a in allowed),
              "%s: message names the option, the value and %s: %s" % (what, allowed, err.strip()))
    for flags, expected in ((["--rmax-cap", "1e-3", "--rMaxCap", "1e-3"], ["--rmax-cap", "--rMaxCap"]),
                            (["--negligibleWeight", "1e-8", "--negligibleWeight", "1e-9"], ["--negligibleWeight",
                                                                                            "twice"]),
                            (["--depositMethod"], ["--depositMethod", "missing value"])):
        code, out, err = run(["--parcels", parcels] + GRID + flags)
        check(code == 2 and all(e in err for e in expected), "%s: exit code 2, %s: %s" % (flags, expected,
                                                                                       err.strip()))


def segments():
    parcels = os.path.join(work, "parcels.csv")
    generate(parcels, 20000, seed=5, spread=0.5)
    segs = write(os.path.join(work, "segments.csv"),
                 "ax,ay,az,bx,by,bz,fiberRadius,ux,uy,uz\n"
                 "0.02,0.035,0.0005,0.03,0.035,0.0005,1e-4,0,0,0\n"   # normal to the mean flow
                 "0.025,0.03,0.0005,0.025,0.04,0.0005,1e-4,0,0,0\n"   # along the mean flow
                 "0.02,0.035,0.0005,0.03,0.035,0.0005,1e-4,0,1,0\n"   # normal, fiber moving up
                 "0.2,0.2,0.0005,0.21,0.2,0.0005,1e-4,0,0,0\n")       # outside the grid
    result = os.path.join(work, "collision.csv")
    code, out, err = run(["--parcels", parcels, "--segments", segs, "--segments-output", result, "--rmax-cap", "5e-3"]
                         + GRID)
    print(out, err)
    check(code == 0, "exit code 0")
    header, rows = read_csv(result)
    check(header == "segment,mass,momentumX,momentumY,momentumZ,rho,rMean,samples,samplesOutside".split(","),
          "segment CSV columns")
    check(len(rows) == 4, "one row per segment")
    seg_list = [(0.01, 0.0, 0.0, (0, 0, 0)), (0.0, 0.01, 0.0, (0, 0, 0)), (0.01, 0.0, 0.0, (0, 1, 0))]
    for k, (lx, ly, lz, vf) in enumerate(seg_list):
        r = rows[k]
        m = r["mass"]
        check(m > 0.0, "segment %d: positive mass" % k)
        if m <= 0.0:
            continue
        u = (r["momentumX"] / m, r["momentumY"] / m, r["momentumZ"] / m)  # droplet velocity at the midpoint
        v = (u[0] - vf[0], u[1] - vf[1], u[2] - vf[2])
        cross = (ly * v[2] - lz * v[1], lz * v[0] - lx * v[2], lx * v[1] - ly * v[0])
        expected = 2.0 * r["rho"] * (1e-4 + r["rMean"]) * math.sqrt(sum(c * c for c in cross)) * 1e-4
        check(close(m, expected, 1e-9), "segment %d: eq. 9 from the printed rho, rMean, velocity" % k)
    check(rows[0]["mass"] > 0.0, "normal segment collects mass")
    # Along the mean flow only the small mean cross-flow (random spread) counts.
    check(rows[1]["mass"] < 0.05 * rows[0]["mass"], "segment along the flow collects (almost) nothing")
    check(rows[2]["mass"] > rows[0]["mass"], "fiber moving up against the falling spray collects more")
    check(rows[3]["mass"] == 0.0 and rows[3]["samplesOutside"] == 1, "segment outside the grid: zero, counted")


def large():
    parcels = os.path.join(work, "parcels-1e5.csv")
    mass = generate(parcels, 100000, seed=7)
    # Droplet counts up to 2000 of up to 100 um give r_max = r_p n up to 10 cm, the whole
    # grid: cap the influence radius at 3 mm (3 node spacings) as a user would.
    code, out, err = run(["--parcels", parcels, "--output", os.path.join(work, "nodes.csv"), "--rmax-cap", "3e-3"]
                         + GRID)
    print(out, err)
    check(code == 0, "exit code 0")
    check(out.startswith("dropletGrid: 100000 parcels"), "100000 parcels read")
    check(printed(out, "kernel cap bound") > 50000, "most parcels capped (and reported)")
    check(close(printed(out, "mass in"), mass, 1e-11), "mass in = sum of n rho 4/3 pi r^3")
    check(close(printed(out, "mass on the grid"), mass, 1e-11), "all paths inside: mass on the grid = mass in")
    check(re.search(r"^\s*time:.*deposit [0-9.]+ s.*total [0-9.]+ s", out, re.MULTILINE) is not None,
          "time printed")


# --- The deposit options of the function object's grid dictionary (CommandLine.cpp) ---

HEADER = "x,y,z,ux,uy,uz,d,nParticle,rhoDroplet\n"
FLAT = {"lower": (0.0, 0.0, 0.0), "upper": (0.05, 0.07, 0.001), "nodes": (51, 71, 1)}  # GRID, 2D
CUBE = {"lower": (0.0, 0.0, 0.0), "upper": (0.02, 0.02, 0.02), "nodes": (21, 21, 21)}  # 3D, h = 1 mm


def grid_flags(grid):
    return ["--lower", ",".join("%.17g" % v for v in grid["lower"]), "--upper",
            ",".join("%.17g" % v for v in grid["upper"]), "--nodes", ",".join(map(str, grid["nodes"])),
            "--dt", "1e-4"]


def dual_volume(grid, row):
    """A node's dual-cell volume (GridSpec.hpp): h per active direction, halved on a face;
    a flat direction contributes its thickness."""
    volume = 1.0
    for d, key in enumerate("ijk"):
        n, length = grid["nodes"][d], grid["upper"][d] - grid["lower"][d]
        if n == 1:
            volume *= length
        else:
            volume *= length / (n - 1) / (2.0 if row[key] in (0, n - 1) else 1.0)
    return volume


def deposit(name, grid, parcels, flags):
    """Run the tool on `parcels` (tuples x,y,z,ux,uy,uz,d,n,rho); return the exit code (0:
    the driver stops on any other), the standard output and {(i, j, k): node mass rho *
    dual volume}."""
    path = write(os.path.join(work, name + ".csv"),
                 HEADER + "".join(",".join("%.17g" % v for v in p) + "\n" for p in parcels))
    nodes = os.path.join(work, name + "-nodes.csv")
    code, out, err = run(["--parcels", path, "--output", nodes] + grid_flags(grid) + flags)
    if code != 0:
        # The checks that follow need the node fields: stop here.
        print(out, err)
        check(False, "%s: exit code 0 (got %d)" % (name, code))
        print("%d failed" % len(failures))
        sys.exit(1)
    _, rows = read_csv(nodes)
    masses = {(int(r["i"]), int(r["j"]), int(r["k"])): r["rho"] * dual_volume(grid, r) for r in rows}
    return code, out, masses


def node_position(grid, key):
    return [grid["lower"][d] + key[d] * (grid["upper"][d] - grid["lower"][d]) / max(grid["nodes"][d] - 1, 1)
            for d in range(3)]


def cloud_in_cell():
    # r_p n = 4 mm, kernel width r_max / sqrt(2 alpha) = 0.56 spacings (eqs. 13-18): above the
    # default 0.5 (the kernel, spread over many nodes), far below --cloudInCellBelow 1e6.
    d, n, rho = 1e-4, 80.0, 1000.0
    m = parcel_mass(d, n, rho)
    every = ["--cloudInCellBelow", "1e6"]
    # A stationary parcel exactly on node (20, 30): all of its mass on that node.
    code, out, masses = deposit("cic-node", FLAT, [(0.020, 0.030, 0.0005, 0, 0, 0, d, n, rho)], every)
    check(code == 0 and printed(out, "cloud-in-cell") == 1, "cloudInCellBelow 1e6: the parcel is cloud-in-cell")
    check(close(masses.get((20, 30, 0), 0.0), m, 1e-12), "on a node: all its mass on that node")
    check(sum(v for k, v in masses.items() if k != (20, 30, 0)) <= 1e-12 * m, "on a node: nothing elsewhere")
    # At a cell centre: 1/4 on each of the 4 corners (2D), 1/8 on each of the 8 (3D).
    code, out, masses = deposit("cic-centre", FLAT, [(0.0205, 0.0305, 0.0005, 0, 0, 0, d, n, rho)], every)
    corners = [(20, 30, 0), (21, 30, 0), (20, 31, 0), (21, 31, 0)]
    check(code == 0 and all(close(masses[c], m / 4, 1e-12) for c in corners), "2D cell centre: m/4 on each corner")
    check(sum(v for k, v in masses.items() if k not in corners) <= 1e-12 * m, "2D cell centre: nothing elsewhere")
    # (3D: 400 droplets, width 0.9 spacings; 80 are cloud-in-cell at the default 0.5 already.)
    m3 = parcel_mass(d, 400.0, rho)
    code, out, masses = deposit("cic-centre3d", CUBE, [(0.0105, 0.0085, 0.0125, 0, 0, 0, d, 400.0, rho)], every)
    corners = [(i, j, k) for i in (10, 11) for j in (8, 9) for k in (12, 13)]
    check(code == 0 and printed(out, "cloud-in-cell") == 1 and all(close(masses[c], m3 / 8, 1e-12) for c in corners),
          "3D cell centre: m/8 on each corner")
    code, out, masses = deposit("kernel-3d", CUBE, [(0.0105, 0.0085, 0.0125, 0, 0, 0, d, 400.0, rho)], [])
    check(code == 0 and printed(out, "cloud-in-cell") == 0 and sum(v > 0 for v in masses.values()) > 8,
          "3D, default 0.5: the kernel, over more than 8 nodes")
    # Moving: multilinear weights keep the centre of mass, the middle of the path.
    velocity = (12.0, -7.0, 0.0)  # 1.2 and 0.7 mm in the step of 1e-4 s
    end = (0.0251, 0.0333, 0.0005)
    code, out, masses = deposit("cic-moving", FLAT, [end + velocity + (d, n, rho)], every)
    total = sum(masses.values())
    for axis in (0, 1):
        centre = sum(v * node_position(FLAT, k)[axis] for k, v in masses.items()) / total
        middle = end[axis] - 0.5 * velocity[axis] * 1e-4
        check(abs(centre - middle) <= 1e-9 * 1e-3, "moving: centre of mass %s = middle of the path" % "xy"[axis])
    check(close(total, m, 1e-12), "moving: mass conserved")
    # The default (0.5) and 0 deposit this parcel with its kernel: not cloud-in-cell, wider.
    for flags in ([], ["--cloudInCellBelow", "0"]):
        code, out, masses = deposit("cic-kernel", FLAT, [(0.020, 0.030, 0.0005, 0, 0, 0, d, n, rho)], flags)
        check(code == 0 and printed(out, "cloud-in-cell") == 0 and sum(v > 0 for v in masses.values()) > 4
              and close(sum(masses.values()), m, 1e-12),
              "cloudInCellBelow %s: the kernel, over more than 4 nodes, mass conserved" % (flags or ["default"]))


# Wide kernels (reach >= 3 spacings after the cut): stationary, moving, across the face
# x = 0 (folded), and 3D. Tuples: grid, parcel.
WIDE = [
    (FLAT, (0.0253, 0.0351, 0.0005, 0, 0, 0, 1e-4, 160, 1000)),
    (FLAT, (0.0247, 0.0302, 0.0005, 0, -5, 0, 1e-4, 400, 1000)),
    (FLAT, (0.030, 0.040, 0.0005, 12, 9, 0, 5e-5, 1000, 1000)),
    (FLAT, (0.0015, 0.035, 0.0005, 0, 0, 0, 1e-4, 300, 1000)),
    (CUBE, (0.0101, 0.0097, 0.0103, 3, -4, 2, 1e-4, 400, 1000)),
]


def deposit_method():
    # docs/model.md P16: each weight of the separable tables within 1e-7 of the parcel's
    # largest weight of the exact integral; the box's corners beyond the cut, which the
    # exact code leaves out, differ by less than negligibleWeight (1e-8) of it (P10).
    bound = 1e-7 + 1e-8
    for p, (grid, parcel) in enumerate(WIDE):
        m = parcel_mass(*parcel[6:])
        code_a, out_a, auto = deposit("wide%d-automatic" % p, grid, [parcel], [])
        code_e, out_e, exact = deposit("wide%d-exact" % p, grid, [parcel], ["--depositMethod", "exact"])
        what = "wide parcel %d: " % p
        check(code_a == 0 and code_e == 0, what + "exit codes 0")
        check(printed(out_a, "separable weights") == 1 and printed(out_e, "separable weights") == 0,
              what + "automatic takes the separable tables, exact does not")
        check(close(sum(auto.values()), m, 1e-12) and close(sum(exact.values()), m, 1e-12),
              what + "both put the parcel's mass on the grid (node sums)")
        check(close(printed(out_a, "mass on the grid"), printed(out_e, "mass on the grid"), 1e-12),
              what + "total masses agree to round-off")
        largest = max(exact.values())
        worst = max(abs(auto[k] - exact[k]) for k in exact) / largest
        check(worst <= bound, what + "every node within %.1e of the largest weight (%.2e)" % (bound, worst))


def negligible_weight():
    # The same parcels under cuts from 0 (exact tails) up to the largest allowed, 1e-6:
    # fewer nodes visited and the mass conserved. Exact method: only the cut differs.
    cuts = ("0", "1e-12", "1e-8", "1e-6")
    parcels = [parcel for grid, parcel in WIDE if grid is FLAT]
    m = sum(parcel_mass(*p[6:]) for p in parcels)
    visited = []
    for cut in cuts:
        code, out, masses = deposit("cut" + cut, FLAT, parcels, ["--negligibleWeight", cut, "--depositMethod", "exact"])
        check(code == 0, "negligibleWeight %s: exit code 0" % cut)
        check(close(printed(out, "mass on the grid"), m, 1e-12) and close(sum(masses.values()), m, 1e-12),
              "negligibleWeight %s: mass on the grid = mass in" % cut)
        visited.append(printed(out, "nodes visited"))
    check(all(a > b for a, b in zip(visited, visited[1:])), "larger negligibleWeight, fewer nodes: %s" % visited)
    # One parcel at a time against exact tails: docs/model.md sec. 4, in 2D the cut moves
    # ~negligibleWeight of the largest node value (the Gaussian's tail beyond the cut to the
    # kept nodes); 2x for the discrete sum and the approximations there.
    for p, parcel in enumerate(parcels):
        reference = deposit("cut0-%d" % p, FLAT, [parcel], ["--negligibleWeight", "0", "--depositMethod", "exact"])[2]
        for cut in cuts[1:]:
            flags = ["--negligibleWeight", cut, "--depositMethod", "exact"]
            masses = deposit("cut%s-%d" % (cut, p), FLAT, [parcel], flags)[2]
            worst = max(abs(masses[k] - reference[k]) for k in reference) / max(reference.values())
            check(worst <= 2 * float(cut), "parcel %d, negligibleWeight %s: nodes within 2x that of the largest "
                  "(%.2e)" % (p, cut, worst))


def vectorised():
    # Moving resolved kernels (the batched exact loop): per parcel, the batched and the
    # per-node weights agree to epsilon (1 + N w_max) of the largest node value, epsilon =
    # 1e-14 (DensityGridVectorisedTest); equal when the CPU has no AVX2 + FMA.
    for p, (grid, parcel) in enumerate(WIDE):
        if parcel[3:6] == (0, 0, 0):
            continue
        flags = ["--depositMethod", "exact"]
        code_v, out_v, fast = deposit("vec%d-true" % p, grid, [parcel], flags + ["--vectorised", "true"])
        code_p, out_p, portable = deposit("vec%d-false" % p, grid, [parcel], flags + ["--vectorised", "false"])
        what = "parcel %d: " % p
        check(code_v == 0 and code_p == 0 and "vectorised false (node by node)" in out_p,
              what + "--vectorised false runs node by node")
        largest = max(portable.values())
        weighted = sum(v > 0 for v in portable.values())
        bound = 1e-14 * (1 + weighted * largest / sum(portable.values()))
        worst = max(abs(fast[k] - portable[k]) for k in portable) / largest
        check(worst <= bound, what + "true and false agree within %.1e of the largest (%.2e)" % (bound, worst))
        for word in ("off", "no", "0", "n", "f"):
            code, out, masses = deposit("vec%d-%s" % (p, word), grid, [parcel], flags + ["--vectorised", word])
            check(code == 0 and masses == portable, what + "--vectorised %s is false" % word)


# The deposit flags and their dictionary entries (grid sub-dictionary, docs/reference.md).
DEPOSIT_ENTRIES = {"--beta": "beta", "--rmax-cap": "rMaxCap", "--dimension": "dimension",
                   "--cloudInCellBelow": "cloudInCellBelow", "--negligibleWeight": "negligibleWeight",
                   "--depositMethod": "depositMethod", "--vectorised": "vectorised"}


def reference_defaults():
    """{entry: default} of the rows of the grid table of docs/reference.md, the one
    reference of the dictionary (columns Entry | Allowed | Default | What it does)."""
    reference = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs",
                             "reference.md")
    defaults, in_grid = {}, False
    for line in open(reference, encoding="utf-8"):
        if line.startswith("#"):
            in_grid = re.match(r"^##\s+`grid`\s*$", line) is not None
            continue
        match = re.match(r"^\|\s*`(\w+)`[^|]*\|[^|]*\|\s*([^|]*?)\s*\|", line)
        if in_grid and match:
            defaults[match.group(1)] = match.group(2).strip("`")
    return defaults


def same_value(a, b):
    try:
        return float(a) == float(b)
    except ValueError:
        return a == b


def same_as_dictionary():
    # Defaults: docs/reference.md's table of the grid entries, against what the tool
    # says in --help and what it prints as the settings in force when no flag is given.
    defaults = reference_defaults()
    code, help_text, err = run(["--help"])
    parcels = write(os.path.join(work, "one.csv"), HEADER + "0.02,0.03,0.0005,0,-5,0,5e-5,100,1000\n")
    code, out, err = run(["--parcels", parcels] + GRID)
    settings = " ".join(re.search(r"deposit settings:(.*?)\n\s*mass in", out, re.S).group(1).split())
    for flag, entry in DEPOSIT_ENTRIES.items():
        expected = defaults.get(entry)
        check(expected is not None, "docs/reference.md documents grid.%s" % entry)
        block = re.search(r"^  " + re.escape(flag) + r"\b(.*?)(?=^  --|^\S|\Z)", help_text, re.M | re.S)
        stated = re.search(r"\(default ([^,:)]+)", " ".join(block.group(1).split())) if block else None
        check(stated is not None and same_value(stated.group(1), expected),
              "%s: --help's default %s = the dictionary's %s" % (flag, stated and stated.group(1), expected))
        used = re.search(r"\b" + entry + r" (\S+?),?(?: |$)", settings)
        check(used is not None and same_value(used.group(1), expected),
              "%s: default in force %s = the dictionary's %s" % (flag, used and used.group(1), expected))
    # Allowed values: the edges and every word the dictionary takes are taken.
    good = [("--depositMethod", v) for v in ("automatic", "exact")] + [
        ("--negligibleWeight", v) for v in ("0", "1e-6")] + [("--cloudInCellBelow", v) for v in ("0", "1e3")] + [
        ("--vectorised", v) for v in ("true", "false", "on", "off", "yes", "no", "y", "n", "t", "f", "1", "0")] + [
        ("--dimension", v) for v in ("automatic", "2", "3")] + [("--rMaxCap", "0"), ("--rmax-cap", "0"),
                                                                ("--beta", "1")]
    for flag, value in good:
        code, out, err = run(["--parcels", parcels] + GRID + [flag, value])
        check(code == 0, "%s %s: taken, as the dictionary takes it%s" % (flag, value, err and ": " + err.strip()))


{"totals": totals, "badInput": bad_input, "segments": segments, "large": large,
 "cloudInCell": cloud_in_cell, "depositMethod": deposit_method, "negligibleWeight": negligible_weight,
 "vectorised": vectorised, "sameAsDictionary": same_as_dictionary}[case]()
print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
