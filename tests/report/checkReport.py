"""Tests of bin/dropletFiberReport on finished runs of the channelSpray tutorial (the
regression runs' folders), on copies of them changed as a stopped run, a decomposed
run never reconstructed, a table with more columns in another order, and on missing
cases. The expected values are derived here from the run's files with this file's own
readers (the table by its header, the cloud's report in the log, the VTK XML), not
taken from the report's code.

Usage: checkReport.py KIND RUN WORK [PARALLEL_RUN]
  KIND  finished | stopped | decomposed | columns | missing | paraview | threeD | evaporating
  RUN   the finished run's folder (serial, or parallel for decomposed; the
        reactingBox case test's run for evaporating)
  WORK  a scratch folder (replaced)
  PARALLEL_RUN  for paraview: the 2-rank run
"""
import base64
import json
import math
import os
import re
import shutil
import struct
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
    last = json.load(open(os.path.join(out, "fibers.pvtp.series")))["files"][-1]["name"]
    check(last.endswith(".pvtp"), "the fibers are in pieces (%s)" % last)
    check_values(text, table(os.path.join(out, "dropletFiber.dat")), os.path.join(case, "log.pimpleFoam"),
                 os.path.join(out, last))


def columns(run, work):
    """The table with its columns in reverse order and columns other features add
    (per-species captured totals, an evaporated total), a binderDistribution.dat and a
    parallelStatistics.dat with an imbalance column: the same figures, and the added
    columns reported by name with the values written here."""
    case = copy_case(run, work)
    out = os.path.join(case, "postProcessing", "dropletFiber", "0")
    path = os.path.join(out, "dropletFiber.dat")
    rows = table(path)
    # The names the function object writes (docs/userGuide.md, Outputs); evaporatedMass replaces
    # the table's own where it has one
    added = {"captured_H2O": 1.25e-10, "captured_RESIN": 2.5e-11, "evaporatedMass": 3.75e-9}
    names = [n for n in reversed(list(rows[0])) if n not in added] + list(added)
    with open(path, "w") as f:
        f.write("# a comment line\n# " + "\t".join(names) + "\n")
        for r in rows:
            f.write("\t".join("%.12e" % {**r, **added}[n] for n in names) + "\n")
    with open(os.path.join(out, "binderDistribution.dat"), "w") as f:
        f.write("# Time\tbareLengthFraction\tsigmaMean\tsigmaCoV\thitsPerLength"
                "\texpectedBareLengthFraction\texpectedSigmaCoV\n")
        f.write("0.02\t0.5\t7e-08\t0.1\t100\t0.2\t0.05\n0.04\t0.25\t7.5e-08\t0.125\t200\t0.125\t0.0625\n")
    with open(os.path.join(out, "parallelStatistics.dat"), "w") as f:
        f.write("# Time\tnodesHeldMax\tparcelImbalance\n0.02\t10\t1.5\n0.04\t10\t2.5\n")
    done, text, _ = run_report(case, work)
    check(done.returncode == 0, "exit 0 (got %d)" % done.returncode)
    check("captured per liquid species    H2O 1.25e-10 kg, RESIN 2.5e-11 kg" in text,
          "the species' captured totals by name")
    check("evaporated (table)             all 3.75e-09 kg" in text, "the evaporated total by name")
    check("bareLengthFraction 0.25" in text and "hitsPerLength 200" in text,
          "binderDistribution.dat's last row by name")
    check("this run / expected mode: bareLengthFraction 0.25 / 0.125, sigmaCoV 0.125 / 0.0625" in text,
          "both modes' binder distribution side by side")
    binder_panel_shows_both_modes(os.path.join(out, "binderDistribution.dat"))
    check(re.search(r"parcelImbalance\s+mean 2, max 2.5 over 2 steps", text) is not None,
          "the imbalance column: mean 2, max 2.5")
    check_values(text, rows, os.path.join(case, "log.pimpleFoam"),
                 os.path.join(out, json.load(open(os.path.join(out, "fibers.vtp.series")))["files"][-1]["name"]))


def binder_panel_shows_both_modes(path):
    """The report's binder distribution panel on the table written by columns(): each
    of the run's fraction and CoV columns solid, the expected mode's dashed in its
    colour, with the values of the table."""
    sys.path.insert(0, os.path.join(ROOT, "tools", "dropletFiberReport"))
    import caseOutputs
    import reportFigure
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots()
    reportFigure._binder_distribution(ax, types.SimpleNamespace(
        siblings={"binderDistribution.dat": caseOutputs.Table(*caseOutputs._read_one(path))}))
    lines = {line.get_label(): line for line in ax.get_lines()}
    plt.close(fig)
    for name, own, expected in (("bareLengthFraction", [0.5, 0.25], [0.2, 0.125]),
                                ("sigmaCoV", [0.1, 0.125], [0.05, 0.0625])):
        mine, theirs = lines.get(name + " (this run)"), lines.get(name + " (expected mode)")
        check(mine is not None and theirs is not None, "%s: a line for each mode" % name)
        if mine is not None and theirs is not None:
            check(list(mine.get_ydata()) == own and list(theirs.get_ydata()) == expected,
                  "%s: the table's values in both lines" % name)
            check(mine.get_linestyle() == "-" and theirs.get_linestyle() == "--"
                  and mine.get_color() == theirs.get_color(), "%s: expected mode dashed, same colour" % name)
    check(len(lines) == 4, "no other lines (got %s)" % sorted(lines))


def never_run(work):
    """A case that never ran: the tutorial's set-up copied without what a run of it in
    its own folder may have left (time folders, postProcessing, processor folders,
    logs): the test does not depend on whether the tutorial's folder has run."""
    tutorial = os.path.join(ROOT, "tutorials", "channelSpray")

    def outputs(folder, names):
        if os.path.abspath(folder) != tutorial:
            return []
        return [n for n in names if n == "postProcessing" or n.startswith(("processor", "log."))
                or re.match(r"^[0-9.e+-]+$", n)]
    case = os.path.join(work, "neverRun")
    shutil.copytree(tutorial, case, ignore=outputs)
    return case


def missing(run, work):
    """No case, a case that never ran (a copy of the tutorial's set-up), a wrong -name:
    exit 2 with a message naming what is missing, no traceback."""
    tutorial = never_run(work)
    for case, options, expected in ((os.path.join(work, "nowhere"), (), "no case folder"),
                                    (tutorial, (), "dropletFiber.dat"),
                                    (run, ("-name", "other"), "no postProcessing/other/")):
        done, _, prefix = run_report(case, work, *options)
        check(done.returncode == 2, "%s %s: exit 2 (got %d)" % (case, " ".join(options), done.returncode))
        check(expected in done.stderr, "the message names it: %s" % expected)
        check("Traceback" not in done.stderr, "no traceback")
        check(not os.path.exists(prefix + ".png"), "no PNG")


class _StandIn(types.SimpleNamespace):
    """A proxy of the stand-in of paraview.simple: methods not listed do nothing; a
    data information of a one-cell-thick channel (a 2D case)."""
    ViewTime = 0.04  # a view's time (printed with a screenshot): the stand-in's TimestepValues

    def __getattr__(self, name):
        return lambda *a, **k: None

    def ApplyPreset(self, preset, rescale):
        self.preset = preset

    def GetDataInformation(self):
        return types.SimpleNamespace(GetBounds=lambda: (0, 0.05, 0, 0.15, 0, 0.01),
                                     GetExtent=lambda: (0, 50, 0, 150, 0, 0))


def paraview_stand_in(calls):
    """A stand-in of paraview.simple (in sys.modules) recording every call in calls."""
    def recorder(name):
        def call(*args, **kwargs):
            proxy = _StandIn(name=name, RGBPoints=[0.0, 0, 0, 0, 1.0, 1, 1, 1], TimestepValues=[0.04])
            calls.append((name, args, kwargs, proxy))
            return proxy
        return call

    simple = types.ModuleType("paraview.simple")
    for name in ("ColorBy", "GetActiveViewOrCreate", "GetAnimationScene", "GetColorTransferFunction",
                 "GetOpacityTransferFunction", "GetScalarBar", "GetTimeKeeper", "OpenDataFile", "OpenFOAMReader",
                 "Render", "RenameSource", "SaveScreenshot", "Show", "Slice"):
        setattr(simple, name, recorder(name))
    sys.modules["paraview"] = types.ModuleType("paraview")
    sys.modules["paraview.simple"] = simple


def run_script(script, cwd, argv, env=None, **given):
    """Runs a ParaView script as ParaView would (argv: [''] for the GUI's --script), in
    cwd, with the environment variables env set; given: its globals. Returns the
    SystemExit it raised, or None."""
    here, old_argv, old_env = os.getcwd(), sys.argv, dict(os.environ)
    os.chdir(cwd)
    sys.argv = argv
    for name, value in (env or {}).items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value
    try:
        exec(compile(open(script).read(), script, "exec"), {"__name__": "__main__", **given})
        return None
    except SystemExit as stop:
        return stop
    finally:
        os.chdir(here)
        sys.argv = old_argv
        os.environ.clear()
        os.environ.update(old_env)


def paraview(run, work):
    """bin/dropletFiberParaView.py against a stand-in of paraview.simple that records
    what it is asked to open and how it colours it, run as ParaView's GUI runs it
    (--script: no arguments, the case the current folder, no screenshot): the serial
    run, and the 2-rank run (PARALLEL_RUN) without its reconstructed times (its series
    list .pvti and .pvtp files: opened as file series). Then as a tutorial's
    Allparaview -batch runs it (pvbatch, the case and the screenshot as arguments) from
    another folder: the case given, not the current folder. (How the launcher finds the
    script, tests/cases/checkTutorialTools.sh checks.)"""
    calls = []
    paraview_stand_in(calls)
    script = os.path.join(ROOT, "bin", "dropletFiberParaView.py")
    for label, decompose in (("reconstructed", False), ("decomposed", True)):
        case = copy_case(sys.argv[4] if decompose else run, os.path.join(work, label))
        if decompose:
            for entry in os.listdir(case):
                if re.match(r"^[0-9.]+$", entry) and float(entry) > 0:
                    shutil.rmtree(os.path.join(case, entry))
        del calls[:]
        stop = run_script(script, case, [""])
        check(stop is None, "%s: runs through (%s)" % (label, stop))
        out = os.path.join(case, "postProcessing", "dropletFiber", "0")
        names = ("fibers.pvtp.series", "grid.pvti.series") if decompose \
            else ("fibers.vtp.series", "grid.vti.series")
        series = {name: [e["name"] for e in json.load(open(os.path.join(out, name)))["files"]]
                  for name in names}
        opened = sorted(c[1][0] if isinstance(c[1][0], str) else tuple(c[1][0])
                        for c in calls if c[0] == "OpenDataFile")
        if decompose:
            check(all(f.endswith((".pvtp", ".pvti")) for files in series.values() for f in files),
                  "decomposed: the series list .pvtp and .pvti files")
        # the series opened as they are (a parallel run's named by the pieces' index)
        expected = sorted(os.path.join(out, name) for name in series)
        check(opened == expected, "%s: opens the grid and the fibers (%s)" % (label, opened))
        readers = [c[2]["FileName"] for c in calls if c[0] == "OpenFOAMReader"]
        settings = [(c[3].CaseType, c[3].MeshRegions) for c in calls if c[0] == "OpenFOAMReader"]
        case_type = "Decomposed Case" if decompose else "Reconstructed Case"
        check(settings == [(case_type, ["internalMesh"]), (case_type, ["lagrangian/kinematicCloud"])],
              "%s: the OpenFOAM reader as %s, the mesh and the cloud (%s)" % (label, case_type, settings))
        check(len(readers) == 2 and os.path.isfile(readers[0]), "%s: the air and the cloud through %s"
              % (label, readers[0] if readers else None))
        coloured = [c for c in calls if c[0] == "ColorBy"]
        colours = [c[1][1][1] for c in coloured]
        check(colours == ["U", "d", "rho", "sigma"], "%s: coloured by U, d, rho, sigma (%s)" % (label, colours))
        check(all(c[1][2:] == (True,) for c in coloured), "%s: each with a colour map of its own" % label)
        maps = [c for c in calls if c[0] == "GetColorTransferFunction"]
        check(all(c[2].get("separate") for c in maps) and len({id(c[1][1]) for c in maps}) == 4,
              "%s: four separate colour maps, one per display" % label)
        presets = [getattr(c[3], "preset", None) for c in maps]
        check(len(set(presets)) == 4 and None not in presets, "%s: four different presets (%s)" % (label, presets))
        check(not [c for c in calls if c[0] == "SaveScreenshot"], "%s: no screenshot in the GUI" % label)

    # As the launcher runs it, from another folder: the case and the screenshot given
    case = copy_case(run, os.path.join(work, "launched"))
    elsewhere = os.path.join(work, "elsewhere")
    os.makedirs(elsewhere)
    screenshot = os.path.join(case, "channelSpray.paraview.png")
    del calls[:]
    stop = run_script(script, elsewhere, [script, case, "--screenshot", screenshot])
    readers = [c[2]["FileName"] for c in calls if c[0] == "OpenFOAMReader"]
    check(stop is None and len(readers) == 2 and os.path.dirname(readers[0]) == case,
          "as Allparaview -batch runs it: shows the case given from another folder (%s)"
          % (readers[0] if readers else stop))
    shots = [c for c in calls if c[0] == "SaveScreenshot"]
    check(len(shots) == 1 and shots[0][1][0] == screenshot,
          "as Allparaview -batch runs it: one screenshot, the one given (%s)" % [c[1][:1] for c in shots])
    print("(the stand-in checks the script's choices, not ParaView's own reading of the files:"
          " report.paraView.* runs it in ParaView)")


def three_d(run, work):
    """A 3D copy: the grid given 4 layers in z (each the 2D layer times its number) and
    the fibers tilted out of the plane (z = 0.002 + x/2): the report takes x-y and x-z
    views; the sigma distribution's length is the tilted segments' length."""
    case = copy_case(run, work)
    out = os.path.join(case, "postProcessing", "dropletFiber", "0")
    grid = os.path.join(out, json.load(open(os.path.join(out, "grid.vti.series")))["files"][-1]["name"])
    tree = ET.parse(grid)
    image = tree.getroot().find("ImageData")
    piece = image.find("Piece")
    extent = image.get("WholeExtent").split()
    extent[5] = "3"
    image.set("WholeExtent", " ".join(extent))
    piece.set("Extent", " ".join(extent))
    for da in piece.find("PointData"):
        raw = base64.b64decode("".join(da.text.split()))
        values = struct.unpack("<%dd" % ((len(raw) - 8) // 8), raw[8:])
        layers = b"".join(struct.pack("<%dd" % len(values), *[v * (k + 1) for v in values]) for k in range(4))
        da.text = base64.b64encode(struct.pack("<Q", len(layers)) + layers).decode()
    tree.write(grid)
    vtp = os.path.join(out, json.load(open(os.path.join(out, "fibers.vtp.series")))["files"][-1]["name"])
    tree = ET.parse(vtp)
    points = tree.getroot().find("PolyData/Piece/Points/DataArray")
    p = [float(v) for v in points.text.split()]
    for k in range(0, len(p), 3):
        p[k + 2] = 0.002 + 0.5 * p[k]
    points.text = " ".join(repr(v) for v in p)
    tree.write(vtp)
    done, text, prefix = run_report(case, work, "-noCheck")
    check(done.returncode == 0, "exit 0 (got %d)" % done.returncode)
    length = fiber_length(vtp)
    printed = number_after(text, r"segments, (\S+) m in total")
    check(abs(printed - length) <= 1e-5 * length, "sigma over %.6g m of tilted fiber (printed %g)" % (length, printed))
    check(open(prefix + ".png", "rb").read(8) == b"\x89PNG\r\n\x1a\n", "the PNG is written")


def evaporating(run, work):
    """reactingParcelFoam's evaporating cloud (the reactingBox case test's run): the
    evaporated mass is the cloud's last "Mass transfer phase change", the sprayed its
    mass introduced, and the balance with them closes."""
    log = os.path.join(run, "log.reactingParcelFoam")
    reports = re.findall(r"^Cloud: reactingCloud1\n((?:    .*\n|   \|.*\n)+)", open(log).read(), re.M)
    last = [r for r in reports if "Current mass in system" in r][-1]
    evaporated = float(re.search(r"Mass transfer phase change\s*=\s*(\S+)", last).group(1))
    sprayed = sum(float(m) for m in re.findall(r"mass introduced\s*=\s*(\S+)", last))
    done, text, _ = run_report(run, work)
    check(done.returncode == 0, "exit 0 (got %d)" % done.returncode)
    check(abs(number_after(text, r"evaporated (\S+)\n") - evaporated) <= 1e-6 * evaporated,
          "evaporated = the cloud's phase change %.7g kg" % evaporated)
    check(abs(number_after(text, r"binder sprayed\s+(\S+) kg") - sprayed) <= 1e-6 * sprayed,
          "sprayed = the cloud's mass introduced %.7g kg" % sprayed)
    check("sprayed = airborne + left + evaporated + captured (1e-06)  ok" in text, "the balance closes")


def main():
    kind, run, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    {"finished": finished, "stopped": stopped, "decomposed": decomposed, "columns": columns,
     "missing": missing, "paraview": paraview, "threeD": three_d,
     "evaporating": evaporating}[kind](run, work)
    print("%s: %d failed" % (kind, len(failed)))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
