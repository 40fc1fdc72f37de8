#!/usr/bin/env bash
# linkage's Python package beside pylinkage 1.3.0, in one process: sets up
# its own environment (benches/peers/.venv-side-by-side: pylinkage with its
# numba extra, SciPy, and this repository's package built in release by
# pip), then writes benches/results/python_side_by_side.md.
#
#     bash benches/peers/python_side_by_side.sh   # a few minutes
set -euo pipefail
cd "$(dirname "$0")"
if [ ! -x .venv-side-by-side/bin/python ]; then
  python3 -m venv .venv-side-by-side
  .venv-side-by-side/bin/pip install --quiet "pylinkage[numba]==1.3.0" scipy==1.17.1 sympy==1.14.0 numba==0.68.1 numpy==2.4.6
fi
.venv-side-by-side/bin/pip install --quiet --force-reinstall --no-deps ../../linkage-python
mkdir -p ../results
.venv-side-by-side/bin/python python_side_by_side.py | tee ../results/python_side_by_side.md
