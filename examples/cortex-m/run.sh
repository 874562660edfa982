#!/usr/bin/env bash
# Builds the firmware (release), runs it on QEMU's emulated Cortex-M4 (mps2-an386), runs the same
# `fisst_cortex_m::run` natively, and compares the two outputs bit for bit: exits non-zero on
# any difference. Prints the firmware's flash size and its peak heap and stack.
# Needs the rustup target thumbv7em-none-eabihf and qemu-system-arm (`scripts/setup.sh --test`).
set -euo pipefail
cd "$(dirname "$0")"

target_dir=${CARGO_TARGET_DIR:-target}
elf=$target_dir/thumbv7em-none-eabihf/release/fisst-cortex-m
host=$(rustc -vV | sed -n 's/^host: //p')
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f s", b - a }'; }

t=$(now)
cargo build --locked --release
echo "[cortex-m] firmware built in $(since "$t")"

t=$(now)
status=0
timeout 120 qemu-system-arm -machine mps2-an386 -nographic \
  -semihosting-config enable=on,target=native -kernel "$elf" </dev/null \
  >"$out/board.txt" 2>"$out/board-stderr.txt" || status=$?
echo "[cortex-m] QEMU ran in $(since "$t") (exit status $status)"
cat "$out/board-stderr.txt"
[ "$status" = 0 ] || { echo "[cortex-m] the firmware failed" >&2; exit 1; }

# The same function natively (the crate's default target is the Cortex-M one: name the host).
cargo run --locked --quiet --target "$host" >"$out/host.txt"

if ! diff -u "$out/host.txt" "$out/board.txt"; then
  echo "[cortex-m] FAILED: the Cortex-M output differs from the native one (diff above: - native, + QEMU)" >&2
  exit 1
fi
echo "[cortex-m] the QEMU and native outputs are identical ($(wc -l <"$out/board.txt") lines, every f64 bit for bit)"

# Flash = text (code, read-only data, vector table) + data (initial values copied to RAM).
size_tool=$(command -v llvm-size || command -v size || true)
[ -n "$size_tool" ] || { echo "[cortex-m] no size tool (llvm-size or binutils' size)" >&2; exit 1; }
read -r text data bss _ < <("$size_tool" "$elf" | tail -1)
flash=$((text + data))
heap=$(sed -n 's/^heap peak: \([0-9]*\) bytes.*/\1/p' "$out/board-stderr.txt")
stack=$(sed -n 's/^stack peak: \([0-9]*\) bytes.*/\1/p' "$out/board-stderr.txt")
echo "[cortex-m] flash $flash bytes (text $text + data $data), heap peak $heap bytes, stack peak $stack bytes;" \
  "static RAM $((data + bss)) bytes (incl. the 1 MiB heap)"

# The README quotes these figures; they must stay within 5% of the build at hand.
figures=$(grep -o 'flash [0-9.]* KB, heap peak [0-9.]* KB, stack peak [0-9.]* KB' ../../README.md || true)
[ -n "$figures" ] || { echo "[cortex-m] the README's figures line is missing" >&2; exit 1; }
read -r _ q_flash _ _ _ q_heap _ _ _ q_stack _ <<<"${figures//,/}"
stale=0
for pair in "flash $q_flash $flash" "heap $q_heap $heap" "stack $q_stack $stack"; do
  read -r what quoted bytes <<<"$pair"
  if ! awk -v q="$quoted" -v b="$bytes" 'BEGIN { d = q * 1000 - b; if (d < 0) d = -d; exit !(d <= 0.05 * b) }'; then
    echo "[cortex-m] README says $what $quoted KB, the build has $bytes bytes: update README.md" >&2
    stale=1
  fi
done
[ "$stale" = 0 ] || exit 1
echo "[cortex-m] ok"
