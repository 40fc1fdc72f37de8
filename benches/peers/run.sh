#!/usr/bin/env bash
# Runs the peers on this machine, on the same work as
# `cargo run --release --example speed_accuracy`: the worksheet's four-bar over a
# revolution of the dense grid, positions, velocities and accelerations, errors
# against tests/data/bench_fourbar.csv. Sets up its own Python environment
# from PyPI (benches/peers/.venv) and writes benches/results/peers.csv, the
# single pose (benches/results/casadi_pose.csv) and the floor of linkage's
# sweep (benches/results/floor.csv).
set -euo pipefail
cd "$(dirname "$0")"
if [ ! -x .venv/bin/python ]; then
  python3 -m venv .venv
  .venv/bin/pip install --quiet sympy==1.14.0 numpy==2.4.6 casadi==3.8.2
fi
PY=.venv/bin/python
mkdir -p build ../results
out=../results/peers.csv
{
  echo "# Written by benches/peers/run.sh on $(date -u +%Y-%m-%d) ($(uname -m), $(nproc) cores): the peers on the worksheet's four-bar,"
  echo "# median ns per sample and worst relative errors against tests/data/bench_fourbar.csv."
  echo "workload,method,ns_per_sample,error_positions,error_velocities,error_accelerations,samples"
} > "$out"
echo "SymPy ..." >&2
$PY sympy_peer.py >> "$out"
echo "CasADi VM ..." >&2
$PY casadi_peer.py vm >> "$out"
echo "CasADi generated C ..." >&2
$PY casadi_peer.py codegen
gcc -O3 -I build casadi_harness.c build/fourbar_step.c -lm -o build/harness
start=$($PY -c 'from common import start; print(*start())')
read -r ns _ < <(./build/harness build/casadi_c.csv $start)
$PY casadi_c_errors.py build/casadi_c.csv "$ns" "CasADi generated C as its users write it (sin/cos per sample)" >> "$out"
# The sweeps in C fail here if their errors leave the rounding floor.
floor_bounds=1e-15,2e-15,2e-15
echo "CasADi generated C with carried sines and cosines ..." >&2
$PY casadi_pose.py
gcc -O3 -I build casadi_pose_harness.c build/fourbar_pose.c -lm -o build/pose_harness
./build/pose_harness carried build/carried.csv $start > build/carried.out
read -r ns _ < build/carried.out
$PY casadi_c_errors.py build/carried.csv "$ns" "CasADi generated C, sin/cos carried (its own predictor)" --max $floor_bounds >> "$out"
./build/pose_harness ours build/ours.csv $start > build/ours.out
read -r ns _ < build/ours.out
$PY casadi_c_errors.py build/ours.csv "$ns" "CasADi generated C, sin/cos carried + linkage's lagged predictor and chord step" --max $floor_bounds >> "$out"
echo "The closed form in C, swept ..." >&2
gcc -O3 closed_form.c -lm -o build/closed_form
./build/closed_form build/closed_form.csv > build/closed_form.out
read -r ns _ < build/closed_form.out
$PY casadi_c_errors.py build/closed_form.csv "$ns" "closed form in C, swept: sin/cos carried, sqrt, 2 reciprocals, angles followed by series" --max $floor_bounds >> "$out"
cat "$out"
# The single-pose job of `analyze` (warm from the converged pose at
# θ2 = 20°, cold from the README's guess), for the analyze table.
pose=$($PY -c 'from common import pose20; print(*pose20())')
./build/pose_harness pose $pose | head -1 | {
  read -r warm cold iterations
  echo "# Written by benches/peers/run.sh on $(date -u +%Y-%m-%d): CasADi's generated C for analyze's job at θ2 = 20°, median ns per call."
  echo "job,ns_per_call,iterations"
  echo "warm,$warm,1"
  echo "cold,$cold,$iterations"
} > ../results/casadi_pose.csv
cat ../results/casadi_pose.csv
# The floor of linkage's sweep (floor.c): every operation of a pose in a
# bare loop, and the chain from one pose to the next alone.
echo "The floor ..." >&2
gcc -O3 floor.c -lm -o build/floor
./build/floor build/floor.csv $start > build/floor.out
read -r pose chain ghz < build/floor.out
{
  echo "# Written by benches/peers/run.sh on $(date -u +%Y-%m-%d): the floor of linkage's sweep (benches/peers/floor.c), median ns per pose,"
  awk -v p="$pose" -v c="$chain" -v g="$ghz" 'BEGIN { printf "# worst relative errors against tests/data/bench_fourbar.csv; clock %.2f GHz by dependent additions: %.0f and %.0f cycles per pose.\n", g, p * g, c * g }'
  echo "workload,method,ns_per_sample,error_positions,error_velocities,error_accelerations,samples"
  $PY casadi_c_errors.py build/floor.csv "$pose" "floor: every operation of linkage's sweep per pose in a bare C loop" --max $floor_bounds
  printf "four-bar,floor: the chain from one pose to the next alone (latency bound),%.2f,,,,1008000\n" "$chain"
} > ../results/floor.csv
cat ../results/floor.csv
