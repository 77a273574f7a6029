#!/usr/bin/env python3
"""Share of the dropletFiber function object in the wall time of a case run.

Reads, from a case directory that has been run:
  - the solver log (log.<application>, e.g. log.pimpleFoam): the last
    "ExecutionTime = <cpu s> s  ClockTime = <wall s> s" line and the number of
    time steps ("Time = ..." lines);
  - the function object's per-step table
    postProcessing/<name>/<startTime>/<name>.dat (all start times, e.g. after a
    restart): the columns wallTimeDeposition, wallTimeCollision (tables written
    before it existed: counted in wallTimeFibers) and wallTimeFibers (seconds of
    wall time per step, measured by the function object on the master rank:
    gathering and depositing the parcels with the cross-rank grid sum; the
    collision and depletion's removal; the fibers' injection, step and
    hand-over).
It prints the function object's total time, its share of the solver's
ExecutionTime (CPU time of the master process) and of its ClockTime (wall time,
1 s resolution), and per-step figures. The VTK files that the function object
writes at write times are not in the two columns (not timed by it).

Usage: tutorialShare.py CASE_DIR [--name dropletFiber] [--log log.pimpleFoam]
                        [--label TEXT] [--markdown]
Exit status 0 when the files were found and read, 1 otherwise. It reports; it
does not judge (no pass/fail threshold).
"""

import argparse
import glob
import os
import re
import sys


def read_log(path):
    execution = clock = None
    steps = 0
    time_line = re.compile(r"^Time = ")
    exec_line = re.compile(r"^ExecutionTime = ([0-9.eE+-]+) s\s+ClockTime = ([0-9.eE+-]+) s")
    with open(path, errors="replace") as f:
        for line in f:
            if time_line.match(line):
                steps += 1
            m = exec_line.match(line)
            if m:
                execution = float(m.group(1))
                clock = float(m.group(2))
    return execution, clock, steps


def read_table(paths):
    columns = None
    rows = []
    for path in paths:
        with open(path) as f:
            for line in f:
                if line.startswith("#"):
                    names = line[1:].split()
                    if names and names[0] == "Time":
                        columns = names
                    continue
                parts = line.split()
                if not parts or columns is None:
                    continue
                rows.append(dict(zip(columns, (float(p) for p in parts))))
    return columns, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("case")
    parser.add_argument("--name", default="dropletFiber", help="function object name (postProcessing/<name>)")
    parser.add_argument("--log", default=None, help="solver log (default: log.<application> from controlDict)")
    parser.add_argument("--label", default=None, help="label for the output line (default: the case path)")
    parser.add_argument("--markdown", action="store_true", help="print one markdown table row")
    args = parser.parse_args()

    case = args.case
    log = args.log
    if log is None:
        application = "pimpleFoam"
        try:
            with open(os.path.join(case, "system", "controlDict")) as f:
                m = re.search(r"^\s*application\s+(\w+)\s*;", f.read(), re.M)
                if m:
                    application = m.group(1)
        except OSError:
            pass
        log = "log." + application
    log_path = os.path.join(case, log)
    tables = sorted(glob.glob(os.path.join(case, "postProcessing", args.name, "*", args.name + "*.dat")))
    if not os.path.isfile(log_path):
        print(f"tutorialShare: no solver log {log_path}", file=sys.stderr)
        return 1
    if not tables:
        print(f"tutorialShare: no table postProcessing/{args.name}/*/{args.name}*.dat in {case} "
              "(is the function object in the case's controlDict?)", file=sys.stderr)
        return 1

    execution, clock, steps = read_log(log_path)
    columns, rows = read_table(tables)
    if execution is None or not rows or "wallTimeDeposition" not in columns or "wallTimeFibers" not in columns:
        print("tutorialShare: log without ExecutionTime or table without the wall-time columns", file=sys.stderr)
        return 1

    deposition = sum(r["wallTimeDeposition"] for r in rows)
    collision = sum(r.get("wallTimeCollision", 0.0) for r in rows)
    fibers = sum(r["wallTimeFibers"] for r in rows)
    total = deposition + collision + fibers
    n = len(rows)
    parcels = sum(r.get("parcels", 0.0) for r in rows) / n
    fiber_count = sum(r.get("fibers", 0.0) for r in rows) / n
    label = args.label or case

    share_exec = 100.0 * total / execution if execution > 0 else float("nan")
    share_clock = 100.0 * total / clock if clock and clock > 0 else float("nan")
    if args.markdown:
        print(f"| {label} | {steps} | {parcels:.0f} | {fiber_count:.1f} | {execution:.2f} | {clock:.0f} | "
              f"{deposition:.3f} | {fibers:.3f} | {share_exec:.1f} % | {share_clock:.1f} % |")
        return 0
    print(f"case: {label}")
    print(f"  solver log {log}: {steps} time steps, ExecutionTime {execution:.2f} s (CPU, master), "
          f"ClockTime {clock:.0f} s (wall)")
    print(f"  function object table: {n} rows from {len(tables)} file(s); mean parcels {parcels:.0f}, "
          f"mean fibers {fiber_count:.1f}")
    print(f"  deposition (gather + grid + cross-rank sum): {deposition:.3f} s = {1e3 * deposition / n:.3f} ms/step")
    print(f"  collision (+ depletion's removal): {collision:.3f} s = {1e3 * collision / n:.3f} ms/step")
    print(f"  fibers (injection + fiber step + hand-over): {fibers:.3f} s = {1e3 * fibers / n:.3f} ms/step")
    print(f"  function object total {total:.3f} s = {share_exec:.2f} % of ExecutionTime, "
          f"{share_clock:.2f} % of ClockTime")
    return 0


if __name__ == "__main__":
    sys.exit(main())
