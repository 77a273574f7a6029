"""The report's text: the lines printed and written to <prefix>.txt, and the checks
that fail the report (exit 1): the binder balance with depletion, captured at most
sprayed, and the function object's own conservation lines in the log."""
import os

import caseOutputs
import fiberDispersion
import tableColumns
from fiberLoad import fiber_load

ABSENT = "not in this case's table"


def _g(value, digits=4):
    return "%.*g" % (digits, value)


class Summary:
    def __init__(self, report):
        self.report = report
        self.lines = []
        self.failed = []

    def line(self, text=""):
        self.lines.append(text)

    def check(self, ok, what):
        self.line("  check: %-58s %s" % (what, "ok" if ok else "FAILED"))
        if not ok:
            self.failed.append(what)

    def build(self):
        r = self.report
        last = r.table.last()
        layout = "serial"
        if r.processors:
            layout = "decomposed, %d processors, %s" % (
                r.processors, "reconstructed" if caseOutputs.reconstructed(r.case) else "not reconstructed")
        self.line("dropletFiber report of %s (function object %s, %s) at t = %g s"
                  % (os.path.abspath(r.case), r.name, layout, last["Time"]))
        if "fibersRepresented" in last:
            self.line("  fibers                         %d computed, representing %.6g physical fibers"
                      % (last["fibers"], last["fibersRepresented"]))
        else:
            self.line("  fibers                         %d" % last["fibers"])
        self.line("  parcels                        %d" % last["parcels"])
        self._balance()
        self._species()
        self.line("  fiber mass now                 %s kg" % _g(last["fiberMass"]))
        self._conservation()
        self._spread()
        self._mat()
        self._fiber_load()
        self._siblings()
        self._wall_time()
        for note in r.notes:
            self.line("  note: " + note)
        return self

    def _balance(self):
        r, last = self.report, self.report.table.last()
        b = r.balance()
        if b is None:
            self.line("  binder captured by the fibers  %s kg (sprayed: no cloud report in the log)"
                      % _g(last["capturedTotal"]))
            return
        self.line("  binder sprayed                 %s kg (clouds %s, last report at t = %g s)"
                  % (_g(b["sprayed"], 7), ", ".join(b["clouds"]), b["time"]))
        efficiency = b["captured"] / b["sprayed"] if b["sprayed"] > 0 else float("nan")
        self.line("  binder captured by the fibers  %s kg (binder efficiency captured / sprayed %.3g %%)"
                  % (_g(b["captured"]), 100 * efficiency))
        evaporated = "%s" % _g(b["evaporated"], 7) if b["evaporated"] is not None else "0 (no phase change)"
        self.line("  binder balance: sprayed %s = airborne %s + left the domain %s + evaporated %s"
                  % (_g(b["sprayed"], 7), _g(b["airborne"], 7), _g(b["left"], 7), evaporated))
        other = " + other transfers %s" % _g(b["otherTransfer"], 7) if b["otherTransfer"] else ""
        self.line("      %s+ captured %s kg (balance %.3g kg, %.2g of the sprayed)"
                  % (other.lstrip() + " " if other else "", _g(b["captured"]), b["residual"],
                     b["residual"] / b["sprayed"] if b["sprayed"] else 0.0))
        if r.depletion():
            digits = min(rep.get("digits", 8) for rep in r.log.clouds.values())
            tolerance = max(1e-6, 2 * 10.0 ** (1 - digits))
            self.check(abs(b["residual"]) <= tolerance * b["sprayed"],
                       "sprayed = airborne + left + evaporated + captured (%.0e)" % tolerance)
        else:
            self.line("  (collision.depletion false: the captured droplets also fly on, counted twice)")
        self.check(b["captured"] <= b["sprayed"], "captured at most sprayed")

    def _species(self):
        species = self.report.species()
        captured = species["captured"]
        if captured:
            self.line("  captured per liquid species    " + ", ".join(
                "%s %s kg" % (s, _g(v[0])) for s, v in sorted(captured.items())))
        else:
            self.line("  captured per liquid species    " + ABSENT)
        evaporated = species["evaporated"]
        if evaporated:
            self.line("  evaporated (table)             " + ", ".join(
                "%s %s kg" % (s or "all", _g(v[0])) for s, v in sorted(evaporated.items())))
        else:
            self.line("  evaporated (table)             " + ABSENT)

    def _conservation(self):
        r = self.report
        if r.log is None:
            return
        if not r.log.conservation:
            self.line("  conservation lines             none in the log (no write time reached)")
        scale = max(r.table.last()["capturedTotal"], 1e-30)
        b = r.balance()
        if b is not None:
            scale = max(scale, b["sprayed"])
        for what, value in sorted(r.log.conservation.items()):
            self.line("  conservation: %-40s balance %.3g kg" % (what, value))
            self.check(abs(value) <= 1e-9 * scale, what + " (1e-9)")

    def _spread(self):
        """The weighted fibers' spread populations at the last write time (P57); a warning
        where the capture is set by holes (capped above 5 %) or the populations are opaque
        at their level (eps above 0.25)"""
        r = self.report
        if r.log is None or r.log.spread is None:
            return
        f = r.log.spread
        self.line("  spread populations (t = %g s)  kernel sigma/h %.3g (%.3g to %.3g); of their capture thin %.3g,"
                  " reaching k others %.3g, capped %.3g; clustering eps %.3g"
                  % (f["time"], f["sigma"], f["sigmaMin"], f["sigmaMax"], f["thin"], f["reaching"], f["capped"],
                     f["eps"]))
        if f["capped"] > 0.05:
            self.line("  warning: %.3g of the weighted fibers' capture from populations that reach too few computed"
                      " fibers: the capture is set by holes in the veil (more computed fibers, or a larger"
                      " collision.spread.maxSpacing)" % f["capped"])
        if f["eps"] > 0.25:
            self.line("  warning: the populations are opaque on their levels (eps %.3g > 0.25): where the veil is"
                      " thin the capture may be low by up to eps (docs/model.md sec. 12, P55)" % f["eps"])

    def _mat(self):
        """The mat's product: its complete rows at the last matProfile_<time>.dat (P60, P61),
        or that no row is complete yet (with fibers.laydown)"""
        r = self.report
        if "laydown.dat" not in r.siblings:
            return
        p = r.mat_profile
        if p is None:
            self.line("  mat                            no complete row yet: the belt has not carried a row across"
                      " the whole laying zone (run longer)")
            return
        self.line("  mat (t = %g s), the product     %s" % (p["time"], p["notes"][1] if len(p["notes"]) > 1 else ""))
        self.line("                                 over %s" % p["notes"][0].split("over its ")[-1].split(":")[0])

    def _fiber_load(self):
        load = fiber_load(self.report.fibers)
        if load is None:
            self.line("  sigma over fiber length        no fibers file with segments")
            return
        self.line("  sigma over fiber length (t = %g s): %d fibers, %d segments, %.6g m in total"
                  % (load["time"], load.get("fibers", -1), load["segments"], load["length"]))
        self.line("      sigma mean %s kg/m (CoV %.3g), min %s, max %s; fiber mass from sigma %s kg"
                  % (_g(load["sigmaMean"]), load["sigmaCoV"], _g(load["sigmaMin"]),
                     _g(load["sigmaMax"]), _g(load["mass"], 7)))
        if "binderMean" in load:
            self.line("      captured binder per length mean %s kg/m (CoV %.3g); length with none %.3g %%"
                      % (_g(load["binderMean"]), load["binderCoV"], 100 * load["bareFraction"]))

    def _siblings(self):
        r = self.report
        distribution = r.siblings.get("binderDistribution.dat")
        if distribution is None:
            self.line("  binder distribution            no binderDistribution.dat in this case")
        else:
            last = distribution.last()
            self.line("  binder distribution (binderDistribution.dat, t = %g s): " % last["Time"]
                      + ", ".join("%s %s" % (n, _g(last[n])) for n in distribution.names if n != "Time"))
            both = [(n, "expected" + n[:1].upper() + n[1:]) for n in distribution.names]
            both = [(n, e) for n, e in both if distribution.has(e)]
            if both:
                self.line("  binder distribution, this run / expected mode: "
                          + ", ".join("%s %s / %s" % (n, _g(last[n]), _g(last[e])) for n, e in both))
        statistics = r.siblings.get("parallelStatistics.dat")
        columns = tableColumns.imbalance_columns(statistics)
        if statistics is None:
            self.line("  load balance                   no parallelStatistics.dat (a serial run)")
        elif not columns:
            self.line("  load imbalance                 " + ABSENT.replace("table", "parallelStatistics.dat"))
        else:
            for c in columns:
                values = statistics.column(c)
                self.line("  %-30s mean %.3g, max %.3g over %d steps"
                          % (c, sum(values) / len(values), max(values), len(values)))

    def _wall_time(self):
        share = self.report.wall_time_share()
        if share is None:
            self.line("  wall time                      no wall-time columns or no log times")
            return
        used, total, which = share
        parts = ", ".join("%s %.3g s" % (c[len("wallTime"):].lower(), v) for c, v in used.items())
        whole = sum(used.values())
        self.line("  function object's wall time    %.3g s of the run's %.3g s (%s) = %.3g %% (%s; master)"
                  % (whole, total, which, 100 * whole / total if total else float("nan"), parts))

    def dispersion(self, points):
        rms = fiberDispersion.rms_beyond(points)
        if rms is None:
            self.line("  fiber dispersion               every fiber written at one time only")
        else:
            self.line("  fiber dispersion               rms %.3g m across the fibers' mean drift from their first "
                      "write, beyond %.3g m of travel (%d fiber positions)" % (rms[0], rms[2], rms[1]))
