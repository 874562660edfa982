//! The JS-visible functions, run by wasm-bindgen-test in Node.
//! `cargo test --target wasm32-unknown-unknown -p fisst-wasm --test node`
mod suite;
