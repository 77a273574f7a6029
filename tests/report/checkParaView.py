"""Run by pvbatch (tests/report/checkParaView.sh): runs the project's
dropletFiberParaView.py as a tutorial's Allparaview -batch has pvbatch run it (the
case and the screenshot as arguments: dropletFiberRunFunctions' dropletFiberParaView;
that launcher's own choices are checked by tests/cases/checkTutorialTools.sh), then
checks what it built in ParaView:
- the air, each cloud's parcels, the grid and the fibers are there, each with data at
  the last time, and the view is at the last time;
- each is coloured by its own array (air U, parcels d, grid rho, fibers sigma) with a
  colour map of its own (none shared), whose range holds the array's values at every
  time (not only at the first: the range over all times);
- the screenshot is written: a PNG of 1280 x 1024 that is not the bare background.

Usage: pvbatch checkParaView.py SCRIPT CASE SCREENSHOT
"""
import os
import struct
import sys

from paraview import servermanager
from paraview.simple import GetActiveView, GetColorTransferFunction, GetSources, GetTimeKeeper

script, case, screenshot = sys.argv[1:4]
failed = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failed.append(what)


if os.path.exists(screenshot):
    os.remove(screenshot)
sys.argv = [script, case, "--screenshot", screenshot]  # as the launcher has pvbatch run it
exec(compile(open(script).read(), script, "exec"), {"__name__": "__main__", "__file__": script})

view = GetActiveView()
times = GetTimeKeeper().TimestepValues
times = sorted(times) if hasattr(times, "__iter__") else [times]
last = times[-1]
check(abs(view.ViewTime - last) <= 1e-12 * max(1.0, abs(last)),
      "the view at the last time %g (at %g)" % (last, view.ViewTime))

# What each source shown must be coloured by: the first word of its name ("air" also
# for the air's mid-plane of a 3D case, whose reader is not shown itself)
expected = {"air": ("CELLS", "U"), "parcels": ("POINTS", "d"), "grid": ("POINTS", "rho"),
            "fibers": ("POINTS", "sigma")}
sources = {}
for (name, _), proxy in GetSources().items():
    display = servermanager.GetRepresentation(proxy, view)
    if display is not None and display.Visibility:
        sources[name] = proxy
kinds = {name.split()[0] for name in sources}
check(kinds >= set(expected), "the air, parcels, grid and fibers are shown (%s)" % sorted(sources))


def value_range(source, association, array, time):
    """The array's range (a vector's magnitude) over the source's data at time."""
    source.UpdatePipeline(time)
    info = source.GetDataInformation()
    arrays = info.GetCellDataInformation() if association == "CELLS" else info.GetPointDataInformation()
    found = arrays.GetArrayInformation(array)
    if found is None:
        return None
    return found.GetComponentRange(-1 if found.GetNumberOfComponents() > 1 else 0)


maps = {}
for name, source in sorted(sources.items()):
    kind = name.split()[0]
    if kind not in expected:
        continue
    association, array = expected[kind]
    display = servermanager.GetRepresentation(source, view)
    coloured = list(display.ColorArrayName)
    check(coloured == [association, array], "%s: coloured by %s %s (%s)" % (name, association, array, coloured))
    check(bool(display.UseSeparateColorMap), "%s: a colour map of its own" % name)
    lut = GetColorTransferFunction(array, display, separate=True)
    maps[name] = lut.SMProxy.GetGlobalIDAsString()
    low, high = lut.RGBPoints[0], lut.RGBPoints[-4]
    source.UpdatePipeline(last)
    info = source.GetDataInformation()
    check(info.GetNumberOfPoints() > 0, "%s: data at the last time (%d points, %d cells)"
          % (name, info.GetNumberOfPoints(), info.GetNumberOfCells()))
    ranges = [r for r in (value_range(source, association, array, t) for t in times) if r]
    check(len(ranges) > 0, "%s: %s at %d times" % (name, array, len(ranges)))
    if ranges:
        lowest, highest = min(r[0] for r in ranges), max(r[1] for r in ranges)
        slack = 1e-9 * max(abs(lowest), abs(highest), 1e-300)
        check(low <= lowest + slack and high >= highest - slack and high > low,
              "%s: colour range %.4g to %.4g holds %s over all %d times (%.4g to %.4g)"
              % (name, low, high, array, len(ranges), lowest, highest))
        last_range = value_range(source, association, array, last)
        check(high - low <= 1.5 * (highest - lowest) + slack,
              "%s: colour range not wider than the data's (last time %.4g to %.4g)"
              % (name, last_range[0], last_range[1]))
check(len(set(maps.values())) == len(maps), "no colour map shared (%d maps for %d sources)"
      % (len(set(maps.values())), len(maps)))

# The screenshot: a PNG of the view's size, not the bare background
check(os.path.isfile(screenshot), "the screenshot %s is written" % screenshot)
if os.path.isfile(screenshot):
    head = open(screenshot, "rb").read(24)
    width, height = struct.unpack(">II", head[16:24])
    check(head[:8] == b"\x89PNG\r\n\x1a\n" and (width, height) == (1280, 1024),
          "the screenshot is a PNG of 1280 x 1024 (%d x %d)" % (width, height))
    from paraview.vtk.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(screenshot)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
    background = pixels[0]
    drawn = (abs(pixels.astype(int) - background.astype(int)).sum(axis=1) > 30).mean()
    colours = len({tuple(p) for p in pixels[::7]})
    check(drawn > 0.1 and colours > 500, "the screenshot shows the case: %.0f %% of it drawn, %d colours"
          % (100 * drawn, colours))

print("%s: %d failed" % (os.path.basename(script), len(failed)))
sys.stdout.flush()
# the status without ParaView's teardown: pvbatch 5.11 may crash in it after
# sys.exit from a script (SIGSEGV), and every check is done
os._exit(1 if failed else 0)
