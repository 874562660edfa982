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
#
# Ways to the filing's size tried (stop 41, 85b8350's six modules 2,438,269 bytes), none reaching
# 2.07 MB: without LTO, the core (and nalgebra, libm) at opt-level 3 and every other crate at
# "z" (a `[profile.*.package]` table): 2,420,226; every crate at "z" without LTO, the floor of
# what the compiler's size settings give: 2,223,786 (the particle filter 2.5× slower at "z",
# measured in stop 40); binaryen's `wasm-opt` (npm, version 132) with only
# `--duplicate-function-elimination --merge-similar-functions --remove-unused-module-elements`:
# 2,388,715. What is left is code: the core's numerics grew by 206 KB with the features of the
# issues since; float formatting of error messages (`core::fmt::float`, flt2dec) is about 20 KB per module.
#
# Stop 43 (same settings): 2,332,289 → 2,157,908 bytes. The standard library's float formatting
# (19 KB per module: f64's Display in four error messages and serde's `Unexpected`, f64's Debug
# in `f64::clamp`'s panic) replaced by `fisst::math::decimal` (5 KB, the same text) and
# `math::fns::clamp`; the 2–5 driftsorts per module (one per element type, 92 KB of the six) by
# the crate's own merge sort (3 KB per module). Named build: runtime 465 → 255 KB.
#
# Stop 44: 2,157,908 → 2,062,958 bytes (`--top N` lists the largest functions; the IR of one part,
# `cargo rustc --release --target wasm32-unknown-unknown -p fisst-wasm --no-default-features
# --features PART --crate-type cdylib -- --emit=llvm-ir`, shows who calls them). Gone: string
# and char `Debug` with the Unicode printable/grapheme tables, the string-slicing panic,
# `u64`/`i64` `Display` (≈ 40 KB of the six); alloc's `String` writer shared instead of one per
# crate (`format!` instead of `to_string`, 10 KB); Decimal's big integer over its used words
# instead of 40-fold unrolled loops (7 KB); one `Error::map_paths` body (4 KB); fixed texts as
# `Cow` (5 KB). Left as they are: dlmalloc (7 KB per module), serde-wasm-bindgen's field-name
# cache (hashbrown, 3 KB per module), and the closure shims of js-sys imports with callbacks that
# wasm-bindgen leaves in the function table (3.5 KB per module).
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
