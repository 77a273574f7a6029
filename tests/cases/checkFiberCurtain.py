"""A fiber curtain falling into still air, coupled both ways (tests/cases/fiberCurtain):
where the fibers' drag goes, checked on a finished run (serial or on 2 ranks).

Usage: checkFiberCurtain.py CASE

1. Budget of the table fiberDrag.dat, every step: onAir = -(onFibers - outsideMesh)
   (the drag of fiber points outside the mesh reaches no cell), to 1e-10 of each
   column's largest value (the table prints 13 digits: 5e-13 each). outsideMesh is
   not zero (the stubs' ends stick out of the slab): all three terms count.
2. The fibers' momentum from the restart states (sum of represents x point mass x
   velocity), between the write times after the injection ended (0.04 s):
   P(t2) - P(t1) = dt sum of onFibers over the steps in (t1, t2] + M g (t2 - t1).
   Tension and bending are internal, nothing else acts (no cloud, no capture). To
   1e-10 of M g (t2 - t1): the fiber solver's Newton iterations stop at a residual of
   1e-12 of its terms (FiberSolverSettings) and the table's 13 digits add 5e-13 per
   row. M is also checked against the injectors' count and size (rate x 0.04 s fibers
   of 40 each) and the state's totals, to 1e-12: no fiber was removed.
3. The air's momentum, rho times the integral of U (function object airMomentum),
   step n (the fvOption adds F + K U* - K U, F and K of the step before):
     rho (I^n - I^(n-1)) / dt = onAir^(n-1) + sum V K^(n-1) (U^(n-1) - U^n) - W^n
   sum V K^(n-1) U^n from airBeforeFibers^n (listed before dropletFiber, which replaces
   K), sum V K^(n-1) U^(n-1) from airAfterFibers^(n-1); W^n the air's force on the
   side walls (wallForces: pressure and viscous; the top and bottom are periodic).
   Per step to 1e-5 of the largest |onAir| (measured 3e-7); over the run, vertical to
   1e-6 of the drag's impulse (measured 1.2e-8), horizontal to 1e-3 of its largest
   term (measured 3e-5, the walls' pressure takes the horizontal drag). What is left
   over: PISO with 4 correctors (2 correctors leave 2.5e-5, 4.7e-4 in a step), and
   the viscous term's explicit part, evaluated at the step's old velocity where
   wallForces takes the new one (the horizontal residual is 0.3 % of its viscous
   force). The vertical wall shear must be 10 times the tolerance: the test sees it.
4. The air falls in the curtain: at the end, in the cell holding most of the
   curtain's points (from the state; a quarter of them at least), U_y < 0 and more
   than 3 times |U_y| 2.5 cm beside it (measured 11 times).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkFiberCurtainFiles import columns, entry, fibers, state_totals, table  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

case = sys.argv[1]
dt = entry(os.path.join(case, "system", "controlDict"), "deltaT")
rho = entry(os.path.join(case, "constant", "transportProperties"), "rho")
steps = int(round(entry(os.path.join(case, "system", "controlDict"), "endTime") / dt))
g = (0.0, -9.81, 0.0)

# --- 1. the table's budget -----------------------------------------------------------
names = columns(case, "dropletFiber", "fiberDrag.dat")
drag = [dict(zip(names, r)) for r in table(case, "dropletFiber", "fiberDrag.dat")]
check(len(drag) == steps and all(abs(r["Time"] - (i + 1) * dt) < 1e-6 for i, r in enumerate(drag)),
      "fiberDrag.dat: one row per step (%d rows, %d steps)" % (len(drag), steps))
for c in "xyz":
    scale = max(abs(r["onFibers_" + c]) for r in drag)
    worst = max(abs(r["onAir_" + c] + r["onFibers_" + c] - r["outsideMesh_" + c]) for r in drag)
    check(worst <= 1e-10 * scale,
          "every step onAir_%s = -(onFibers_%s - outsideMesh_%s): largest difference %.2g of %.3g N"
          % (c, c, c, worst / scale, scale))
outside = max(abs(r["outsideMesh_y"]) for r in drag)
check(outside > 1e-2 * max(abs(r["onFibers_y"]) for r in drag),
      "outsideMesh_y reaches %.3g N: the stubs' ends outside the mesh drag" % outside)

# --- 2. the fibers' momentum -----------------------------------------------------------
physical = 40 * 2500 * math.pi * 5e-6 ** 2 * (20 * 0.01 + 10 * 0.012)  # curtain, stubs
times = ["0.0625", "0.09375", "0.125", "0.15625"]  # write times after the injection ended
state = {}
for t in times:
    fs = fibers(case, t)
    mass = sum(f["represents"] * sum(f["masses"]) for f in fs)
    P = [sum(f["represents"] * m * v[d] for f in fs for m, v in zip(f["masses"], f["velocities"]))
         for d in range(3)]
    state[t] = (P, mass)
    origins = sorted(f["origin"] for f in fs)
    totals = state_totals(case, t)
    check(origins.count("curtain") == 20 and origins.count("stubs") == 10
          and totals["fiberCount"] == 30 and totals["fibersRemoved"] == 0,
          "%s: 20 curtain and 10 stub fibers, none removed" % t)
    check(abs(mass / physical - 1) < 1e-12
          and abs((totals["fiberMassAdded"] - totals["fiberMassRemoved"]) / physical - 1) < 1e-12,
          "%s: the fibers' mass %.12g kg = 40 x the injected fibers' %.12g kg = the state's totals"
          % (t, mass, physical))
for t1, t2 in list(zip(times, times[1:])) + [(times[0], times[-1])]:
    (P1, M), (P2, _) = state[t1], state[t2]
    n1, n2 = int(round(float(t1) / dt)), int(round(float(t2) / dt))
    weight = [M * g[d] * (n2 - n1) * dt for d in range(3)]
    impulse = [dt * sum(drag[n - 1]["onFibers_" + c] for n in range(n1 + 1, n2 + 1)) for c in "xyz"]
    worst = max(abs(P2[d] - P1[d] - impulse[d] - weight[d]) for d in range(3))
    check(worst <= 1e-10 * abs(weight[1]),
          "fibers' momentum %s -> %s: change %.6g = drag %.6g + weight %.6g kg m/s (y), "
          "largest difference %.2g of the weight's impulse"
          % (t1, t2, P2[1] - P1[1], impulse[1], weight[1], worst / abs(weight[1])))

# --- 3. the air's momentum -------------------------------------------------------------
zero = [0.0] * 10
air = [zero] + table(case, "airMomentum", "volFieldValue.dat")
before = [zero] + table(case, "airBeforeFibers", "volFieldValue.dat")
after = [zero] + table(case, "airAfterFibers", "volFieldValue.dat")
walls = [zero] + table(case, "wallForces", "force.dat")
check(all(len(t) == steps + 1 for t in (air, before, after, walls)),
      "airMomentum, airBeforeFibers, airAfterFibers, wallForces: one row per step")
onAir = [(0.0, 0.0, 0.0)] + [tuple(r["onAir_" + c] for c in "xyz") for r in drag]
largest = max(math.sqrt(sum(v * v for v in f)) for f in onAir)
for d, c in ((0, "x"), (1, "y")):
    terms = {"change": 0.0, "drag": 0.0, "implicit": 0.0, "walls": 0.0}
    worst = 0.0
    for n in range(1, steps + 1):
        change = rho * (air[n][1 + d] - air[n - 1][1 + d])
        implicit = dt * (after[n - 1][1 + d] - before[n][1 + d])
        applied = dt * onAir[n - 1][d]
        wall = -dt * walls[n][1 + d]  # total force on the walls: columns 1-3
        worst = max(worst, abs(change - applied - implicit - wall) / dt)
        for key, value in (("change", change), ("drag", applied), ("implicit", implicit), ("walls", wall)):
            terms[key] += value
    left = terms["change"] - terms["drag"] - terms["implicit"] - terms["walls"]
    check(worst <= 1e-5 * largest,
          "air momentum %s, every step: largest imbalance %.2g of the largest drag %.3g N"
          % (c, worst / largest, largest))
    scale = abs(terms["drag"]) if c == "y" else max(abs(v) for v in terms.values())
    tol = 1e-6 if c == "y" else 1e-3
    check(abs(left) <= tol * scale,
          "air momentum %s over the run: gained %.6g = drag %.6g + implicit part %.6g + walls %.6g"
          " kg m/s, imbalance %.2g (tolerance %g)"
          % (c, terms["change"], terms["drag"], terms["implicit"], terms["walls"], left / scale, tol))
    if c == "y":
        check(abs(terms["walls"]) > 10 * tol * scale and abs(terms["implicit"]) > 10 * tol * scale,
              "the walls' shear (%.2g) and the implicit part (%.2g of the drag) are seen"
              % (terms["walls"] / scale, terms["implicit"] / scale))

# --- 4. the air falls in the curtain ----------------------------------------------------
curtain = [x for f in fibers(case, times[-1]) if f["origin"] == "curtain" for x in f["positions"]]
check(min(x[0] for x in curtain) < 0.05 < max(x[0] for x in curtain),
      "the curtain's fibers span x = 0.05 at the end (the 2-rank cut): one rank samples"
      " the air of the other's fibers")
# The height (cell row, 5 mm) holding most of the curtain's points in the probes' column
# of cells (x 0.045-0.05); probes 2i and 2i + 1 are at y 0.1025 + 0.005 i, in the
# column and beside it
points = [x for x in curtain if 0.045 <= x[0] < 0.05]
rows = [int((x[1] - 0.1) / 0.005) for x in points]
row = max(set(rows), key=rows.count) if rows else -1
check(0 <= row < 14 and rows.count(row) >= 0.25 * 11 * 20,
      "%d of the curtain's %d points in the cell at x 0.0475, y %.4f at the end"
      % (rows.count(row), 11 * 20, 0.1025 + 0.005 * row))
last = table(case, "airProbes", "U")[-1]
inCurtain, beside = last[1 + 3 * 2 * row + 1], last[1 + 3 * (2 * row + 1) + 1]
check(inCurtain < 0 and abs(inCurtain) > 3 * abs(beside),
      "U_y at the end: %.4g m/s there, %.4g m/s beside it (x 0.0225)" % (inCurtain, beside))
finish()
