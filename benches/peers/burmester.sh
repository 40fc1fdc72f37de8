#!/usr/bin/env bash
# pylinkage 1.3.0's Burmester dyads for the poses of tests/data/burmester_poses.csv, and how
# they compare with the 50-digit reference of benches/reference/burmester.py. Uses (or
# creates) benches/peers/.venv and installs pylinkage 1.3.0 from PyPI there if it is
# missing (with SciPy, which its synthesis module imports); writes
# tests/data/burmester_pylinkage.csv and tests/data/burmester_pylinkage_comparison.csv.
set -euo pipefail
cd "$(dirname "$0")"
if [ ! -x .venv/bin/python ]; then
  python3 -m venv .venv
fi
if ! .venv/bin/python -c 'import pylinkage, scipy, sys; sys.exit(pylinkage.__version__ != "1.3.0")' 2>/dev/null; then
  .venv/bin/pip install --quiet pylinkage==1.3.0 scipy==1.17.1 numpy==2.4.6
fi
.venv/bin/python burmester_pylinkage.py
