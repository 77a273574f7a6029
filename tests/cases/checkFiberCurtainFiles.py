"""Readers of the fiberCurtain case's files for checkFiberCurtain.py and
checkFiberCurtainSame.py (plain Python, standard library only; independent of
OpenFOAM and of dropletFiber).

- table(case, fo, name, start="0"): a postProcessing table of function object fo
  (postProcessing/<fo>/<start>/<name>) as rows of numbers, time first, vectors
  flattened: `(x y z)` gives three numbers.
- columns(case, fo, name, start="0"): its column names (the last comment line).
- entry(path, key): a scalar entry `key value;` of an OpenFOAM dictionary file.
- fibers(case, time): the fibers of the restart state at time (over the
  processor* folders of a parallel run) as dicts: origin, represents, point
  masses (lumped: half of each adjacent segment, rho_F pi r_F^2 l_j plus its
  captured mass, docs/model.md sec. 1), velocities, positions.
- state_totals(case, time): the state's totals (processor 0's in parallel) and
  fiberCount summed over the processors.
"""
import glob
import math
import os
import re

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def table(case, fo, name, start="0"):
    rows = []
    for line in open(os.path.join(case, "postProcessing", fo, start, name)):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(v) for v in re.sub(r"[()]", " ", line).split()])
    return rows


def columns(case, fo, name, start="0"):
    names = []
    for line in open(os.path.join(case, "postProcessing", fo, start, name)):
        if line.startswith("#"):
            names = [c.strip() for c in line[1:].split("\t") if c.strip()]
    return names


def entry(path, key):
    return entry_in(re.sub(r"//[^\n]*", "", open(path).read()), key)


def entry_in(text, key):
    """The first scalar entry `key value;` of a dictionary text."""
    return float(re.search(r"\b%s\s+(%s)\s*;" % (key, _NUMBER), text).group(1))


def _list(block, key):
    """A list entry `key N ( ... );` or `key N { value };` as floats."""
    m = re.search(r"\b%s\s+(\d+)\s*(?:\{\s*(%s)\s*\}|\(([^()]*)\))\s*;" % (key, _NUMBER), block)
    n = int(m.group(1))
    values = [float(m.group(2))] * n if m.group(2) else [float(v) for v in m.group(3).split()]
    if len(values) != n:
        raise ValueError("%s: %d values, the list says %d" % (key, len(values), n))
    return values


def _states(case, time):
    rel = os.path.join(time, "uniform", "dropletFiber", "dropletFiber")
    procs = sorted(glob.glob(os.path.join(case, "processor[0-9]*")),
                   key=lambda p: int(p.split("processor")[-1]))
    return [os.path.join(p, rel) for p in procs] or [os.path.join(case, rel)]


def fibers(case, time):
    out = []
    for path in _states(case, time):
        text = open(path).read()
        part = text[text.index("\nfibers"):text.index("\ninjectors")]
        for m in re.finditer(r"\n    fiber(\d+)\n    \{\n(.*?)\n    \}", part, re.S):
            block = m.group(2)
            rho, radius, n = (entry_in(block, k) for k in ("density", "radius", "represents"))
            segments = [rho * math.pi * radius ** 2 * l + c for l, c in
                        zip(_list(block, "restLengths"), _list(block, "capturedMass"))]
            masses = [0.0] * (len(segments) + 1)
            for j, s in enumerate(segments):
                masses[j] += s / 2
                masses[j + 1] += s / 2
            v, x = _list(block, "velocities"), _list(block, "positions")
            out.append({
                "id": int(m.group(1)),
                "origin": re.search(r"\borigin\s+(\w+)\s*;", block).group(1),
                "represents": n, "masses": masses,
                "velocities": [v[3 * i:3 * i + 3] for i in range(len(masses))],
                "positions": [x[3 * i:3 * i + 3] for i in range(len(masses))],
            })
    return out


def state_totals(case, time):
    paths = _states(case, time)
    text = open(paths[0]).read()
    body = re.search(r"\ntotals\n\{(.*?)\n\}", text, re.S).group(1)
    totals = dict((k, float(v)) for k, v in re.findall(r"\n\s+(\w+)\s+(%s)\s*;" % _NUMBER, body))
    totals["fiberCount"] = sum(entry(p, "fiberCount") for p in paths)
    return totals
