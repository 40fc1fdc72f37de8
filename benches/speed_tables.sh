#!/usr/bin/env bash
# Re-measures every speed table of docs/performance.md in one session: three runs,
# each of them ours (`speed_accuracy`), the peers (benches/peers/run.sh), the
# criterion benchmarks of analyze and the sweep, and the batch, back to back
# so that they share the machine's state; then prints the tables with the
# medians of the three runs and their spread (benches/speed_tables.py), and
# copies the last run's ours.csv, batch.csv and speed chart
# to benches/results/ and docs/figures/.
#
#     benches/speed_tables.sh            # about 10 minutes on 2 cores
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
out=benches/results/runs
rm -rf "$out" && mkdir -p "$out"
for r in $(seq 1 "$runs"); do
  echo "run $r of $runs ..." >&2
  LINKAGE_OUT=out/speed_accuracy cargo run --quiet --release --example speed_accuracy > /dev/null
  cp out/speed_accuracy/ours.csv "$out/ours.$r.csv"
  benches/peers/run.sh > /dev/null
  cp benches/results/peers.csv "$out/peers.$r.csv"
  cp benches/results/casadi_pose.csv "$out/casadi_pose.$r.csv"
  cargo bench --quiet --bench kernels -- 'analyze|sweep' > /dev/null 2>&1
  { echo "group,benchmark,median_ns"
  for f in target/criterion/*/*/new/estimates.json; do
    group=$(basename "$(dirname "$(dirname "$(dirname "$f")")")")
    name=$(basename "$(dirname "$(dirname "$f")")")
    python3 -c 'import json,sys; print(sys.argv[2], sys.argv[3], json.load(open(sys.argv[1]))["median"]["point_estimate"], sep=",")' "$f" "$group" "$name"
  done; } > "$out/kernels.$r.csv"
  LINKAGE_OUT=out/batch cargo run --quiet --release --example batch > /dev/null
  cp out/batch/batch.csv "$out/batch.$r.csv"
done
# The last run's measurements and chart become the committed ones.
cp out/speed_accuracy/ours.csv benches/results/ours.csv
cp out/speed_accuracy/speed_accuracy.svg docs/figures/speed_accuracy.svg
cp out/batch/batch.csv benches/results/batch.csv
python3 benches/speed_tables.py "$out" "$(git rev-parse --short HEAD)" | tee benches/results/speed_tables.md
