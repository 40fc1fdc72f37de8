"""The reference scripts' one environment: mpmath 1.3.0 in benches/reference/.venv.

`ensure_venv(script)` re-runs `script` (with its arguments) in that venv,
creating it first if needed; within the venv it does nothing. With
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


def ensure_venv(script):
    if os.environ.get("REFERENCE_NO_VENV") == "1":
        return
    if os.path.abspath(sys.prefix) == os.path.abspath(VENV):
        return
    if not os.path.exists(PY):
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([PY, "-m", "pip", "install", "--quiet", "mpmath==1.3.0"])
    os.execv(PY, [PY, os.path.abspath(script)] + sys.argv[1:])
