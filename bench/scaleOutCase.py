#!/usr/bin/env python3
"""The 3D scale-out case of bench/scaleOut.sh, and the figures of its runs.

  scaleOutCase.py case DIR --nodes N --steps S --ranks P [--localised]
                     [--holders cells|roundRobin] [--blocks subdomains|balanced]
      DIR holds a copy of tutorials/channelSpray; it is made 3D in place:
      - mesh 25 x 75 x 10 cells over 5 x 15 x DEPTH cm, the front and back
        faces walls (no empty patch), the spray nozzles and fiber injectors
        at mid-depth and spread across it;
      - the density grid over the whole channel with one spacing h chosen so
        that the grid has about N nodes;
      - FIBER_STREAMS injectors at a high rate (several hundred fibers within
        the run) at three heights, so that fibers cross the processors' cuts, S steps of the tutorial's time step, no write time (no
        restart state, no VTK files: the bench measures the steps);
      - system/decomposeParDict for P subdomains (simple, split along the
        channel's length).
      --localised: the spray and the fibers near the top only, as nozzles and
        spinner streams occupy a few processors' subdomains of a hood: the
        three nozzles 4-10 mm below the top aiming 5 degrees below the
        horizontal (the droplets reach the far wall within ~1.5 cm of the
        top), all 12 fiber streams at 3 mm below the top (4 across x 3
        across the depth; they fall ~3 cm in 30 steps). Spray and fibers then
        occupy the top ~3 cm of the 15 cm channel, within the top slab at 4
        processors.
      --holders: the function object's fibers.holders (default: its own,
        cells).
      --blocks: the function object's grid.blocks (default: its own,
        subdomains); balanced re-partitions every --balance-steps steps
        (grid.balanceSteps, default 5: after step 5, before the steps
        measured).
      Prints the grid's node count.

  scaleOutCase.py estimate [--nodes 250 250 150] [--window 10] [--fibers 5000]
                           [--points 50] [--ranks 64 1024] [--box 1]
      Memory and bytes sent per step of the busiest processor with the grid and
      fibers replicated (the design before grid blocks): the formulas of
      docs/scaleOut.md, with Pstream's tree schedule (the one used: the
      optimisation switch nProcsSimpleSum is 0). --box: the fraction of the
      grid inside the union of the boxes the processors' parcels touch.

  scaleOutCase.py report DIR --ranks P --nodes M [--skip K]
      Reads the run in DIR (postProcessing/dropletFiber/0/dropletFiber.dat,
      .../parallelStatistics.dat, the per-rank peak RSS files rss.<rank> of
      GNU time in KiB) and prints the bench's line. depositMsPerStep is the
      mean of the table's wallTimeDeposition (the master's wall time of
      gathering, depositing and summing across processors) over the steps
      after the first K; the other figures are maxima over processors and
      steps. From the work columns, over the steps after the first K:
      depositImbalance and fiberImbalance, the sum over steps of the
      maximum over processors of the stage's thread CPU time divided by the
      sum of its mean (1 is even); couplingCpuMsPerStep, the mean over steps
      of the sum of the three stages' maxima (the busiest processor's CPU
      time of the coupling's computing, an upper bound when different
      processors are the busiest in different stages).
"""

import argparse
import glob
import os
import re
import sys

LENGTH = (0.05, 0.15)  # the tutorial's channel, x and y [m]
DEPTH = 0.02  # z [m]: 10 cells of 2 mm, like the tutorial's cells in x and y
CELLS = (25, 75, 10)
FIBER_STREAMS = 12  # 4 across the channel x 3 heights
FIBER_RATE = 2400  # fibers per second per stream: ~430 fibers after 30 steps
DELTA_T = 5e-4  # the tutorial's time step [s]


def replace(text, pattern, new, count=1):
    result, n = re.subn(pattern, new, text, flags=re.S)
    if n != count:
        raise SystemExit(f"scaleOutCase: pattern {pattern!r} found {n} times, expected {count}")
    return result


def edit(path, *substitutions):
    with open(path) as f:
        text = f.read()
    for substitution in substitutions:
        text = replace(text, *substitution)
    with open(path, "w") as f:
        f.write(text)


def grid_nodes(target):
    """Nodes per direction for one spacing h giving about target nodes."""
    extent = (LENGTH[0], LENGTH[1], DEPTH)
    volume = extent[0] * extent[1] * extent[2]
    h = (volume / target) ** (1.0 / 3.0)
    for _ in range(50):  # the + 1 per direction: iterate h
        nodes = [max(2, round(e / h) + 1) for e in extent]
        count = nodes[0] * nodes[1] * nodes[2]
        h *= (count / target) ** (1.0 / 3.0)
    return [max(2, round(e / h) + 1) for e in extent]


def make_mesh_3d(case):
    edit(
        os.path.join(case, "system", "blockMeshDict"),
        (r"0\.01\)", f"{DEPTH})", 4),
        (r"\(25 75 1\)", "({} {} {})".format(*CELLS)),
        (r"faces \(\(0 4 7 3\) \(1 2 6 5\)\);", "faces ((0 4 7 3) (1 2 6 5) (0 3 2 1) (4 5 6 7));"),
        (r"\s*frontAndBack\s*\{\s*type empty;\s*faces[^;]*;\s*\}", ""),
    )
    for field in ("U", "p"):
        edit(os.path.join(case, "0.orig", field), (r"\s*frontAndBack\s*\{\s*type\s+empty;\s*\}", ""))
    # The nozzles at mid-depth (they were at mid-thickness of the 2D case)
    edit(os.path.join(case, "constant", "kinematicCloudProperties"),
         (r"\(0\.049 0\.140 0\.005\)", f"(0.049 0.140 {DEPTH / 2})"),
         (r"\(0\.049 0\.130 0\.005\)", f"(0.049 0.130 {DEPTH / 2})"),
         (r"\(0\.049 0\.120 0\.005\)", f"(0.049 0.120 {DEPTH / 2})"))


def fiber_injectors(localised=False):
    # Streams at three heights: the fibers fall ~3 cm in 30 steps, so those of the
    # lower two heights cross the cuts between the processors' slabs (y = 3.75, 7.5,
    # 11.25 cm on 4; 7.5 cm on 2) and each slab holds some of them. Localised: all
    # at the top, three across the depth instead
    lines = []
    for i, x in enumerate((0.01, 0.02, 0.03, 0.04)):
        for k, y in enumerate((0.147, 0.10, 0.06)):
            position = (x, y, 0.5 * DEPTH) if not localised else (x, 0.147, (0.25 + 0.25 * k) * DEPTH)
            lines += [
                f"                s{i}{k}",
                "                {",
                "                    position    ({} {} {});".format(*position),
                f"                    direction   (1 0.3 {0.2 * (i % 2)});",
                "                    velocity    (0 -2 0);",
                "                    length      0.008;",
                f"                    rate        {FIBER_RATE};",
                "                }",
            ]
    return "\n".join(lines)


def set_controls(case, nodes, steps, localised=False):
    end_time = steps * DELTA_T
    edit(
        os.path.join(case, "system", "controlDict"),
        (r"endTime         0\.4;[^\n]*", f"endTime         {end_time:.6g};"),
        (r"#sinclude       \"controlDict\.short\"", ""),
        # No write time within the run: no restart state of a 4e6-node window
        (r"writeControl    runTime;", "writeControl    timeStep;"),
        (r"writeInterval   0\.04;[^\n]*", "writeInterval   1000000;"),
        (r"upper           \(0\.05 0\.15 0\.01\);\s*spacing         1e-3;",
         "upper           (0.05 0.15 {});\n            nodes           ({} {} {});".format(DEPTH, *nodes)),
        (r"injectors\s*\{.*?\n            \}\n", "injectors\n            {\n" + fiber_injectors(localised) + "\n            }\n"),
        (r"writeVtk        true;", "writeVtk        false;"),
        (r"writeGridVtk    true;", "writeGridVtk    false;"),
    )


def set_decomposition(case, ranks):
    edit(
        os.path.join(case, "system", "decomposeParDict"),
        (r"numberOfSubdomains 2;", f"numberOfSubdomains {ranks};"),
        (r"n           \(1 2 1\);", f"n           (1 {ranks} 1);"),
    )


def localise_spray(case):
    # The nozzles 4, 7 and 10 mm below the top, aiming 5 degrees down
    edit(os.path.join(case, "constant", "kinematicCloudProperties"),
         (r"\(0\.049 0\.140 ", "(0.049 0.146 "),
         (r"\(0\.049 0\.130 ", "(0.049 0.143 "),
         (r"\(0\.049 0\.120 ", "(0.049 0.140 "),
         (r"direction       \(-0\.9659 -0\.2588 0\);", "direction       (-0.9962 -0.0872 0);"),
         (r"direction       \(-0\.8660 -0\.5 0\);", "direction       (-0.9962 -0.0872 0);"),
         (r"direction       \(-0\.7071 -0\.7071 0\);", "direction       (-0.9962 -0.0872 0);"))


def make_case(args):
    nodes = grid_nodes(args.nodes)
    make_mesh_3d(args.dir)
    if args.localised:
        localise_spray(args.dir)
    set_controls(args.dir, nodes, args.steps, args.localised)
    if args.samples_per_segment > 0:
        # Collision samples fixed per segment instead of one per grid spacing
        edit(os.path.join(args.dir, "system", "controlDict"),
             (r"sampling        integrated;",
              f"sampling        integrated;\n            samplesPerSegment {args.samples_per_segment};"))
    if args.holders:
        edit(os.path.join(args.dir, "system", "controlDict"),
             (r"(\n            drag            [^\n]*\n)", f"\\1            holders         {args.holders};\n"))
    if args.blocks:
        edit(os.path.join(args.dir, "system", "controlDict"),
             (r"(\n            nodes           [^\n]*\n)",
              f"\\1            blocks          {args.blocks};\n            balanceSteps    {args.balance_steps};\n"))
    set_decomposition(args.dir, args.ranks)
    print(nodes[0] * nodes[1] * nodes[2])
    return 0


def read_table(path):
    # The function object's tables, read as bench/tutorialShare.py reads them
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from tutorialShare import read_table as read_tables

    _, rows = read_tables([path])
    if not rows:
        raise SystemExit(f"scaleOutCase: no rows in {path}")
    return rows


def report(args):
    out = os.path.join(args.dir, "postProcessing", "dropletFiber", "0")
    table = read_table(os.path.join(out, "dropletFiber.dat"))
    statistics_path = os.path.join(out, "parallelStatistics.dat")
    if os.path.exists(statistics_path):
        statistics = read_table(statistics_path)
    elif args.ranks == 1:
        # A serial run writes no parallelStatistics.dat: one processor holds the whole
        # grid and every fiber, and sends nothing
        statistics = [
            {"nodesHeldMax": float(args.nodes), "fibersHeldMax": r["fibers"], "bytesSentMax": 0.0,
             "bytesParcelsMax": 0.0, "bytesGridQueriesMax": 0.0, "bytesFibersMax": 0.0}
            for r in table
        ]
    else:
        raise SystemExit(f"scaleOutCase: no {statistics_path} in a run on {args.ranks} processors")
    rss_files = sorted(glob.glob(os.path.join(args.dir, "rss.*")))
    if len(rss_files) != args.ranks:
        raise SystemExit(f"scaleOutCase: {len(rss_files)} peak-RSS files in {args.dir}, expected {args.ranks}")
    rss_kib = []
    for path in rss_files:
        with open(path) as f:
            numbers = [int(w) for w in f.read().split() if w.isdigit()]
        if not numbers:
            raise SystemExit(f"scaleOutCase: no peak RSS in {path}")
        rss_kib.append(numbers[-1])
    timed = table[args.skip:] if len(table) > args.skip else table
    deposit_ms = 1e3 * sum(r["wallTimeDeposition"] for r in timed) / len(timed)
    work = statistics[args.skip:] if len(statistics) > args.skip else statistics
    print(
        f"ranks={args.ranks} nodes={args.nodes}"
        f" nodesHeldMax={max(r['nodesHeldMax'] for r in statistics):.0f}"
        f" peakRssMaxMiB={max(rss_kib) / 1024:.0f}"
        f" bytesSentPerStepMax={max(r['bytesSentMax'] for r in statistics):.0f}"
        f" fibersHeldMax={max(r['fibersHeldMax'] for r in statistics):.0f}"
        f" (bytes per step max: parcels={max(r['bytesParcelsMax'] for r in statistics):.0f}"
        f" gridQueries={max(r['bytesGridQueriesMax'] for r in statistics):.0f}"
        f" fibers={max(r['bytesFibersMax'] for r in statistics):.0f})"
        f" depositMsPerStep={deposit_ms:.1f}"
        f"{work_figures(work)}"
    )
    if args.balance_steps > 0 and statistics and "cpuDepositMax" in statistics[0]:
        print(f"#   deposit by phase (step numbers from 1):{phase_figures(statistics, args.balance_steps)}")
    return 0


def phase_figures(rows, balance_steps):
    """The deposit's max / mean and the busiest processor's thread CPU ms per step in the
    window's fill (steps 6-10), the steady steps (11 on, but the re-partition steps: every
    balance_steps-th, which weigh the work and may move the window), those after the first
    weighing, those of the run's second half (the spray developed: on the localised case
    its parcels per step level off after ~140 steps), and the re-partition steps; and the
    coupling's (three stages' maxima) ms per steady and developed step."""
    stages = ("cpuDeposit", "cpuCollision", "cpuFibers")
    phases = {"fill": [r for i, r in enumerate(rows) if 6 <= i + 1 <= 10],
              "steady": [r for i, r in enumerate(rows) if i + 1 > 10 and (i + 1) % balance_steps],
              "steadyAfterFirstWeighing": [r for i, r in enumerate(rows)
                                           if i + 1 > max(10, balance_steps) and (i + 1) % balance_steps],
              "developed": [r for i, r in enumerate(rows)
                            if i + 1 > len(rows) // 2 and (i + 1) % balance_steps],
              "repartition": [r for i, r in enumerate(rows) if i + 1 > 5 and (i + 1) % balance_steps == 0]}
    out = ""
    for name, chosen in phases.items():
        if not chosen:
            continue
        ms = 1e3 * sum(r["cpuDepositMax"] for r in chosen) / len(chosen)
        out += f" {name} max/mean={imbalance(chosen, 'cpuDeposit'):.2f} maxMs={ms:.2f}"
        if name.startswith("steady") or name == "developed":
            coupling = 1e3 * sum(sum(r[s + "Max"] for s in stages) for r in chosen) / len(chosen)
            weights = sum(r["nodeWeightsMax"] for r in chosen) / len(chosen)
            out += (f" couplingMs={coupling:.2f} nodeWeightsMax={weights:.0f}"
                    f" nodeWeights max/mean={imbalance(chosen, 'nodeWeights'):.2f};")
    return out


def imbalance(rows, figure):
    mean = sum(r[figure + "Mean"] for r in rows)
    return sum(r[figure + "Max"] for r in rows) / mean if mean > 0 else 1.0


def work_figures(rows):
    """The bench line's work part (empty for tables written before the work columns)."""
    if not rows or "cpuDepositMax" not in rows[0]:
        return ""
    stages = ("cpuDeposit", "cpuCollision", "cpuFibers")
    coupling_ms = 1e3 * sum(sum(r[s + "Max"] for s in stages) for r in rows) / len(rows)
    per_step = {f: sum(r[f + "Max"] for r in rows) / len(rows) for f in ("parcels", "parcelCopies", "nodeWeights")}
    return (f" depositImbalance={imbalance(rows, 'cpuDeposit'):.2f}"
            f" fiberImbalance={imbalance(rows, 'cpuFibers'):.2f}"
            f" collisionImbalance={imbalance(rows, 'cpuCollision'):.2f}"
            f" couplingCpuMsPerStep={coupling_ms:.1f}"
            f" (per step max: cpuDepositMs={1e3 * sum(r['cpuDepositMax'] for r in rows) / len(rows):.1f}"
            f" cpuCollisionMs={1e3 * sum(r['cpuCollisionMax'] for r in rows) / len(rows):.1f}"
            f" cpuFibersMs={1e3 * sum(r['cpuFibersMax'] for r in rows) / len(rows):.1f}"
            f" parcels={per_step['parcels']:.0f} parcelCopies={per_step['parcelCopies']:.0f}"
            f" nodeWeights={per_step['nodeWeights']:.0f};"
            f" max/mean parcels={imbalance(rows, 'parcels'):.2f}"
            f" nodeWeights={imbalance(rows, 'nodeWeights'):.2f}"
            f" fiberPoints={imbalance(rows, 'fiberPoints'):.2f})")


QUANTITIES = 7  # doubles per node and slot (src/core/grid/GridQuantities.hpp)


def tree_schedule(ranks):
    """Pstream's tree (UPstream.C): each processor's neighbours below and above."""
    above, below = [-1] * ranks, [[] for _ in range(ranks)]
    for proc in range(ranks):
        step = 1
        while step < ranks:
            mod = 2 * step
            if proc % mod:
                above[proc] = proc - proc % mod
                break
            below[proc] += [j for j in range(proc + step, min(ranks, proc + mod), step)]
            step = mod
    return above, below


def subtree_sizes(below):
    sizes = [1] * len(below)
    for proc in reversed(range(len(below))):  # children have higher numbers
        sizes[proc] += sum(sizes[c] for c in below[proc])
    return sizes


def busiest_bytes(ranks, grid_bytes, air_bytes, fiber_bytes):
    """Bytes sent in one step by the processor that sends most, and who it is."""
    above, below = tree_schedule(ranks)
    sizes = subtree_sizes(below)
    best = (0.0, 0)
    for proc in range(ranks):
        messages = (above[proc] >= 0) + len(below[proc])
        combined = messages * (grid_bytes + air_bytes)  # listCombineGather + Scatter
        listed = (sizes[proc] * fiber_bytes / ranks if above[proc] >= 0 else 0.0) + sum(
            (ranks - sizes[c]) * fiber_bytes / ranks for c in below[proc]
        )  # gatherList + scatterList of the fiber states, fibers spread evenly
        best = max(best, (combined + listed, proc))
    return best


def estimate(args):
    nodes = args.nodes[0] * args.nodes[1] * args.nodes[2]
    points = args.fibers * args.points
    fiber_doubles = args.fibers * (6 * args.points + 3 * (args.points - 1))
    grid_bytes = 8 * QUANTITIES * nodes * args.box
    air_bytes = 8 * 6 * points
    # Grid: step accumulator, window total and W slots (7 doubles per node each), and
    # the total's step stamp; the packed step box and one receive buffer in the sum;
    # every fiber's state and its copy in the exchange; the air sample and its sum
    memory = (nodes * (8 * QUANTITIES * (args.window + 2) + 8) + 2 * grid_bytes
              + 2 * 8 * fiber_doubles + 2 * air_bytes)
    print(f"grid {nodes} nodes, window {args.window}, {args.fibers} fibers of {args.points} points, "
          f"box {args.box:g} of the grid")
    for ranks in args.ranks:
        sent, proc = busiest_bytes(ranks, grid_bytes, air_bytes, 8 * fiber_doubles)
        print(f"ranks={ranks} memoryPerProcessorGB={memory / 1e9:.2f} "
              f"bytesSentPerStepMaxGB={sent / 1e9:.2f} (processor {proc})")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    c = sub.add_parser("case")
    c.add_argument("dir")
    c.add_argument("--nodes", type=float, required=True)
    c.add_argument("--steps", type=int, required=True)
    c.add_argument("--ranks", type=int, required=True)
    c.add_argument("--samples-per-segment", type=int, default=0)
    c.add_argument("--localised", action="store_true")
    c.add_argument("--holders", choices=("cells", "roundRobin"))
    c.add_argument("--blocks", choices=("subdomains", "balanced"))
    c.add_argument("--balance-steps", type=int, default=5)
    r = sub.add_parser("report")
    r.add_argument("dir")
    r.add_argument("--ranks", type=int, required=True)
    r.add_argument("--nodes", type=int, required=True)
    r.add_argument("--skip", type=int, default=5)
    r.add_argument("--balance-steps", type=int, default=0,
                   help="print the deposit by phase: fill, steady, re-partition steps (0: not)")
    e = sub.add_parser("estimate")
    e.add_argument("--nodes", type=int, nargs=3, default=[250, 250, 150])
    e.add_argument("--window", type=int, default=10)
    e.add_argument("--fibers", type=int, default=5000)
    e.add_argument("--points", type=int, default=50)
    e.add_argument("--ranks", type=int, nargs="+", default=[64, 1024])
    e.add_argument("--box", type=float, default=1.0)
    args = parser.parse_args()
    return {"case": make_case, "report": report, "estimate": estimate}[args.command](args)


if __name__ == "__main__":
    sys.exit(main())
