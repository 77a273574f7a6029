"""Compare the averaging window of a serial run with the windows of a parallel
run's blocks (each processor keeps the window of the grid nodes it owns).

Usage: compareBlockWindows.py SERIAL_STATE PARALLEL_CASE STATE_PATH REL_TOL [--merged]

SERIAL_STATE is a restart state dictionary (<time>/uniform/dropletFiber/<name>)
with its <name>.gridWindow beside it (node values), or, when that holds the
deposit log, the node values written with writeWindowValues
(<name>.gridWindowValues, entry gridWindowValuesCounters); the parallel case's states are
PARALLEL_CASE/processor*/STATE_PATH, or with --merged the one state
PARALLEL_CASE/STATE_PATH that reconstructDropletFiberState merged from them. Checks: the blocks (entry gridBlock) are
disjoint and cover every node of the grid; the steps committed agree; per node,
the window total (sum of the slots) of the owning block equals the serial one to
REL_TOL times the largest magnitude of its quantity (of the momentum vector's
components for a momentum component). Exit 1 otherwise.
"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compareWindow import QUANTITIES, read  # noqa: E402


def entry(text, key):
    m = re.search(r"^%s\s+(?:\d+\s*)?\(([^)]*)\)" % key, text, re.M)
    return [int(float(v)) for v in m.group(1).split()] if m else None


def window_totals(state_path):
    """Per node (i, j, k): the window total; the block's box; committed steps."""
    text = open(state_path).read()
    counters = entry(text, "gridWindowCounters")
    values = None
    if counters[0] in (3, 4):
        # A deposit log: the node values are those written with writeWindowValues
        counters = entry(text, "gridWindowValuesCounters")
        if counters is None:
            raise SystemExit("FAILED: %s holds a deposit log and no node values"
                             " (run with writeWindowValues yes)" % state_path)
        values = read(state_path + ".gridWindowValues")
    else:
        values = read(state_path + ".gridWindow")
    nodes = counters[1:4]
    header = 8
    block = [0, 0, 0, nodes[0] - 1, nodes[1] - 1, nodes[2] - 1]
    if counters[0] == 2:
        block = counters[8:14]
        header = 14
    totals, position = {}, 0
    for s in range(counters[6]):
        lo = counters[header + 6 * s:header + 6 * s + 3]
        hi = counters[header + 6 * s + 3:header + 6 * s + 6]
        for k in range(lo[2], hi[2] + 1):
            for j in range(lo[1], hi[1] + 1):
                for i in range(lo[0], hi[0] + 1):
                    sums = totals.setdefault((i, j, k), [0.0] * QUANTITIES)
                    for q in range(QUANTITIES):
                        sums[q] += values[position + q]
                    position += QUANTITIES
    return totals, block, counters[7], nodes


def main():
    serial, case, path, tol = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    expected, _, committed, nodes = window_totals(serial)
    if sys.argv[5:] == ["--merged"]:
        states = [os.path.join(case, path)]
    else:
        states = sorted(glob.glob(os.path.join(case, "processor*", path)))
    owned, actual, failed = {}, {}, 0
    for state in states:
        totals, block, steps, _ = window_totals(state)
        if steps != committed:
            print("FAILED: %s committed %d steps, the serial run %d" % (state, steps, committed))
            failed += 1
        for k in range(block[2], block[5] + 1):
            for j in range(block[1], block[4] + 1):
                for i in range(block[0], block[3] + 1):
                    owned[(i, j, k)] = owned.get((i, j, k), 0) + 1
        actual.update(totals)
    all_nodes = nodes[0] * nodes[1] * nodes[2]
    if len(owned) != all_nodes or any(c != 1 for c in owned.values()):
        print("FAILED: the %d blocks do not tile the %d nodes" % (len(states), all_nodes))
        failed += 1
    # Per quantity its largest magnitude; the momentum's three components share one
    # (a component that is zero but for round-off, z in a 2D case, has no scale of its own)
    scale = [max([abs(v[q]) for v in expected.values()] or [0.0]) for q in range(QUANTITIES)]
    scale[4:7] = [max(scale[4:7])] * 3
    scale = [s or 1.0 for s in scale]
    worst = 0.0
    for node in set(expected) | set(actual):
        a = expected.get(node, [0.0] * QUANTITIES)
        b = actual.get(node, [0.0] * QUANTITIES)
        worst = max([worst] + [abs(x - y) / scale[q] for q, (x, y) in enumerate(zip(a, b))])
    print("%d blocks, largest difference %.3g of the quantity's scale (tolerance %g)" % (len(states), worst, tol))
    if worst > tol:
        failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
