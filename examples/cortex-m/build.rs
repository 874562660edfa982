//! Puts `memory.x` (the board's flash and RAM) where cortex-m-rt's linker script `link.x`
//! finds it. The host build links without it (`-Tlink.x` is set for the Cortex-M target only,
//! in `.cargo/config.toml`).

use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    fs::write(out.join("memory.x"), include_bytes!("memory.x")).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
}
