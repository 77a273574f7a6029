"""ParaView view of this tutorial after ./Allrun: the air, the parcels, the coupling
grid and the fibers at all written times, each with a colour map of its own (the
project's dropletFiberParaView.py, run on this folder).

In the GUI, in this folder:  paraview --script=formingHood.paraview.py
Headless (writes formingHood.paraview.png):
    xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch formingHood.paraview.py
    (pvbatch alone where a display is; any folder: pvbatch PATH/formingHood.paraview.py)

dropletFiberParaView.py is found where the project's ./Allwmake installs it, beside
OpenFOAM's utilities ($FOAM_USER_APPBIN, on PATH with OpenFOAM's environment), or in
$DROPLETFIBER_DIR/bin when that is set."""
import os


def _project_script(name="dropletFiberParaView.py"):
    if os.environ.get("DROPLETFIBER_DIR"):
        folders = [os.path.join(os.environ["DROPLETFIBER_DIR"], "bin")]
    else:
        folders = os.environ.get("PATH", "").split(os.pathsep) + [os.environ.get("FOAM_USER_APPBIN", "")]
    for folder in folders:
        if folder and os.path.isfile(os.path.join(folder, name)):
            return os.path.join(folder, name)
    raise SystemExit("%s not found in %s: load the OpenFOAM environment the dropletFiber project was\n"
                     "    built in (its ./Allwmake installs it into $FOAM_USER_APPBIN), or set DROPLETFIBER_DIR\n"
                     "    to the project's folder" % (name, os.pathsep.join(f for f in folders if f) or "PATH"))


# This folder: the script's own when ParaView says it (pvbatch, pvpython), else the
# current one (the GUI's --script runs it without its name)
_here = os.path.dirname(os.path.abspath(globals().get("__file__") or os.path.join(os.getcwd(), "x")))
_script = _project_script()
exec(compile(open(_script).read(), _script, "exec"),
     {"__name__": "__main__", "__file__": _script,
      "dropletFiberCase": _here, "dropletFiberScreenshot": "formingHood.paraview.png"})
