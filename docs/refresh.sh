#!/usr/bin/env bash
# Refreshes the committed figures and result tables: runs every example with
# its output folder (LINKAGE_OUT) pointed at the tracked files. Running an
# example by hand writes to out/ instead, which git ignores.
#
#     docs/refresh.sh            # the figures (a few minutes)
#     docs/refresh.sh --speed    # and the speed tables: benches/speed_tables.sh
#                                # (three runs of ours and the peers, ~20 minutes),
#                                # and the synthesis side by side with pylinkage:
#                                # benches/peers/synthesis.sh (one run, ~5 minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
run() { # example, folder, [cargo args]
  local example=$1 folder=$2
  shift 2
  LINKAGE_OUT="$folder" cargo run --quiet --release "$@" --example "$example" > /dev/null
  echo "refreshed $folder ($example)"
}
run fourbar docs/figures/fourbar
run shaper docs/figures/shaper
run cam docs/figures/cam
run tolerance docs/figures/tolerance
run stability docs/figures
run expansion_cost docs/figures -p linkage-macros
cargo run --quiet --release -p linkage-cli -- draw mechanisms/joints/jansen_double.toml \
  -o docs/figures/topology/jansen_double.svg
echo "refreshed docs/figures/topology (linkage draw)"
# The page, as a reader sees it (headless Chromium through `linkage serve`,
# the engine built; a Python with websocket-client, as CI's target/ci-venv).
bash web/build.sh > /dev/null
cargo build -q -p linkage-cli
mkdir -p docs/figures/web
"${PYTHON:-target/ci-venv/bin/python}" tests/web/page_figure.py docs/figures/web/page.png
echo "refreshed docs/figures/web/page.png"
if [[ ${1:-} == --speed ]]; then
  benches/speed_tables.sh
  LINKAGE_OUT=docs/figures/synthesis bash benches/peers/synthesis.sh > /dev/null
  echo "refreshed docs/figures/synthesis and benches/results/synthesis*.{csv,md} (synthesis beside pylinkage)"
else
  # (The synthesis figures and designs.csv are left alone: they are the
  # output of one run of benches/peers/synthesis.sh, with its tables.)
  # The speed chart from the committed measurements.
  LINKAGE_OUT=docs/figures cargo run --quiet --release --example speed_accuracy -- --chart > /dev/null
  rm -f docs/figures/ours.csv
  echo "refreshed docs/figures/speed_accuracy.svg"
fi
