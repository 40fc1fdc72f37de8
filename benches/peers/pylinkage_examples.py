#!/usr/bin/env python3
"""Reference simulations of pylinkage 1.3.0 example linkages.

Run with a venv of pylinkage==1.3.0, numpy and scipy (no numba):
    python3 -m venv /tmp/pylinkage-venv && /tmp/pylinkage-venv/bin/pip install pylinkage==1.3.0 scipy
    /tmp/pylinkage-venv/bin/python benches/peers/pylinkage_examples.py
The reference under tests/data/pylinkage/ is, for each example, <name>.json as
written and <name>_positions.json with its iterations, dt, joint names, initial
and per-step positions (and the re-simulation check) kept.

For every example this writes, in /tmp/pylinkage-work/:
  <name>.json             -- pylinkage's own serialisation: mechanism_to_dict() of the
                             Mechanism (for simulation.Linkage examples: of
                             pylinkage.dyads.to_mechanism(linkage), the library's own bridge).
  <name>_hypergraph.json  -- {"graph": hypergraph.graph_to_dict(hg),
                              "dimensions": Dimensions.to_dict()} from Linkage.to_hypergraph()
                             (simulation.Linkage examples only).
  <name>_positions.json   -- NOT a pylinkage format: description of the components
                             (constructor arguments), iterations, dt, the positions before
                             stepping ("initial") and the position of every component/joint
                             after every step ("steps"), floats written by json (repr, i.e.
                             shortest round-trip -> exact binary64), plus round-trip checks.
"""

from __future__ import annotations

import json
import math
import os
import sys
from math import tau

import pylinkage as pl
from pylinkage.actuators import ArcCrank, Crank, LinearActuator
from pylinkage.components import Ground, PointTracker
from pylinkage.dyads import FixedDyad, PPDyad, RRPDyad, RRRDyad
from pylinkage.dyads import to_mechanism as dyads_to_mechanism
from pylinkage.hypergraph import graph_to_dict, to_mechanism as hg_to_mechanism
from pylinkage.mechanism import (
    Mechanism,
    MechanismBuilder,
    fourbar,
    mechanism_from_dict,
    mechanism_to_dict,
    slider_crank,
)
from pylinkage.simulation import Linkage

OUT = os.path.dirname(os.path.abspath(__file__))


# ---------------------------------------------------------------------------
# Example definitions (copied from pylinkage 1.3.0 README / docs)
# ---------------------------------------------------------------------------

def readme_fourbar() -> Linkage:
    """README.md 'Define and Visualize a Four-Bar Linkage'."""
    O1 = Ground(0, 0, name="O1")
    O2 = Ground(3, 0, name="O2")
    crank = Crank(anchor=O1, radius=1.0, angular_velocity=0.31, name="crank")
    rocker = RRRDyad(anchor1=crank.output, anchor2=O2, distance1=3.0, distance2=1.0,
                     name="rocker")
    return Linkage([O1, O2, crank, rocker], name="Four-Bar")


def docs_fourbar_linkage() -> Linkage:
    """docs/examples/fourbar_linkage.py define_linkage()."""
    A = Ground(0.0, 0.0, name="A")
    D = Ground(3.0, 0.0, name="D")
    crank = Crank(anchor=A, radius=1.0, angular_velocity=tau / 20, name="B")
    pin = RRRDyad(anchor1=crank.output, anchor2=D, distance1=3.0, distance2=1.0, name="C")
    return Linkage([A, D, crank, pin], name="My four-bar linkage")


def stroke_engine() -> Linkage:
    """docs/examples/inverted_stroke_engine.py create_stroke_engine_linkage()."""
    anchor = Ground(0.0, 0.0, name="Crank anchor")
    line_a = Ground(0.0, 0.0, name="Line A")
    line_b = Ground(1.0, 0.0, name="Line B")
    crank = Crank(anchor=anchor, radius=1.0, angular_velocity=0.1, name="Crank")
    slider = RRPDyad(revolute_anchor=crank.output, line_anchor1=line_a, line_anchor2=line_b,
                     distance=1.5, name="Slider")
    return Linkage([anchor, line_a, line_b, crank, slider], name="Simple four-stroke engine")


# --- docs/examples/strider.py (verbatim constants) --------------------------
STRIDER_LAP_POINTS = 10
STRIDER_DIMENSIONS = (2, math.pi / 4, 1.8, 2.6, 1.4, math.pi + 0.2, 2.5, 1.8)
STRIDER_INIT_COORD = (
    (0, 0), (0, 1), (1.41, 1.41), (-1.41, 1.41), (0, -1), (-2.25, 0), (2.25, 0),
    (-1.4, -1.2), (1.4, -1.2), (-2.7, -2.7), (2.7, -2.7),
)


def strider() -> Linkage:
    """docs/examples/strider.py complete_strider(param2dimensions(DIMENSIONS), INIT_COORD)."""
    p = STRIDER_DIMENSIONS
    prev = STRIDER_INIT_COORD
    A = Ground(*prev[0], name="A")
    Y = Ground(*prev[1], name="Point (0, 1)")
    B = FixedDyad(anchor1=A, anchor2=Y, distance=p[0], angle=-p[1], name="Frame right (B)")
    B_p = FixedDyad(anchor1=A, anchor2=Y, distance=p[0], angle=p[1], name="Frame left (B_p)")
    C = Crank(anchor=A, radius=1, angular_velocity=-2 * math.pi / STRIDER_LAP_POINTS,
              name="Crank link (C)")
    D = RRRDyad(anchor1=B_p, anchor2=C.output, distance1=p[2], distance2=p[3],
                name="Left knee link (D)")
    E = RRRDyad(anchor1=B, anchor2=C.output, distance1=p[2], distance2=p[3],
                name="Right knee link (E)")
    F = FixedDyad(anchor1=C.output, anchor2=E, distance=p[4], angle=-p[5],
                  name="Left ankle link (F)")
    G = FixedDyad(anchor1=C.output, anchor2=D, distance=p[4], angle=p[5],
                  name="Right ankle link (G)")
    H = RRRDyad(anchor1=D, anchor2=F, distance1=p[6], distance2=p[7], name="Left foot (H)")
    I_ = RRRDyad(anchor1=E, anchor2=G, distance1=p[6], distance2=p[7], name="Right foot (I)")
    lk = Linkage([A, Y, B, B_p, C, D, E, F, G, H, I_], name="Strider")
    lk.set_coords(list(prev))  # as complete_strider() does
    return lk


def hoeken() -> Linkage:
    """docs/notebooks/01_straight_line_synthesis.ipynb (Hoeken straight-line linkage)."""
    A = Ground(0, 0, name="A")
    D = Ground(2, 0, name="D")
    B = Crank(anchor=A, radius=1.0, angular_velocity=2 * math.pi / 300, name="B")
    C = RRRDyad(anchor1=B, anchor2=D, distance1=2.5, distance2=2.5, name="C")
    P = FixedDyad(anchor1=B, anchor2=C, distance=5.0, angle=0.0, name="P")
    return Linkage(components=[A, D, B, C, P], name="Hoeken")


def fourbar_from_lengths_basic() -> Linkage:
    """docs/examples/fourbar_from_lengths_demo.py demo_basic_fourbar()."""
    from pylinkage.synthesis import fourbar_from_lengths
    return fourbar_from_lengths(crank_length=1.0, coupler_length=3.5, rocker_length=3.0,
                                ground_length=4.0, ground_pivot_a=(0.0, 0.0),
                                initial_crank_angle=math.pi / 4)


def readme_builder_fourbar() -> Mechanism:
    """README.md 'Alternative: Links-First Builder' (a Mechanism, not a simulation.Linkage)."""
    return (
        MechanismBuilder("four-bar")
        .add_ground_link("ground", ports={"O1": (0, 0), "O2": (4, 0)})
        .add_driver_link("crank", length=1.0, motor_port="O1", omega=0.1)
        .add_link("coupler", length=3.5)
        .add_link("rocker", length=3.0)
        .connect("crank.tip", "coupler.0")
        .connect("coupler.1", "rocker.0")
        .connect("rocker.1", "ground.O2")
        .build()
    )


def mechanism_fourbar_factory() -> Mechanism:
    """pylinkage.mechanism.fourbar docstring example."""
    return fourbar(crank=1.0, coupler=3.0, rocker=3.0, ground=4.0)


def mechanism_slider_crank_factory() -> Mechanism:
    """pylinkage.mechanism.slider_crank docstring example."""
    return slider_crank(crank=1.0, rod=3.0)


def readme_path_synthesis() -> Linkage:
    """README.md first snippet: path_generation([(0,0),(1,1),(2,1),(3,0)]).solutions[0]."""
    from pylinkage.synthesis import path_generation
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = path_generation([(0, 0), (1, 1), (2, 1), (3, 0)])
    return result.solutions[0]


# ---------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------

def _aname(a):
    return getattr(a, "_parent", a).name


def describe_component(c) -> dict:
    """Constructor arguments of a simulation component (not a pylinkage format)."""
    d = {"type": type(c).__name__, "name": c.name}
    if isinstance(c, Ground):
        d.update(x=c.x, y=c.y)
    elif isinstance(c, Crank):
        d.update(anchor=_aname(c.anchor), radius=c.radius,
                 angular_velocity=c.angular_velocity, initial_angle=c.initial_angle)
    elif isinstance(c, ArcCrank):
        d.update(anchor=_aname(c.anchor), radius=c.radius,
                 angular_velocity=c.angular_velocity, arc_start=c.arc_start,
                 arc_end=c.arc_end, initial_angle=c.initial_angle)
    elif isinstance(c, LinearActuator):
        d.update(anchor=_aname(c.anchor), angle=c.angle, stroke=c.stroke, speed=c.speed,
                 initial_extension=c.initial_extension)
    elif isinstance(c, RRRDyad):
        d.update(anchor1=_aname(c.anchor1), anchor2=_aname(c.anchor2),
                 distance1=c.distance1, distance2=c.distance2)
    elif isinstance(c, (FixedDyad, PointTracker)):
        d.update(anchor1=_aname(c.anchor1), anchor2=_aname(c.anchor2),
                 distance=c.distance, angle=c.angle)
    elif isinstance(c, RRPDyad):
        d.update(revolute_anchor=_aname(c.revolute_anchor),
                 line_anchor1=_aname(c.line_anchor1), line_anchor2=_aname(c.line_anchor2),
                 distance=c.distance)
    elif isinstance(c, PPDyad):
        d.update(line1_anchor1=_aname(c.line1_anchor1), line1_anchor2=_aname(c.line1_anchor2),
                 line2_anchor1=_aname(c.line2_anchor1), line2_anchor2=_aname(c.line2_anchor2))
    return d


def residuals(lk: Linkage, steps) -> dict:
    """Max |constraint violation| over all steps, absolute and relative to the length."""
    idx = {id(c): i for i, c in enumerate(lk.components)}

    def pos(step, a):
        return step[idx[id(getattr(a, "_parent", a))]]

    worst_abs = 0.0
    worst_rel = 0.0
    for s in steps:
        for i, c in enumerate(lk.components):
            checks = []
            if isinstance(c, Crank):
                checks.append((pos(s, c.anchor), c.radius))
            elif isinstance(c, RRRDyad):
                checks.append((pos(s, c.anchor1), c.distance1))
                checks.append((pos(s, c.anchor2), c.distance2))
            elif isinstance(c, (FixedDyad, RRPDyad)):
                a = c.anchor1 if isinstance(c, FixedDyad) else c.revolute_anchor
                checks.append((pos(s, a), c.distance))
            for (ax, ay), L in checks:
                err = abs(math.hypot(s[i][0] - ax, s[i][1] - ay) - L)
                worst_abs = max(worst_abs, err)
                worst_rel = max(worst_rel, err / L)
    return {"max_abs_length_error": worst_abs, "max_rel_length_error": worst_rel}


def crank_angle_drift(lk: Linkage, initial, steps, dt) -> float | None:
    """Max |actual crank angle - (theta0 + k*omega*dt)| (wrapped), over steps."""
    for i, c in enumerate(lk.components):
        if isinstance(c, Crank):
            ax, ay = c.anchor.x, c.anchor.y
            th0 = math.atan2(initial[i][1] - ay, initial[i][0] - ax)
            worst = 0.0
            for k, s in enumerate(steps, start=1):
                th = math.atan2(s[i][1] - ay, s[i][0] - ax)
                d = (th - (th0 + k * c.angular_velocity * dt) + math.pi) % tau - math.pi
                worst = max(worst, abs(d))
            return worst
    return None


def max_diff(a, b) -> float | None:
    if a is None or b is None or len(a) != len(b):
        return None
    m = 0.0
    for sa, sb in zip(a, b):
        if len(sa) != len(sb):
            return None
        for (xa, ya), (xb, yb) in zip(sa, sb):
            if None in (xa, ya, xb, yb):
                return None
            m = max(m, abs(xa - xb), abs(ya - yb))
    return m


def _mech_steps(mech, iterations, dt, order=None):
    """Simulate a Mechanism; return positions re-ordered to `order` (list of joint ids)."""
    ids = [j.id for j in mech.joints]
    perm = list(range(len(ids))) if order is None else [ids.index(o) for o in order]
    return [[tuple(s[k]) for k in perm] for s in mech.step(iterations=iterations, dt=dt)]


def simulate_mechanism_json(data: dict, iterations: int, dt: float, order=None):
    try:
        mech = mechanism_from_dict(json.loads(json.dumps(data)))
        return _mech_steps(mech, iterations, dt, order), None
    except Exception as e:  # noqa: BLE001
        return None, f"{type(e).__name__}: {e}"


def write(name: str, obj) -> str:
    path = os.path.join(OUT, name)
    with open(path, "w") as f:
        json.dump(obj, f, indent=1)
    return path


# ---------------------------------------------------------------------------
# Runners
# ---------------------------------------------------------------------------

def run_sim_linkage(name: str, lk: Linkage, source: str, iterations: int | None = None,
                    dt: float = 1.0, note: str = "") -> dict:
    initial = [tuple(p) for p in lk.get_coords()]
    mech_dict = mechanism_to_dict(dyads_to_mechanism(lk))
    hg, dims = lk.to_hypergraph()
    hg_json = {"graph": graph_to_dict(hg), "dimensions": dims.to_dict()}
    write(f"{name}.json", mech_dict)
    write(f"{name}_hypergraph.json", hg_json)

    period = lk.get_rotation_period()
    n = period if iterations is None else iterations
    error = None
    steps = []
    try:
        for s in lk.step(iterations=n, dt=dt):
            steps.append([tuple(p) for p in s])
    except pl.UnbuildableError as e:
        error = f"UnbuildableError at step {len(steps) + 1}: {e}"
    lk.set_coords(initial)  # restore

    names = [c.name for c in lk.components]
    via_mech, mech_err = simulate_mechanism_json(mech_dict, n, dt, names)
    try:
        mech2 = hg_to_mechanism(hg, dims)
        via_hg = _mech_steps(mech2, n, dt, names)
        hg_err = None
    except Exception as e:  # noqa: BLE001
        via_hg, hg_err = None, f"{type(e).__name__}: {e}"

    record = {
        "name": name,
        "linkage_name": lk.name,
        "source": source,
        "note": note,
        "pylinkage_version": pl.__version__,
        "container": "pylinkage.simulation.Linkage",
        "components": [describe_component(c) for c in lk.components],
        "solve_order": [c.name for c in lk._solve_order],
        "get_rotation_period": period,
        "iterations": n,
        "dt": dt,
        "crank_turn_covered_rad": [c.angular_velocity * n * dt for c in lk.components
                                   if isinstance(c, Crank)],
        "get_constraints": lk.get_constraints(),
        "joint_names": [c.name for c in lk.components],
        "initial": initial,
        "steps": steps,
        "error": error,
        "checks": {
            **residuals(lk, steps),
            "crank_angle_drift_rad": crank_angle_drift(lk, initial, steps, dt),
            "max_abs_diff_vs_mechanism_from_json": max_diff(steps, via_mech),
            "mechanism_from_json_error": mech_err,
            "max_abs_diff_vs_hypergraph_to_mechanism": max_diff(steps, via_hg),
            "hypergraph_to_mechanism_error": hg_err,
        },
    }
    write(f"{name}_positions.json", record)
    return record


def run_mechanism(name: str, mech: Mechanism, source: str, iterations: int | None = None,
                  dt: float = 1.0) -> dict:
    initial = [tuple(j.position) for j in mech.joints]
    mech_dict = mechanism_to_dict(mech)
    write(f"{name}.json", mech_dict)
    period = mech.get_rotation_period()
    n = period if iterations is None else iterations
    error = None
    steps = []
    try:
        for s in mech.step(iterations=n, dt=dt):
            steps.append([tuple(p) for p in s])
    except pl.UnbuildableError as e:
        error = f"UnbuildableError at step {len(steps) + 1}: {e}"
    via_json, json_err = simulate_mechanism_json(mech_dict, n, dt)
    # link-length residuals using cached lengths
    worst = 0.0
    jidx = {j.id: i for i, j in enumerate(mech.joints)}
    for s in steps:
        for link in mech.links:
            js = link.joints
            for a in range(len(js)):
                for b in range(a + 1, len(js)):
                    L = link.get_distance(js[a], js[b])
                    if L:
                        pa, pb = s[jidx[js[a].id]], s[jidx[js[b].id]]
                        worst = max(worst, abs(math.hypot(pa[0] - pb[0], pa[1] - pb[1]) - L) / L)
    record = {
        "name": name,
        "linkage_name": mech.name,
        "source": source,
        "pylinkage_version": pl.__version__,
        "container": "pylinkage.mechanism.Mechanism",
        "get_rotation_period": period,
        "iterations": n,
        "dt": dt,
        "use_group_solver": mech._use_group_solver,
        "joint_names": [j.id for j in mech.joints],
        "initial": initial,
        "steps": steps,
        "error": error,
        "checks": {
            "max_rel_length_error": worst,
            "max_abs_diff_vs_mechanism_from_json": max_diff(steps, via_json),
            "mechanism_from_json_error": json_err,
        },
    }
    write(f"{name}_positions.json", record)
    return record


def main() -> None:
    sd = "sdist pylinkage-1.3.0/"
    records = [
        run_sim_linkage("readme_fourbar", readme_fourbar(), "README.md (Quick Start four-bar)"),
        run_sim_linkage("fourbar_linkage", docs_fourbar_linkage(),
                        sd + "docs/examples/fourbar_linkage.py"),
        run_sim_linkage("stroke_engine", stroke_engine(),
                        sd + "docs/examples/inverted_stroke_engine.py"),
        run_sim_linkage("strider", strider(), sd + "docs/examples/strider.py",
                        note="default period (LAP_POINTS=10, dt=1)"),
        run_sim_linkage("strider_eval", strider(), sd + "docs/examples/strider.py",
                        iterations=12, dt=STRIDER_LAP_POINTS / 12,
                        note="as sym_stride_evaluator: step(iterations=12, dt=10/12)"),
        run_sim_linkage("hoeken", hoeken(),
                        sd + "docs/notebooks/01_straight_line_synthesis.ipynb",
                        iterations=300),
        run_sim_linkage("fourbar_from_lengths", fourbar_from_lengths_basic(),
                        sd + "docs/examples/fourbar_from_lengths_demo.py demo_basic_fourbar"),
        run_sim_linkage("readme_path_synthesis", readme_path_synthesis(),
                        "README.md first snippet, path_generation(...).solutions[0]"),
        run_mechanism("readme_builder_fourbar", readme_builder_fourbar(),
                      "README.md (Links-First Builder)"),
        # omega = tau/100; get_rotation_period() = int(tau/omega) = 99, so force 100.
        run_mechanism("mechanism_fourbar", mechanism_fourbar_factory(),
                      "pylinkage.mechanism.fourbar(1,3,3,4) docstring", iterations=100),
        run_mechanism("mechanism_slider_crank", mechanism_slider_crank_factory(),
                      "pylinkage.mechanism.slider_crank(1,3) docstring", iterations=100),
    ]
    for r in records:
        print(f"{r['name']:24s} n={r['iterations']:4d} dt={r['dt']:.6g} "
              f"err={r['error']} checks={r['checks']}")


if __name__ == "__main__":
    sys.exit(main())
