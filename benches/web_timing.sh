#!/usr/bin/env bash
# The page's speed in a real browser: headless Chromium opens
# web/index.html?timing, which sweeps the six-bar of the library through
# 720 poses and redraws its picture 25 times (what a drag of the driver
# asks), and logs the median. Three runs. Build the page first
# (bash web/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
for run in 1 2 3; do
  timeout 60 chromium --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
    --enable-logging=stderr --v=0 "file://$PWD/web/index.html?timing" 2>&1 |
    grep -o 'six-bar: .*ms ([^)]*)' | head -1 || true
done
