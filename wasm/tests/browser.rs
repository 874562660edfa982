//! The JS-visible functions, run by wasm-bindgen-test in headless Chromium
//! (`CHROMEDRIVER=/usr/bin/chromedriver`, options in `wasm/webdriver.json`).
//! `cargo test --target wasm32-unknown-unknown -p fisst-wasm --test browser`
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);
mod suite;
