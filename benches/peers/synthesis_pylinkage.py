"""pylinkage 1.3.0 on the synthesis tasks of `cargo run --release --example synthesis`.

- Path generation, no prescribed timing: a four-bar's coupler point through
  5 and through 9 points of the Maple worksheet's coupler curve of G3
  (l = 80, 20, 50, 70 mm; G3 the coupler's midpoint), taken at evenly spaced
  crank angles 360°·k/n from θ2 = 0, on the assembly with C above the ground
  line. Every dimension free, within bounds derived from the targets.
  pylinkage's tools for it: Burmester path synthesis (`path_generation`),
  and its optimisers on the nine dimensions — the particle swarm followed by
  a Nelder–Mead polish (`chain_optimizers`, the documented pattern), and
  differential evolution (SciPy's, through pylinkage's wrapper).
- Function generation: Freudenstein's three precision points for
  y = log10 x on 1 ≤ x ≤ 10, Chebyshev spacing, the crank from 0° to 60° and
  the rocker from 90° to 180° (`function_generation`, its closed form).

Writes benches/results/synthesis_pylinkage.csv: the targets, every design
returned (its joints at its first frame, as pylinkage simulates it), the
runs that returned none, the optimisers' convergence (the best design so far
after each improvement) and the objective's evaluation rate. The example
judges every design with linkage's own certificate, the same way as its own.
"""

import math
import platform
import sys
import time
import warnings
from importlib.metadata import version

import numpy as np
from pylinkage.optimization import (
    chain_optimizers,
    differential_evolution_optimization,
    minimize_linkage,
    particle_swarm_optimization,
)
from pylinkage.optimization.utils import kinematic_minimization
from pylinkage.synthesis import function_generation, path_generation
from pylinkage.synthesis._types import FourBarSolution
from pylinkage.synthesis.conversion import solution_to_linkage

# Burmester search warns that five points take seconds; the optimisers that
# an unbuildable candidate scores +inf. Both are expected here.
warnings.simplefilter("ignore")

WORKSHEET = (80.0, 20.0, 50.0, 70.0)
#: Frames per crank turn (pylinkage's default crank speed, 1° a frame).
FRAMES = 360
#: Runs of the random optimisers.
PSO_RUNS = 5
DE_RUNS = 3

COLUMNS = "record,task,method,run,evaluations,seconds,objective,ax,ay,bx,by,cx,cy,dx,dy,px,py"


def worksheet_pose(theta2):
    """B and C of the worksheet's four-bar at θ2, C above the line B→D."""
    l1, l2, l3, l4 = WORKSHEET
    b = (l2 * math.cos(theta2), l2 * math.sin(theta2))
    ex, ey = l1 - b[0], -b[1]
    d = math.hypot(ex, ey)
    a = (l3 * l3 - l4 * l4 + d * d) / (2.0 * d)
    h = math.sqrt(l3 * l3 - a * a)
    c = (b[0] + (a * ex - h * ey) / d, b[1] + (a * ey + h * ex) / d)
    return b, c


def targets(n):
    """G3 at θ2 = 360°·k/n, k = 0 … n − 1."""
    out = []
    for k in range(n):
        b, c = worksheet_pose(2.0 * math.pi * k / n)
        out.append((0.5 * (b[0] + c[0]), 0.5 * (b[1] + c[1])))
    return out


def bounds(points):
    """The bounds of both tools, from the targets' box (centre c, diagonal d):
    pivots within 2d of c, links from 0.05d to 2d, the coupler point within
    2d of B in each coordinate (here, in pylinkage's polar form, within
    2√2·d at any angle)."""
    p = np.asarray(points)
    lo, hi = p.min(axis=0), p.max(axis=0)
    c, d = 0.5 * (lo + hi), float(np.linalg.norm(hi - lo))
    lower = [c[0] - 2 * d, c[1] - 2 * d, c[0] - 2 * d, c[1] - 2 * d, 0.05 * d, 0.05 * d, 0.05 * d, 0.0, -math.pi]
    upper = [c[0] + 2 * d, c[1] + 2 * d, c[0] + 2 * d, c[1] + 2 * d, 2 * d, 2 * d, 2 * d, 2 * math.sqrt(2) * d, math.pi]
    return lower, upper


class Writer:
    def __init__(self, out):
        self.out = out

    def row(self, record, task, method, run, evaluations=math.nan, seconds=math.nan, objective=math.nan, joints=None):
        joints = joints if joints is not None else [math.nan] * 10
        cells = [record, task, method, str(run), repr(evaluations), repr(seconds), repr(objective)]
        cells += [repr(float(x)) for x in joints]
        print(",".join(cells), file=self.out, flush=True)


def solution_joints(s):
    """A, B, C, D, P of a Burmester or Freudenstein solution as it exports them."""
    p = s.coupler_point if s.coupler_point is not None else (math.nan, math.nan)
    return [*s.ground_pivot_a, *s.crank_pivot_b, *s.coupler_pivot_c, *s.ground_pivot_d, *p]


class NineDimensions:
    """The four-bar of the optimisers, all nine dimensions free: the ground
    pivots A, D, the crank, coupler and rocker, and the coupler point P in
    pylinkage's polar form (distance from B, angle from B→C). Each design
    starts with its crank along +x and C on the left of B→D, the assembly of
    the targets' curve."""

    def __init__(self, points, lower, upper):
        b, c = worksheet_pose(0.0)
        p = (0.5 * (b[0] + c[0]), 0.5 * (b[1] + c[1]))
        self.linkage = solution_to_linkage(
            FourBarSolution((0.0, 0.0), (80.0, 0.0), b, c, 20.0, 50.0, 70.0, 80.0, p),
            iterations=FRAMES,
        )
        self.a, self.d, self.b, self.c, self.p = self.linkage.components
        self.targets = np.asarray(points)
        self.centre = [0.5 * (lo + hi) for lo, hi in zip(lower, upper)]

    # What pylinkage's optimisers ask of the linkage they optimise: its
    # dimensions (here nine, the ground pivots among them) and its joints.
    def get_constraints(self):
        return list(self.centre)

    def get_coords(self):
        return self.linkage.get_coords()

    def place(self, x):
        xa, ya, xd, yd, l2, l3, l4, r, angle = x
        self.a.set_coord(xa, ya)
        self.d.set_coord(xd, yd)
        self.linkage.set_constraints([l2, l3, l4, r, angle])
        bx, by = xa + l2, ya
        self.b.set_coord(bx, by)
        ex, ey = xd - bx, yd - by
        self.c.set_coord(0.5 * (bx + xd) - ey, 0.5 * (by + yd) + ex)
        self.p.set_coord(bx, by)

    def frames(self, x):
        """One crank turn by pylinkage's compiled solver; None if unbuildable."""
        self.place(x)
        trajectory = self.linkage.step_fast(iterations=FRAMES)
        return trajectory if np.isfinite(trajectory).all() else None

    def cost(self, trajectory):
        """The sum over the targets of the squared distance to the nearest
        frame of P's locus."""
        locus = trajectory[:, 4, :]
        squared = ((locus[None, :, :] - self.targets[:, None, :]) ** 2).sum(axis=2)
        return float(squared.min(axis=1).sum())


def joints_of_frame(frame):
    a, d, b, c, p = frame
    return [*a, *b, *c, *d, *p]


def optimise(writer, task, method, run, nine, stages):
    """One run of pylinkage's optimisers; the best design so far recorded
    whenever its objective has fallen by a tenth since the last one recorded,
    with its time and evaluation count."""
    best = [math.inf]
    recorded = [math.inf]
    count = [0]
    start = time.perf_counter()

    def evaluate(linkage, params, init_pos):
        count[0] += 1
        trajectory = nine.frames(params)
        if trajectory is None:
            return math.inf
        value = nine.cost(trajectory)
        if value < best[0]:
            best[0] = value
            if value < 0.9 * recorded[0]:
                recorded[0] = value
                seconds = time.perf_counter() - start
                writer.row("trace", task, method, run, count[0], seconds, value, joints_of_frame(trajectory[0]))
        return value

    result = chain_optimizers(evaluate, nine, stages, order_relation=min, verbose=False)
    seconds = time.perf_counter() - start
    trajectory = nine.frames(list(result[0].dimensions))
    if trajectory is None:
        writer.row("none", task, method, run, count[0], seconds)
    else:
        writer.row("design", task, method, run, count[0], seconds, nine.cost(trajectory), joints_of_frame(trajectory[0]))
    print(f"  {method} run {run}: {seconds:.1f} s, {count[0]} evaluations, cost {best[0]:.3e}", file=sys.stderr)


def path_task(writer, n):
    task = f"path{n}"
    points = targets(n)
    for i, (x, y) in enumerate(points):
        writer.row("target", task, "worksheet", i, joints=[math.nan] * 8 + [x, y])
    # Burmester: the first verified design (max_solutions=1, what governs
    # its time), then its default search (up to 10 designs).
    for method, most in [("Burmester (max_solutions 1)", 1), ("Burmester (max_solutions 10: its default)", 10)]:
        start = time.perf_counter()
        result = path_generation(points, max_solutions=most)
        seconds = time.perf_counter() - start
        if not result.raw_solutions:
            writer.row("none", task, method, 0, seconds=seconds)
        for s in result.raw_solutions:
            writer.row("design", task, method, 0, seconds=seconds, joints=solution_joints(s))
        print(f"  {method}: {seconds:.1f} s, {len(result.raw_solutions)} designs", file=sys.stderr)
    lower, upper = bounds(points)
    nine = NineDimensions(points, lower, upper)
    for run in range(PSO_RUNS):
        stages = [
            (particle_swarm_optimization, {"dimensions": 9, "bounds": (lower, upper)}),
            (minimize_linkage, {"method": "Nelder-Mead", "maxiter": 4000}),
        ]
        optimise(writer, task, "PSO + Nelder-Mead", run, nine, stages)
    for run in range(DE_RUNS):
        # SciPy's random stream: the run's number.
        stages = [(differential_evolution_optimization, {"bounds": (lower, upper), "maxiter": 300, "seed": run})]
        optimise(writer, task, "differential evolution", run, nine, stages)


def rate(writer, n):
    """Evaluations per second of the optimisers' objective on the n-point
    task, at the source design: as pylinkage's decorator runs it
    (`kinematic_minimization`, `Linkage.step`) and as run here
    (`Linkage.step_fast`, the compiled solver)."""
    task = f"path{n}"
    points = targets(n)
    lower, upper = bounds(points)
    nine = NineDimensions(points, lower, upper)
    x = [0.0, 0.0, 80.0, 0.0, 20.0, 50.0, 70.0, 25.0, 0.0]
    nine.place(x)
    init = nine.linkage.get_coords()
    targets_array = nine.targets

    @kinematic_minimization
    def fitness(linkage, params, init_pos, loci):
        locus = np.array([frame[4] for frame in loci])
        squared = ((locus[None, :, :] - targets_array[:, None, :]) ** 2).sum(axis=2)
        return float(squared.min(axis=1).sum())

    params = x[4:]
    cases = [
        ("kinematic_minimization + Linkage.step", lambda: fitness(nine.linkage, params, init)),
        ("Linkage.step_fast", lambda: nine.cost(nine.frames(x))),
    ]
    for method, call in cases:
        call()
        for repeat in range(3):
            count, start = 0, time.perf_counter()
            while time.perf_counter() - start < 1.0:
                call()
                count += 1
            writer.row("rate", task, method, repeat, count, time.perf_counter() - start)


def function_task(writer):
    """Freudenstein's three precision points for y = log10 x."""
    task = "function"
    xs = [5.5 - 4.5 * math.cos(math.pi * (2 * j - 1) / 6) for j in (1, 2, 3)]
    pairs = [(math.radians(60.0 * (x - 1.0) / 9.0), math.radians(90.0 + 90.0 * math.log10(x))) for x in xs]
    for i, (theta, phi) in enumerate(pairs):
        writer.row("target", task, "log10", i, joints=[math.nan] * 8 + [theta, phi])
    method = "Freudenstein (function_generation)"
    result = function_generation(pairs)
    calls = 200
    times = []
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(calls):
            function_generation(pairs)
        times.append((time.perf_counter() - start) / calls)
    seconds = sorted(times)[len(times) // 2]
    if not result.raw_solutions:
        writer.row("none", task, method, 0, seconds=seconds)
    for s in result.raw_solutions:
        writer.row("design", task, method, 0, seconds=seconds, joints=solution_joints(s))


def main():
    out = sys.argv[1]
    with open(out, "w") as f:
        writer = Writer(f)
        print(
            f"# Written by benches/peers/synthesis_pylinkage.py on {time.strftime('%Y-%m-%d', time.gmtime())} "
            f"({platform.machine()}, Python {platform.python_version()}, pylinkage {version('pylinkage')}, "
            f"numba {version('numba')}, numpy {version('numpy')}, scipy {version('scipy')}).",
            file=f,
        )
        print("# Joints: A, B, C, D, P (mm) at a design's first frame; a target's (x, y) in px, py "
              "(for the function task its crank and rocker angles θ2, φ in rad). Seconds: wall time of the run.", file=f)
        print(COLUMNS, file=f)
        function_task(writer)
        rate(writer, 9)
        for n in (5, 9):
            print(f"path through {n} points", file=sys.stderr)
            path_task(writer, n)


if __name__ == "__main__":
    main()
