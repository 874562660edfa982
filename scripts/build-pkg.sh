#!/usr/bin/env bash
# Builds the npm package `fisst` into wasm/pkg/: one wasm module per part (a Cargo feature of
# fisst-wasm each, by wasm-bindgen --target web), then the entries that join them
# (scripts/pkg-facade.mjs): `fisst_wasm.js` (browser, `await init()`), `node.js` (Node, no
# init), `fisst_wasm.d.ts`, and per part `<part>.js` / `<part>.node.js` for `fisst/<part>`.
set -euo pipefail
cd "$(dirname "$0")/.."
parts=(bernoulli splitting filters bounds metrics control)
target_dir=${CARGO_TARGET_DIR:-target}
rm -rf wasm/pkg
for part in "${parts[@]}"; do
  cargo build --release --locked --target wasm32-unknown-unknown -p fisst-wasm \
    --no-default-features --features "$part"
  wasm-bindgen --target web --remove-name-section --remove-producers-section \
    --out-dir wasm/pkg --out-name "$part" "$target_dir/wasm32-unknown-unknown/release/fisst_wasm.wasm"
  node scripts/pkg-guards.mjs wasm/pkg "$part"
done
cp wasm/npm/README.md LICENSE-MIT LICENSE-APACHE CHANGELOG.md wasm/pkg/
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -n 1)
node scripts/pkg-facade.mjs wasm/pkg "$version" "${parts[@]}"
