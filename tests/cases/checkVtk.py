"""Check the ParaView files of a run with an independent reader (xml.etree).

Usage: checkVtk.py CASE [NAME]

For the last fibers_<time>.vtp (in parallel fibers_<time>.pvtp: the pieces it
lists, one per processor, read together; every array it declares in every
piece; no fiber in two pieces): a polyline per fiber, point fields velocity,
sigma, capturedMass, cell field tension; sigma integrated along the fibers
(sigma_i times the length point i stands for: half of each neighbouring segment)
equals the fiber mass the per-step table reports at that time. For the last
grid_<time>.vti: point count = product of the extent, fields rho, rMeanNumber,
rMeanMass, U. The .series files list every written file.
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402

case = sys.argv[1]
name = sys.argv[2] if len(sys.argv) > 2 else "dropletFiber"
out = os.path.join(case, "postProcessing", name, "0")
passed = failed = 0


def check(ok, what):
    global passed, failed
    passed += bool(ok)
    failed += not ok
    print(("ok: " if ok else "FAILED: ") + what)


def arrays(piece, tag):
    block = piece.find(tag)
    result = {}
    for da in (block if block is not None else []):
        values = [float(v) for v in (da.text or "").split()]
        result[da.get("Name")] = (int(da.get("NumberOfComponents", "1")), values)
    return result


def fibers_of(path):
    """Points, line cells (point pairs), point and cell arrays of a .vtp, or of
    the pieces a .pvtp lists, read together (point numbers offset per piece)."""
    root = ET.parse(path).getroot()
    if root.get("type") != "PPolyData":
        return [read_piece(root.find("PolyData/Piece"))]
    index = root.find("PPolyData")
    declared = {"PPointData": [], "PCellData": []}
    for block in declared:
        for da in index.find(block) if index.find(block) is not None else []:
            declared[block].append((da.get("Name"), int(da.get("NumberOfComponents", "1"))))
    sources = [p.get("Source") for p in index.findall("Piece")]
    check(len(sources) > 0, "%s lists %d pieces" % (os.path.basename(path), len(sources)))
    pieces = []
    for source in sources:
        piece_path = os.path.join(os.path.dirname(path), source)
        check(os.path.isfile(piece_path), "piece %s exists" % source)
        piece = read_piece(ET.parse(piece_path).getroot().find("PolyData/Piece"))
        for block, data in (("PPointData", piece[2]), ("PCellData", piece[3])):
            for name, comps in declared[block]:
                check(name in data and data[name][0] == comps,
                      "piece %s holds %s (%d components)" % (source, name, comps))
        pieces.append(piece)
    ids = [set(p[2]["fiberId"][1]) for p in pieces if "fiberId" in p[2]]
    check(sum(len(i) for i in ids) == len(set().union(*ids)), "no fiber in two pieces")
    return pieces


def read_piece(piece):
    n_points = int(piece.get("NumberOfPoints"))
    pts = [float(v) for v in (piece.find("Points/DataArray").text or "").split()]
    conn = [int(v) for v in (piece.find("Lines/DataArray[@Name='connectivity']").text or "").split()]
    return ([pts[3 * i:3 * i + 3] for i in range(n_points)], conn, arrays(piece, "PointData"),
            arrays(piece, "CellData"), int(piece.get("NumberOfLines")))


def joined(pieces):
    """The pieces as one set of points, line cells and arrays."""
    points, conn, pdata, cdata, n_lines = [], [], {}, {}, 0
    for p_points, p_conn, p_pdata, p_cdata, p_lines in pieces:
        conn += [len(points) + c for c in p_conn]
        points += p_points
        n_lines += p_lines
        for data, p_data in ((pdata, p_pdata), (cdata, p_cdata)):
            for name, (comps, values) in p_data.items():
                data.setdefault(name, (comps, []))[1].extend(values)
    return points, conn, pdata, cdata, n_lines


for kind, ext in (("fibers", "vtp"), ("grid", "vti")):
    series = json.load(open(os.path.join(out, "%s.%s.series" % (kind, ext))))
    files = series["files"]
    check(len(files) > 0, "%s series lists %d files" % (kind, len(files)))
    for f in files:
        check(os.path.isfile(os.path.join(out, f["name"])), "%s exists" % f["name"])
    times = [f["time"] for f in files]
    check(times == sorted(set(times)), "%s series times increase" % kind)

# Fibers
series = json.load(open(os.path.join(out, "fibers.vtp.series")))
last = series["files"][-1]
points, conn, pdata, cdata, n_lines = joined(fibers_of(os.path.join(out, last["name"])))
n_points = len(points)
check(len(points) == n_points, "%d points read" % n_points)
check(len(conn) == 2 * n_lines, "%d line cells of 2 points" % n_lines)
for field, comps in (("velocity", 3), ("sigma", 1), ("capturedMass", 1)):
    check(field in pdata and len(pdata[field][1]) == comps * n_points,
          "point field %s with %d values per point" % (field, comps))
check("tension" in cdata and len(cdata["tension"][1]) == n_lines, "cell field tension per segment")

sigma = pdata["sigma"][1]
nodal = [0.0] * n_points
for s in range(n_lines):
    a, b = conn[2 * s], conn[2 * s + 1]
    seg = math.dist(points[a], points[b])
    nodal[a] += seg / 2
    nodal[b] += seg / 2
integral = sum(s * l for s, l in zip(sigma, nodal))
rows = read_table(os.path.join(out, "dropletFiber.dat"))
row = min(rows, key=lambda r: abs(r["Time"] - last["time"]))
check(abs(integral - row["fiberMass"]) <= 1e-6 * row["fiberMass"],
      "integral of sigma %.10g kg = fiber mass in the table %.10g kg" % (integral, row["fiberMass"]))

# Grid
series = json.load(open(os.path.join(out, "grid.vti.series")))
root = ET.parse(os.path.join(out, series["files"][-1]["name"])).getroot()
image = root.find("ImageData")
ext = [int(v) for v in image.get("WholeExtent").split()]
n_nodes = (ext[1] - ext[0] + 1) * (ext[3] - ext[2] + 1) * (ext[5] - ext[4] + 1)
gdata = arrays(image.find("Piece"), "PointData")
for field, comps in (("rho", 1), ("rMeanNumber", 1), ("rMeanMass", 1), ("U", 3)):
    check(field in gdata and len(gdata[field][1]) == comps * n_nodes,
          "grid field %s with %d values per node (%d nodes)" % (field, comps, n_nodes))
check(max(gdata["rho"][1]) > 0, "grid holds droplets")
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
