//! The example's program. Built for the Cortex-M4 (the default target, `.cargo/config.toml`)
//! it is the firmware of `board.rs`; built for the host (`--target x86_64-unknown-linux-gnu`)
//! it is an ordinary program running the same `fisst_cortex_m::run` with `std`.

#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
mod board;

#[cfg(not(target_os = "none"))]
fn main() -> std::process::ExitCode {
    let mut out = String::new();
    let result = fisst_cortex_m::run(&mut out);
    print!("{out}");
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{e}");
            std::process::ExitCode::FAILURE
        }
    }
}
