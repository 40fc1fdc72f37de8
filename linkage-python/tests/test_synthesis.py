"""Synthesis from Python: path generation through points of the Maple
worksheet's coupler curve (an exact design exists), every design
certified; a search split into shards gives the whole search's rows;
impossible problems raise typed exceptions."""

import math

import numpy as np
import pytest

import linkage
from linkage import errors

# The library's CouplerFourBar: ground pivots, three links and the coupler
# point P in the coupler's frame free, nine parameters.
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
WORKSHEET = {"xa": 0.0, "ya": 0.0, "xd": 80.0, "yd": 0.0, "l2": 20.0, "l3": 50.0, "l4": 70.0,
             "px": 25.0, "py": 0.0}


def coupler():
    return linkage.Mechanism.from_text(COUPLER_FOUR_BAR, WORKSHEET, name="CouplerFourBar")


def path_targets(n):
    """G3 of the worksheet's four-bar at θ2 = 360°·k/n."""
    bar, u, targets = coupler(), [1.3, -0.8], []
    for k in range(n):
        pose = bar.analyze(v=2 * math.pi * k / n, u=u)
        u = pose.u
        targets.append(pose["P"])
    return np.array(targets)


def path_bounds(targets):
    """The bounds of the performance tables' path tasks: from the targets'
    box (centre c, diagonal d)."""
    lo, hi = targets.min(axis=0), targets.max(axis=0)
    c, d = (lo + hi) / 2, np.linalg.norm(hi - lo)
    return {
        "xa": (c[0] - 2 * d, c[0] + 2 * d), "ya": (c[1] - 2 * d, c[1] + 2 * d),
        "xd": (c[0] - 2 * d, c[0] + 2 * d), "yd": (c[1] - 2 * d, c[1] + 2 * d),
        "l2": (0.05 * d, 2 * d), "l3": (0.05 * d, 2 * d), "l4": (0.05 * d, 2 * d),
        "px": (-2 * d, 2 * d), "py": (-2 * d, 2 * d),
    }


def test_five_points_of_the_worksheets_coupler_curve():
    targets = path_targets(5)
    bar = coupler()
    designs = bar.synthesize(path="P", targets=targets, free=path_bounds(targets),
                             precision_points=True, starts=48, at=0.0)
    assert len(designs) >= 1 and designs.free == list(path_bounds(targets))
    assert designs.parameters.shape == (len(designs), 9)
    assert (designs.largest_error < 1e-9).all(), designs.largest_error
    assert np.all(np.diff(designs.rms_error) >= 0), "best first"
    # Certified over a whole turn.
    np.testing.assert_allclose(np.abs(designs.certified_to - designs.certified_from), 2 * math.pi)
    assert (designs.transmission >= math.radians(40) - 1e-12).all()
    # The best design, as a mechanism, passes through every target at its driver.
    best = designs.design(0)
    assert best.parameters == dict(zip(designs.parameter_names, designs.parameters[0]))
    for target, driver in zip(targets, designs.drivers[0]):
        miss = np.linalg.norm(best.analyze(v=driver)["P"] - target)
        assert miss < 1e-9 or min(
            np.linalg.norm(best.analyze(v=driver, u=u)["P"] - target) for u in best.assemble(v=driver)
        ) < 1e-9


def test_shards_of_a_search_are_the_whole_search_row_for_row():
    targets = path_targets(5)
    bar = coupler()
    common = dict(path="P", targets=targets, free=path_bounds(targets), precision_points=True,
                  random_state=3, distinct=False, at=0.0, none_is_error=False)
    whole = bar.synthesize(starts=24, **common)
    parts = [bar.synthesize(first=a, starts=b - a, **common) for a, b in [(0, 7), (7, 16), (16, 24)]]
    assert sum(p.starts for p in parts) == whole.starts == 24
    order = np.argsort(whole.start, kind="stable")
    rows = np.concatenate([p.parameters[np.argsort(p.start, kind="stable")] for p in parts])
    assert len(rows) == len(whole) > 1
    assert np.array_equal(rows, whole.parameters[order])  # bit for bit
    assert sorted(s for p in parts for s in p.start) == sorted(whole.start)


def test_impossible_or_malformed_problems_raise_typed_exceptions():
    bar = coupler()
    far = np.array([[1e4, 1e4], [1e4 + 1, 1e4], [1e4, 1e4 + 1]])
    tight = {"l2": (19.0, 21.0), "l3": (49.0, 51.0)}
    # Least squares certifies the closest design it can run; precision
    # points must be met.
    closest = bar.synthesize(path="P", targets=far, free=tight, starts=8, at=0.0)
    assert closest.largest_error[0] > 1e4
    with pytest.raises(errors.NoDesignError, match="no design found from 8 starts"):
        bar.synthesize(path="P", targets=far, free=tight, starts=8, at=0.0, precision_points=True)
    assert len(bar.synthesize(path="P", targets=far, free=tight, starts=8, at=0.0,
                              precision_points=True, none_is_error=False)) == 0
    targets = path_targets(5)
    with pytest.raises(errors.BadInputError, match="timing"):
        bar.synthesize(path="P", targets=targets, free=tight, timing="sometimes")
    with pytest.raises(errors.BadInputError, match="`zz`"):
        bar.synthesize(path="P", targets=targets, free={"zz": (1.0, 2.0)})
    with pytest.raises(errors.BadInputError, match="`Q`"):
        bar.synthesize(path="Q", targets=targets, free=tight)
    with pytest.raises(errors.BadInputError, match="empty or not finite"):
        bar.synthesize(path="P", targets=targets, free={"l2": (2.0, 1.0)})
    with pytest.raises(errors.BadInputError, match="one of `path`"):
        bar.synthesize(targets=targets, free=tight)
    with pytest.raises(TypeError, match="rows of 2 numbers"):
        bar.synthesize(path="P", targets=[1.0, 2.0], free=tight)
    with pytest.raises(errors.BadInputError):
        bar.synthesize(path="P", targets=[[math.nan, 0.0]], free=tight)


def test_the_smallest_transmission_angle_is_the_callers():
    targets = path_targets(5)
    bar = coupler()
    common = dict(path="P", targets=targets, free=path_bounds(targets), precision_points=True,
                  starts=48, at=0.0, none_is_error=False)
    loose = bar.synthesize(min_transmission=0.0, **common)
    strict = bar.synthesize(min_transmission=math.radians(50), **common)
    default = bar.synthesize(**common)
    assert len(strict) <= len(default) <= len(loose) and len(loose) > len(strict)
    assert (strict.transmission >= math.radians(50) - 1e-12).all()
    assert (loose.transmission < math.radians(40)).any()
    with pytest.raises(errors.BadInputError, match="min_transmission"):
        bar.synthesize(min_transmission=2.0, **common)
