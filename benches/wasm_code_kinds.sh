#!/usr/bin/env bash
# Where the bytes of the six wasm modules go (issue 25's size check): builds each part as
# scripts/build-pkg.sh does but keeps the function names (wasm-bindgen --keep-debug), then
# benches/wasm_code_kinds.mjs sorts every function body by kind (serialisation, binding glue,
# the core's numerics, nalgebra + libm, Rust runtime) and adds the data section.
#
#   benches/wasm_code_kinds.sh [REV]     # REV (default: the work tree) via a temporary worktree
#
# Measured (stop 40): the filing commit of issue 25 (52f9197^, six modules 2.0 MB) against
# 063f7c2 (2.43 MB): serde 248 → 358 KB, binding glue 322 → 317 KB, numerics 762 → 968 KB,
# nalgebra + libm 135 → 148 KB, runtime 464 → 479 KB, data 122 → 133 KB.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=$(mktemp -d)
src=$root
if [ $# -ge 1 ]; then
  src=$out/tree
  git worktree add -q --detach "$src" "$1"
  trap 'git -C "$root" worktree remove --force "$src"' EXIT
fi
target_dir=${CARGO_TARGET_DIR:-$root/target}
for part in bernoulli splitting filters bounds metrics control; do
  (cd "$src" && CARGO_TARGET_DIR=$target_dir cargo build -q --release --locked \
    --target wasm32-unknown-unknown -p fisst-wasm --no-default-features --features "$part")
  wasm-bindgen --target web --keep-debug --out-dir "$out/named" --out-name "$part" \
    "$target_dir/wasm32-unknown-unknown/release/fisst_wasm.wasm"
done
node benches/wasm_code_kinds.mjs "$out/named"
