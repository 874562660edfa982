#!/usr/bin/env bash
# Builds the npm package of git revision BASELINE_REV (default: the last commit with the
# hand-written JS converters) into benches/.baseline/pkg, for benches/boundary_node.mjs.
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${BASELINE_REV:-ddcaa74}
out=benches/.baseline
if [ -f "$out/pkg/.rev" ] && [ "$(cat "$out/pkg/.rev")" = "$rev" ]; then
  echo "baseline $rev already built in $out/pkg"
  exit 0
fi
rm -rf "$out/src" "$out/pkg"
mkdir -p "$out/src"
git archive "$rev" | tar -x -C "$out/src"
(cd "$out/src" && CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/../../../target}/baseline" scripts/build-pkg.sh)
mv "$out/src/wasm/pkg" "$out/pkg"
echo "$rev" > "$out/pkg/.rev"
rm -rf "$out/src"
echo "baseline $rev built in $out/pkg"
