"""A uniform rain of straight fibers falling without air onto a moving belt
(tests/cases/fiberRain, fibers.laydown on the patch bottom): the finished run
(serial or on 2 ranks) against the case worked out by hand (checkFiberRainFiles.py).

Usage: checkFiberRain.py CASE [LOG]     (LOG: default CASE/log.pimpleFoam)

The case: ten injectors, one per 10 mm column across the 0.1 m belt, at 10 k degrees to
its motion (k = 0..9), 256 fibers a second each (one every 4 steps of 2^-10 s), each
standing for 1000 fibers of 8 mm, r 5 um, glass 2500 kg/m3: m = 1.5708e-9 kg. Thrown down
at 1 m/s from 9 cm with gravity only, every fiber is laid 69 steps after its birth step
(70 steps of flight, the birth step's included), its centre 0.125 mm behind the belt's
point along the motion, so along = 0.25 mm x (step) + 0.125 mm, never near a row's edge.
A 10 mm row passes in 40 steps, in which each injector gives 10 fibers: every cell of a
complete row holds exactly 10 fibers, G = 10 N m / h^2 = mass flow / (W V) = 157.08 g/m2.
The rain is deterministic: the sampling error of G is zero by construction, what is left
is round-off.

1. The table laydown.dat: one row per fiber laid by endTime (1110), each equal to the
   hand's row of its id: the time to the bit (k / 1024); across and along to 1e-12 m
   (measured 3e-17: the belt's point and the fiber's centre are sums of positions);
   the orientation (across, along, normal) = the injector's direction (d_z, d_x, -d_y) to
   1e-12 (measured 1.5e-14: the implicit midpoint's Newton iterations leave the straight
   line by round-off); length and glass to 1e-12 of themselves (measured 9e-16: from the
   points); binder 0, represents 1000, bare fraction 1, sigma's CoV 0, exactly.
   The step table dropletFiber.dat, every step: the computed and physical fibers held,
   the fiber mass in the air and laidGlass (so far) the hand's (1e-12; measured 1.2e-14),
   laidBinder 0.
2. At every write time (the series lists each mat_<time>.vti once): the map against the
   hand's fibers laid by then, each along its length over the rows it crosses (P58), every cell (area weight, fibers per m2 to 1e-12 of the
   complete rows' value; orientation order to 1e-12; binder and LOI 0); the complete rows
   (P48: the rows the whole laying zone passed since the first fiber) as the log's; in
   them every cell = G (1e-12 of it: each of its 10 fibers' glass is off by <1e-15) and
   the orientation order in column k = cos(20 k deg) (1e-12); the log's area weight = G
   and = the complete cells' mean (to its 12 digits: 1e-11), its CoV < 1e-12 (measured
   6e-16; the hand's is 0).
3. Totals: the map's glass (sum G h^2) and physical fibers = the table's sums (1e-12)
   = the log's laid glass and physical fibers (its 12 digits: 1e-11) = the hand's; the
   computed fibers laid = the table's rows = the hand's count.
4. Balances (the log at every write time): glass injected = in the air + laid + lost
   with injected, in the air, laid the hand's (1e-11) and lost 0; its balance < 1e-12 of
   injected (round-off; measured 2e-15) and the printed terms' sum to their digits; the
   binder all 0; fiber mass = added + captured - removed - laid: the in-air and added
   masses the hand's, laid = the laid glass, balance < 1e-12 of added.
5. The restart state's `laydown` entry at every write time: totals as the table's (the
   first time and the feet x_c - p_x = -0.125 mm the hand's), its cells the map's to the bit
   (area weight = 1000 glass / h^2, as written); on 2 ranks the same text on each
   processor, and the fibers held as the checkerboard decomposition says (processor 1:
   upper half at z < 0.05, lower half at z > 0.05), all four quarters held: every fiber
   is born on one processor and laid by the other.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkFiberCurtainFiles import columns, fibers  # noqa: E402
from checkFiberCurtainFiles import table as steptable  # noqa: E402
from checkFiberRainFiles import (ACROSS_MAX, ACROSS_MIN, hand, laid, mat,  # noqa: E402
                                 series, settings, state_laydown, write_reports)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

case = sys.argv[1]
log = sys.argv[2] if len(sys.argv) > 2 else os.path.join(case, "log.pimpleFoam")
s = settings(case)
dt, h = s["deltaT"], s["cell"]
V = math.sqrt(sum(c * c for c in s["beltVelocity"]))
W = ACROSS_MAX - ACROSS_MIN
expected, births = hand(case)
m = s["density"] * math.pi * s["radius"] ** 2 * s["injectors"][0]["length"]
N = s["injectors"][0]["represents"]
massFlow = sum(i["rate"] * i["represents"] for i in s["injectors"]) * m
G = 1000 * massFlow / (W * V)  # g/m2, P48
print("hand: %d fibers born, %d laid by %g s; m = %.10g kg, G = mass flow / (W V) = %.12g g/m2"
      % (len(births), len(expected), s["endTime"], m, G))


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def order(o):
    """cos 2 theta of an orientation (across, along, normal): of its projection."""
    inPlane = o[0] ** 2 + o[1] ** 2
    return (o[1] ** 2 - o[0] ** 2) / inPlane if inPlane > 0 else 0.0


# --- 1. the table -------------------------------------------------------------------
table = laid(case)
ids = [r["id"] for r in table]
check(sorted(ids) == sorted(expected) and len(set(ids)) == len(ids),
      "laydown.dat: %d rows, each fiber the hand lays by %g s once (%d)"
      % (len(table), s["endTime"], len(expected)))
check(all(a["Time"] <= b["Time"] for a, b in zip(table, table[1:])), "laydown.dat: rows in time order")
worst = {}
for r in table:
    e = expected.get(r["id"])
    if e is None:
        continue
    for key in ("Time", "binderMass", "represents", "bareFraction", "sigmaCoV"):
        worst[key] = max(worst.get(key, 0.0), abs(r[key] - e[key]))
    for key in ("across", "along"):
        worst[key] = max(worst.get(key, 0.0), abs(r[key] - e[key]))
    worst["orientation"] = max([worst.get("orientation", 0.0)] + [
        abs(r["orientation_" + c] - e["orientation_" + c]) for c in ("across", "along", "normal")])
    for key in ("length", "glassMass"):
        worst[key] = max(worst.get(key, 0.0), rel(r[key], e[key]))
exact = ("Time", "binderMass", "represents", "bareFraction", "sigmaCoV")
check(all(worst[k] == 0 for k in exact),
      "every row's time (the hand's step), binder 0, represents %g, bare fraction 1, sigma CoV 0:"
      " exactly (largest differences %s)" % (N, ", ".join("%s %.3g" % (k, worst[k]) for k in exact)))
check(worst["across"] <= 1e-12 and worst["along"] <= 1e-12,
      "across and along the hand's to 1e-12 m (largest %.3g, %.3g m)" % (worst["across"], worst["along"]))
check(worst["orientation"] <= 1e-12,
      "every fiber's orientation its injector's direction (d_z, d_x, -d_y) to 1e-12 (largest %.3g)"
      % worst["orientation"])
check(worst["length"] <= 1e-12 and worst["glassMass"] <= 1e-12,
      "length and glass mass the hand's to 1e-12 (largest %.3g, %.3g of them)"
      % (worst["length"], worst["glassMass"]))
first = min(e["Time"] for e in expected.values())
# The feet along the motion in the fixed frame, V t - along = (x_c - p_x) . e_a
footMin = min(V * e["Time"] - e["along"] for e in expected.values())
footMax = max(V * e["Time"] - e["along"] for e in expected.values())
reach = max(e["length"] / 2 * abs(e["orientation_along"]) for e in expected.values())
worstSpan = max(rel(r["endToEnd"], expected[r["id"]]["length"]) for r in table if r["id"] in expected)
check(worstSpan <= 1e-12 and all(r["spread"] == 0 for r in table),
      "laydown.dat: every fiber's endToEnd its length (straight; 1e-12, largest %.3g), spread 0 (no"
      " population spread without a spray)" % worstSpan)


# The step table dropletFiber.dat: every step the fibers held, the fiber mass in the air
# and the glass laid so far (laidGlass) the hand's; laidBinder 0
names = columns(case, "dropletFiber", "dropletFiber.dat")
stepRows = [dict(zip(names, r)) for r in steptable(case, "dropletFiber", "dropletFiber.dat")]
steps = int(round(s["endTime"] / dt))
laidBy = [0] * (steps + 1)
for e in expected.values():
    laidBy[int(round(e["Time"] / dt))] += 1
worstStep, held = 0.0, True
for n, r in enumerate(stepRows, 1):
    laidSoFar = sum(laidBy[:n + 1])
    airborne = sum(1 for b in births if b[1] <= n and (b[2] is None or b[2] > n))
    held = held and r["fibers"] == airborne and r["fibersRepresented"] == airborne * N \
        and r["laidBinder"] == 0
    worstStep = max(worstStep, abs(r["laidGlass"] - laidSoFar * N * m) / (max(laidSoFar, 1) * N * m),
                    abs(r["fiberMass"] - airborne * N * m) / (max(airborne, 1) * N * m))
check(len(stepRows) == steps and held and worstStep <= 1e-12,
      "dropletFiber.dat: %d steps, each step's fibers held (the hand's count), fiber mass and laidGlass"
      " the hand's to 1e-12 (largest %.3g), laidBinder 0" % (len(stepRows), worstStep))

# --- 2.-5. at every write time --------------------------------------------------------
def shares_of(r):
    """P58, by hand: a straight fiber of length L lies along across +- L/2 o_across, along
    +- L/2 o_along; in this rain within its column across (checked), so only the rows cut
    it: each row takes its overlap with the along interval over the interval's length."""
    half = r["length"] / 2
    lo, hi = r["along"] - half * abs(r["orientation_along"]), r["along"] + half * abs(r["orientation_along"])
    column = int(math.floor((r["across"] - ACROSS_MIN) / h))
    a0, a1 = r["across"] - half * abs(r["orientation_across"]), r["across"] + half * abs(r["orientation_across"])
    if not (ACROSS_MIN + column * h <= a0 and a1 <= ACROSS_MIN + (column + 1) * h):
        raise ValueError("fiber %d crosses its column's edge: the hand's shares assume it does not" % r["id"])
    if hi == lo:
        return {(column, int(math.floor(lo / h))): 1.0}
    return {(column, j): (min(hi, (j + 1) * h) - max(lo, j * h)) / (hi - lo)
            for j in range(int(math.floor(lo / h)), int(math.floor(hi / h)) + 1)
            if min(hi, (j + 1) * h) > max(lo, j * h)}


def cells_of(rows):
    """(column, row) -> [glass, physical fibers, glass x cos 2 theta] of rows."""
    cells = {}
    for r in rows:
        o = (r["orientation_across"], r["orientation_along"], r["orientation_normal"])
        for key, share in shares_of(r).items():
            c = cells.setdefault(key, [0.0, 0.0, 0.0])
            c[0] += share * r["represents"] * r["glassMass"]
            c[1] += share * r["represents"]
            c[2] += share * r["represents"] * r["glassMass"] * order(o)
    return cells


reports = write_reports(log)
files = series(case)
writeTimes = [n * dt for n in range(s["writeInterval"], steps + 1, s["writeInterval"])]
check([f for f, _ in files] == ["mat_%g.vti" % t for t in writeTimes]
      and [t for _, t in files] == writeTimes,
      "mat.vti.series lists mat_<time>.vti at the %d write times once each" % len(writeTimes))
states = sorted(d for d in os.listdir(case) if d.startswith("processor")) or ["."]
quarters = set()
for T in writeTimes:
    name = "%g" % T
    byHand = [e for e in expected.values() if e["Time"] <= T + 1e-12]
    inTable = [r for r in table if r["Time"] <= T + 1e-12]
    handCells, tableCells = cells_of(byHand), cells_of(inTable)
    vti = mat(os.path.join(case, "postProcessing", "dropletFiber", "0", "mat_%s.vti" % name))
    nx, ny = vti["shape"]
    r0 = int(round(vti["origin"][1] / h - 0.5))
    c0 = int(round((vti["origin"][0] - ACROSS_MIN) / h - 0.5))
    rows = sorted({k[1] for k in handCells})
    check(c0 == 0 and nx == 10 and r0 == rows[0] and ny == rows[-1] - rows[0] + 1
          and abs(vti["origin"][0] - (ACROSS_MIN + h / 2)) <= 1e-12
          and abs(vti["origin"][1] - (r0 + 0.5) * h) <= 1e-12 and vti["spacing"][:2] == [h, h],
          "%s: the map's 10 columns across x rows %d to %d, points at the cells' centres"
          % (name, rows[0], rows[-1]))
    a = vti["arrays"]
    worstG = worstN = worstO = 0.0
    zeros = True
    for j in range(ny):
        for i in range(nx):
            k = j * nx + i
            c = handCells.get((c0 + i, r0 + j), [0.0, 0.0, 0.0])
            worstG = max(worstG, abs(a["areaWeight"][k] - 1000 * c[0] / h ** 2) / G)
            worstN = max(worstN, abs(a["fibersPerArea"][k] - c[1] / h ** 2) / (10 * N / h ** 2))
            worstO = max(worstO, abs(a["orientationOrder"][k] - (c[2] / c[0] if c[0] else 0.0)))
            zeros = zeros and a["binderAreaWeight"][k] == 0 and a["LOI"][k] == 0
    check(worstG <= 1e-12 and worstN <= 1e-12 and worstO <= 1e-12 and zeros,
          "%s: every cell the hand's: area weight, fibers per m2 to 1e-12 of G (%.3g, %.3g),"
          " orientation order to 1e-12 (%.3g), binder and LOI 0" % (name, worstG, worstN, worstO))
    # The complete rows (P48), the hand's way: they entered the laying zone [footMin,
    # footMax] after the first fiber and have left it, less the footprints' reach along
    # beyond their centres (P58: L/2 |o_along|)
    fromRow = math.ceil((V * first - footMin + reach) / h - 1e-9)
    toRow = math.floor((V * T - footMax - reach) / h + 1e-9) - 1
    rep = reports.get(name, {})
    logMat = rep.get("mat")
    if fromRow > toRow:
        check("mat" in rep and logMat is None,
              "%s: no complete row yet, as the log says (the hand's rows %d to %d)" % (name, fromRow, toRow))
    else:
        check(logMat is not None and logMat["rows"] == (fromRow, toRow) and logMat["columns"] == 10
              and abs(logMat["along"][0] - fromRow * h) <= 1e-12
              and abs(logMat["along"][1] - (toRow + 1) * h) <= 1e-12,
              "%s: the log's complete rows %s, the hand's %d to %d (along %g to %g m)"
              % (name, logMat and logMat["rows"], fromRow, toRow, fromRow * h, (toRow + 1) * h))
        complete = [(i, j) for j in range(ny) for i in range(nx) if fromRow <= r0 + j <= toRow]
        cellG = [a["areaWeight"][j * nx + i] for i, j in complete]
        worstC = max(abs(v - G) / G for v in cellG)
        check(len(complete) == 10 * (toRow - fromRow + 1) and worstC <= 1e-12,
              "%s: the complete rows' %d cells each G = %.12g g/m2 to 1e-12 (largest %.3g of it)"
              % (name, len(complete), G, worstC))
        worstK = max(abs(a["orientationOrder"][j * nx + i] - math.cos(math.radians(20 * (c0 + i))))
                     for i, j in complete)
        check(worstK <= 1e-12, "%s: orientation order in column k cos(20 k deg) to 1e-12 (largest %.3g)"
              % (name, worstK))
        if logMat:
            mean = sum(cellG) / len(cellG)
            check(rel(logMat["areaWeight"], G) <= 1e-11 and rel(logMat["areaWeight"], mean) <= 1e-11
                  and logMat["CoV"] < 1e-12 and logMat.get("CoVReal") == 0,
                  "%s: the log's area weight %.12g g/m2 = G and the cells' mean to 1e-11, across-width"
                  " CoV %.3g < 1e-12, the mat's own 0" % (name, logMat["areaWeight"], logMat["CoV"]))
    # 3. totals
    mapGlass = sum(a["areaWeight"]) * h ** 2 / 1000
    mapFibers = sum(a["fibersPerArea"]) * h ** 2
    tableGlass = sum(r["represents"] * r["glassMass"] for r in inTable)
    tableFibers = sum(r["represents"] for r in inTable)
    handGlass = len(byHand) * N * m
    check(rel(mapGlass, tableGlass) <= 1e-12 and rel(mapFibers, tableFibers) <= 1e-12
          and rel(tableGlass, handGlass) <= 1e-12 and tableFibers == len(byHand) * N,
          "%s: map totals = table sums = the hand's: glass %.12g kg (map %.3g, hand %.3g off),"
          " %g physical fibers" % (name, tableGlass, rel(mapGlass, tableGlass), rel(tableGlass, handGlass),
                                   tableFibers))
    check(rep.get("computed") == len(inTable) == len(byHand) and rep.get("physical") == tableFibers
          and rel(rep.get("glass", 0), tableGlass) <= 1e-11 and rep.get("binder") == 0,
          "%s: the log's %s computed (%s physical) fibers laid, glass %s kg: the table's"
          % (name, rep.get("computed"), rep.get("physical"), rep.get("glass")))
    # 4. balances
    bornBy = [b for b in births if b[1] <= round(T / dt)]
    inAir = [b for b in bornBy if b[2] is None or b[2] > round(T / dt)]
    injected, air = len(bornBy) * N * m, len(inAir) * N * m
    gb = rep.get("glassBalance") or [float("nan")] * 5
    check(rel(gb[0], injected) <= 1e-11 and rel(gb[1], air) <= 1e-11 and rel(gb[2], tableGlass) <= 1e-11
          and gb[3] == 0 and abs(gb[4]) <= 1e-12 * injected
          and abs(gb[0] - gb[1] - gb[2] - gb[3]) <= 1e-11 * injected,
          "%s: glass injected %.12g kg (%d fibers) = in the air %.12g (%d) + laid %.12g + lost %g,"
          " balance %.3g kg" % (name, gb[0], len(bornBy), gb[1], len(inAir), gb[2], gb[3], gb[4]))
    bb = rep.get("binderBalance")
    check(bb == [0.0] * 5, "%s: binder captured 0 = airborne 0 + laid 0 + lost 0 (%s)" % (name, bb))
    fm = rep.get("fiberMass") or [float("nan")] * 6
    check(rel(fm[0], air) <= 1e-11 and rel(fm[1], injected) <= 1e-11 and fm[2] == 0 and fm[3] == 0
          and rel(fm[4], tableGlass) <= 1e-11 and abs(fm[5]) <= 1e-12 * injected,
          "%s: fiber mass %.12g kg = added %.12g + captured 0 - removed 0 - laid %.12g, balance %.3g kg"
          % (name, fm[0], fm[1], fm[4], fm[5]))
    # 5. the restart state
    texts = []
    for p in states:
        text, st = state_laydown(os.path.join(case, p, name, "uniform", "dropletFiber", "dropletFiber"))
        texts.append(text)
    check(texts[0] is not None and all(t == texts[0] for t in texts),
          "%s: the state's laydown entry%s"
          % (name, " the same on every processor" if len(texts) > 1 else ""))
    if st is None:
        continue
    # As the map writes them: 1000 glass / (h h), orientation sum / glass, fibers / (h h)
    at = dict(((c0 + i, r0 + j), j * nx + i) for j in range(ny) for i in range(nx))
    stateMap = all(
        (int(c), int(r)) in at and 1000 * g / (h * h) == a["areaWeight"][at[(int(c), int(r))]]
        and ob / g == a["orientationOrder"][at[(int(c), int(r))]]
        and f / (h * h) == a["fibersPerArea"][at[(int(c), int(r))]]
        for c, r, g, ob, f in zip(st["columns"], st["rows"], st["cellGlass"], st["cellOrientation"],
                                  st["cellFibers"]))
    mapCells = dict((k, a["areaWeight"][v]) for k, v in at.items())
    occupied = sorted(k for k, v in mapCells.items() if v > 0)
    check(st["computed"] == len(inTable) and st["physical"] == tableFibers
          and rel(st["glass"], tableGlass) <= 1e-12 and st["binder"] == 0 and st["firstTime"] == first
          and abs(st["footMin"] - footMin) <= 1e-12 and abs(st["footMax"] - footMax) <= 1e-12
          and st["cell"] == h and stateMap
          and sorted(zip((int(c) for c in st["columns"]), (int(r) for r in st["rows"]))) == occupied
          and all(abs(f - tableCells[(int(c), int(r))][1]) <= 1e-12 * N for c, r, f in
                  zip(st["columns"], st["rows"], st["cellFibers"]))
          and all(b == 0 for b in st["cellBinder"]),
          "%s: the state's laydown: %d computed, glass, first time %g, feet %.6g to %.6g m, %d cells:"
          " the map's to the bit, its fibers the table's (1e-12 of a fiber's N)" % (name, st["computed"], st["firstTime"], st["footMin"], st["footMax"],
                                     len(st["columns"])))
    # Where the fibers are held on 2 ranks (checkerboard: processor (y >= 0.05) xor (z >= 0.05))
    if len(states) > 1:
        wrong = 0
        for p in states:
            rank = int(p.replace("processor", ""))
            for f in fibers(os.path.join(case, p), name):
                y, z = f["positions"][0][1], f["positions"][0][2]
                quarters.add((rank, y >= 0.05, z >= 0.05))
                wrong += rank != int((y >= 0.05) != (z >= 0.05))
        check(wrong == 0, "%s: every fiber held by its cells' processor (%d not)" % (name, wrong))
if len(states) > 1:
    check(len(quarters) == 4, "2 ranks: fibers held in all four quarters %s: born on one processor,"
          " laid by the other" % sorted(quarters))
finish()
