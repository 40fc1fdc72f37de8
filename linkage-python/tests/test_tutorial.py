"""docs/python.md's code blocks, run in order from the repository's root:
the tutorial says what the package does."""

import contextlib
import io
import os
import re

from conftest import ROOT


def test_the_tutorial_runs():
    text = (ROOT / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 6
    namespace = {}
    here = os.getcwd()
    os.chdir(ROOT)
    try:
        with contextlib.redirect_stdout(io.StringIO()) as out:
            for block in blocks:
                exec(compile(block, "docs/python.md", "exec"), namespace)
    finally:
        os.chdir(here)
    printed = out.getvalue()
    assert "Mechanism(FourBar: u = [theta3, theta4], v = [theta2], 5 points)" in printed
    assert "non-finite input: v[0] = NaN" in printed
    assert "cannot assemble:" in printed
