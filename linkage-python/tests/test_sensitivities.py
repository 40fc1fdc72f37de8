"""Exact sensitivities from Python against mpmath's at 50 digits: the
worksheet's four-bar at θ2 = 20°, 400 rpm (tests/data/sensitivities.csv,
closed forms differentiated by mpmath)."""

import csv

import numpy as np
import pytest

import linkage
from linkage import errors
from conftest import ROOT


def reference():
    rows = [line for line in (ROOT / "tests/data/sensitivities.csv").read_text().splitlines()
            if line and not line.startswith("#")]
    table = {}
    for row in csv.DictReader(rows):
        if row["mechanism"] == "fourbar" and row["param"] != "-":
            table[(row["quantity"], row["param"])] = [
                float(row[k]) for k in ("by_param", "dot_by_param", "ddot_by_param")]
    return table


def test_the_worksheets_four_bar_against_mpmath():
    bar = linkage.Mechanism.from_file(ROOT / "mechanisms/four_bar.toml")
    s = bar.sensitivities()
    assert s.parameter_names == ["l1", "l2", "l3", "l4"]
    assert s.u.shape == (2, 4) and s.points.shape == (len(bar.point_names), 2, 4)
    ref = reference()
    compared = 0
    for (quantity, param), (x, xdot, xddot) in ref.items():
        j = s.parameter_names.index(param)
        if quantity in s.u_names:
            i = s.u_names.index(quantity)
            ours = [s.u[i, j], s.udot[i, j], s.uddot[i, j]]
        else:
            name, axis = quantity.split(".")
            if name not in s.point_names:
                continue
            i, a = s.point_names.index(name), "xy".index(axis)
            ours = [s.points[i, a, j], s.point_velocities[i, a, j], s.point_accelerations[i, a, j]]
        for value, exact in zip(ours, [x, xdot, xddot]):
            assert value == pytest.approx(exact, rel=1e-12, abs=1e-12 * max(1.0, abs(xddot)))
        compared += 1
    assert compared >= 16


def test_chosen_parameters_and_refusals():
    bar = linkage.Mechanism.from_file(ROOT / "mechanisms/four_bar.toml")
    all_four = bar.sensitivities()
    two = bar.sensitivities(params=["l3", "l2"])
    assert two.parameter_names == ["l3", "l2"]
    np.testing.assert_array_equal(two.u, all_four.u[:, [2, 1]])
    with pytest.raises(errors.BadInputError, match="l9"):
        bar.sensitivities(params=["l9"])
    with pytest.raises(errors.BadInputError):
        bar.sensitivities(v=float("inf"))
