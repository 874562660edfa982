# fisst — the two set-up commands are `make demo` and `make test`; each installs what is missing.
SHELL := /bin/bash
.SHELLFLAGS := -euo pipefail -c
PORT ?= 8000
export CHROMEDRIVER ?= /usr/bin/chromedriver

.PHONY: demo test pkg web-pkg setup setup-test setup-python check lint test-native test-nostd test-embedded test-wasm test-js test-python wheel fuzz-python fuzz soak bench clean

## make demo: install what is missing, build the npm package, serve web/ on 127.0.0.1:$(PORT)
demo: setup web-pkg
	node scripts/serve.mjs web $(PORT)

## make test: install what is missing, then every test (native, no_std, Cortex-M4 in QEMU, wasm in Node and Chromium, npm package, pages)
test: setup-test lint test-native test-nostd test-embedded test-wasm test-js test-python
	@echo "make test: all passed"

## make pkg: the npm package `fisst` in wasm/pkg/
pkg: setup
	scripts/build-pkg.sh

## make web-pkg: the served folder web/: the npm package in web/pkg/, uPlot in web/vendor/
web-pkg: pkg
	rm -rf web/pkg
	cp -r wasm/pkg web/pkg
	scripts/web-deps.sh

setup:
	scripts/setup.sh

setup-test:
	scripts/setup.sh --test

lint:
	cargo fmt --all -- --check
	cd benches && cargo fmt --all -- --check
	cargo clippy --locked --workspace --all-targets -- -D warnings
	cargo clippy --locked -p fisst-wasm --target wasm32-unknown-unknown --all-targets -- -D warnings
	RUSTDOCFLAGS="-D warnings" cargo doc --locked --workspace --no-deps
	# benches/ is its own workspace (criterion stays out of the main build); check that every
	# bench and bin still compiles against the core, in the main target directory.
	cd benches && CARGO_TARGET_DIR=$(CURDIR)/target cargo check --locked --all-targets
	# examples/cortex-m is its own crate too (built for thumbv7em-none-eabihf by default).
	cd examples/cortex-m && cargo fmt -- --check
	cd examples/cortex-m && cargo clippy --locked --release -- -D warnings

test-native:
	cargo test --locked
	cargo test --locked -p fisst --features serde --lib
	cargo test --locked -p fisst-wasm --lib --test tsgen

test-nostd:
	cargo test --locked -p fisst --no-default-features
	cargo build --locked -p fisst --no-default-features --target thumbv7em-none-eabihf
	cargo test --locked -p fisst --no-default-features --features serde --lib
	cargo build --locked -p fisst --no-default-features --features serde --target thumbv7em-none-eabihf

## make test-python: the Python package's wheel built once (profile `py`, into dist/) and installed
## into .venv, then its tests (contract, parity with native and npm, Stone Soup, a seeded
## hypothesis slice, the wheel in a fresh venv) and the stubs checked against the module
test-python: setup-python
	rm -f dist/fisst-*.whl
	cd python && ../.venv/bin/maturin build --locked --profile py --out ../dist --quiet
	.venv/bin/python -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps dist/fisst-*.whl
	.venv/bin/python -m pytest -q python/tests
	cd python && ../.venv/bin/python -m mypy.stubtest fisst --allowlist stubtest-allowlist.txt --mypy-config-file pyproject.toml

## make wheel: the Python package's abi3 wheel (Linux x86_64, Python >= 3.10) in dist/
wheel: setup-python
	rm -f dist/fisst-*.whl
	cd python && ../.venv/bin/maturin build --locked --release --out ../dist --quiet

## make fuzz-python: the Python fuzz at full size (10^6 calls over every function)
fuzz-python: setup-python
	rm -f dist/fisst-*.whl
	cd python && ../.venv/bin/maturin build --locked --profile py --out ../dist --quiet
	.venv/bin/python -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps dist/fisst-*.whl
	FISST_FUZZ_EXAMPLES=1000000 .venv/bin/python -m pytest -q python/tests/test_fuzz.py

setup-python:
	scripts/setup-python.sh

## make test-embedded: the Cortex-M4 example in QEMU, its output compared bit for bit with the native run
test-embedded:
	examples/cortex-m/run.sh

test-wasm:
	cargo test --locked --target wasm32-unknown-unknown -p fisst-wasm --test node
	cargo test --locked --target wasm32-unknown-unknown -p fisst-wasm --test browser

test-js: web-pkg
	scripts/npm-deps.sh
	cd tests/js && node --test contract.test.mjs readme.test.mjs types.test.mjs lib.test.mjs bernoulli_filters.test.mjs mistakes_filters.test.mjs metrics_series.test.mjs bounds.test.mjs control.test.mjs package.test.mjs recipes.test.mjs first_day.test.mjs mistakes.test.mjs
	cd tests/js && node --expose-gc --test fuzz/ soak/
	cd tests/js && node --test --test-concurrency=1 pages/

## make fuzz: the boundary fuzzer at full size (1,000,000 cases, fresh seed; FUZZ_CASES, FUZZ_SEED)
fuzz: web-pkg
	scripts/npm-deps.sh
	cd tests/js && node fuzz/run.mjs --cases $${FUZZ_CASES:-1000000} $${FUZZ_SEED:+--seed $$FUZZ_SEED}

## make soak: every function 100,000 times in Node; fails if wasm memory or the JS heap keeps growing
soak: web-pkg
	scripts/npm-deps.sh
	cd tests/js && node --expose-gc soak/soak.mjs --calls 100000

## make bench: criterion benches and the side-by-side scripts (not part of `make test`)
bench: pkg
	cd benches && cargo bench
	python3 benches/gospa_vs_scipy.py
	python3 benches/gospa_vs_stonesoup.py
	python3 benches/pmf_vs_scipy.py
	python3 benches/map_vs_numpy.py
	python3 benches/bernoulli_vs_scipy.py
	python3 benches/bernoulli_vs_stonesoup.py
	python3 benches/airport_curve.py

clean:
	cargo clean
	rm -rf examples/cortex-m/target
	rm -rf wasm/pkg web/pkg web/vendor web/node_modules tests/js/node_modules tests/browser/screenshots
