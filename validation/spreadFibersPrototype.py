#!/usr/bin/python3
"""Prototype of docs/model.md sec. 12 (spread fibers, eqs. P49-P57): the penetration of a
random mat of few, heavily weighted fibers, today's point interceptors (eq. P40) against
the spread population, at three coupling-grid spacings a factor 2 apart and weights
N = 1, 10, 100.

The mat (2D, the plane of the flow): M computed fibers of weight N, each a straight fiber
across the whole depth (y), placed uniformly at random in the slab 1.25 <= z <= 1.75 of a
box periodic in x (width W = 0.75 m) and 0 <= z <= 3; strip c = 2 (r_F + r_p) = 1e-4 m
(thin: c / dx <= 0.013; the computed fibers' own self-shadow, eqs. P20-P21, is left out,
which leaves their c / 4dx: at most +0.3 % per unit of S). A uniform spray crosses the mat
along z at dx / 2 per step (m = 2 steps per spacing). The mat's depth S = M N c / W is
fixed: a mat of M N independently placed fibers passes exp(-S) (eq. P15).

Per step and node (eqs. P12, P13; a_s = c (v dt) / dx^2, the fraction of a node one fiber
asks at hat weight 1):

  today    x_n = -N ln(1 - a_s w_n)                w_n the hat weights at the fiber (eq. P40)
  spread   x_n = -ln(1 - a_s w_n) + (N - 1) a_s W_n (1 + sigma_n)
                                                   the fiber itself on its line, its N - 1
                                                   others spread with the weights W_n (P50)

The spread three ways:
  gauss    W_n the Gaussian of standard deviation h_s convolved with the node's hat
           (eq. P49), h_s the distance to the k-th nearest other computed fiber (eq. P52);
           sigma_n = 0;
  levels   the implementation's form (eq. P53): the sample's hat weights on the coarse
           lattice of spacing H = r dx (r = 1, 2, 3, 4, 6, 8, 12, ...: 2^j and 3 2^j),
           interpolated (multilinear) back to the coupling grid, the level the finest whose
           kernel (standard deviation H / sqrt 3) reaches k other computed fibers within one
           standard deviation, by the level's own count of them; sigma_n = 0;
  shadow   levels, with the population's shadow on itself (eq. P54: P21's sigma on the
           level with the strip (N + 1) c).
A parcel (cloud-in-cell) keeps exp(-sum_n w_pn x_n) per step (eq. P14); over its straight
path the steps add up to the column depths D_i = m sum_j x_ij, and the lane at x keeps
exp(-sum_i hat_i(x) D_i), integrated over x exactly (the depth is linear in each cell).

Prints P / exp(-S) (mean over the draws of the mat, and their range), and checks on one
step that the spread keeps captured = removed exactly (eq. P51).

    python3 validation/spreadFibersPrototype.py [--draws 32] [--k 8] [--S 1 2.3]
"""
import argparse
import math
import random

C_STRIP = 1e-4          # c = 2 (r_F + r_p), m
WIDTH = 0.75            # W, m (periodic in x; a multiple of every level spacing used)
Z_BOX = 3.0             # grid box 0 <= z <= Z_BOX
SLAB = (1.25, 1.75)     # the mat
STEPS_PER_SPACING = 2   # m: the spray moves dx / m per step


def phi(u):
    return math.exp(-0.5 * u * u) / math.sqrt(2.0 * math.pi)


def ramp_gauss(a, sigma):
    """E[(Y - b)^+] for Y ~ N(b + a, sigma^2): the Gaussian's second antiderivative."""
    if sigma == 0.0:
        return max(a, 0.0)
    t = a / sigma
    return a * 0.5 * math.erfc(-t / math.sqrt(2.0)) + sigma * phi(t)


def gauss_hat_weights(y, sigma, dx, n_nodes, periodic):
    """P50 along one direction: W_i = integral G_sigma(u - y) hat_i(u) du (exact: the hat is
    a second difference of ramps). Returns {node: weight}, normalised over the nodes kept
    (the Gaussian cut at 5 sigma + dx; periodic wraps, otherwise the box's nodes only)."""
    reach = 5.0 * sigma + dx
    lo, hi = int(math.floor((y - reach) / dx)), int(math.ceil((y + reach) / dx))
    weights = {}
    for i in range(lo, hi + 1):
        xi = i * dx
        w = (ramp_gauss(y - xi + dx, sigma) - 2.0 * ramp_gauss(y - xi, sigma)
             + ramp_gauss(y - xi - dx, sigma)) / dx
        if w <= 0.0:
            continue
        if periodic:
            j = i % n_nodes
        elif 0 <= i < n_nodes:
            j = i
        else:
            continue
        weights[j] = weights.get(j, 0.0) + w
    total = sum(weights.values())
    return {j: w / total for j, w in weights.items()}


def hat_weights(y, spacing, n_nodes, periodic):
    """Cloud-in-cell weights of a point on the lattice i * spacing."""
    i = int(math.floor(y / spacing))
    t = y / spacing - i
    out = {}
    for j, w in ((i, 1.0 - t), (i + 1, t)):
        if w == 0.0:
            continue
        j = j % n_nodes if periodic else j
        out[j] = out.get(j, 0.0) + w
    return out


def level_weights(y, level_spacing, dx, n_nodes, strip=0.0):
    """P53 along the periodic direction: the sample's hat weights on the coarse lattice of
    spacing H, each coarse node's hat sampled at the fine nodes (times dx / H: a partition
    of unity, H a multiple of dx). Level 0 (H = dx) is the hat itself. strip > 0: each
    coarse part scaled by the population's self-shadow 1 + sigma_C, P21 on the level with
    the strip (N + 1) c (eq. P54: the population and its cross term with the fiber itself)."""
    ratio = int(round(level_spacing / dx))
    n_coarse = n_nodes // ratio
    weights = {}
    coarse_w = hat_weights(y, level_spacing, n_coarse, True)
    for coarse, wc in coarse_w.items():
        if strip > 0.0:
            other = sum(v for c, v in coarse_w.items() if c != coarse)
            wc *= 1.0 + strip / (2.0 * level_spacing) * (2.0 / 3.0 * wc + other / 6.0)
        centre = coarse * ratio
        for off in range(-ratio + 1, ratio):
            w = wc * (1.0 - abs(off) / ratio) / ratio
            j = (centre + off) % n_nodes
            weights[j] = weights.get(j, 0.0) + w
    return weights


def draw_mat(n_fibers, rng):
    return [(rng.random() * WIDTH, SLAB[0] + rng.random() * (SLAB[1] - SLAB[0])) for _ in range(n_fibers)]


def periodic_dx(a, b):
    d = abs(a - b) % WIDTH
    return min(d, WIDTH - d)


def knn_distance(fibers, k):
    """h_s: the distance to the k-th nearest other computed fiber (P52), x periodic."""
    cell = max(math.sqrt(k * WIDTH * (SLAB[1] - SLAB[0]) / (math.pi * len(fibers))), 1e-3)
    buckets = {}
    ncx = max(1, int(WIDTH / cell))
    for idx, (x, z) in enumerate(fibers):
        buckets.setdefault((int(x / WIDTH * ncx) % ncx, int(z / cell)), []).append(idx)
    out = []
    for idx, (x, z) in enumerate(fibers):
        cx, cz = int(x / WIDTH * ncx) % ncx, int(z / cell)
        ring = 1
        while True:
            dists = []
            for bx in range(cx - ring, cx + ring + 1):
                for bz in range(cz - ring, cz + ring + 1):
                    for other in buckets.get((bx % ncx, bz), ()):
                        if other != idx:
                            ox, oz = fibers[other]
                            dists.append(math.hypot(periodic_dx(x, ox), z - oz))
            dists.sort()
            # the ring's inner radius bounds what lies beyond it
            if len(dists) >= k and dists[k - 1] <= ring * cell or ring * cell > WIDTH:
                out.append(dists[k - 1])
                break
            ring += 1
    return out


RATIOS = sorted({2 ** j for j in range(12)} | {3 * 2 ** j for j in range(11)})


def level_of(fibers, k, dx):
    """l_s: the finest level (coarse spacing H = r_l dx, RATIOS) whose kernel, of standard deviation
    H / sqrt(3) per direction, reaches k other computed fibers within one standard deviation
    (P53): pi (H^2 / 3) n_l >= k, n_l the other fibers' number per area on that level (their
    cloud-in-cell count, interpolated at the sample, its own fiber taken out). Level 0 is
    the grid's own hat."""
    levels = [0] * len(fibers)
    pending = list(range(len(fibers)))
    level = 0
    while pending:
        spacing = dx * RATIOS[level]
        ncx = max(1, int(round(WIDTH / spacing)))
        counts = {}
        hats = []
        for x, z in fibers:
            w = {(i, j): vx * vz for i, vx in hat_weights(x, spacing, ncx, True).items()
                 for j, vz in hat_weights(z, spacing, 10 ** 9, False).items()}
            hats.append(w)
            for node, v in w.items():
                counts[node] = counts.get(node, 0.0) + v
        still = []
        for idx in pending:
            w = hats[idx]
            others = sum(v * (counts[node] - w[node]) for node, v in w.items())  # per node's cell
            density = others / spacing ** 2
            if math.pi * spacing ** 2 / 3.0 * density >= k or spacing >= WIDTH / 2:
                levels[idx] = level
            else:
                still.append(idx)
        pending = still
        level += 1
    return levels


def column_depths(fibers, weight, dx, method, fiber_levels=None, bandwidths=None):
    """D_i = m sum_j x_ij over the lattice columns (x periodic, W / dx nodes)."""
    n_x = int(round(WIDTH / dx))
    n_z = int(round(Z_BOX / dx)) + 1
    a = C_STRIP * (dx / STEPS_PER_SPACING) / dx ** 2  # one physical fiber, hat weight 1
    depth = [0.0] * n_x
    for idx, (x, z) in enumerate(fibers):
        wx = hat_weights(x, dx, n_x, True)
        wz = hat_weights(z, dx, n_z, False)
        own = weight if method == "today" else 1.0
        for i, vx in wx.items():
            for _, vz in wz.items():
                depth[i] += -own * math.log1p(-a * vx * vz)
        if method == "today" or weight == 1.0:
            continue
        if method == "gauss":
            spread = gauss_hat_weights(x, bandwidths[idx], dx, n_x, True)
        else:
            strip = (weight + 1.0) * C_STRIP if method == "shadow" else 0.0
            spread = level_weights(x, dx * RATIOS[fiber_levels[idx]], dx, n_x, strip)
        # the population's parts are thin (a W << 1): linear, their z weights sum to 1
        for i, w in spread.items():
            depth[i] += (weight - 1.0) * a * w
    return [STEPS_PER_SPACING * d for d in depth]


def penetration(depth, dx):
    """(1 / W) integral exp(-f(x)) dx, f linear between the columns' depths (P14's lanes)."""
    total = 0.0
    n = len(depth)
    for i in range(n):
        d0, d1 = depth[i], depth[(i + 1) % n]
        diff = d1 - d0
        if abs(diff) < 1e-12:
            total += dx * math.exp(-0.5 * (d0 + d1))
        else:
            total += dx * (math.exp(-d0) - math.exp(-d1)) / diff
    return total / WIDTH


def balance_check(fibers, weight, dx, k, rng):
    """One step of P12-P14, P19 with the spread (P50, P51, P53) on a uniform window (rho = 1):
    the fibers' granted mass against the parcels' loss. Returns the relative difference."""
    n_x = int(round(WIDTH / dx))
    n_z = int(round(Z_BOX / dx)) + 1
    levels = level_of(fibers, k, dx)
    volume = dx * dx
    strip = C_STRIP * dx / STEPS_PER_SPACING      # c |v_rel| dt per unit depth
    parts = []                                    # (node, demand d_sn, interceptors)
    for idx, (x, z) in enumerate(fibers):
        for i, vx in hat_weights(x, dx, n_x, True).items():
            for j, vz in hat_weights(z, dx, n_z, False).items():
                parts.append(((i, j), strip * vx * vz, 1.0))   # d = m_s w_c rho_c, rho = 1
        if weight > 1.0:
            wx = level_weights(x, dx * RATIOS[levels[idx]], dx, n_x)
            wz = level_weights_z(z, dx * RATIOS[levels[idx]], dx, n_z)
            for i, vx in wx.items():
                for j, vz in wz.items():
                    parts.append(((i, j), strip * vx * vz, weight - 1.0))
    demand, depth = {}, {}
    for node, d, count in parts:
        demand[node] = demand.get(node, 0.0) + count * d
        depth[node] = depth.get(node, 0.0) - count * math.log1p(-d / volume)   # s_n = rho V
    removed = {}
    lost = 0.0
    for _ in range(4000):   # parcels of mass 1 at random points (cloud-in-cell)
        px, pz = rng.random() * WIDTH, SLAB[0] - 0.1 + rng.random() * (SLAB[1] - SLAB[0] + 0.2)
        w = {(i, j): vx * vz for i, vx in hat_weights(px, dx, n_x, True).items()
             for j, vz in hat_weights(pz, dx, n_z, False).items()}
        big_x = sum(wn * depth.get(n, 0.0) for n, wn in w.items())
        if big_x == 0.0:
            continue
        c_p = -math.expm1(-big_x)
        lost += c_p
        for n, wn in w.items():
            if n in depth:
                removed[n] = removed.get(n, 0.0) + c_p * wn * depth[n] / big_x
    grant = {n: removed.get(n, 0.0) / demand[n] for n in demand}
    captured = sum(count * d * grant[node] for node, d, count in parts)
    return abs(captured - lost) / lost


def level_weights_z(z, spacing, dx, n_z):
    """P53 along a bounded direction: as level_weights, the coarse hats cut at the box and
    each coarse node's share renormalised over the fine nodes it reaches (conservative)."""
    ratio = int(round(spacing / dx))
    weights = {}
    for coarse, wc in hat_weights(z, spacing, 10 ** 9, False).items():
        centre = coarse * ratio
        fine = {}
        for off in range(-ratio + 1, ratio):
            j = centre + off
            if 0 <= j < n_z:
                fine[j] = 1.0 - abs(off) / ratio
        norm = sum(fine.values())
        for j, w in fine.items():
            weights[j] = weights.get(j, 0.0) + wc * w / norm
    return weights


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--draws", type=int, default=32)
    parser.add_argument("--k", type=int, default=8, help="other computed fibers per kernel")
    parser.add_argument("--S", type=float, nargs="+", default=[1.0, 2.3])
    parser.add_argument("--weights", type=float, nargs="+", default=[1.0, 10.0, 100.0])
    parser.add_argument("--spacings", type=int, nargs="+", default=[32, 64, 128], help="1 / dx")
    args = parser.parse_args()
    for depth_s in args.S:
        print(f"\nS = {depth_s}, exp(-S) = {math.exp(-depth_s):.4f}; P / exp(-S), mean (min .. max) over "
              f"{args.draws} mats; k = {args.k}")
        print(f"{'N':>5} {'M':>6} {'1/dx':>5} {'today (P40)':>22} {'spread, Gaussian':>22} "
              f"{'spread, levels':>22} {'levels, self-shadow':>22} {'h/dx':>6} {'H/dx':>6}")
        for weight in args.weights:
            n_fibers = int(round(depth_s * WIDTH / (weight * C_STRIP)))
            mats = [draw_mat(n_fibers, random.Random(1000 * seed + int(weight))) for seed in range(args.draws)]
            widths = [knn_distance(m, args.k) if weight > 1 else None for m in mats]
            for inv_dx in args.spacings:
                dx = 1.0 / inv_dx
                row = {}
                level_mean, h_mean = 0.0, 0.0
                for method in ("today", "gauss", "levels", "shadow"):
                    ratios = []
                    for mat, h in zip(mats, widths):
                        lv = level_of(mat, args.k, dx) if method in ("levels", "shadow") and weight > 1 else None
                        if lv and method == "levels":
                            level_mean += sum(RATIOS[v] for v in lv) / len(lv) / len(mats)
                        if h and method == "gauss":
                            h_mean += sum(h) / len(h) / dx / len(mats)
                        depth = column_depths(mat, weight, dx, method, lv, h)
                        ratios.append(penetration(depth, dx) / math.exp(-depth_s))
                    row[method] = ratios
                cells = [f"{sum(r) / len(r):.3f} ({min(r):.3f}..{max(r):.3f})" for r in row.values()]
                print(f"{weight:5.0f} {n_fibers:6d} {inv_dx:5d} {cells[0]:>22} {cells[1]:>22} {cells[2]:>22} "
                      f"{cells[3]:>22} {h_mean:6.1f} {level_mean:6.1f}")
    rng = random.Random(7)
    mat = draw_mat(100, rng)
    for inv_dx in (32, 128):
        err = balance_check(mat, 100.0, 1.0 / inv_dx, args.k, rng)
        print(f"\ncaptured = removed, N = 100, M = 100, 1/dx = {inv_dx}: relative difference {err:.1e}")


if __name__ == "__main__":
    main()
