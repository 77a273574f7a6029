#!/usr/bin/env python3
"""The gas the veil entrains: the vertical gas velocity across the hood through the
veil (y = 1.0 m) and below it (y = 0.6 m), from the sets function object veilAir
(postProcessing/veilAir/<time>/<set>_U.xy, x and U along z = 0), averaged over the
write times from FROM s on (the last write time when the run ended before FROM, as
Allrun -short does); with a second case (the same run one-way, or two-way)
both, and their difference: what the fibers' drag does to the gas.

Figures per line: the mean downward speed -U_y in the veil's ring, 0.10 m <= |x| <=
0.25 m from the spinner's axis (where half of the fibers' points lie), at the axis
(|x| <= 0.05 m) and outside the ring (0.3 m <= |x| <= 0.45 m).

The write times' folders are listed by the project's report package (caseOutputs;
found by reportPackage.py).

Usage: hoodVeilAir.py CASE [OTHER_CASE] [-from T]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reportPackage  # noqa: E402,F401  (the report's modules on the import path)
import caseOutputs  # noqa: E402

SETS = (("throughVeil", "y = 1.0 m"), ("belowVeil", "y = 0.6 m"))
BANDS = (("axis", 0.0, 0.05), ("veil ring", 0.10, 0.25), ("outside", 0.30, 0.45))


def write_times(case, name):
    """(time, file) of every write time with the set's file, in time order."""
    if not os.path.isdir(os.path.join(case, "postProcessing", "veilAir")):
        return []
    found = [(float(os.path.basename(folder)), os.path.join(folder, name + "_U.xy"))
             for folder in caseOutputs.start_folders(case, "veilAir")]
    return [(t, path) for t, path in found if os.path.isfile(path)]


def profiles(case, name, start):
    """x and the mean of U_y over the write times >= start, else the last one
    (None: no files)."""
    found = write_times(case, name)
    if not found:
        return None, None
    files = [f for t, f in found if t >= start - 1e-9] or [found[-1][1]]
    data = [np.loadtxt(f) for f in files]
    return data[0][:, 0], np.mean([d[:, 2] for d in data], axis=0)


def band_means(x, uy):
    return [float(-np.mean(uy[(abs(x) >= lo - 1e-9) & (abs(x) <= hi + 1e-9)])) for _, lo, hi in BANDS]


def main():
    args = sys.argv[1:]
    start = 0.3
    if "-from" in args:
        i = args.index("-from")
        start = float(args[i + 1])
        del args[i:i + 2]
    if not 1 <= len(args) <= 2:
        print(__doc__)
        return 1
    print("Downward gas speed -U_y [m/s], mean over the write times from %g s (veilAir)" % start)
    print("%-14s %-10s %-34s" % ("line", "case", "  ".join("%10s" % b[0] for b in BANDS)))
    for name, where in SETS:
        means = []
        for case in args:
            x, uy = profiles(case, name, start)
            if x is None:
                print("%s: no veilAir files of %s" % (case, name))
                return 1
            means.append(band_means(x, uy))
            print("%-14s %-10s %s" % (where, os.path.basename(os.path.abspath(case))[:10],
                                      "  ".join("%10.3f" % m for m in means[-1])))
        if len(means) == 2:
            print("%-14s %-10s %s" % (where, "difference", "  ".join(
                "%10.3f" % (a - b) for a, b in zip(means[0], means[1]))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
