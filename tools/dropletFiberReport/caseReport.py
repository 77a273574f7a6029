"""Everything the report says about one case, gathered from its outputs: the tables,
the solver's log and the VTK files. Missing parts are noted, not guessed."""
import os

import numpy as np

import caseOutputs
import tableColumns
import vtkFiles
from caseOutputs import MissingOutput
from solverLog import SolverLog


class CaseReport:
    def __init__(self, case, name=None):
        self.case = case
        self.notes = []
        if not os.path.isdir(case):
            raise MissingOutput("no case folder %s" % case)
        self.name = self._function_object(name)
        self.table = caseOutputs.read_table(case, self.name, "dropletFiber.dat")
        self.notes += self.table.notes
        if not self.table.rows:
            raise MissingOutput("%s has no rows: the run stopped before the function object's "
                                "first step" % self._table_path())
        self.siblings = {}
        for sibling in ("fiberDispersion.dat", "parallelStatistics.dat", "binderDistribution.dat",
                        "laydown.dat"):
            table = caseOutputs.read_table(case, self.name, sibling)
            if table is not None and table.rows:
                self.siblings[sibling] = table
                self.notes += table.notes
        self.processors = caseOutputs.processor_count(case)
        log_path = caseOutputs.solver_log(case)
        self.log = SolverLog(log_path) if log_path else None
        if self.log is None:
            self.notes.append("no solver log (log.<application>) in %s: sprayed, airborne, left and "
                              "evaporated binder come from the clouds' reports there" % case)
        self._read_vtk()
        self.mat_profile = caseOutputs.latest_mat_profile(case, self.name)

    def _function_object(self, name):
        names = caseOutputs.function_object_names(self.case)
        if name is not None:
            if name not in names:
                raise MissingOutput(
                    "no postProcessing/%s/<startTime>/dropletFiber.dat in %s (function objects with a "
                    "table there: %s)" % (name, self.case, ", ".join(names) or "none"))
            return name
        if len(names) == 1:
            return names[0]
        if len(names) > 1:
            raise MissingOutput("several dropletFiber function objects in %s (%s): choose one with -name"
                                % (self.case, ", ".join(names)))
        log = caseOutputs.solver_log(self.case)
        raise MissingOutput(
            "no postProcessing/<name>/<startTime>/dropletFiber.dat in %s: the dropletFiberCollision "
            "function object did not run there (yet).\n    Look in %s for 'Unknown function type "
            "dropletFiberCollision' or 'Could not load \"libdropletFiber.so\"': the library is then "
            "neither in $FOAM_USER_LIBBIN nor on LD_LIBRARY_PATH of the environment the case ran in."
            % (self.case, log or "the solver's log"))

    def _table_path(self):
        return os.path.join(self.case, "postProcessing", self.name, "<startTime>", "dropletFiber.dat")

    def _read_vtk(self):
        self.fibers = self.grid = self.mat = None
        for folder in reversed(caseOutputs.start_folders(self.case, self.name)):
            if self.fibers is None:
                self.fibers = vtkFiles.last_readable(folder, "fibers.vtp", vtkFiles.Fibers, self.notes)
            if self.grid is None:
                self.grid = vtkFiles.last_readable(folder, "grid.vti", vtkFiles.Grid, self.notes)
            if self.mat is None:
                self.mat = vtkFiles.last_readable(folder, "mat.vti", vtkFiles.Grid, self.notes)
        if self.fibers is None:
            self.notes.append("no readable fibers_<time>.vtp/.pvtp: no fiber view, no sigma distribution")
        if self.grid is None:
            self.notes.append("no readable grid_<time>.vti/.pvti: the fiber view has no droplet background")

    def fiber_centres(self):
        """{fiberId: [(time, centre)]} over every readable fibers file (for the dispersion)."""
        centres = {}
        for folder in caseOutputs.start_folders(self.case, self.name):
            for time, path in vtkFiles.series(folder, "fibers.vtp"):
                try:
                    fibers = vtkFiles.Fibers(time, path)
                except Exception:  # noqa: BLE001 a damaged file: noted for the last one only
                    continue
                ids = fibers.point_data.get("fiberId")
                if ids is None:
                    return {}
                unique, which = np.unique(ids, return_inverse=True)
                counts = np.bincount(which)
                means = np.stack([np.bincount(which, weights=fibers.points[:, k]) / counts for k in range(3)], axis=1)
                for f, centre in zip(unique, means):
                    centres.setdefault(int(f), []).append((time, centre))
        return centres

    # --- the binder balance -------------------------------------------------------
    def balance(self):
        """Sprayed, airborne, left, evaporated, other transfers and captured (kg),
        at the clouds' last reports, with the captured total of the table row the
        reports follow; None without a log or cloud report."""
        if self.log is None or not self.log.clouds:
            return None
        b = {"sprayed": 0.0, "airborne": 0.0, "left": 0.0, "evaporated": None, "otherTransfer": 0.0,
             "clouds": sorted(self.log.clouds), "time": None, "capturedTime": None}
        for report in self.log.clouds.values():
            b["sprayed"] += report["introduced"]
            b["airborne"] += report["inSystem"]
            b["left"] += self._left(report)
            b["otherTransfer"] += report["otherTransfer"]
            if report["phaseChange"] is not None:
                b["evaporated"] = (b["evaporated"] or 0.0) + report["phaseChange"]
            b["time"] = report["time"] if b["time"] is None else max(b["time"], report["time"])
            paired = report["functionObjectTimes"].get(self.name)
            if paired is not None:
                b["capturedTime"] = paired if b["capturedTime"] is None else min(b["capturedTime"], paired)
        lost = b["airborne"] + b["left"] + (b["evaporated"] or 0.0) + b["otherTransfer"]
        if b["capturedTime"] is None and b["time"] is not None:
            b["capturedTime"] = self._unlogged_pairing(b["time"], b["sprayed"] - lost)
        b["captured"] = self.captured_at(b["capturedTime"])
        b["residual"] = b["sprayed"] - (lost + b["captured"])
        return b

    def _unlogged_pairing(self, time, taken):
        """Without the function object's per-step log lines (entry log false) the row a
        cloud report follows is not known: that of the report's time (a cloud evolved by
        a function object after this one) or the one before (the solver's cloud, evolved
        before the function objects run); the one whose captured total is nearer the
        mass the cloud lost is taken, and noted."""
        rows = [r for r in self.table.rows if r["Time"] <= time * (1 + 1e-12)]
        candidates = [r["Time"] for r in rows[-2:]]
        if not candidates:
            return None
        if "log lines" not in " ".join(self.notes):
            self.notes.append("no per-step log lines of the function object (log false?): the captured "
                              "mass of the balance is the table row's nearer to what the clouds lost")
        return min(candidates, key=lambda t: abs(self.captured_at(t) - taken))

    def _left(self, report):
        """The mass of the parcels that left the domain: those counted by the cloud's
        system line (any non-wall patch), and those a wall's interaction removed
        (escape on a wall patch). A patch of unknown type counts as a wall."""
        types = caseOutputs.patch_types(self.case)
        unknown = [p for p in report["escapedPatches"] if p not in types]
        if unknown and report["escapedPatches"] and not getattr(self, "_unknown_noted", False):
            self._unknown_noted = True
            self.notes.append("patch types of %s not read from constant/polyMesh/boundary: their "
                              "escaped parcels counted as removed at walls" % ", ".join(unknown))
        walls = sum(m for p, m in report["escapedPatches"].items() if types.get(p, "wall") == "wall")
        return report["escapedSystem"] + walls

    def captured_at(self, time):
        """capturedTotal of the table row at time (0 before the first row)."""
        if time is None:
            return 0.0
        rows = [r for r in self.table.rows if r["Time"] <= time * (1 + 1e-12)]
        return rows[-1]["capturedTotal"] if rows else 0.0

    def depletion(self):
        return self.table.has("removedStep")

    def species(self):
        """Per liquid species from the table: {'captured': {...}, 'evaporated': {...}}."""
        return {"captured": {k: v for k, v in tableColumns.species_totals(self.table, tableColumns.CAPTURED).items() if k},
                "evaporated": tableColumns.species_totals(self.table, tableColumns.EVAPORATED)}

    # --- the run's times --------------------------------------------------------------
    def wall_time_share(self):
        """({wall-time column: its sum}, the run's time, which time) over the rows of
        the log's run; None without log times or wall-time columns."""
        columns = tableColumns.wall_time_columns(self.table)
        if not columns or self.log is None or self.log.execution_time is None or not self.log.times:
            return None
        first = self.log.times[0] * (1 - 1e-12)
        rows = [r for r in self.table.rows if r["Time"] >= first]
        used = {c: sum(r[c] for r in rows) for c in columns}
        # ClockTime counts whole seconds: ExecutionTime (the CPU time) for a short run,
        # unless waiting (a loaded machine, other ranks) made the wall time longer
        if self.log.clock_time >= 20:
            return used, self.log.clock_time, "ClockTime"
        if sum(used.values()) > self.log.execution_time:
            return used, max(self.log.clock_time, 1.0), "ClockTime, whole seconds"
        return used, self.log.execution_time, "ExecutionTime"

    def case_name(self):
        return os.path.basename(os.path.abspath(self.case))

    def planar(self):
        """A 2D case: one grid layer, or (without a grid) fibers in one z plane."""
        if self.grid is not None:
            return self.grid.shape[0] == 1
        if self.fibers is not None and len(self.fibers.points):
            z = self.fibers.points[:, 2]
            return float(z.max() - z.min()) == 0.0
        return True
