#!/usr/bin/env bash
# Synthesis side by side with pylinkage 1.3.0, in one run: pylinkage on the
# tasks of `cargo run --release --example synthesis` (path generation through
# 5 and 9 points of the worksheet's coupler curve of G3, Freudenstein's three
# precision points), written to benches/results/synthesis_pylinkage.csv, then
# the example itself, which measures ours and judges every design of both with
# linkage's certificate. Sets up its own Python environment from PyPI
# (benches/peers/.venv-synthesis: pylinkage with its numba extra, SciPy for its
# differential evolution, SymPy). The example's tables go to
# benches/results/synthesis.md, its figures and designs.csv where LINKAGE_OUT
# says (out/synthesis/ by default; docs/refresh.sh --speed: docs/figures/synthesis).
#
#     bash benches/peers/synthesis.sh            # a few minutes
set -euo pipefail
cd "$(dirname "$0")"
if [ ! -x .venv-synthesis/bin/python ]; then
  python3 -m venv .venv-synthesis
  .venv-synthesis/bin/pip install --quiet "pylinkage[numba]==1.3.0" scipy==1.17.1 sympy==1.14.0 numba==0.68.1 numpy==2.4.6
fi
mkdir -p ../results
out=../results/synthesis_pylinkage.csv
echo "pylinkage ..." >&2
.venv-synthesis/bin/python synthesis_pylinkage.py "$out"
cd ../..
echo "linkage ..." >&2
cargo run --quiet --release --example synthesis -- --peers benches/results/synthesis_pylinkage.csv |
  tee benches/results/synthesis.md
