#!/usr/bin/env python3
"""Extract the parcels of an OpenFOAM Lagrangian cloud at one write time into the
plain text format of gridTrafficBench (one file per processor):

    # x y z Ux Uy Uz d nParticle rho
    0.0281895 0.0572870 0.005 -0.12 -2.1 0 3.26e-05 714.2 1050

Reads <case>/[processorN/]<time>/lagrangian/<cloud>/{positions,U,d,nParticle,rho}
(ASCII; `positions` with Cartesian coordinates as v1912 writes them with
writeLagrangianPositions, i.e. "(x y z) celli").

Usage: foamParcels.py CASE TIME OUTPUT_PREFIX [--cloud kinematicCloud]
Writes OUTPUT_PREFIX<rank>.txt for every processor directory (rank = N), or
OUTPUT_PREFIX0.txt for a serial case, and prints the file names.
"""

import argparse
import glob
import os
import re
import sys


def read_list(path):
    """Values of an OpenFOAM ASCII list field: list of strings (one per entry)."""
    with open(path) as f:
        text = f.read()
    # skip the header (FoamFile dictionary) and comments
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    m = re.search(r"FoamFile\s*\{.*?\}", text, flags=re.S)
    if m:
        text = text[m.end():]
    m = re.search(r"(\d+)\s*\(", text)
    if not m:
        # uniform list "N{value}" or empty
        m2 = re.search(r"(\d+)\s*\{([^}]*)\}", text)
        if m2:
            return [m2.group(2).strip()] * int(m2.group(1))
        return []
    count = int(m.group(1))
    body = text[m.end():]
    entries = []
    if body.lstrip().startswith("("):
        for e in re.finditer(r"\(([^()]*)\)\s*(\d*)", body):
            entries.append(e.group(1))
            if len(entries) == count:
                break
    else:
        entries = body.split()[:count]
    if len(entries) != count:
        raise ValueError(f"{path}: expected {count} entries, read {len(entries)}")
    return entries


def convert(cloud_dir, out_path):
    positions = read_list(os.path.join(cloud_dir, "positions"))
    velocities = read_list(os.path.join(cloud_dir, "U"))
    diameters = read_list(os.path.join(cloud_dir, "d"))
    counts = read_list(os.path.join(cloud_dir, "nParticle"))
    densities = read_list(os.path.join(cloud_dir, "rho"))
    with open(out_path, "w") as f:
        f.write("# x y z Ux Uy Uz d nParticle rho\n")
        for p, u, d, n, r in zip(positions, velocities, diameters, counts, densities):
            f.write(f"{p} {u} {d} {n} {r}\n")
    return len(positions)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("case")
    parser.add_argument("time")
    parser.add_argument("prefix")
    parser.add_argument("--cloud", default="kinematicCloud")
    args = parser.parse_args()
    processors = sorted(glob.glob(os.path.join(args.case, "processor[0-9]*")),
                        key=lambda p: int(re.search(r"(\d+)$", p).group(1)))
    sources = []
    if processors:
        for p in processors:
            rank = int(re.search(r"(\d+)$", p).group(1))
            sources.append((rank, os.path.join(p, args.time, "lagrangian", args.cloud)))
    else:
        sources.append((0, os.path.join(args.case, args.time, "lagrangian", args.cloud)))
    for rank, cloud_dir in sources:
        out = f"{args.prefix}{rank}.txt"
        if not os.path.isdir(cloud_dir):
            # a processor without parcels at that time has no cloud directory
            with open(out, "w") as f:
                f.write("# x y z Ux Uy Uz d nParticle rho\n")
            print(f"{out}: 0 parcels (no {cloud_dir})")
            continue
        n = convert(cloud_dir, out)
        print(f"{out}: {n} parcels")
    return 0


if __name__ == "__main__":
    sys.exit(main())
