"""Captured mass on a fixed fiber across a uniform droplet stream (case fixedFiber).

Usage: checkCapture.py CASE

The expected value is computed here by hand from the case's injection settings,
independently of the library:
  50 streams, one parcel per stream per step (floor(50 * 505/s * 0.002 s) = 50),
  200 droplets of d = 50 um, rho_d = 1000 kg/m3, moving with the air at U = 1 m/s
  through a channel of height H = 0.05 m and depth 0.01 m:
      droplet mass density  rho = 50 * 200 * m(d) / deltaT / (U * H * depth)
  A fixed fiber from (0.05, 0.01) to (0.05, 0.04): l = 0.03 m normal to the flow,
  r_F = 1e-4 m, so per step (eq. 9 with |l x v_rel| = l U):
      m_coll = 2 rho (r_F + d/2) l U deltaT
The steady part of the run (droplets have crossed the fiber and the averaging
window is full: t >= 0.1 s) must match within 1 %, and the fiber's mass must grow
by exactly the captured mass.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from foamfiles import read_table  # noqa: E402
from checks import check, finish  # noqa: E402

case = sys.argv[1]
dt, U, H, depth = 0.002, 1.0, 0.05, 0.01
d, rho_d, n_droplets, streams = 50e-6, 1000.0, 200, 50
r_fiber, length = 1e-4, 0.03
droplet_mass = rho_d * math.pi / 6.0 * d ** 3
rho = streams * n_droplets * droplet_mass / dt / (U * H * depth)
expected = 2.0 * rho * (r_fiber + d / 2.0) * length * U * dt

rows = read_table(os.path.join(case, "postProcessing/dropletFiber/0/dropletFiber.dat"))
steady = [r for r in rows if r["Time"] >= 0.1 - 1e-9]



mean = sum(r["capturedStep"] for r in steady) / max(len(steady), 1)
print("rho = %.6g kg/m3, expected capture %.6g kg/step, measured mean %.6g kg/step over %d steps"
      % (rho, expected, mean, len(steady)))
check(len(steady) >= 20, "%d steady steps" % len(steady))
check(abs(mean / expected - 1) < 0.01, "mean capture within 1 %% (error %.3f %%)"
      % (100 * (mean / expected - 1)))
worst = max(abs(r["capturedStep"] / expected - 1) for r in steady)
check(worst < 0.02, "every steady step within 2 %% (worst %.3f %%)" % (100 * worst))
# mass balance: the fixed fiber gains exactly what it captures
first, last = rows[0], rows[-1]
gain = last["fiberMass"] - (first["fiberMass"] - first["capturedStep"])
check(abs(gain - last["capturedTotal"]) <= 1e-9 * last["fiberMass"],
      "fiber mass gain %.10g = captured total %.10g" % (gain, last["capturedTotal"]))
finish()
