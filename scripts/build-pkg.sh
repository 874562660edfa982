#!/usr/bin/env bash
# Builds the npm package `fisst` into wasm/pkg/ (wasm-bindgen --target web + a Node entry).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --locked --target wasm32-unknown-unknown -p fisst-wasm
target_dir=${CARGO_TARGET_DIR:-target}
rm -rf wasm/pkg
wasm-bindgen --target web --remove-name-section --remove-producers-section --out-dir wasm/pkg --out-name fisst_wasm \
  "$target_dir/wasm32-unknown-unknown/release/fisst_wasm.wasm"
cp wasm/npm/node.js wasm/npm/README.md wasm/pkg/
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -n 1)
sed "s/\"version\": \"0.0.0\"/\"version\": \"$version\"/" wasm/npm/package.json > wasm/pkg/package.json
printf 'built wasm/pkg (fisst %s): %s bytes of wasm\n' "$version" "$(wc -c < wasm/pkg/fisst_wasm_bg.wasm)"
