"""Where a case's dropletFiber outputs are, and its per-step tables read by column name.

The function object writes postProcessing/<name>/<startTime>/ (one folder per run
start: a restarted case has several) with dropletFiber.dat and its sibling tables
(fiberDispersion.dat, parallelStatistics.dat, binderDistribution.dat, ...), and the
VTK files. A decomposed case writes them in the case folder as well (the master
writes), so an unreconstructed case reads the same way.
"""
import glob
import math
import os
import re


class MissingOutput(Exception):
    """What a case lacks for the report, in words for the user."""


def _number(text):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def application(case):
    """The solver named in system/controlDict, or None."""
    path = os.path.join(case, "system", "controlDict")
    if not os.path.isfile(path):
        return None
    m = re.search(r"^\s*application\s+([^\s;]+)\s*;", open(path, errors="replace").read(), re.M)
    return m.group(1) if m else None


def solver_log(case):
    """log.<application> (as OpenFOAM's RunFunctions name it), else a single log.*Foam."""
    app = application(case)
    if app and os.path.isfile(os.path.join(case, "log." + app)):
        return os.path.join(case, "log." + app)
    logs = sorted(glob.glob(os.path.join(case, "log.*Foam")))
    return logs[0] if len(logs) == 1 else None


def function_object_names(case):
    """Names of the folders in postProcessing that hold a dropletFiber.dat."""
    found = glob.glob(os.path.join(case, "postProcessing", "*", "*", "dropletFiber.dat"))
    return sorted({os.path.basename(os.path.dirname(os.path.dirname(p))) for p in found})


def start_folders(case, name):
    """postProcessing/<name>/<startTime> folders in time order."""
    base = os.path.join(case, "postProcessing", name)
    folders = [(t, os.path.join(base, d)) for d in os.listdir(base)
               if (t := _number(d)) is not None and os.path.isdir(os.path.join(base, d))]
    return [path for _, path in sorted(folders)]


def processor_count(case):
    return len(glob.glob(os.path.join(case, "processor[0-9]*")))


def time_folders(folder):
    """The time folders' names in a case or processor folder (0 and constant aside)."""
    if not os.path.isdir(folder):
        return set()
    return {d for d in os.listdir(folder) if (t := _number(d)) is not None and t != 0
            and os.path.isdir(os.path.join(folder, d))}


def reconstructed(case):
    """Whether every time of processor0 is also in the case folder."""
    return time_folders(os.path.join(case, "processor0")) <= time_folders(case)


class Table:
    """A postProcessing table: names from the last comment line (tab separated),
    rows as dicts by name. A last row shorter than the header (a run stopped while
    writing it) is dropped and noted."""

    def __init__(self, names, rows, notes):
        self.names, self.rows, self.notes = names, rows, notes

    def has(self, column):
        return column in self.names

    def column(self, name):
        return [r[name] for r in self.rows]

    def last(self):
        return self.rows[-1]


def _read_one(path):
    names, rows, notes = [], [], []
    with open(path, errors="replace") as f:
        lines = f.read().split("\n")
    for number, line in enumerate(lines):
        if line.startswith("#"):
            names = [c.strip() for c in line[1:].split("\t") if c.strip()]
            continue
        if not line.strip():
            continue
        values = [_number(v) for v in line.split()]
        if len(values) != len(names) or None in values:
            notes.append("%s: line %d has %d of %d values (the run stopped while writing it?): left out"
                         % (path, number + 1, len(values), len(names)))
            continue
        rows.append(dict(zip(names, values)))
    return names, rows, notes


def read_table(case, name, file_name):
    """The table file_name of every start folder of the function object, joined in
    time order (a later start's rows replace the earlier's from its first time on);
    None when no start folder has it."""
    names, rows, notes = [], [], []
    for folder in start_folders(case, name):
        path = os.path.join(folder, file_name)
        if not os.path.isfile(path):
            continue
        these_names, these_rows, these_notes = _read_one(path)
        notes += these_notes
        if these_rows:
            first = these_rows[0]["Time"]
            rows = [r for r in rows if r["Time"] < first] + these_rows
        names = names + [n for n in these_names if n not in names]
    if not names:
        return None
    return Table(names, rows, notes)


def patch_types(case):
    """{patch: type} of the mesh (constant/polyMesh/boundary, or processor0's in a
    decomposed case); {} when unreadable."""
    for folder in (case, os.path.join(case, "processor0")):
        path = os.path.join(folder, "constant", "polyMesh", "boundary")
        if os.path.isfile(path):
            text = open(path, errors="replace").read()
            return dict(re.findall(r"(\w+)\s*\{[^{}]*?\btype\s+(\w+)\s*;", text))
    return {}


def latest_mat_profile(case, name):
    """The last matProfile_<time>.dat of the function object (the mat across the width
    over its complete rows, with errors): {"time", "notes": its comment lines, and its
    columns by name as lists}; None when there is none (no belt, or no complete row)."""
    found = []
    for folder in start_folders(case, name):
        for entry in os.listdir(folder):
            m = re.match(r"^matProfile_([-+0-9.eE]+)\.dat$", entry)
            if m:
                found.append((float(m.group(1)), os.path.join(folder, entry)))
    if not found:
        return None
    time, path = max(found)
    comments = [line[1:].strip() for line in open(path) if line.startswith("#")]
    names, rows, _ = _read_one(path)
    if not rows:
        return None
    profile = {"time": time, "notes": comments[:-1]}
    for n in names:
        profile[n] = [r[n] for r in rows]
    return profile
