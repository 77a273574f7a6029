"""ParaView view of this tutorial after ./Allrun: the air, the parcels, the coupling
grid and the fibers, all times (bin/dropletFiberParaView.py of the project).
Run in this folder: paraview --script=formingHood.paraview.py
ParaView's --script runs one file: this one runs the project's, found through
DROPLETFIBER_DIR or, for the tutorial in its place in the project, two folders up."""
import os

script = os.path.join(os.environ.get("DROPLETFIBER_DIR") or os.path.join(os.getcwd(), "..", ".."),
                      "bin", "dropletFiberParaView.py")
exec(compile(open(script).read(), script, "exec"))
