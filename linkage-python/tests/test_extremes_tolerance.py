"""Extremes and tolerance analysis from Python: the worksheet's four-bar's
extrema against mpmath's roots of the derivative at 50 digits
(tests/data/fourbar_extrema.csv), the spreads against sums of the exact
sensitivities, and the Monte Carlo run against the linear σ."""

import csv
import math

import numpy as np
import pytest

import linkage
from linkage import errors
from conftest import ROOT


@pytest.fixture(scope="module")
def bar():
    return linkage.Mechanism.from_file(ROOT / "mechanisms/four_bar.toml")


def reference():
    rows = [line for line in (ROOT / "tests/data/fourbar_extrema.csv").read_text().splitlines()
            if line and not line.startswith("#")]
    return list(csv.DictReader(rows))


def test_extremes_over_the_turn_against_mpmath(bar):
    omega2 = 400 * 2 * math.pi / 60
    found = bar.extremes(["theta3", "theta4", "theta3'", "theta4'"], steps=360,
                         start=0.0, stop=2 * math.pi, rate=omega2)
    names = {"theta3_deg": "theta3", "theta4_deg": "theta4", "omega3": "theta3'", "omega4": "theta4'"}
    compared = 0
    for row in reference():
        if row["quantity"] not in names:
            continue
        kind = {"min": "minimum", "max": "maximum"}[row["extremum"]]
        match = [f for f in found if f["quantity"] == names[row["quantity"]] and f["kind"] == kind]
        assert len(match) == 1, (row, match)
        scale = math.degrees(1) if row["quantity"].endswith("_deg") else 1.0
        assert match[0]["value"] * scale == pytest.approx(float(row["value"]), rel=1e-12)
        assert math.degrees(match[0]["v"][0]) == pytest.approx(float(row["theta2_deg"]), abs=1e-6)
        compared += 1
    assert compared == 8


def test_zeros_are_found_when_asked(bar):
    found = bar.extremes(["theta4'"], zeros=True, start=0.0, stop=2 * math.pi, steps=360)
    zeros = [f for f in found if f["kind"].startswith("zero")]
    assert len(zeros) == 2 and all(abs(f["value"]) < 1e-9 for f in zeros)
    with pytest.raises(errors.BadInputError, match="not `.z`"):
        bar.extremes(["C.z"])
    with pytest.raises(errors.BadInputError, match="`C.path`"):
        bar.extremes(["C.path"])
    with pytest.raises(errors.BadInputError, match="zz"):
        bar.extremes(["zz"])


def test_spreads_are_sums_of_the_exact_sensitivities(bar):
    t = {"l2": 0.05, "l3": 0.02}
    result = bar.tolerance(t, quantities=["theta4", "C.y"], steps=72)
    assert result["parameters"] == ["l2", "l3"] and result["limit"] is None
    band = result["bands"]["theta4"]
    assert band["value"].shape == (73,) and band["v"].shape == (73, 1)
    for k in [0, 17, 40]:
        s = bar.sensitivities(v=band["v"][k], params=["l2", "l3"])
        assert bar.analyze(v=band["v"][k])["theta4"] == pytest.approx(band["value"][k], abs=1e-9)
        worst = abs(s.u[1, 0]) * t["l2"] + abs(s.u[1, 1]) * t["l3"]
        assert band["worst_case"][k] == pytest.approx(worst, rel=1e-12)
        assert band["rss"][k] == pytest.approx(math.hypot(s.u[1, 0] * t["l2"], s.u[1, 1] * t["l3"]), rel=1e-12)
    k = band["largest"]
    assert band["worst_case"][k] == np.nanmax(band["worst_case"])
    assert sum(band["shares"].values()) == pytest.approx(band["worst_case"][k], rel=1e-12)


def test_monte_carlo_agrees_with_the_linear_sigma(bar):
    result = bar.tolerance({"l2": ("normal", 0.01), "l4": 0.03}, quantities=["theta3"],
                           steps=36, samples=4000, random_state=7)
    band = result["bands"]["theta3"]
    assert result["failed_samples"] == 0
    ratio = band["sigma_monte_carlo"] / band["sigma"]
    assert np.all(np.abs(ratio - 1) < 0.06), ratio
    again = bar.tolerance({"l2": ("normal", 0.01), "l4": 0.03}, quantities=["theta3"],
                          steps=36, samples=4000, random_state=7)
    np.testing.assert_array_equal(again["bands"]["theta3"]["sigma_monte_carlo"], band["sigma_monte_carlo"])


def test_bad_tolerances_are_typed(bar):
    with pytest.raises(errors.BadInputError):
        bar.tolerance({"l2": -0.1})
    with pytest.raises(errors.BadInputError, match="zz"):
        bar.tolerance({"zz": 0.1})
    with pytest.raises(errors.BadInputError, match="\"normal\" or \"band\""):
        bar.tolerance({"l2": ("uniform", 0.1)})
    with pytest.raises(TypeError):
        bar.tolerance({"l2": "0.1"})
