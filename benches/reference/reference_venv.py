"""The reference scripts' one environment: mpmath 1.3.0 (and, for the scripts
that ask for it, SymPy) in benches/reference/.venv.

`ensure_venv(script, packages)` re-runs `script` (with its arguments) in that
venv, creating it first if needed and installing `packages` (pinned
requirements; mpmath's by default) that it lacks; within the venv it does
nothing. With
REFERENCE_NO_VENV=1 the script runs where it was started (an mpmath already
installed there).
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
VENV = os.path.join(HERE, ".venv")
PY = os.path.join(VENV, "bin", "python")


def ensure_venv(script, packages=("mpmath==1.3.0",)):
    if os.environ.get("REFERENCE_NO_VENV") == "1":
        return
    if os.path.abspath(sys.prefix) == os.path.abspath(VENV):
        return
    if not os.path.exists(PY):
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
    # pip leaves a requirement already met alone.
    subprocess.check_call([PY, "-m", "pip", "install", "--quiet", *packages])
    os.execv(PY, [PY, os.path.abspath(script)] + sys.argv[1:])
