#!/usr/bin/env python3
"""Write a parcel CSV for the dropletGrid tool (x,y,z,ux,uy,uz,d,nParticle,rhoDroplet).

Parcels are uniform at random in a box, moving with a common velocity plus a random
part, with random diameters and droplet counts. Every parcel's path during the step,
from position - velocity*dt to position, lies inside the box given (so, for a grid box
that contains it, the whole mass must end up on the grid).

Usage: generateParcels.py OUT.csv [--count N] [--seed S] [--lower X,Y,Z] [--upper X,Y,Z]
                          [--dt DT] [--velocity UX,UY,UZ] [--spread U]
Prints the total droplet mass n * rho * 4/3 pi (d/2)^3 of the file, in kg.
Standard library only.
"""
import argparse
import math
import random


def parcel_mass(d, n, rho):
    return n * rho * 4.0 / 3.0 * math.pi * (0.5 * d) ** 3


def generate(path, count, seed=1, lower=(0.0, 0.0, 0.0), upper=(0.05, 0.07, 0.001), dt=1e-4,
             velocity=(0.0, -5.0, 0.0), spread=1.0):
    """Write `count` parcels to `path`; return their total mass (kg)."""
    rng = random.Random(seed)
    total = 0.0
    with open(path, "w") as out:
        out.write("x,y,z,ux,uy,uz,d,nParticle,rhoDroplet\n")
        for _ in range(count):
            u = [velocity[k] + spread * (2.0 * rng.random() - 1.0) for k in range(3)]
            for k in range(3):
                if upper[k] - lower[k] < 2.0 * abs(u[k]) * dt:
                    u[k] = 0.0  # a thin slab (2D depth): keep the path inside it
            # End position such that the start (end - u dt) is inside the box too.
            p = []
            for k in range(3):
                lo = lower[k] + max(0.0, u[k] * dt)
                hi = upper[k] + min(0.0, u[k] * dt)
                p.append(lo + (hi - lo) * rng.random())
            d = 1e-5 + 9e-5 * rng.random()
            n = float(rng.randint(1, 2000))
            rho = 1000.0
            total += parcel_mass(d, n, rho)
            out.write("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n" % (*p, *u, d, n, rho))
    return total


def _vector(text):
    values = [float(v) for v in text.split(",")]
    if len(values) != 3:
        raise argparse.ArgumentTypeError("expected X,Y,Z")
    return tuple(values)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--count", type=int, default=100000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--lower", type=_vector, default=(0.0, 0.0, 0.0))
    parser.add_argument("--upper", type=_vector, default=(0.05, 0.07, 0.001))
    parser.add_argument("--dt", type=float, default=1e-4)
    parser.add_argument("--velocity", type=_vector, default=(0.0, -5.0, 0.0))
    parser.add_argument("--spread", type=float, default=1.0)
    a = parser.parse_args()
    print("%.17g" % generate(a.out, a.count, a.seed, a.lower, a.upper, a.dt, a.velocity, a.spread))
