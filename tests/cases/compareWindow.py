"""Compare two averaging windows of dropletFiber restart states (the binary
OpenFOAM scalar lists <name>.gridWindow, or <name>.gridWindowValues written with
writeWindowValues) value by value.

Usage: compareWindow.py A B REL_TOL

The layout comes from the state dictionary beside each list (<name>: entry
gridWindowCounters, or gridWindowValuesCounters for .gridWindowValues):
node values (formats 1, 2: 7 quantities per node: mass, count, radius sums,
momentum x y z) agree when they differ by at most REL_TOL times the largest
magnitude of their quantity; a deposit log (formats 3, 4: per step the runs
(dt, parcels) and the parcels' 9 values) must have the same counters, and its
values agree to REL_TOL times the largest magnitude of their field (dt, count,
position x y z, velocity (its three components together), diameter, nParticle,
rhoDroplet).
Prints the largest difference; exit 1 when the lists differ beyond it.
"""
import os
import re
import struct
import sys

QUANTITIES = 7
PARCEL_VALUES = 9


def read(path):
    data = open(path, "rb").read()
    head = re.match(rb"\s*(\d+)\s*\(", data)
    if head is None and re.fullmatch(rb"\s*0\s*", data):
        return ()  # an empty list (a processor without window nodes): "0"
    count = int(head.group(1))
    return struct.unpack("<%dd" % count, data[head.end():head.end() + 8 * count])


def counters_of(path):
    """The counters of the list at path, from the state dictionary beside it."""
    state, extension = os.path.splitext(path)
    key = "gridWindowValuesCounters" if extension == ".gridWindowValues" else "gridWindowCounters"
    text = open(state).read()
    m = re.search(r"^%s\s+(?:\d+\s*)?\(([^)]*)\)" % key, text, re.M)
    if not m:
        m = re.search(r"^%s\s+(\d+)\s*\{\s*([^}]*)\}" % key, text, re.M)
        return [int(float(m.group(2)))] * int(m.group(1)) if m else None
    return [int(float(v)) for v in m.group(1).split()]


def log_fields(counters, count):
    """Per value of a deposit log: its field (0 dt, 1 count, 2.. the parcel's values)."""
    header = 14 if counters[0] == 4 else 8
    fields = []
    for s in range(counters[6]):
        parcels, runs = counters[header + 2 * s], counters[header + 2 * s + 1]
        fields += [0, 1] * runs + list(range(2, 2 + PARCEL_VALUES)) * parcels
    return fields if len(fields) == count else None


def main():
    a, b, tol = read(sys.argv[1]), read(sys.argv[2]), float(sys.argv[3])
    ca, cb = counters_of(sys.argv[1]), counters_of(sys.argv[2])
    if len(a) != len(b):
        print("FAILED: %d values against %d" % (len(a), len(b)))
        return 1
    if ca is not None and ca[0] in (3, 4):
        if ca != cb:
            print("FAILED: the deposit logs' counters differ (steps, parcels, runs)")
            return 1
        fields = log_fields(ca, len(a))
        if fields is None:
            print("FAILED: the deposit log's values do not match its counters")
            return 1
        what = "deposit log"
    else:
        fields = [i % QUANTITIES for i in range(len(a))]
        what = "averaging window"
    groups = max(fields or [0]) + 1
    scale = [0.0] * groups
    for f, v in zip(fields, a):
        scale[f] = max(scale[f], abs(v))
    if what == "deposit log" and len(scale) >= 8:
        # a velocity's components against the velocity's scale: a component
        # near zero (a fall along y) differs at round-off of the others
        scale[5:8] = [max(scale[5:8])] * 3
    scale = [s or 1.0 for s in scale]
    worst = max([abs(x - y) / scale[f] for f, x, y in zip(fields, a, b)] or [0.0])
    print("%s: %d values, largest difference %.3g of the field's scale" % (what, len(a), worst))
    return 0 if worst <= tol else 1


if __name__ == "__main__":
    sys.exit(main())
