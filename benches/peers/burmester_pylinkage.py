#!/usr/bin/env python3
"""pylinkage 1.3.0's Burmester dyads for the poses of tests/data/burmester_poses.csv,
and how they compare with the 50-digit ones of benches/reference/burmester.py.

    benches/peers/burmester.sh        (installs pylinkage into benches/peers/.venv, then runs this)

For each set of poses, five and four positions, pylinkage.synthesis.compute_circle_point_curve
(its Burmester entry point) is run; its dyads (circle point in the world at the first pose,
centre point) are written to tests/data/burmester_pylinkage.csv with the circle point also in
the moving plane's frame (b = R_1^T (w_1 - d_1), the convention of the reference and of the
tests). Then each is compared with the reference:

  five positions: the nearest reference dyad (tests/data/burmester_dyads.csv) and the
      distances of the circle and centre points to it, relative to the poses' size (the largest
      distance between two poses' positions); a pylinkage dyad within a tenth of the size of a
      reference dyad approximates it, one farther is no Burmester dyad; a reference dyad that
      none approximates is missed;
  four positions: the distance of the circle point to the reference circle-point cubic and of
      the centre point to the centre-point cubic (tests/data/burmester_curves.csv; to the
      cubic's nearest point sampled every 2e-3 of its scale, or |C|/|grad C| closer than 1e-2),
      relative to the same size.

The comparison is printed and written to tests/data/burmester_pylinkage_comparison.csv.
pylinkage's method (read in pylinkage/synthesis/burmester.py): a polar grid of body points
(16 radii x 72 angles for five positions, 12 x 72 for four) kept when the circumcircle of the
first three positions passes within 1 % (five) or 2 % (four) of the radius of the others;
for five, the best six of them; then those within 5 % of the size of one kept before dropped.
"""
import csv
import math
import os
import sys
import time

import numpy as np

import pylinkage
from pylinkage.synthesis import Pose, compute_circle_point_curve

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(ROOT, "tests", "data")
COMMAND = "benches/peers/burmester.sh"


def rows(name):
    with open(os.path.join(DATA, name)) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def poses_by_set():
    sets = {}
    for r in rows("burmester_poses.csv"):
        sets.setdefault(r["set"], []).append((float(r["x"]), float(r["y"]), float(r["angle"])))
    return sets


def size(poses):
    return max(math.hypot(p[0] - q[0], p[1] - q[1]) for p in poses for q in poses)


def body(pose, w):
    """The moving plane's coordinates of the world point w at `pose`."""
    c, s = math.cos(pose[2]), math.sin(pose[2])
    dx, dy = w.real - pose[0], w.imag - pose[1]
    return (c * dx + s * dy, -s * dx + c * dy)


def terms(curve):
    return [(int(k[1]), int(k[2]), float(c)) for k, c in curve.items()
            if len(k) == 3 and k.startswith("c")]


def first_order(curve, x, y):
    """|C|/|grad C| at (x, y): the distance to the cubic, to first order."""
    ox, oy, s = float(curve["origin_x"]), float(curve["origin_y"]), float(curve["scale"])
    X, Y = (x - ox) / s, (y - oy) / s
    value = gx = gy = 0.0
    for i, j, c in terms(curve):
        value += c * X ** i * Y ** j
        if i:
            gx += c * i * X ** (i - 1) * Y ** j
        if j:
            gy += c * j * X ** i * Y ** (j - 1)
    return abs(value) / math.hypot(gx, gy) * s


def points_on(curve, reach=12.0, step=2e-3):
    """The cubic's real points, |X|, |Y| <= reach (scaled units), on lines
    X = const and Y = const every `step`."""
    ox, oy, s = float(curve["origin_x"]), float(curve["origin_y"]), float(curve["scale"])
    t = terms(curve)
    grid = np.arange(-reach, reach, step)
    out = []
    for along in (0, 1):
        # The cubic as a polynomial in the other coordinate, its coefficients
        # polynomials in the fixed one, for every line at once.
        coefficients = np.zeros((4, grid.size))
        for i, j, c in t:
            fixed, free = (i, j) if along == 0 else (j, i)
            coefficients[free] += c * grid ** fixed
        for k in range(grid.size):
            for r in np.roots(coefficients[::-1, k]):
                if abs(r.imag) < 1e-9 and abs(r.real) <= reach:
                    X, Y = (grid[k], r.real) if along == 0 else (r.real, grid[k])
                    out.append((ox + s * X, oy + s * Y))
    return np.array(out)


def distance_to_cubic(cloud, curve, x, y):
    """The distance from (x, y) to the cubic: to its nearest sampled point,
    or to first order where that is finer than the sampling."""
    near = float(np.min(np.hypot(cloud[:, 0] - x, cloud[:, 1] - y)))
    s = float(curve["scale"])
    return first_order(curve, x, y) if near < 1e-2 * s else near


def digits(relative):
    return "inf" if relative == 0 else f"{-math.log10(relative):.1f}"


def main():
    sets = poses_by_set()
    reference = {}
    for r in rows("burmester_dyads.csv"):
        reference.setdefault(r["set"], []).append(
            tuple(float(r[k]) for k in ("ax", "ay", "bx", "by", "r")))
    curves = {(r["set"], r["curve"]): r for r in rows("burmester_curves.csv")}
    clouds = {key: points_on(curve) for key, curve in curves.items()}

    out = [["set", "positions", "dyad", "ax", "ay", "wx", "wy", "bx", "by", "r", "seconds"]]
    comparison = [["set", "positions", "dyad", "nearest_reference", "circle_error", "centre_error",
                   "digits", "note"]]
    report = []
    for name, poses in sets.items():
        scale = size(poses)
        for n in (5, 4):
            chosen = poses[:n]
            start = time.perf_counter()
            curve = compute_circle_point_curve([Pose(x, y, t) for x, y, t in chosen])
            seconds = time.perf_counter() - start
            found = []
            for k, dyad in enumerate(curve.get_all_dyads()):
                b = body(chosen[0], dyad.circle_point)
                a = dyad.center_point
                found.append((a.real, a.imag, b[0], b[1], dyad.link_length))
                out.append([name, str(n), str(k)] + [repr(float(v)) for v in (
                    a.real, a.imag, dyad.circle_point.real, dyad.circle_point.imag, b[0], b[1],
                    dyad.link_length)] + [f"{seconds:.4f}"])
            if n == 5:
                hit = set()
                for k, (ax, ay, bx, by, r) in enumerate(found):
                    errors = [(math.hypot(bx - r[2], by - r[3]), math.hypot(ax - r[0], ay - r[1]), i)
                              for i, r in enumerate(reference[name])]
                    circle, centre, i = min(errors, key=lambda e: max(e[0], e[1]))
                    worst = max(circle, centre) / scale
                    if worst <= 0.1:
                        hit.add(i)
                        note = f"approximates reference {i}"
                    else:
                        note = "no Burmester dyad"
                    comparison.append([name, "5", str(k), str(i), f"{circle / scale:.3e}",
                                       f"{centre / scale:.3e}", digits(worst), note])
                    report.append(f"{name}, 5 positions: pylinkage dyad {k} (radius {r:.4g}): "
                                  f"{note}; nearest reference {i}, circle point off by {circle / scale:.1e}, "
                                  f"centre by {centre / scale:.1e} of the size ({digits(worst)} digits)")
                for i, r in enumerate(reference[name]):
                    if i not in hit:
                        comparison.append([name, "5", "-", str(i), "-", "-", "-",
                                           f"missed (radius {r[4]:.6g})"])
                        report.append(f"{name}, 5 positions: reference dyad {i} (radius {r[4]:.6g}) missed")
            else:
                for k, (ax, ay, bx, by, _) in enumerate(found):
                    circle = distance_to_cubic(clouds[(name, "circle")], curves[(name, "circle")], bx, by)
                    centre = distance_to_cubic(clouds[(name, "centre")], curves[(name, "centre")], ax, ay)
                    worst = max(circle, centre) / scale
                    comparison.append([name, "4", str(k), "-", f"{circle / scale:.3e}",
                                       f"{centre / scale:.3e}", digits(worst), "distance to the cubics"])
                mine = [r for r in comparison[1:] if r[0] == name and r[1] == "4"]
                if mine:
                    def spread(column):
                        v = sorted(float(r[column]) for r in mine)
                        return (f"median {v[len(v) // 2]:.1e}, best {v[0]:.1e}, worst {v[-1]:.1e}, "
                                f"{sum(x <= 1e-2 for x in v)} within 1e-2")
                    report.append(f"{name}, 4 positions: {len(found)} dyads; of the size, circle points off the "
                                  f"circle-point cubic: {spread(4)}; centres off the centre-point cubic: {spread(5)}")
    version = pylinkage.__version__
    header = [
        f"Burmester dyads by pylinkage {version} (pylinkage.synthesis.compute_circle_point_curve) for the poses of",
        "burmester_poses.csv, five and four positions: centre a, circle point w at the first pose (world) and b in",
        "the moving plane's frame, radius r; seconds: pylinkage's wall time for the set (this machine).",
        f"Produced by pylinkage {version} through {COMMAND} (benches/peers/burmester_pylinkage.py).",
    ]
    write("burmester_pylinkage.csv", header, out)
    write("burmester_pylinkage_comparison.csv", [
        f"pylinkage {version}'s Burmester dyads (burmester_pylinkage.csv) against the 50-digit reference: five",
        "positions, the nearest reference dyad (burmester_dyads.csv) and the distances of circle and centre points to",
        "it; four positions, the distances to the circle-point and centre-point cubics (burmester_curves.csv); all",
        "relative to the poses' size; digits = -log10 of the larger. Five positions: a pylinkage dyad within 0.1 of",
        "the size of a reference dyad approximates it, one farther is no Burmester dyad, a reference dyad none",
        f"approximates is missed. Written by {COMMAND} (benches/peers/burmester_pylinkage.py).",
    ], comparison)
    print("\n".join(report))


def write(name, header, table):
    with open(os.path.join(DATA, name), "w") as f:
        for line in header:
            f.write("# " + line + "\n")
        for row in table:
            f.write(",".join(row) + "\n")
    print("wrote", os.path.join("tests", "data", name), len(table) - 1, "rows", file=sys.stderr)


if __name__ == "__main__":
    main()
