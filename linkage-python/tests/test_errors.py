"""Bad input from Python raises a typed exception whose message is the
Rust library's: the class says what failed (`linkage.errors`), never a
crash of the interpreter."""

import math
import subprocess

import numpy as np
import pytest

import linkage
from linkage import errors
from conftest import ROOT

FOUR_BAR = ROOT / "mechanisms" / "four_bar.toml"
CLI = ROOT / "target" / "debug" / "linkage"


@pytest.fixture(scope="module")
def bar():
    return linkage.Mechanism.from_file(FOUR_BAR)


def test_every_class_is_a_linkage_error():
    for name in dir(errors):
        value = getattr(errors, name)
        if isinstance(value, type) and issubclass(value, Exception):
            assert issubclass(value, errors.LinkageError), name


def test_arguments_out_of_range(bar):
    with pytest.raises(errors.BadInputError, match=r"non-finite input: v\[0\] = NaN"):
        bar.analyze(v=math.nan)
    with pytest.raises(errors.BadInputError, match=r"non-finite input: vdot\[0\] = inf"):
        bar.analyze(vdot=[math.inf])
    with pytest.raises(errors.BadInputError, match=r"`v` has 2 values; it takes 1, one for each of \[theta2\]"):
        bar.analyze(v=[1.0, 2.0])
    with pytest.raises(errors.BadInputError, match="`u` has 3 values"):
        bar.analyze(u=np.zeros(3))
    with pytest.raises(errors.BadInputError, match="`steps` is 0"):
        bar.sweep(steps=0)
    with pytest.raises(errors.BadInputError, match="1 to 1000000 steps"):
        bar.sweep(steps=10**9)
    with pytest.raises(errors.BadInputError, match="the mechanism has no parameter `l9`; its parameters: l1, l2, l3, l4"):
        bar.set_parameter("l9", 1.0)
    with pytest.raises(errors.BadInputError, match="NaN"):
        bar.with_parameters(l2=math.nan)
    with pytest.raises(errors.BadInputError):
        bar.svg(width=-1.0)
    with pytest.raises(errors.BadInputError, match="give `v`"):
        linkage.Mechanism.from_text("u = [x], v = [t], closure = [x - t]", {}).analyze()


def test_wrong_types_and_names_are_pythons_own(bar):
    with pytest.raises(TypeError):
        bar.analyze(v="twenty degrees")
    with pytest.raises(TypeError, match="a number or a sequence of numbers"):
        bar.analyze(v=["one"])
    with pytest.raises(TypeError):
        bar.analyze(v=[[1.0]])
    with pytest.raises(TypeError):
        bar.analyze(v=1 + 2j)
    with pytest.raises(TypeError):
        bar.analyze(v=np.array([True]))
    with pytest.raises(OverflowError):
        bar.sweep(steps=-1)
    with pytest.raises(TypeError):
        linkage.Mechanism.from_text("u = [x], v = [t], closure = [x - t]", {"a": "one"})
    with pytest.raises(KeyError, match="`Z` is no coordinate or point"):
        bar.analyze()["Z"]


def test_what_fails_in_the_analysis_says_so(bar):
    too_short = bar.with_parameters(l4=5.0)
    with pytest.raises(errors.CannotAssembleError, match="cannot be assembled"):
        too_short.analyze()
    # Coupler and rocker in line: Ψ_u singular at Newton's start.
    with pytest.raises(errors.SingularPoseError, match="Ψ_u is singular in the position solve"):
        bar.analyze(u=[0.5, 0.5])
    nine = ", ".join(f"x{k}" for k in range(9))
    closure = ", ".join(f"x{k} - t" for k in range(9))
    with pytest.raises(errors.SizeError, match="m = 9"):
        linkage.Mechanism.from_text(f"u = [{nine}], v = [t], closure = [{closure}]", {}).analyze(v=0.0)
    with pytest.raises(errors.FormatError):
        linkage.Mechanism.from_pyslvs("M[J[nonsense", [(0, 1)])
    with pytest.raises(errors.FormatError):
        linkage.Mechanism.from_pylinkage("{not json")
    with pytest.raises(FileNotFoundError) as missing:
        linkage.Mechanism.from_file(ROOT / "no such file.toml")
    assert isinstance(missing.value, errors.FileMissingError) and isinstance(missing.value, errors.FileError)
    with pytest.raises(errors.FileError) as directory:
        linkage.Mechanism.from_file(ROOT / "mechanisms")
    assert not isinstance(directory.value, FileNotFoundError)


BAD_FILE = """name = "Bad"
equations = '''
u = [a],
v = [b],
closure = [a - c * b.sin() - d],
'''
[parameters]
c = "2 mm"

[drive.b]
from = 0
to = 1
"""


def test_a_files_mistakes_are_located_as_the_command_line_tool_shows_them(tmp_path):
    with pytest.raises(errors.MistakesError) as raised:
        linkage.Mechanism.from_toml(BAD_FILE, name="bad.toml")
    message = str(raised.value)
    assert "bad.toml:5:" in message and "`d`" in message
    assert CLI.exists(), "the command-line tool is built by `cargo test --workspace` first"
    path = tmp_path / "bad.toml"
    path.write_text(BAD_FILE)
    tool = subprocess.run([CLI, "check", path], capture_output=True, text=True, cwd=tmp_path)
    assert tool.returncode == 1
    with pytest.raises(errors.MistakesError) as from_file:
        linkage.Mechanism.from_file(path)
    assert tool.stderr.rstrip("\n") == str(from_file.value)


def test_an_analysis_refused_at_the_drive_says_what_the_tool_says(tmp_path):
    text = FOUR_BAR.read_text().replace('l4 = "70 mm"', 'l4 = "5 mm"')
    assert text != FOUR_BAR.read_text()
    path = tmp_path / "short.toml"
    path.write_text(text)
    with pytest.raises(errors.CannotAssembleError) as raised:
        linkage.Mechanism.from_file(path).analyze()
    tool = subprocess.run([CLI, "analyze", path], capture_output=True, text=True, cwd=tmp_path)
    assert tool.returncode == 3
    assert str(raised.value) in tool.stderr
