"""Tests of bin/dropletFiberReport on finished runs of the channelSpray tutorial (the
regression runs' folders), on copies of them changed as a stopped run, a decomposed
run never reconstructed, a table with more columns in another order, and on missing
cases. The expected values are derived here from the run's files with this file's own
readers (the table by its header, the cloud's report in the log, the VTK XML), not
taken from the report's code.

Usage: checkReport.py KIND RUN WORK
  KIND  finished | stopped | decomposed | columns | missing | paraview
  RUN   the finished run's folder (serial, or parallel for decomposed)
  WORK  a scratch folder (replaced)
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import types
import xml.etree.ElementTree as ET

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
REPORT = os.path.join(ROOT, "bin", "dropletFiberReport")
failed = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failed.append(what)


def table(path):
    """Rows of a table as dicts by the names of its last comment line."""
    names, rows = [], []
    for line in open(path):
        if line.startswith("#"):
            names = line[1:].split()
        elif len(line.split()) == len(names):  # a half-written last line left out
            rows.append(dict(zip(names, map(float, line.split()))))
    return rows


def sprayed_in(log):
    """The mass introduced by every injector in the log's last complete report of
    kinematicCloud."""
    reports = re.findall(r"^Cloud: kinematicCloud\n((?:    .*\n|   \|.*\n)+)", open(log).read(), re.M)
    complete = [r for r in reports if "Current mass in system" in r]
    return sum(float(m) for m in re.findall(r"mass introduced\s*=\s*(\S+)", complete[-1]))


def fiber_length(vtp):
    """The summed length of the line segments of a .vtp, or of the pieces of a .pvtp."""
    root = ET.parse(vtp).getroot()
    pieces = [vtp] if root.get("type") == "PolyData" else [
        os.path.join(os.path.dirname(vtp), p.get("Source")) for p in root.iter("Piece")]
    total = 0.0
    for path in pieces:
        piece = ET.parse(path).getroot().find("PolyData/Piece")
        p = [float(v) for v in piece.find("Points/DataArray").text.split()]
        arrays = {da.get("Name"): [int(float(v)) for v in (da.text or "").split()] for da in piece.find("Lines")}
        start = 0
        for end in arrays["offsets"]:
            ids = arrays["connectivity"][start:end]
            for a, b in zip(ids, ids[1:]):
                total += math.dist(p[3 * a:3 * a + 3], p[3 * b:3 * b + 3])
            start = end
    return total


def run_report(case, work, *options):
    prefix = os.path.join(work, "report")
    done = subprocess.run([REPORT, "-o", prefix, *options, case], capture_output=True, text=True)
    print(done.stdout + done.stderr)
    text = open(prefix + ".txt").read() if os.path.isfile(prefix + ".txt") else ""
    return done, text, prefix


def number_after(text, pattern):
    m = re.search(pattern, text)
    return float(m.group(1)) if m else float("nan")


def check_values(text, rows, log, vtp, fiber_row=None):
    """The report's figures against the table's last row, the log and the VTK (whose
    fiber mass is that of fiber_row, by default the last row)."""
    last = rows[-1]
    fiber_row = fiber_row or last
    check(number_after(text, r"fibers\s+(\d+)") == last["fibers"], "fibers = the table's %d" % last["fibers"])
    check(number_after(text, r"parcels\s+(\d+)") == last["parcels"], "parcels = the table's %d" % last["parcels"])
    efficiency = 100 * last["capturedTotal"] / sprayed_in(log)
    printed = number_after(text, r"captured / sprayed (\S+) %")
    check(abs(printed - efficiency) <= 5e-3 * efficiency,
          "binder efficiency %.4g %% = captured %.6g / sprayed %.6g (printed %g)"
          % (efficiency, last["capturedTotal"], sprayed_in(log), printed))
    length = fiber_length(vtp)
    printed = number_after(text, r"segments, (\S+) m in total")
    check(abs(printed - length) <= 1e-5 * length, "sigma over %.6g m of fiber = the segments' length (printed %g)"
          % (length, printed))
    printed = number_after(text, r"fiber mass from sigma (\S+) kg")
    check(abs(printed - fiber_row["fiberMass"]) <= 1e-6 * fiber_row["fiberMass"],
          "sigma integrated along the fibers %.7g kg = the table's fiber mass %.7g kg at t = %g"
          % (printed, fiber_row["fiberMass"], fiber_row["Time"]))


def finished(run, work):
    done, text, prefix = run_report(run, work)
    check(done.returncode == 0, "exit 0 (got %d)" % done.returncode)
    out = os.path.join(run, "postProcessing", "dropletFiber", "0")
    last_vtp = json.load(open(os.path.join(out, "fibers.vtp.series")))["files"][-1]["name"]
    check_values(text, table(os.path.join(out, "dropletFiber.dat")), os.path.join(run, "log.pimpleFoam"),
                 os.path.join(out, last_vtp))
    check(open(prefix + ".png", "rb").read(8) == b"\x89PNG\r\n\x1a\n", "the PNG is written")
    check(text == done.stdout.split("wrote ")[0], "the text file holds what was printed")
    check("captured per liquid species    not in this case's table" in text, "no species columns: said so")
    check("sprayed = airborne + left + evaporated + captured (1e-06)  ok" in text, "the balance closes")


def copy_case(run, work, skip=()):
    case = os.path.join(work, "case")
    shutil.copytree(run, case, ignore=shutil.ignore_patterns(*skip))
    return case


def stopped(run, work):
    """A run stopped mid-way: the table cut after half its rows with a half-written
    line, the log cut at the same step, and a fibers file listed but never written."""
    case = copy_case(run, work)
    out = os.path.join(case, "postProcessing", "dropletFiber", "0")
    path = os.path.join(out, "dropletFiber.dat")
    written = table(path)[-1]  # the row of the fibers file's time
    lines = open(path).read().splitlines(True)
    header = [l for l in lines if l.startswith("#")]
    data = [l for l in lines if not l.startswith("#")]
    keep = data[:len(data) // 2]
    cut_time = data[len(data) // 2].split()[0]
    open(path, "w").write("".join(header + keep) + data[len(data) // 2][:40])
    log = os.path.join(case, "log.pimpleFoam")
    text = open(log).read()
    open(log, "w").write(text[:text.index("\nTime = %s\n" % cut_time) + 1])
    series = os.path.join(out, "fibers.vtp.series")
    entries = json.load(open(series))
    last_vtp = entries["files"][-1]["name"]
    entries["files"].append({"name": "fibers_9.vtp", "time": 9})
    json.dump(entries, open(series, "w"))
    done, text, _ = run_report(case, work)
    check(done.returncode == 0, "exit 0 (got %d)" % done.returncode)
    rows = table(path)
    check(len(rows) == len(keep), "the half-written line is left out: %d rows" % len(rows))
    check(re.search(r"at t = %g s" % rows[-1]["Time"], text) is not None, "reported at the last full row's time")
    check("values (the run stopped while writing it?)" in text, "the cut line is noted")
    check("fibers_9.vtp at t = 9 cannot be read" in text, "the fibers file never written is noted")
    check_values(text, rows, log, os.path.join(out, last_vtp), written)


def decomposed(run, work):
    """The 2-rank run without its reconstructed times: only processor* hold them."""
    case = copy_case(run, work)
    for entry in os.listdir(case):
        if re.match(r"^[0-9.]+$", entry) and float(entry) > 0:
            shutil.rmtree(os.path.join(case, entry))
    done, text, _ = run_report(case, work)
    check(done.returncode == 0, "exit 0 (got %d)" % done.returncode)
    check("decomposed, 2 processors, not reconstructed" in text, "the report says decomposed, not reconstructed")
    out = os.path.join(case, "postProcessing", "dropletFiber", "0")
    last = json.load(open(os.path.join(out, "fibers.vtp.series")))["files"][-1]["name"]
    check(last.endswith(".pvtp"), "the fibers are in pieces (%s)" % last)
    check_values(text, table(os.path.join(out, "dropletFiber.dat")), os.path.join(case, "log.pimpleFoam"),
                 os.path.join(out, last))


def main():
    kind, run, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    {"finished": finished, "stopped": stopped, "decomposed": decomposed}[kind](run, work)
    print("%s: %d failed" % (kind, len(failed)))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
