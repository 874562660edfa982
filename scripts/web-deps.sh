#!/usr/bin/env bash
# What the demo pages load besides the fisst package (uPlot, pinned in web/package.json and
# web/package-lock.json): installed with `npm ci` into web/node_modules when missing or out
# of date, then copied into web/vendor/, the folder the pages import it from (served with
# them; no CDN, nothing fetched at run time).
set -euo pipefail
cd "$(dirname "$0")/../web"
stamp=node_modules/.package-lock.json
if [ ! -f "$stamp" ] || [ package-lock.json -nt "$stamp" ] || [ ! -d node_modules/uplot ]; then
  echo "[setup] npm ci in web"
  npm ci --no-audit --no-fund --loglevel=error
fi
rm -rf vendor
mkdir -p vendor/uplot
cp node_modules/uplot/dist/uPlot.min.css node_modules/uplot/LICENSE vendor/uplot/
# uPlot ships its ES module unminified (145 KB) and minified only as an IIFE (51 KB) that
# assigns `var uPlot`: that file with `export default uPlot;` appended is the same code as an
# ES module, and the pages' first figure comes about 30 ms sooner with it (parse time).
{ cat node_modules/uplot/dist/uPlot.iife.min.js; printf '\nexport default uPlot;\n'; } > vendor/uplot/uPlot.esm.min.js
printf 'web/vendor: uPlot %s\n' "$(sed -n 's/.*"version": "\(.*\)".*/\1/p' node_modules/uplot/package.json | head -n 1)"
