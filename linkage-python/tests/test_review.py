"""What an outside review of the package found, each held here: forked
processes, threads sharing a mechanism, arguments at their limits, rates
of several drivers or backwards, results that must not be written to."""

import math
import multiprocessing
import threading
import time
import _thread

import numpy as np
import pytest

import linkage
from linkage import errors
from conftest import ROOT
from test_synthesis import coupler, path_bounds, path_targets

FOUR_BAR = ROOT / "mechanisms" / "four_bar.toml"
CRANK = "u = [x], v = [t], points = [P = (x, r)], closure = [x - r * t.cos()]"


def _synthesize_in_child(queue):
    m = linkage.Mechanism.from_text(CRANK, {"r": 1.0})
    designs = m.synthesize(function="x", targets=[[0.0, 2.0], [1.0, 2.0 * math.cos(1.0)]],
                           free={"r": (0.5, 3.0)}, starts=16)
    queue.put(len(designs))


def test_a_process_forked_after_a_parallel_call_can_call_again():
    parent = linkage.Mechanism.from_text(CRANK, {"r": 1.0})
    parent.synthesize(function="x", targets=[[0.0, 2.0], [1.0, 2.0 * math.cos(1.0)]],
                      free={"r": (0.5, 3.0)}, starts=16)
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    child = context.Process(target=_synthesize_in_child, args=(queue,))
    child.start()
    child.join(60)
    alive = child.is_alive()
    if alive:
        child.kill()
    assert not alive, "the forked child hangs in its first parallel call"
    assert child.exitcode == 0 and queue.get(timeout=5) >= 1


def test_threads_share_a_mechanism():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    failures = []

    def draw():
        try:
            for _ in range(3):
                bar.svg()
        except Exception as e:  # noqa: BLE001 - any failure is the finding
            failures.append(e)

    thread = threading.Thread(target=draw)
    thread.start()
    for k in range(200):
        bar.set_parameter("l2", 20.0 + 1e-9 * k)
    thread.join()
    assert failures == []


def test_arguments_at_their_limits():
    m = linkage.Mechanism.from_text(CRANK, {"r": 1.0})
    with pytest.raises(errors.BadInputError, match="past the largest start index"):
        m.synthesize(function="x", targets=[[0.0, 2.0]], free={"r": (0.5, 3.0)}, starts=10,
                     first=2**64 - 5)
    with pytest.raises(errors.BadInputError, match="`enough`"):
        m.synthesize(function="x", targets=[[0.0, 2.0]], free={"r": (0.5, 3.0)}, enough=0)
    with pytest.raises(errors.NoDesignError):
        m.synthesize(function="x", targets=[[0.0, 1e200], [1.0, 1e200]], free={"r": (0.5, 3.0)},
                     starts=4)
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    with pytest.raises(errors.BadInputError, match="0 to 100000"):
        bar.svg(width=1e300)


def test_several_drivers_move_at_unit_speed_and_refuse_a_rate():
    two = linkage.Mechanism.from_text("u = [x], v = [a, b], closure = [x - a - b]", {})
    with pytest.raises(errors.BadInputError, match="`rate` is for one driving coordinate"):
        two.sweep(start=[0, 0], stop=[1, 2], steps=4, rate=[5.0, -3.0])
    sweep = two.sweep(start=[0, 0], stop=[1, 2], steps=4)
    np.testing.assert_allclose(np.linalg.norm(sweep.vdot, axis=1), 1.0)
    one = linkage.Mechanism.from_text(CRANK, {"r": 1.0})
    with pytest.raises(errors.BadInputError, match="rate"):
        one.sweep(start=0, stop=1, steps=4, rate=math.nan)
    with pytest.raises(errors.BadInputError, match="stop"):
        one.sweep(start=0, stop=math.nan, steps=4)


def test_extremes_of_a_drive_run_backwards():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    ahead = bar.extremes(["theta4"], start=0, stop=2 * math.pi, rate=1.0)
    back = bar.extremes(["theta4"], start=0, stop=2 * math.pi, rate=-1.0)
    assert [f["kind"] for f in ahead] == [f["kind"] for f in back] and len(back) == 2
    for a, b in zip(ahead, back):
        assert a["value"] == pytest.approx(b["value"], rel=1e-12)
    shaper = linkage.Mechanism.from_file(ROOT / "mechanisms/joints/shaper.toml")
    assert shaper.drive[shaper.v_names[0]]["rate"] < 0
    assert {f["kind"] for f in shaper.extremes()} >= {"maximum", "minimum"}


def test_a_monte_carlo_sigma_of_too_few_samples_is_unknown():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    one = bar.tolerance({"l2": 0.05}, samples=1, steps=8)
    assert np.isnan(one["bands"]["theta3"]["sigma_monte_carlo"]).all()


def test_results_are_read_only_and_behave_as_mappings():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    pose, sweep = bar.analyze(), bar.sweep(steps=10)
    for array in [pose.u, pose.points, sweep.u, sweep.points, sweep.rcond]:
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 99
    assert "C" in sweep and "theta3" in pose and "zz" not in sweep
    assert list(sweep) == sweep.keys() == ["theta3", "theta4", "theta2", *bar.point_names]


def test_lists_where_pairs_are_expected_and_negative_indices():
    m = coupler()
    targets = path_targets(5)
    bounds = {name: list(pair) for name, pair in path_bounds(targets).items()}
    designs = m.synthesize(path="P", targets=targets, free=bounds, precision_points=True,
                           starts=48, at=0.0)
    assert designs.design(-1).parameters == designs.design(len(designs) - 1).parameters
    with pytest.raises(IndexError):
        designs.design(-len(designs) - 1)
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    assert bar.tolerance({"l2": ["normal", 0.01]}, steps=8)["parameters"] == ["l2"]
    assert bar.extremes("theta4", steps=36)[0]["quantity"] == "theta4"
    import json
    examples = json.loads((ROOT / "tests/data/pyslvs_examples.json").read_text())["examples"]
    jansen = next(e for e in examples if e["name"] == "Jansen's linkage (Single)")
    assert linkage.Mechanism.from_pyslvs(jansen["expression"], jansen["inputs"]).f == 1


def test_ctrl_c_stops_a_synthesis_too():
    m = coupler()
    targets = path_targets(9)
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        m.synthesize(path="P", targets=targets, free=path_bounds(targets),
                     precision_points=True, starts=100_000, at=0.0)
    timer.join()
    # The starts under way end; no other begins: the process idles.
    time.sleep(0.2)
    cpu, wall = time.process_time(), time.perf_counter()
    time.sleep(0.5)
    busy = (time.process_time() - cpu) / (time.perf_counter() - wall)
    assert busy < 0.3, f"{busy:.2f} cores still busy after Ctrl-C"


def test_a_mechanism_pickles_whole():
    import copy
    import json
    import pickle

    bar = linkage.Mechanism.from_file(FOUR_BAR).with_parameters(l2=21.5)
    crank = linkage.Mechanism.from_text(CRANK, {"r": 1.0}, name="Crank")
    crank.set_parameter("r", 2.5)
    examples = json.loads((ROOT / "tests/data/pyslvs_examples.json").read_text())["examples"]
    jansen = next(e for e in examples if e["name"] == "Jansen's linkage (Single)")
    leg = linkage.Mechanism.from_pyslvs(jansen["expression"], jansen["inputs"], name="Jansen")
    for m, v in [(bar, None), (crank, 0.4), (leg, 0.9)]:
        back = pickle.loads(pickle.dumps(m))
        assert repr(back) == repr(m) and back.parameters == m.parameters
        assert back.topology_text == m.topology_text
        assert np.array_equal(back.analyze(v=v).u, m.analyze(v=v).u)
        assert np.array_equal(copy.deepcopy(m).analyze(v=v).points, m.analyze(v=v).points)
    with pytest.raises(errors.BadInputError, match="a path's"):
        crank.synthesize(function="x", targets=[[0.0, 2.0]], free={"r": (0.5, 3.0)},
                         timing="prescribed", drivers=[0.0])
