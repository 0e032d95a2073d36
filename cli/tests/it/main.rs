//! The command line's integration tests: one test binary (`cargo test -p maugis-cli
//! --test it`), one module a file. They run the built `maugis` binary
//! (`CARGO_BIN_EXE_maugis`); `crate::render` rasterises the SVGs it writes.
//!
//! A new test file goes in this folder as `cli/tests/it/<name>.rs` and is listed
//! below as `mod <name>;` (`use crate::render;` for the picture checks). Run one
//! file's tests with `cargo test -p maugis-cli --test it <name>::`. What the default
//! tier and `./dev test --long` run: docs/testing.md.

// shared helpers
mod render;
#[path = "../../../tests/it/tier.rs"]
mod tier;

// test files, one module each
mod cli_curve;
mod cli_eval;
mod cli_integrate;
mod cli_profile_prec;
mod cli_simulate;
mod cli_simulate_profile;
mod cli_sweep_waves;
mod cli_waves;
mod cli_multiscale;
mod figures;
mod render_check;
mod cli_integrate_auto;
