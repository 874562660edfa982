#!/usr/bin/env bash
# npm packages of tests/js (playwright-core and a link to the built package in wasm/pkg):
# installed from package-lock.json, skipped when node_modules is already current.
set -euo pipefail
cd "$(dirname "$0")/../tests/js"
stamp=node_modules/.package-lock.json
if [ ! -f "$stamp" ] || [ package-lock.json -nt "$stamp" ] || [ ! -e node_modules/fisst ]; then
  echo "[setup] npm ci in tests/js"
  npm ci --no-audit --no-fund --loglevel=error
fi
