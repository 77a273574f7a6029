"""Compare two averaging windows of dropletFiber restart states (the binary
OpenFOAM scalar lists <name>.gridWindow) value by value.

Usage: compareWindow.py A B REL_TOL

Values agree when they differ by at most REL_TOL times the largest magnitude of
their quantity (7 per node: mass, count, radius sums, momentum x y z).
Prints the largest difference; exit 1 when the lists differ beyond it.
"""
import re
import struct
import sys

QUANTITIES = 7


def read(path):
    data = open(path, "rb").read()
    head = re.match(rb"\s*(\d+)\s*\(", data)
    count = int(head.group(1))
    return struct.unpack("<%dd" % count, data[head.end():head.end() + 8 * count])


def main():
    a, b, tol = read(sys.argv[1]), read(sys.argv[2]), float(sys.argv[3])
    if len(a) != len(b):
        print("FAILED: %d values against %d" % (len(a), len(b)))
        return 1
    scale = [max([abs(v) for v in a[q::QUANTITIES]] or [0.0]) or 1.0 for q in range(QUANTITIES)]
    worst = max([abs(x - y) / scale[i % QUANTITIES] for i, (x, y) in enumerate(zip(a, b))] or [0.0])
    print("averaging window: %d values, largest difference %.3g of the quantity's scale" % (len(a), worst))
    return 0 if worst <= tol else 1


if __name__ == "__main__":
    sys.exit(main())
