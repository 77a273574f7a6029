"""Readers of the fiberRain case's files and the case worked out by hand, for
checkFiberRain.py and checkFiberRainSame.py (plain Python, standard library only;
independent of OpenFOAM and of dropletFiber).

Readers
- settings(case): system/controlDict's figures: deltaT, endTime, writeInterval, the
  fibers' radius, density and gravity, the belt's velocity and cell, and the injectors
  (name, position, unit direction, velocity, length, rate, represents, startTime) in
  the dictionary's order.
- laid(case, start="0"): laydown.dat as dicts (id an int), in the file's order.
- laid_lines(case, start="0"): its data lines as text (to compare to the bit).
- mat(path): a mat_<time>.vti as {"origin", "spacing", "shape": (nx, ny), arrays by
  name: lists of nx * ny values, x (across) fastest}.
- series(case, start="0"): mat.vti.series as [(file, time)].
- write_reports(log): the function object's lines at each write time, by time name:
  laydown (computed, physical, glass, binder, LOI), mat (rows, area weight, CoV, or
  None: no complete row), glass and binder balances, the fiber-mass balance.
- state_laydown(path): the `laydown { }` entry of a restart state as text and values.

The case by hand (hand(case))
- The belt is the patch bottom of system/blockMeshDict (y = 0, x 0 to 0.2, z 0 to
  0.1): its area-weighted centre p = (0.1 0 0.05), outward normal n = (0 -1 0);
  velocity V e_a with e_a = x, so e_c = n x e_a = z; across -0.05 to 0.05.
- Fiber k of an injector is born at t_k = startTime + k / rate. It joins at the end of
  the step of its birth, placed as at that step's time t_s, and is then moved by that
  step as by every later one: at the end of step n it has flown tau = t_n - t_k + dt
  (BIRTH_STEP_FLIGHT = 1 step; measured: a fiber born at step 125 is at its 4-step
  height at step 128). No air force (drag none), gravity only: the centre falls as
  y_c(tau) = y_c0 + v0_y tau + g_y tau^2 / 2 (the implicit midpoint steps a constant
  acceleration exactly), straight (no transverse force), x and z fixed.
- It is laid in the first step n with y_c <= 0 (its centre reached the plane), at
  time t_n, across = z_c - p_z, along = V t_n - (x_c - p_x), orientation (d.e_c,
  d.e_a, d.n) = (d_z, d_x, -d_y), its length, glass rho pi r^2 L, no binder,
  `represents`, bare fraction 1 and sigma's CoV 0 (no binder on it).
- ids are birth numbers: the births of a step in the injectors' order, no fixed
  fibers: the fiber born j-th of injector k (all injectors alike) has id 10 j + k.
"""
import base64
import math
import os
import re
import struct
import xml.etree.ElementTree as ET

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
VECTOR = r"\(\s*(%s)\s+(%s)\s+(%s)\s*\)" % (NUMBER, NUMBER, NUMBER)

# The belt: the patch bottom (above)
BELT_POINT = (0.1, 0.0, 0.05)
BELT_NORMAL = (0.0, -1.0, 0.0)
ACROSS_MIN, ACROSS_MAX = -0.05, 0.05
# Steps a fiber flies in the step of its birth (above)
BIRTH_STEP_FLIGHT = 1


def _text(path):
    text = open(path).read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def _scalar(text, key):
    return float(re.search(r"\b%s\s+(%s)\s*;" % (key, NUMBER), text).group(1))


def _vector(text, key):
    return tuple(float(v) for v in re.search(r"\b%s\s+%s\s*;" % (key, VECTOR), text).groups())


def _block(text, key):
    """The body of the first sub-dictionary `key { ... }` (nested braces allowed)."""
    m = re.search(r"\b%s\s*\{" % key, text)
    depth, i = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[m.end():i - 1]


def settings(case):
    text = _text(os.path.join(case, "system", "controlDict"))
    shared = _block(text, "rainInjector")
    fibers = _block(_block(text, "functions"), "fibers")
    laydown = _block(fibers, "laydown")
    injectors = []
    for m in re.finditer(r"\b(\w+)\s*\{\s*\$rainInjector\s*;(.*?)\}", _block(fibers, "injectors"), re.S):
        d = _vector(m.group(2), "direction")
        norm = math.sqrt(sum(c * c for c in d))
        injectors.append({
            "name": m.group(1), "position": _vector(m.group(2), "position"),
            "direction": tuple(c / norm for c in d), "velocity": _vector(shared, "velocity"),
            "length": _scalar(shared, "length"), "rate": _scalar(shared, "rate"),
            "represents": _scalar(shared, "represents"), "startTime": _scalar(shared, "startTime"),
        })
    return {
        "deltaT": _scalar(text, "deltaT"), "endTime": _scalar(text, "endTime"),
        "writeInterval": int(_scalar(text, "writeInterval")),
        "radius": _scalar(fibers, "radius"), "density": _scalar(fibers, "density"),
        "gravity": _vector(fibers, "gravity"),
        "beltVelocity": _vector(laydown, "velocity"), "cell": _scalar(laydown, "cell"),
        "injectors": injectors,
    }


def hand(case):
    """The case worked out by hand (module docstring): the laid fibers up to endTime as
    rows like laid()'s, by id, and the births: [(id, birth step, laid step or None)]."""
    s = settings(case)
    dt, steps = s["deltaT"], int(round(s["endTime"] / s["deltaT"]))
    V = math.sqrt(sum(c * c for c in s["beltVelocity"]))
    g = s["gravity"][1]
    rows, births = {}, []
    count = len(s["injectors"])
    j = 0
    while True:
        born = False
        for k, inj in enumerate(s["injectors"]):
            tk = inj["startTime"] + j / inj["rate"]
            birth_step = tk / dt
            if birth_step > steps + 1e-9:
                continue
            born = True
            if abs(birth_step - round(birth_step)) > 1e-9:
                raise ValueError("%s: birth %d off the step times" % (inj["name"], j))
            birth_step = int(round(birth_step))
            L, d, x0 = inj["length"], inj["direction"], inj["position"]
            centre = [x0[i] + d[i] * L / 2 for i in range(3)]
            v0 = inj["velocity"][1]

            def height(n):
                tau = (n - birth_step + BIRTH_STEP_FLIGHT) * dt
                return centre[1] + v0 * tau + g * tau * tau / 2

            n = birth_step
            while height(n) > 0:
                n += 1
            # Far from the plane on both sides: round-off cannot move the step
            if not (height(n) < -1e-4 and (n == birth_step or height(n - 1) > 1e-4)):
                raise ValueError("%s: laid too close to the plane" % inj["name"])
            fid = count * j + k
            births.append((fid, birth_step, n if n <= steps else None))
            if n > steps:
                continue
            t = n * dt
            rows[fid] = {
                "Time": t, "id": fid,
                "across": centre[2] - BELT_POINT[2],
                "along": V * t - (centre[0] - BELT_POINT[0]),
                "orientation_across": d[2], "orientation_along": d[0],
                "orientation_normal": -d[1],
                "length": L, "glassMass": s["density"] * math.pi * s["radius"] ** 2 * L,
                "binderMass": 0.0, "represents": inj["represents"],
                "bareFraction": 1.0, "sigmaCoV": 0.0, "injector": k,
            }
        if not born:
            break
        j += 1
    return rows, births


def laid_lines(case, start="0"):
    path = os.path.join(case, "postProcessing", "dropletFiber", start, "laydown.dat")
    return [line for line in open(path) if line.strip() and not line.startswith("#")]


def laid(case, start="0"):
    path = os.path.join(case, "postProcessing", "dropletFiber", start, "laydown.dat")
    names = None
    for line in open(path):
        if line.startswith("#"):
            names = [c.strip() for c in line[1:].split("\t") if c.strip()]
    out = []
    for line in laid_lines(case, start):
        row = dict(zip(names, (float(v) for v in line.split())))
        row["id"] = int(row["id"])
        out.append(row)
    return out


def _values(array):
    if array.get("format") == "ascii":
        return [float(v) for v in array.text.split()]
    raw = base64.b64decode("".join((array.text or "").split()))
    (count,) = struct.unpack("<Q", raw[:8])
    return list(struct.unpack("<%dd" % (count // 8), raw[8:8 + count]))


def mat(path):
    image = ET.parse(path).getroot().find("ImageData")
    e = [int(v) for v in image.get("WholeExtent").split()]
    out = {
        "origin": [float(v) for v in image.get("Origin").split()],
        "spacing": [float(v) for v in image.get("Spacing").split()],
        "shape": (e[1] - e[0] + 1, e[3] - e[2] + 1),
        "arrays": {},
    }
    for array in image.find("Piece").find("PointData"):
        out["arrays"][array.get("Name")] = _values(array)
    return out


def series(case, start="0"):
    text = open(os.path.join(case, "postProcessing", "dropletFiber", start, "mat.vti.series")).read()
    return [(m.group(1), float(m.group(2))) for m in
            re.finditer(r'"name"\s*:\s*"([^"]+)"\s*,\s*"time"\s*:\s*(%s)' % NUMBER, text)]


_LAYDOWN = re.compile(r"laydown at time (\S+): (\d+) computed fibers laid \((\S+) physical\), glass (\S+) kg,"
                      r" binder (\S+) kg: LOI (\S+) %")
_MAT = re.compile(r"^    mat \(rows (-?\d+) to (-?\d+), along (\S+) to (\S+) m, (\d+) columns across\):"
                  r" glass area weight (\S+) \+- (\S+) g/m2, LOI (\S+) \+- (\S+) %, across-width CoV (\S+)")
_MAT_COV = re.compile(r"^    mat's across-width CoV: counting noise (\S+), the mat's own (\S+)"
                      r" \(two-sigma bound (\S+)\)")
_GLASS = re.compile(r"^    glass: injected (\S+) kg = in the air (\S+) \+ laid (\S+) \+ lost (\S+)"
                    r" \(balance (\S+) kg\)")
_BINDER = re.compile(r"^    binder: captured (\S+) kg = on airborne fibers (\S+) \+ laid (\S+) \+ on lost"
                     r" fibers (\S+) \(balance (\S+) kg\)")
_CONSERVATION = re.compile(r"conservation at time (\S+),")
_FIBER_MASS = re.compile(r"^    fiber mass (\S+) kg = added (\S+) \+ captured (\S+) - removed (\S+)"
                         r" - laid (\S+) \(balance (\S+) kg\)")


def write_reports(log):
    reports, now, conservation = {}, None, None
    for line in open(log):
        m = _CONSERVATION.search(line)
        if m:
            conservation = m.group(1)
            continue
        m = _FIBER_MASS.match(line)
        if m and conservation:
            reports.setdefault(conservation, {})["fiberMass"] = [float(v) for v in m.groups()]
            continue
        m = _LAYDOWN.search(line)
        if m:
            now = m.group(1)
            r = reports.setdefault(now, {})
            r["computed"] = int(m.group(2))
            r["physical"], r["glass"], r["binder"], r["LOI"] = (float(v) for v in m.groups()[2:])
            continue
        if now is None:
            continue
        m = _MAT.match(line)
        if m:
            reports[now]["mat"] = {"rows": (int(m.group(1)), int(m.group(2))),
                                   "along": (float(m.group(3)), float(m.group(4))),
                                   "columns": int(m.group(5)), "areaWeight": float(m.group(6)),
                                   "areaWeightError": float(m.group(7)), "LOI": float(m.group(8)),
                                   "LOIError": float(m.group(9)), "CoV": float(m.group(10))}
        elif _MAT_COV.match(line) and reports[now].get("mat"):
            noise, real, bound = (float(v) for v in _MAT_COV.match(line).groups())
            reports[now]["mat"].update({"CoVNoise": noise, "CoVReal": real, "CoVRealBound": bound})
        elif line.startswith("    mat: no complete row yet"):
            reports[now]["mat"] = None
        elif _GLASS.match(line):
            reports[now]["glassBalance"] = [float(v) for v in _GLASS.match(line).groups()]
        elif _BINDER.match(line):
            reports[now]["binderBalance"] = [float(v) for v in _BINDER.match(line).groups()]
            now = None
    return reports


def state_laydown(path):
    """(text, values) of the `laydown { }` entry of a restart state: the text of the
    entry as written, and its scalars and lists by name."""
    text = open(path).read()
    m = re.search(r"\nlaydown\n\{\n(.*?)\n\}", text, re.S)
    if not m:
        return None, None
    body, values = m.group(1), {}
    for key, value in re.findall(r"^\s+(\w+)\s+([^;]*);", body, re.M):
        lst = re.match(r"(\d+)\s*(?:\{\s*(\S+)\s*\}|\((.*)\))\s*$", value.strip(), re.S)
        if lst:
            n = int(lst.group(1))
            values[key] = ([float(lst.group(2))] * n if lst.group(2)
                           else [float(v) for v in lst.group(3).split()])
        else:
            values[key] = float(value)
    return m.group(0), values
