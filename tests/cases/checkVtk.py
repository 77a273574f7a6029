"""Check the ParaView files of a run with an independent reader (xml.etree).

Usage: checkVtk.py CASE [NAME]

For the last fibers_<time>.vtp (in parallel fibers_<time>.pvtp: the pieces it
lists, one per processor, read together; every array it declares in every
piece; no fiber in two pieces): a polyline per fiber, point fields velocity,
sigma, capturedMass, cell field tension; sigma integrated along the fibers
(sigma_i times the length point i stands for: half of each neighbouring segment)
equals the fiber mass the per-step table reports at that time. For the last
grid_<time>.vti: point count = product of the extent, fields rho, rMeanNumber,
rMeanMass, U. A parallel run's grid_<time>.pvti (ParaView's parallel image data):
its pieces exist, each with the fields over its extent, lie within the whole
extent, and their cells tile it (every cell in exactly one piece; neighbouring
pieces share their boundary nodes, with the same values). The .series files
list every written file.
"""
import base64
import json
import math
import os
import struct
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402
from checks import check, finish  # noqa: E402

case = sys.argv[1]
name = sys.argv[2] if len(sys.argv) > 2 else "dropletFiber"
out = os.path.join(case, "postProcessing", name, "0")
parallel = os.path.isdir(os.path.join(case, "processor0"))


def series_file(kind, ext):
    """kind's ParaView series index: a parallel run's is named by the pieces' index it
    lists (fibers.pvtp.series, grid.pvti.series), so that ParaView picks the reader that
    opens them"""
    return os.path.join(out, "%s.%s%s.series" % (kind, "p" if parallel else "", ext))



def array_values(da):
    """An array's numbers: ASCII, or VTK's inline binary form (the grid): base64 of
    a UInt64 byte count (header_type UInt64) and the little-endian doubles."""
    if da.get("format") != "binary":
        return [float(v) for v in (da.text or "").split()]
    raw = base64.b64decode("".join((da.text or "").split()), validate=True)
    (count,) = struct.unpack("<Q", raw[:8])
    if count != len(raw) - 8:
        raise ValueError("binary array %s: header says %d bytes, holds %d" % (da.get("Name"), count, len(raw) - 8))
    return list(struct.unpack("<%dd" % (count // 8), raw[8:]))


def arrays(piece, tag):
    block = piece.find(tag)
    result = {}
    for da in (block if block is not None else []):
        result[da.get("Name")] = (int(da.get("NumberOfComponents", "1")), array_values(da))
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
    series = json.load(open(series_file(kind, ext)))
    files = series["files"]
    check(len(files) > 0, "%s series lists %d files" % (kind, len(files)))
    for f in files:
        check(os.path.isfile(os.path.join(out, f["name"])), "%s exists" % f["name"])
    times = [f["time"] for f in files]
    check(times == sorted(set(times)), "%s series times increase" % kind)

# Fibers
series = json.load(open(series_file("fibers", "vtp")))
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
series = json.load(open(series_file("grid", "vti")))
last_grid = os.path.join(out, series["files"][-1]["name"])
FIELDS = (("rho", 1), ("rMeanNumber", 1), ("rMeanMass", 1), ("U", 3))


def extent_of(element, key):
    return [int(v) for v in element.get(key).split()]


def nodes_of(ext):
    return (ext[1] - ext[0] + 1) * (ext[3] - ext[2] + 1) * (ext[5] - ext[4] + 1)


def check_pvti(path):
    """The pieces of a .pvti: fields, extents inside the whole, cells tiled."""
    index = ET.parse(path).getroot().find("PImageData")
    whole = extent_of(index, "WholeExtent")
    declared = [(a.get("Name"), int(a.get("NumberOfComponents"))) for a in index.find("PPointData")]
    check(declared == list(FIELDS), "pvti declares the fields %s" % [n for n, _ in declared])
    cells = {}
    values = {}
    rho_max = 0.0
    pieces = index.findall("Piece")
    check(len(pieces) > 1, "pvti lists %d pieces" % len(pieces))
    for piece in pieces:
        ext = extent_of(piece, "Extent")
        source = os.path.join(os.path.dirname(path), piece.get("Source"))
        check(os.path.isfile(source), "piece %s exists" % piece.get("Source"))
        inside = all(whole[2 * d] <= ext[2 * d] <= ext[2 * d + 1] <= whole[2 * d + 1] for d in range(3))
        check(inside, "piece extent %s within the whole extent %s" % (ext, whole))
        image = ET.parse(source).getroot().find("ImageData")
        check(extent_of(image.find("Piece"), "Extent") == ext, "piece file's extent is the listed one")
        data = arrays(image.find("Piece"), "PointData")
        n = nodes_of(ext)
        for field, comps in FIELDS:
            check(field in data and len(data[field][1]) == comps * n,
                  "piece field %s with %d values per node (%d nodes)" % (field, comps, n))
        rho = data["rho"][1]
        rho_max = max([rho_max] + rho)
        # Cells of the piece (a flat direction: its single layer is the cell)
        ranges = [range(ext[2 * d], max(ext[2 * d + 1], ext[2 * d] + 1)) for d in range(3)]
        for k in ranges[2]:
            for j in ranges[1]:
                for i in ranges[0]:
                    cells[(i, j, k)] = cells.get((i, j, k), 0) + 1
        nx, ny = ext[1] - ext[0] + 1, ext[3] - ext[2] + 1
        for k in range(ext[4], ext[5] + 1):
            for j in range(ext[2], ext[3] + 1):
                for i in range(ext[0], ext[1] + 1):
                    v = rho[(i - ext[0]) + nx * ((j - ext[2]) + ny * (k - ext[4]))]
                    values.setdefault((i, j, k), set()).add(v)
    whole_ranges = [range(whole[2 * d], max(whole[2 * d + 1], whole[2 * d] + 1)) for d in range(3)]
    expected = {(i, j, k) for k in whole_ranges[2] for j in whole_ranges[1] for i in whole_ranges[0]}
    check(set(cells) == expected and all(c == 1 for c in cells.values()),
          "the pieces' %d cells tile the whole extent's %d, each once" % (len(cells), len(expected)))
    check(len(values) == nodes_of(whole) and all(len(v) == 1 for v in values.values()),
          "every node in some piece, shared nodes with one rho")
    check(rho_max > 0, "grid holds droplets")


if last_grid.endswith(".pvti"):
    check_pvti(last_grid)
else:
    root = ET.parse(last_grid).getroot()
    image = root.find("ImageData")
    ext = [int(v) for v in image.get("WholeExtent").split()]
    n_nodes = (ext[1] - ext[0] + 1) * (ext[3] - ext[2] + 1) * (ext[5] - ext[4] + 1)
    gdata = arrays(image.find("Piece"), "PointData")
    for field, comps in FIELDS:
        check(field in gdata and len(gdata[field][1]) == comps * n_nodes,
              "grid field %s with %d values per node (%d nodes)" % (field, comps, n_nodes))
    check(max(gdata["rho"][1]) > 0, "grid holds droplets")
finish()
