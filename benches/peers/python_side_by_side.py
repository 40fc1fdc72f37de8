"""linkage's Python package beside pylinkage 1.3.0, in one process, on the
path-synthesis tasks of docs/performance.md (a four-bar's coupler point
through 5 and 9 points of the Maple worksheet's coupler curve of G3, every
dimension free) and the path-synthesis example of pylinkage's README
(`path_generation([(0, 0), (1, 1), (2, 1), (3, 0)])`).

pylinkage's methods are those of benches/peers/synthesis_pylinkage.py:
its Burmester path synthesis stopped at its first verified design (warmed
by one call, then the median of three: it repeats its work exactly, and
its first call in a process costs 2–3× the next), its particle swarm with
a Nelder–Mead polish and differential evolution (one run each). Ours,
`Mechanism.synthesize` with precision points (every design it returns
certified over a turn), to its first certified design (`enough=1`)
and over 128 starts, three timings each. Every design of both is judged
the same way, by this package: its largest distance from a target to its
coupler curve, swept over a turn in 3 600 steps from the pose it was
returned at, each target's nearest sample refined by golden-section search
on the crank angle (a design that cannot turn a whole revolution is
judged ∞).

    bash benches/peers/python_side_by_side.sh   # a few minutes
"""

import math
import platform
import statistics
import sys
import time
import warnings
from importlib.metadata import version

import numpy as np

import linkage
import synthesis_pylinkage as peer

warnings.simplefilter("ignore")

COUPLER_FOUR_BAR = """
u = [theta3, theta4],
v = [theta2],
points = [
    B = (xa + l2 * theta2.cos(), ya + l2 * theta2.sin()),
    C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
    P = (B.x + px * theta3.cos() - py * theta3.sin(), B.y + px * theta3.sin() + py * theta3.cos()),
],
closure = [
    xa + l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - xd,
    ya + l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin() - yd,
],
"""
WORKSHEET = {"xa": 0.0, "ya": 0.0, "xd": 80.0, "yd": 0.0, "l2": 20.0, "l3": 50.0,
             "l4": 70.0, "px": 25.0, "py": 0.0}
NAMES = list(WORKSHEET)
TIMINGS = 3
STREAMS = 5


def coupler(parameters=WORKSHEET):
    return linkage.Mechanism.from_text(COUPLER_FOUR_BAR, dict(parameters), name="CouplerFourBar")


def bounds(points):
    """docs/performance.md's bounds from the targets' box (centre c,
    diagonal d)."""
    p = np.asarray(points, dtype=float)
    lo, hi = p.min(axis=0), p.max(axis=0)
    c, d = (lo + hi) / 2, float(np.linalg.norm(hi - lo))
    return {"xa": (c[0] - 2 * d, c[0] + 2 * d), "ya": (c[1] - 2 * d, c[1] + 2 * d),
            "xd": (c[0] - 2 * d, c[0] + 2 * d), "yd": (c[1] - 2 * d, c[1] + 2 * d),
            "l2": (0.05 * d, 2 * d), "l3": (0.05 * d, 2 * d), "l4": (0.05 * d, 2 * d),
            "px": (-2 * d, 2 * d), "py": (-2 * d, 2 * d)}


def judge(parameters, theta2, u, points):
    """The largest distance from a target to the design's coupler curve."""
    bar = coupler(parameters)
    try:
        sweep = bar.sweep(start=theta2, stop=theta2 + 2 * math.pi, steps=3600, u=u)
    except linkage.LinkageError:
        return math.inf
    if not sweep.complete or sweep.events:
        return math.inf
    path, worst = sweep["P"], 0.0
    for target in np.asarray(points, dtype=float):
        k = int(np.argmin(np.linalg.norm(path - target, axis=1)))
        lo, hi = sweep.v[max(k - 1, 0), 0], sweep.v[min(k + 1, len(sweep) - 1), 0]
        guess = sweep.u[k]

        def distance(v):
            return float(np.linalg.norm(bar.analyze(v=v, u=guess)["P"] - target))

        g = (math.sqrt(5) - 1) / 2
        a, b = lo, hi
        for _ in range(60):
            c, d = b - g * (b - a), a + g * (b - a)
            if distance(c) < distance(d):
                b = d
            else:
                a = c
        worst = max(worst, min(distance((a + b) / 2), float(np.linalg.norm(path[k] - target))))
    return worst


def from_joints(joints):
    """A design given by its joints A, B, C, D, P (pylinkage's): its
    parameters, θ2 and u = [θ3, θ4] there."""
    ax, ay, bx, by, cx, cy, dx, dy, px, py = joints
    e = np.array([cx - bx, cy - by]) / math.hypot(cx - bx, cy - by)
    n = np.array([-e[1], e[0]])
    rel = np.array([px - bx, py - by])
    parameters = {"xa": ax, "ya": ay, "xd": dx, "yd": dy, "l2": math.hypot(bx - ax, by - ay),
                  "l3": math.hypot(cx - bx, cy - by), "l4": math.hypot(dx - cx, dy - cy),
                  "px": float(rel @ e), "py": float(rel @ n)}
    theta2 = math.atan2(by - ay, bx - ax)
    u = [math.atan2(cy - by, cx - bx), math.atan2(dy - cy, dx - cx)]
    return parameters, theta2, u


def ours(points, stream, enough):
    """One of our runs: (seconds, designs)."""
    bar = coupler()
    start = time.perf_counter()
    designs = bar.synthesize(path="P", targets=points, free=bounds(points), precision_points=True,
                             starts=128, random_state=stream, enough=enough, at=0.0,
                             none_is_error=False)
    return time.perf_counter() - start, designs


def our_rows(task, points):
    rows = []
    for label, enough in [("synthesize, first design", 1), ("synthesize, 128 starts", None)]:
        times, errors, count = [], [], 0
        for stream in range(1, STREAMS + 1):
            runs = [ours(points, stream, enough) for _ in range(TIMINGS)]
            times.append(statistics.median(t for t, _ in runs))
            designs = runs[0][1]
            count += len(designs)
            if len(designs) == 0:
                errors.append(math.inf)
                continue
            judged = [judge(dict(zip(designs.parameter_names, designs.parameters[k])),
                            designs.drivers[k][0], designs.poses[k][0], points)
                      for k in range(len(designs))]
            errors.append(min(judged))
        rows.append((task, f"linkage (Python): {label}", f"{STREAMS} streams × {TIMINGS} timings",
                     statistics.median(times), statistics.median(errors), count))
    return rows


def pylinkage_rows(task, points, optimisers=True):
    rows = []
    for label, most in [("Burmester (max_solutions 1)", 1)]:
        # Deterministic and repeatable: one call to warm it (numba's
        # compilation, its caches), then the median of TIMINGS calls.
        result = peer.path_generation(points, max_solutions=most)
        times = []
        for _ in range(TIMINGS):
            start = time.perf_counter()
            result = peer.path_generation(points, max_solutions=most)
            times.append(time.perf_counter() - start)
        seconds = statistics.median(times)
        judged = [judge(*from_joints(peer.solution_joints(s)), points) for s in result.raw_solutions]
        rows.append((task, f"pylinkage: {label}", f"warm, {TIMINGS} timings", seconds,
                     min(judged) if judged else math.inf, len(judged)))
    if not optimisers:
        return rows
    lower, upper = peer.bounds(points)
    nine = peer.NineDimensions(points, lower, upper)
    for label, stages in [
        ("PSO + Nelder-Mead", [(peer.particle_swarm_optimization, {"dimensions": 9, "bounds": (lower, upper)}),
                               (peer.minimize_linkage, {"method": "Nelder-Mead", "maxiter": 4000})]),
        ("differential evolution", [(peer.differential_evolution_optimization,
                                     {"bounds": (lower, upper), "maxiter": 300, "seed": 0})]),
    ]:
        def evaluate(_, params, __):
            trajectory = nine.frames(params)
            return math.inf if trajectory is None else nine.cost(trajectory)

        start = time.perf_counter()
        result = peer.chain_optimizers(evaluate, nine, stages, order_relation=min, verbose=False)
        seconds = time.perf_counter() - start
        trajectory = nine.frames(list(result[0].dimensions))
        error = math.inf if trajectory is None else judge(
            *from_joints(peer.joints_of_frame(trajectory[0])), points)
        rows.append((task, f"pylinkage: {label}", "one run", seconds, error, 1))
    return rows


def main():
    print(f"# linkage's Python package beside pylinkage, {time.strftime('%Y-%m-%d', time.gmtime())}: "
          f"{platform.machine()}, Python {platform.python_version()}, pylinkage {version('pylinkage')}, "
          f"numba {version('numba')}, numpy {version('numpy')}; benches/peers/python_side_by_side.py\n")
    print("| task | tool: method | runs | wall time (median) | error of the best design (median) | designs |")
    print("|---|---|---|---:|---:|---:|")
    readme = [(0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, 0.0)]
    tasks = [("pylinkage's README, 4 points", readme, False),
             ("path, 5 points", peer.targets(5), True),
             ("path, 9 points", peer.targets(9), True)]
    summary = []
    for task, points, optimisers in tasks:
        print(f"{task} ...", file=sys.stderr)
        mine = our_rows(task, points)
        theirs = pylinkage_rows(task, points, optimisers)
        for row in mine + theirs:
            t, method, runs, seconds, error, count = row
            print(f"| {t} | {method} | {runs} | {seconds * 1e3:.1f} ms | {error:.1e} | {count} |", flush=True)
        first = mine[0]
        for their in theirs:
            summary.append((task, their[1], their[3] / first[3], their[4], first[4]))
    print("\n| task | pylinkage's method | its time / ours (first design) | its error | ours |")
    print("|---|---|---:|---:|---:|")
    for task, method, ratio, theirs, mine in summary:
        print(f"| {task} | {method[len('pylinkage: '):]} | {ratio:.0f}× | {theirs:.1e} | {mine:.1e} |")


if __name__ == "__main__":
    main()
