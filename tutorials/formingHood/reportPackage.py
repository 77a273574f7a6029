"""Puts the project's report package on the import path of the hood's helpers: the
modules of dropletFiberReport (caseOutputs, solverLog, vtkFiles, ...), which read the
function object's tables and VTK files and the solver's log; the helpers import them
rather than parse those again.

The report is found as the tutorial's Allrun finds it (dropletFiberRunFunctions): in
$DROPLETFIBER_DIR/bin when that is set, else on PATH; its modules as the report finds
them: in dropletFiberPython/ beside it (./Allwmake installs them there, in
$FOAM_USER_APPBIN), or in the project's tools/dropletFiberReport beside its bin/.
Imported for this effect (import reportPackage), before the report's modules.
"""
import os
import shutil
import sys

HOW = ("load the OpenFOAM environment that the dropletFiber project was built in and run the\n"
       "    project's ./Allwmake there (it installs the report and its modules into $FOAM_USER_APPBIN),\n"
       "    or set DROPLETFIBER_DIR to the project's folder")


def modules_folder():
    """The folder of the report's modules; exits saying what to do without them."""
    project = os.environ.get("DROPLETFIBER_DIR")
    if project:
        report, where = os.path.join(project, "bin", "dropletFiberReport"), "in %s/bin (DROPLETFIBER_DIR)" % project
    else:
        report, where = shutil.which("dropletFiberReport"), "on PATH"
    if not report or not os.path.isfile(report):
        sys.exit("%s: dropletFiberReport not found %s: %s" % (os.path.basename(sys.argv[0]), where, HOW))
    here = os.path.dirname(os.path.realpath(report))
    for folder in (os.path.join(here, "dropletFiberPython"), os.path.join(here, "..", "tools", "dropletFiberReport")):
        if os.path.isfile(os.path.join(folder, "caseOutputs.py")):
            return folder
    sys.exit("%s: the report's modules are neither in %s/dropletFiberPython nor in the project's\n"
             "    tools/dropletFiberReport: %s" % (os.path.basename(sys.argv[0]), here, HOW))


sys.path.insert(0, modules_folder())
