"""The function object's VTK files read with the standard library's XML parser.

They are VTK's XML formats as the function object writes them: the fibers as
PolyData (.vtp, ASCII arrays; a parallel run's .pvtp lists one .vtp piece per
processor), the grid as ImageData (.vti; a parallel run's .pvti lists one piece per
processor) with inline binary arrays (base64 of a UInt64 byte count and the
little-endian doubles). No appended data, no compression: a VTK library would add
nothing here. The .series files (JSON) list the files by time.
"""
import base64
import json
import os
import re
import struct
import xml.etree.ElementTree as ET

import numpy as np


def _values(da):
    if da.get("format") != "binary":
        return np.array((da.text or "").split(), dtype=float)
    raw = base64.b64decode("".join((da.text or "").split()))
    (count,) = struct.unpack("<Q", raw[:8])
    if count != len(raw) - 8:
        raise ValueError("array %s: header says %d bytes, holds %d" % (da.get("Name"), count, len(raw) - 8))
    return np.frombuffer(raw[8:8 + count], dtype="<f8").astype(float)


def _arrays(block):
    return {da.get("Name"): _values(da) for da in (block if block is not None else [])}


def series(folder, name):
    """[(time, path)] of a .series file (name e.g. 'fibers.vtp'), else of the files
    fibers_<time>.vtp/.pvtp found in the folder; in time order."""
    path = os.path.join(folder, name + ".series")
    stem, ext = name.split(".")
    if os.path.isfile(path):
        try:
            entries = json.load(open(path))["files"]
            return sorted((float(e["time"]), os.path.join(folder, e["name"])) for e in entries)
        except (ValueError, KeyError, TypeError):
            pass  # a series cut short while written: the files themselves
    found = []
    for entry in os.listdir(folder) if os.path.isdir(folder) else []:
        m = re.match(r"^%s_([-+0-9.eE]+)\.p?%s$" % (stem, ext), entry)
        if m:
            found.append((float(m.group(1)), os.path.join(folder, entry)))
    return sorted(found)


def _segments(piece):
    """The point pairs of a piece's line cells and each pair's cell values (a
    polyline of n points gives n - 1 pairs with its cell's values)."""
    lines = _arrays(piece.find("Lines"))
    ends = lines.get("offsets", np.array([])).astype(int)
    starts = np.concatenate(([0], ends[:-1])).astype(int)
    connectivity = lines.get("connectivity", np.array([])).astype(int)
    cells = _arrays(piece.find("CellData"))
    if np.all(ends - starts == 2):  # the function object's cells: one segment each
        return connectivity.reshape(-1, 2), cells
    pairs, owner = [], []
    for c, (a, b) in enumerate(zip(starts, ends)):
        ids = connectivity[a:b]
        pairs += [(ids[k], ids[k + 1]) for k in range(len(ids) - 1)]
        owner += [c] * (len(ids) - 1)
    return np.array(pairs, dtype=int).reshape(-1, 2), {k: v[owner] for k, v in cells.items()}


class PolyData:
    """A .vtp (or a .pvtp's pieces): points, point arrays, and the line cells'
    segments (point pairs) with their cell arrays. The function object's fibers, and
    the clouds' parcels as OpenFOAM's vtkCloud writes them (ASCII, no lines)."""

    def __init__(self, time, path):
        self.time, self.path = time, path
        points, point_data, segments, cell_data = [], {}, [], {}
        offset = 0
        for piece in _pieces(path):
            p = _values(piece.find("Points/DataArray")).reshape(-1, 3)
            pairs, cells = _segments(piece)
            segments.append(offset + pairs)
            for key, values in cells.items():
                cell_data.setdefault(key, []).append(values)
            for key, values in _arrays(piece.find("PointData")).items():
                point_data.setdefault(key, []).append(values)
            points.append(p)
            offset += len(p)
        self.points = np.vstack(points) if points else np.zeros((0, 3))
        self.point_data = {k: np.concatenate(v) for k, v in point_data.items()}
        self.segments = np.vstack(segments) if segments else np.zeros((0, 2), dtype=int)
        self.cell_data = {k: np.concatenate(v) for k, v in cell_data.items()}


class Fibers(PolyData):
    """The function object's fibers: each line cell one segment of a fiber."""

    def segment_lengths(self):
        a, b = self.points[self.segments[:, 0]], self.points[self.segments[:, 1]]
        return np.linalg.norm(b - a, axis=1)

    def segment_mean(self, name):
        """A point array's mean over each segment's two ends."""
        v = self.point_data[name]
        return 0.5 * (v[self.segments[:, 0]] + v[self.segments[:, 1]])


def _pieces(path):
    root = ET.parse(path).getroot()
    if root.get("type") != "PPolyData":
        return [root.find("PolyData/Piece")]
    folder = os.path.dirname(path)
    return [ET.parse(os.path.join(folder, p.get("Source"))).getroot().find("PolyData/Piece")
            for p in root.findall("PPolyData/Piece")]


class Grid:
    """The grid's node values as arrays indexed [k, j, i], with origin and spacing;
    start: the first node's (i, j, k) index (WholeExtent's lower ends), so that node
    [k, j, i] lies at origin + spacing * (start + (i, j, k))."""

    def __init__(self, time, path):
        self.time, self.path = time, path
        root = ET.parse(path).getroot()
        image = root.find("ImageData")
        parallel = image is None
        if parallel:
            image = root.find("PImageData")
        whole = [int(v) for v in image.get("WholeExtent").split()]
        self.origin = np.array([float(v) for v in image.get("Origin").split()])
        self.spacing = np.array([float(v) for v in image.get("Spacing").split()])
        self.start = np.array(whole[0::2])
        self.shape = (whole[5] - whole[4] + 1, whole[3] - whole[2] + 1, whole[1] - whole[0] + 1)
        self.fields = {}
        pieces = [image.find("Piece")] if not parallel else [
            ET.parse(os.path.join(os.path.dirname(path), p.get("Source"))).getroot().find("ImageData/Piece")
            for p in image.findall("Piece")]
        for piece in pieces:
            e = [int(v) for v in piece.get("Extent").split()]
            size = (e[5] - e[4] + 1, e[3] - e[2] + 1, e[1] - e[0] + 1)
            for name, values in _arrays(piece.find("PointData")).items():
                components = values.size // (size[0] * size[1] * size[2])
                full = self.fields.setdefault(name, np.zeros(self.shape + ((components,) if components > 1 else ())))
                block = values.reshape(size + ((components,) if components > 1 else ()))
                full[e[4] - whole[4]:e[5] - whole[4] + 1, e[2] - whole[2]:e[3] - whole[2] + 1,
                     e[0] - whole[0]:e[1] - whole[0] + 1] = block


def last_readable(folder, name, reader, notes):
    """The last file of a series that reads (a run stopped while writing one leaves it
    missing or cut short: the one before is taken, and noted); None when none reads."""
    for time, path in reversed(series(folder, name)):
        try:
            return reader(time, path)
        except (OSError, ET.ParseError, ValueError, AttributeError, IndexError, struct.error) as error:
            notes.append("%s at t = %g cannot be read (%s): the one before is used"
                         % (os.path.basename(path), time, str(error).split("\n")[0]))
    return None
