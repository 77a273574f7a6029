"""dropletFiberFormingLine on the fiberRain mat (tests/cases/fiberRain, run to 0.5 s).

Usage: checkFormingLine.py RUN (a finished fiberRain run; the utility on PATH)

By hand (checkFiberRain.py's rain): the complete rows at 0.5 s are 3 to 11 (9 rows of
10 mm), each cell of them G = 157.08 g/m2 with 10 fibers of N m glass; 900 computed fibers
in them, 90 per column. Every computed fiber an independent draw (P60): the mean's error
is G / sqrt(900) (each fiber's glass in the rows times its total N m sums to 900 (N m)^2),
a column's G / sqrt(90); the counting noise of the CoV sqrt(1/90 - 1/900) = 0.1 (P61),
the mat's own 0 (the rain is uniform). A line of 3 hoods: area weight 3 G, its error
sqrt(3) G / 30, noise 0.1 / sqrt(3), LOI 0 (no binder); the profile file has the 10
columns, each hood G and line 3 G. -hoods 0 and a line longer than the complete rows stop
with a FatalError naming the option.
"""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from checks import check, finish  # noqa: E402

run = sys.argv[1]
G = 2500 * math.pi * 5e-6 ** 2 * 0.008 * 1000 * 10 / 0.01 ** 2 * 1000  # g/m2


def tool(*args):
    p = subprocess.run(["dropletFiberFormingLine", "-case", run] + list(args),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


rc, out = tool("-hoods", "3")
figures = {}
for what, line in re.findall(r"^    (one hood|the line of 3): (.*)$", out, re.M):
    m = re.match(r"glass area weight (\S+) \+- (\S+) g/m2, LOI (\S+) \+- (\S+) %, across-width CoV (\S+)"
                 r" \(counting noise (\S+), the mat's own (\S+),", line)
    figures[what] = [float(v) for v in m.groups()] if m else None
check(rc == 0 and "complete rows 3 to 11 (9), the hoods 3 rows apart" in out,
      "the utility runs on the rain's state at 0.5 s: complete rows 3 to 11, hoods 3 rows apart")
hood, line = figures.get("one hood"), figures.get("the line of 3")


def near(a, b, tol=1e-9):
    return a is not None and abs(a - b) <= tol * max(abs(b), 1e-300)


check(hood and near(hood[0], G) and near(hood[1], G / 30) and hood[2] == 0 and hood[3] == 0
      and hood[4] < 1e-12 and near(hood[5], 0.1) and hood[6] == 0,
      "one hood: %s g/m2 +- %s = G +- G/30, LOI 0, CoV ~0, counting noise 0.1, the mat's own 0 (%s)"
      % (hood and hood[0], hood and hood[1], hood))
check(line and near(line[0], 3 * G) and near(line[1], math.sqrt(3) * G / 30) and line[2] == 0
      and near(line[5], 0.1 / math.sqrt(3)) and line[6] == 0,
      "the line of 3: 3 G +- sqrt(3) G / 30, LOI 0, counting noise 0.1 / sqrt(3), its own 0 (%s)" % line)
path = os.path.join(run, "postProcessing", "formingLine", "0.5", "profile.dat")
rows = [[float(v) for v in r.split()] for r in open(path) if not r.startswith("#")] if os.path.exists(path) else []
check(len(rows) == 10 and all(near(r[1], G) and near(r[5], 3 * G) and near(r[2], G / math.sqrt(90))
                              for r in rows)
      and all(abs(r[0] - (-0.045 + 0.01 * k)) < 1e-12 for k, r in enumerate(rows)),
      "profile.dat: 10 columns at their centres, each hood G +- G/sqrt(90), line 3 G")
rc, out = tool("-hoods", "0")
check(rc != 0 and "Option -hoods is 0: allowed are 1 or more" in out, "-hoods 0 stops, naming the option")
rc, out = tool("-hoods", "10")
check(rc != 0 and "10 hoods 1 rows apart need more than the 9 complete rows" in out and "-hoods 10" in out,
      "10 hoods on 9 complete rows stop, naming -hoods and the rows")
finish()
