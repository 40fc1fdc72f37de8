"""The analyses from Python, against numbers computed elsewhere: the Maple
worksheet's four-bar recomputed with mpmath at 50 digits, Jansen's leg
solved dyad by dyad at 50 digits, pyslvs's and pylinkage's own
simulations (tests/data/)."""

import json
import math
import re

import numpy as np
import pytest

import linkage
from conftest import ROOT, read_csv

FOUR_BAR = ROOT / "mechanisms" / "four_bar.toml"


def test_the_worksheet_pose_from_the_file():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    pose = bar.analyze()
    reference = {}
    for line in (ROOT / "tests/data/fourbar_worksheet.csv").read_text().splitlines():
        if line and not line.startswith(("#", "key,")):
            key, value, _ = line.split(",", 2)
            reference[key] = float(value)
    assert pose.v_names == ["theta2"]
    assert pose["theta2"] == pytest.approx(math.radians(20), rel=1e-15)
    assert math.degrees(pose["theta3"]) == pytest.approx(70.55076547002993, rel=1e-13)
    assert pose.u.shape == (2,) and pose.points.shape == (len(bar.point_names), 2)
    assert pose.residual < 1e-12


def test_a_sweep_matches_the_50_digit_turn():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    ref = read_csv(ROOT / "tests/data/fourbar_sweep.csv")
    omega2 = 400 * 2 * math.pi / 60
    sweep = bar.sweep(start=0.0, stop=math.radians(359), steps=359, rate=omega2)
    assert len(sweep) == 360 and sweep.complete and sweep.events == []
    assert sweep.u.shape == (360, 2) and sweep.v.shape == (360, 1)
    assert sweep.points.shape == (360, len(bar.point_names), 2)
    np.testing.assert_allclose(np.degrees(sweep["theta3"]), ref["theta3_deg"], rtol=0, atol=1e-11)
    np.testing.assert_allclose(np.degrees(sweep["theta4"]), ref["theta4_deg"], rtol=0, atol=1e-11)
    np.testing.assert_allclose(sweep.udot[:, 0], ref["omega3"], rtol=1e-11, atol=1e-11)
    np.testing.assert_allclose(sweep.uddot[:, 1], ref["alpha4"], rtol=1e-10, atol=1e-9)


def test_jansens_leg_against_its_dyads():
    leg = linkage.Mechanism.from_file(ROOT / "mechanisms" / "jansen_leg.toml")
    ref = read_csv(ROOT / "tests/data/jansen_leg.csv")
    names = [n for n in ref if n.startswith("phi_")]
    assert [f"phi_{n[4:]}" for n in names] == names
    for k, theta in enumerate(ref["theta"]):
        guess = [ref[n][k] for n in names]
        pose = leg.analyze(v=theta, u=guess)
        for n in names:
            assert pose[n] == pytest.approx(ref[n][k], abs=1e-12)
        assert pose["Foot"] == pytest.approx([ref["foot_x"][k], ref["foot_y"][k]], abs=1e-11)


def test_every_assembly_mode_without_a_guess():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    modes = bar.assemble()
    assert modes.shape == (2, 2)
    # The file's assembly is one of them.
    assert np.abs(modes - bar.analyze().u).max(axis=1).min() < 1e-12


def test_a_mechanism_from_its_equations():
    slider = linkage.Mechanism.from_text(
        "u = [x], v = [t], points = [P = (x, 0.0)], closure = [x - r * t.cos() - (l * l - (r * t.sin()).powi(2)).sqrt()]",
        {"r": 1.0, "l": 3.0},
        name="Slider",
    )
    assert (slider.name, slider.m, slider.f, slider.point_names) == ("Slider", 1, 1, ["P"])
    assert slider.drive is None and slider.file_text is None
    pose = slider.analyze(v=0.0)
    assert pose["x"] == pytest.approx(4.0, rel=1e-15)
    assert pose["P"] == pytest.approx([4.0, 0.0])
    sweep = slider.sweep(start=0.0, stop=math.pi, steps=6)
    assert sweep["x"][-1] == pytest.approx(2.0, rel=1e-14)
    longer = slider.with_parameters(l=4.0)
    assert longer.analyze(v=0.0)["x"] == pytest.approx(5.0, rel=1e-15)
    assert slider.parameters == {"r": 1.0, "l": 3.0}


def test_pyslvs_jansen_as_pyslvs_draws_it():
    examples = json.loads((ROOT / "tests/data/pyslvs_examples.json").read_text())["examples"]
    jansen = next(e for e in examples if e["name"] == "Jansen's linkage (Single)")
    leg = linkage.Mechanism.from_pyslvs(
        jansen["expression"], [tuple(i) for i in jansen["inputs"]], name="Jansen"
    )
    pose = leg.analyze(v=np.radians(jansen["drawn_input_angles_deg"]))
    drawn = re.findall(r"P\[([-\d.e]+), ([-\d.e]+)\]", jansen["expression"])
    for name in pose.point_names:
        assert pose[name] == pytest.approx([float(x) for x in drawn[int(name[1:])]], abs=1e-10)
    assert "[joints]" in leg.topology_text


def test_pylinkage_hoeken_step_by_step():
    source = (ROOT / "tests/data/pylinkage/hoeken.json").read_text()
    steps = json.loads((ROOT / "tests/data/pylinkage/hoeken_positions.json").read_text())
    from_text = linkage.Mechanism.from_pylinkage(source)
    from_dict = linkage.Mechanism.from_pylinkage(json.loads(source))
    assert from_text.topology_text == from_dict.topology_text
    (driver, drive), = from_text.drive.items()
    n, dt = steps["iterations"], steps["dt"]
    sweep = from_text.sweep(
        start=drive["at"] + drive["rate"] * dt,
        stop=drive["at"] + drive["rate"] * dt * n,
        steps=n - 1,
    )
    assert sweep.complete and len(sweep) == n
    moving = [j for j, joint in enumerate(steps["joint_names"]) if joint in sweep.point_names]
    assert [steps["joint_names"][j] for j in moving] == ["B", "C", "P"]
    worst = max(
        np.abs(sweep[steps["joint_names"][j]][k] - step[j]).max()
        for k, step in enumerate(steps["steps"])
        for j in moving
    )
    # pylinkage solves each step in closed form, its crank angle re-read
    # from the positions (a drift of ~1e-14 a turn): held, as the Rust
    # tests hold it, to 1e-11 of the drawing's size (about 5 here).
    size = np.ptp(np.array(steps["initial"]), axis=0).max()
    assert worst < 1e-11 * size


def test_a_file_draws_itself():
    bar = linkage.Mechanism.from_file(FOUR_BAR)
    svg = bar._repr_svg_()
    assert svg.startswith("<svg") and svg == bar.svg()
    assert "The four-bar of the Maple worksheet" in svg
    assert linkage.Mechanism.from_text("u = [x], v = [t], closure = [x - t]", {})._repr_svg_() is None
