"""ParaView view of a case run with the dropletFiberCollision function object: the
air (the case's mesh, coloured by |U|), the parcels of every cloud (points coloured
by diameter d), the coupling grid (coloured by the droplet mass density rho) and the
fibers (lines coloured by sigma, mass per length), all times.

Usage, in the case folder:  paraview --script=PATH/TO/bin/dropletFiberParaView.py
(the tutorials have a one-line <tutorial>.paraview.py that runs this file). Also
from ParaView's Python shell (Run Script) with the case as the current folder.

A Python script rather than a .pvsm state file: a state file names the absolute
paths of its files and every proxy property of one ParaView version; this script
uses paraview.simple only (ParaView 5.x), finds the case's clouds, function object
folders and processor folders itself and works for any case. Not tested with a
ParaView installation (the project's machines and CI have none); the project's test
runs it against a stand-in of paraview.simple that records what it opens.
"""
import glob
import os

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction,
                             OpenDataFile, OpenFOAMReader, Render, RenameSource, Show)

case = os.getcwd()
view = GetActiveViewOrCreate("RenderView")


def foam_reader(regions):
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
    return reader


def clouds():
    """The clouds' names: the lagrangian folders of any time (or processor0's)."""
    names = set()
    for folder in glob.glob(os.path.join(case, "*", "lagrangian", "*")) + \
            glob.glob(os.path.join(case, "processor0", "*", "lagrangian", "*")):
        names.add(os.path.basename(folder))
    return sorted(names)


def colour(display, association, array, preset):
    ColorBy(display, (association, array))
    GetColorTransferFunction(array).ApplyPreset(preset, True)
    display.SetScalarBarVisibility(view, True)


air = foam_reader(["internalMesh"])
RenameSource("air", air)
display = Show(air, view)
colour(display, "CELLS", "U", "Cool to Warm")
display.Opacity = 0.3

for cloud in clouds():
    parcels = foam_reader(["lagrangian/" + cloud])
    RenameSource("parcels " + cloud, parcels)
    display = Show(parcels, view)
    display.SetRepresentationType("Points")
    display.PointSize = 3
    colour(display, "POINTS", "d", "Viridis (matplotlib)")

for folder in sorted(glob.glob(os.path.join(case, "postProcessing", "*", "*"))):
    grid_series = os.path.join(folder, "grid.vti.series")
    fiber_series = os.path.join(folder, "fibers.vtp.series")
    if os.path.isfile(grid_series):
        grid = OpenDataFile(grid_series)
        RenameSource("grid " + os.path.relpath(folder, case), grid)
        display = Show(grid, view)
        display.SetRepresentationType("Surface")
        display.Opacity = 0.6
        colour(display, "POINTS", "rho", "Blues")
    if os.path.isfile(fiber_series):
        fibers = OpenDataFile(fiber_series)
        RenameSource("fibers " + os.path.relpath(folder, case), fibers)
        display = Show(fibers, view)
        display.LineWidth = 3
        colour(display, "POINTS", "sigma", "Inferno (matplotlib)")

GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
GetAnimationScene().GoToLast()
view.ResetCamera()
Render()
