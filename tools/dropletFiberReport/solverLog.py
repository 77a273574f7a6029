"""What the solver's log says that the tables do not: the clouds' own mass reports
(mass introduced by the injectors, mass in the system, the parcels that left at the
patches, mass lost to phase change and other transfers) and the run's times.

OpenFOAM prints a cloud's report after each of its steps ("Cloud: NAME" and indented
lines); the last complete one of each cloud is used.
"""
import re

NUMBER = r"([-+0-9.eE]+|nan|inf)"


def _cloud_report(lines):
    """A cloud's report from its indented lines. Escaped mass: 'system' counts the
    parcels that hit a patch that is neither a wall nor a constraint (KinematicParcel::
    hitPatch), the patch lines what the interaction model did per patch (stuck
    parcels stay in the cloud, inactive: their mass is still in the system)."""
    report = {"introduced": 0.0, "inSystem": None, "escapedSystem": 0.0, "escapedPatches": {},
              "phaseChange": None, "otherTransfer": 0.0, "time": None}
    patch = None
    for line in lines:
        s = line.strip()
        if s.startswith("Parcel fate:"):
            # "Parcel fate: patch NAME (number, mass)" or "Parcel fate: patch (number, mass) NAME"
            words = s.replace("(number, mass)", "").split()
            patch = "system" if words[2] == "system" else (words[3] if len(words) > 3 else "")
            continue
        m = re.match(r"- escape[^=]*=\s*\S+,\s*" + NUMBER, s)
        if m and patch is not None:
            if patch == "system":
                report["escapedSystem"] += float(m.group(1))
            else:
                report["escapedPatches"][patch] = report["escapedPatches"].get(patch, 0.0) + float(m.group(1))
            continue
        if s.startswith("- stick") and patch is not None:
            continue
        patch = None
        m = re.match(r"Current mass in system\s*=\s*" + NUMBER, s)
        if m:
            report["inSystem"] = float(m.group(1))
            mantissa = m.group(1).lower().split("e")[0].lstrip("-+0.")
            report["digits"] = len(mantissa.replace(".", ""))
        m = re.match(r"- mass introduced\s*=\s*" + NUMBER, s)
        if m:
            report["introduced"] += float(m.group(1))
        m = re.match(r"Mass transfer ([a-z ]+?)\s*=\s*" + NUMBER, s)
        if m:
            if m.group(1) == "phase change":
                report["phaseChange"] = float(m.group(2))
            else:
                report["otherTransfer"] += float(m.group(2))
    return report


class SolverLog:
    """Cloud reports, time and the run's execution and clock time from a log file."""

    def __init__(self, path):
        self.path = path
        self.clouds = {}
        self.history = {}  # cloud name: [(time, mass introduced)]
        self.times = []
        self.execution_time = None
        self.clock_time = None
        self.ended = False
        # the function object's conservation lines at its last write time
        self.conservation = {}
        # the spread populations' resolution at its last write time (docs/model.md sec. 12,
        # P57): time, sigma / h (mean, min, max), shares thin, reaching, capped, eps
        self.spread = None
        self._read(open(path, errors="replace").read().split("\n"))

    def _read(self, lines):
        time = time_name = None
        stepped = {}  # function object name: time of its last per-step line
        i = 0
        while i < len(lines):
            line = lines[i]
            m = re.match(r"^Time = " + NUMBER + r"\s*$", line)
            if m:
                time, time_name = float(m.group(1)), m.group(1)
                self.times.append(time)
            m = re.match(r"^ExecutionTime = " + NUMBER + r" s\s+ClockTime = " + NUMBER + " s", line)
            if m:
                self.execution_time, self.clock_time = float(m.group(1)), float(m.group(2))
            m = re.match(r"^dropletFiberCollision (\S+): parcels ", line)
            if m:
                stepped[m.group(1)] = time
            m = re.match(r"^    (parcel mass|fiber mass) .*\(balance " + NUMBER + r" kg\)", line)
            if m:
                what = {"parcel mass": "parcel mass = grid + outside",
                        "fiber mass": "fiber mass = added + captured - removed"}[m.group(1)]
                self.conservation[what] = float(m.group(2))
            m = re.match(r"^dropletFiberCollision \S+ spread populations at time (\S+) ", line)
            if m and i + 1 < len(lines):
                self.spread = _spread_figures(float(m.group(1)), lines[i + 1])
            if line.strip() == "End":
                self.ended = True
            m = re.match(r"^Cloud: (\S+)\s*$", line)
            if m:
                j = i + 1
                while j < len(lines) and lines[j].startswith(("    ", "   |")):
                    j += 1
                report = _cloud_report(lines[i + 1:j])
                if report["inSystem"] is not None:
                    report["time"] = time
                    report["timeName"] = time_name  # as the log writes it (for printing)
                    # the table row whose captured mass this report has lost already
                    report["functionObjectTimes"] = dict(stepped)
                    self.clouds[m.group(1)] = report
                    self.history.setdefault(m.group(1), []).append((time, report["introduced"]))
                i = j
                continue
            i += 1


def _spread_figures(time, line):
    """P57's figures from the line after the heading (None if it does not read)"""
    m = re.match(r"^\s+kernel sigma / h " + NUMBER + r" \(" + NUMBER + " to " + NUMBER + r"\); thin on their level "
                 + NUMBER + r", reaching \S+ other computed fibers " + NUMBER + r", capped " + NUMBER
                 + r"; clustering eps " + NUMBER, line)
    if not m:
        return None
    names = ("sigma", "sigmaMin", "sigmaMax", "thin", "reaching", "capped", "eps")
    figures = dict(zip(names, (float(v) for v in m.groups())))
    figures["time"] = time
    return figures


def sprayed_at(history, time):
    """The mass all clouds had introduced by their last report at or before time."""
    total = 0.0
    for reports in history.values():
        before = [introduced for t, introduced in reports if t is not None and t <= time * (1 + 1e-12)]
        total += before[-1] if before else 0.0
    return total
