#!/usr/bin/env python3
"""CTest driver for the dropletGrid tool.

Usage: testDropletGrid.py DROPLETGRID CASE WORKDIR
CASE: totals | badInput | segments | large. Expected values are computed here from the
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
    # --help documents every flag.
    code, out, err = run(["--help"])
    flags = ["--parcels", "--lower", "--upper", "--nodes", "--dt", "--output", "--beta", "--rmax-cap",
             "--dimension", "--segments", "--segments-output", "--radius-average", "--samples", "--help"]
    check(code == 0 and all(f in out for f in flags), "--help documents every flag")


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


{"totals": totals, "badInput": bad_input, "segments": segments, "large": large}[case]()
print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
