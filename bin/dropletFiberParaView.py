"""ParaView view of a case run with the dropletFiberCollision function object: the
air (the case's mesh through ParaView's OpenFOAM reader, coloured by U), the parcels
of every cloud (points coloured by diameter d), the coupling grid (coloured by the
droplet mass density rho, transparent where there are no droplets) and the fibers
(lines coloured by sigma, binder mass per length), at all written times. Each source
has a colour map of its own (the air's U and the grid's droplet U are not one map),
its range over all times, with its own colour legend in a corner of the view. The air
is drawn without the faces towards the camera (its far side), so that the parcels,
grid and fibers inside it stay in view from any side.

Usage
  in the GUI, in the case folder:   paraview --script=PATH/dropletFiberParaView.py
  headless (writes a screenshot):   pvbatch PATH/dropletFiberParaView.py [CASE] [-screenshot FILE]
                                    (where no display is: xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch ...)
CASE defaults to the current folder; FILE to CASE/dropletFiberParaView.png (pvbatch
writes one always, pvpython with -screenshot). ./Allwmake of the project installs this
file in $FOAM_USER_APPBIN, beside OpenFOAM's utilities; the tutorials' Allparaview
finds it there (or in $DROPLETFIBER_DIR/bin) and runs it on the tutorial's folder
(dropletFiberParaView of bin/dropletFiberRunFunctions). A script that execs this file
may set dropletFiberCase and dropletFiberScreenshot in the globals it passes (the
arguments still win).

A Python script rather than a .pvsm state file: a state file names the absolute
paths of its files and every proxy property of one ParaView version; this script
uses paraview.simple only (ParaView 5.x; checked with Debian's 5.11), finds the
case's clouds, function object folders and processor folders itself and works for
any case.
"""
import glob
import json
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction,
                             GetOpacityTransferFunction, GetScalarBar, OpenDataFile, OpenFOAMReader, Render,
                             GetTimeKeeper, RenameSource, SaveScreenshot, Show, Slice)

USAGE = "Usage: pvbatch dropletFiberParaView.py [CASE] [-screenshot FILE]"
# The colour legends' places, one per coloured source (more sources: anywhere)
LEGEND_PLACES = ["Upper Left Corner", "Upper Right Corner", "Lower Left Corner", "Lower Right Corner"]


def batch():
    """True under pvbatch (no GUI, nobody to look: the view goes to a screenshot)."""
    try:
        from paraview import servermanager
        module = servermanager.vtkProcessModule
        return module.GetProcessType() == module.PROCESS_BATCH
    except (ImportError, AttributeError):
        return False


def settings():
    """The case folder and the screenshot file (None: none): the arguments (pvbatch,
    pvpython), else what an exec'ing script set, else the current folder."""
    given = globals()
    case = given.get("dropletFiberCase") or os.getcwd()
    screenshot = given.get("dropletFiberScreenshot")
    # the GUI's --script leaves sys.argv as [''] (no script name, no arguments)
    args = list(sys.argv[1:]) if sys.argv and sys.argv[0] else []
    asked = False
    while args:
        arg = args.pop(0)
        if arg in ("-screenshot", "--screenshot") and args:
            screenshot, asked = os.path.abspath(args.pop(0)), True
        elif arg in ("-h", "-help", "--help"):
            print(__doc__)
            sys.exit(0)
        elif not arg.startswith("-"):
            case = arg
        else:
            raise SystemExit("dropletFiberParaView.py: unknown argument '%s'\n%s" % (arg, USAGE))
    case = os.path.abspath(case)
    if not os.path.isfile(os.path.join(case, "system", "controlDict")):
        raise SystemExit("dropletFiberParaView.py: %s is not an OpenFOAM case (no system/controlDict): run\n"
                         "    the script in the case's folder (ParaView's --script runs it in the current\n"
                         "    folder) or give the case: %s" % (case, USAGE))
    if asked or batch():
        screenshot = os.path.join(case, screenshot or "dropletFiberParaView.png")
    else:
        screenshot = None
    return case, screenshot


case, screenshot = settings()
view = GetActiveViewOrCreate("RenderView")
if screenshot:
    view.ViewSize = [1280, 1024]  # the screenshot's, so that the legends' fonts keep their size
legends = list(LEGEND_PLACES)


def foam_reader(regions, cell_arrays=None):
    """The case through ParaView's OpenFOAM reader (an empty <case>.foam file names it)."""
    foam = os.path.join(case, os.path.basename(case) + ".foam")
    if not os.path.exists(foam):
        open(foam, "w").close()
    reader = OpenFOAMReader(FileName=foam)
    decomposed = glob.glob(os.path.join(case, "processor0"))
    times = [d for d in os.listdir(case) if d.replace(".", "", 1).isdigit() and d != "0"]
    # an unreconstructed case: its times are in the processor folders only
    reader.CaseType = "Decomposed Case" if decomposed and not times else "Reconstructed Case"
    reader.MeshRegions = regions
    if cell_arrays is not None:
        reader.CellArrays = cell_arrays  # read only what is shown (a large case has many fields)
    return reader


def clouds():
    """The clouds' names: the lagrangian folders of any time (or processor0's)."""
    names = set()
    for folder in glob.glob(os.path.join(case, "*", "lagrangian", "*")) + \
            glob.glob(os.path.join(case, "processor0", "*", "lagrangian", "*")):
        names.add(os.path.basename(folder))
    return sorted(names)


def open_series(series):
    """A function object's .series file; when its entries are in another format than
    its name says (parallel runs written before their indices were named
    grid.pvti.series and fibers.pvtp.series listed their .pvti and .pvtp files in
    grid.vti.series and fibers.vtp.series), ParaView finds no reader for it: then its
    entries are opened as a file series (their times from their TimeValue)."""
    entries = json.load(open(series))["files"]
    named = os.path.splitext(os.path.splitext(series)[0])[1]  # ".vti" of grid.vti.series, ".pvti" ...
    if all(entry["name"].endswith(named) for entry in entries):
        return OpenDataFile(series)
    return OpenDataFile([os.path.join(os.path.dirname(series), entry["name"]) for entry in entries])


def colour(display, association, array, preset, title, invert=False):
    """Colours display by array with a colour map of its own (another source's array of
    the same name keeps its own), ranged over the array's values at all times and kept
    so, with a legend in a corner of its own. Returns the colour map."""
    ColorBy(display, (association, array), True)
    lut = GetColorTransferFunction(array, display, separate=True)
    lut.ApplyPreset(preset, True)
    if invert:
        lut.InvertTransferFunction()
    display.RescaleTransferFunctionToDataRangeOverTime()
    lut.AutomaticRescaleRangeMode = "Never"  # the range over all times, not re-grown per time
    display.SetScalarBarVisibility(view, True)
    legend = GetScalarBar(lut, view)
    legend.Title = title
    legend.ComponentTitle = ""
    legend.TitleFontSize = 14
    legend.LabelFontSize = 12
    legend.ScalarBarLength = 0.3
    legend.WindowLocation = legends.pop(0) if legends else "Any Location"
    return lut


def transparent_where_empty(display, array, lut):
    """Opacity by value (0 at the lowest, 0.7 at 30 % of the range, 0.9 at the
    highest): the air shows through where there are no droplets."""
    low, high = lut.RGBPoints[0], lut.RGBPoints[-4]
    opacity = GetOpacityTransferFunction(array, display, separate=True)
    opacity.Points = [low, 0.0, 0.5, 0.0, low + 0.3 * (high - low), 0.7, 0.5, 0.0, high, 0.9, 0.5, 0.0]
    lut.EnableOpacityMapping = 1


air = foam_reader(["internalMesh"], ["U"])
RenameSource("air", air)
air.UpdatePipeline()
bounds = air.GetDataInformation().GetBounds()
sizes = [bounds[2 * k + 1] - bounds[2 * k] for k in range(3)]
thin = min(sizes) < 0.2 * sorted(sizes)[1]  # a 2D case: one cell across
if thin:
    # the mesh's faces towards the camera left out: its far side, coloured by the
    # air, behind the parcels, grid and fibers inside
    display = Show(air, view)
    display.BackfaceRepresentation = "Cull Frontface"
else:
    # a 3D case: the air on the mid-plane across the view (half-transparent: the
    # spray and fibers behind it stay in view)
    middle = Slice(Input=air)
    RenameSource("air mid-plane", middle)
    middle.SliceType = "Plane"
    middle.SliceType.Origin = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
    middle.SliceType.Normal = [0, 0, 1]
    display = Show(middle, view)
    display.Opacity = 0.6
lut = colour(display, "CELLS", "U", "Grayscale", "air U [m/s]")
# grey from dark to light, not black: dark fibers and parcels stay visible on slow air
lut.RGBPoints = [lut.RGBPoints[0], 0.3, 0.3, 0.3, lut.RGBPoints[-4], 0.95, 0.95, 0.95]

for cloud in clouds():
    parcels = foam_reader(["lagrangian/" + cloud], [])
    # ParaView 5.11's reader loses the parcels of a case with one time when the time
    # changes (the cached mesh); they are read anew
    parcels.Cachemesh = 0
    RenameSource("parcels " + cloud, parcels)
    display = Show(parcels, view)
    display.SetRepresentationType("Points")
    display.PointSize = 4
    display.RenderPointsAsSpheres = 1
    colour(display, "POINTS", "d", "Viridis (matplotlib)", "%s d [m]" % cloud)

for folder in sorted(glob.glob(os.path.join(case, "postProcessing", "*", "*"))):
    # a serial run's series, or a parallel run's under either name
    grid_series = ([f for f in (os.path.join(folder, "grid.vti.series"), os.path.join(folder, "grid.pvti.series"))
                    if os.path.isfile(f)] + [""])[0]
    fiber_series = ([f for f in (os.path.join(folder, "fibers.vtp.series"), os.path.join(folder, "fibers.pvtp.series"))
                     if os.path.isfile(f)] + [""])[0]
    name = os.path.relpath(folder, os.path.join(case, "postProcessing"))
    if grid_series:
        grid = open_series(grid_series)
        RenameSource("grid " + name, grid)
        display = Show(grid, view)
        extent = grid.GetDataInformation().GetExtent()
        flat = min(extent[1] - extent[0], extent[3] - extent[2], extent[5] - extent[4]) == 0
        # one layer of nodes (2D case): a surface; a 3D grid: a volume
        display.SetRepresentationType("Surface" if flat else "Volume")
        if not flat:
            # the opacity per eighth of the grid's size (not per node spacing): the
            # parcels inside the spray stay in view
            box = grid.GetDataInformation().GetBounds()
            display.ScalarOpacityUnitDistance = max(box[2 * k + 1] - box[2 * k] for k in range(3)) / 8
        lut = colour(display, "POINTS", "rho", "Reds", "grid rho [kg/m3]", invert=True)
        transparent_where_empty(display, "rho", lut)
    if fiber_series:
        fibers = open_series(fiber_series)
        RenameSource("fibers " + name, fibers)
        display = Show(fibers, view)
        display.LineWidth = 3
        display.RenderLinesAsTubes = 1
        colour(display, "POINTS", "sigma", "Plasma (matplotlib)", "fibers sigma [kg/m]")

scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
times = GetTimeKeeper().TimestepValues
times = list(times) if hasattr(times, "__iter__") else [times]
# the last time written (not the scene's end: one time t gives the scene t to t + 1)
scene.AnimationTime = max(times)
if thin:
    view.CameraParallelProjection = 1  # a thin (2D) case seen flat
view.ResetCamera()
Render()
if screenshot:
    SaveScreenshot(screenshot, view, ImageResolution=[1280, 1024])
    print("dropletFiberParaView.py: wrote %s (t = %g)" % (screenshot, view.ViewTime))
