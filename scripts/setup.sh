#!/usr/bin/env bash
# Installs what the build and the tests need, skipping whatever is already there:
#   scripts/setup.sh          Rust targets and the wasm-bindgen CLI (enough for `make demo`)
#   scripts/setup.sh --test   also the npm packages of tests/js, Debian's Chromium + driver
#                             and Debian's qemu-system-arm (the Cortex-M example)
# Everything comes from the package registries (crates.io, npm, Debian).
set -euo pipefail
cd "$(dirname "$0")/.."

want_test=0
[ "${1:-}" = "--test" ] && want_test=1

say() { printf '[setup] %s\n' "$*"; }

# Installs Debian packages, as root or through sudo.
apt_install() {
  local sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  say "apt-get install $*"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$@"
}

# Rust targets: wasm for the npm package, thumbv7em for the no_std check and examples/cortex-m.
targets="wasm32-unknown-unknown thumbv7em-none-eabihf"
installed=$(rustup target list --installed)
for t in $targets; do
  if ! grep -qx "$t" <<<"$installed"; then
    say "rustup target add $t"
    rustup target add "$t"
  fi
done

# The wasm-bindgen CLI at exactly the version in Cargo.lock.
wb_version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
if [ -z "$wb_version" ]; then
  echo "[setup] cannot find wasm-bindgen in Cargo.lock" >&2
  exit 1
fi
if [ "$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')" != "$wb_version" ]; then
  say "cargo install wasm-bindgen-cli $wb_version (takes several minutes, once)"
  cargo install wasm-bindgen-cli --version "$wb_version" --locked \
    || cargo install wasm-bindgen-cli --version "$wb_version"
fi

command -v node >/dev/null || { echo "[setup] node (>= 20) is required" >&2; exit 1; }

if [ "$want_test" = 1 ]; then
  # Debian's Chromium and ChromeDriver, for the wasm-bindgen browser tests and the page tests.
  if [ ! -x /usr/bin/chromium ] || [ ! -x /usr/bin/chromedriver ]; then
    apt_install chromium chromium-driver
  fi
  # Debian's QEMU, to run examples/cortex-m on an emulated Cortex-M4 (mps2-an386).
  command -v qemu-system-arm >/dev/null || apt_install qemu-system-arm
fi
say "ok (wasm-bindgen $wb_version)"
