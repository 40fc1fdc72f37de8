#!/usr/bin/env bash
# Builds the page's engine: linkage compiled to WebAssembly (release) and
# its JavaScript bindings into web/pkg/. Needs the target
# wasm32-unknown-unknown (rustup target add wasm32-unknown-unknown) and
# wasm-bindgen's command-line tool of the same version as the crate
# (cargo install wasm-bindgen-cli --version =0.2.130).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build -p linkage-web --target wasm32-unknown-unknown --release
wasm-bindgen --target web --out-dir web/pkg --no-typescript \
  target/wasm32-unknown-unknown/release/linkage_web.wasm
