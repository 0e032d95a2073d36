//! The solver's integration tests: one test binary (`cargo test -p maugis-solver
//! --test it`), one module a file, so that the suite links the solver once.
//!
//! A new test file goes in this folder as `solver/tests/it/<name>.rs` and is listed
//! below as `mod <name>;`. Run one file's tests with `cargo test -p maugis-solver
//! --test it <name>::`. What the default tier and `./dev test --long` run:
//! docs/testing.md.

// shared helpers
#[path = "../../../tests/it/tier.rs"]
mod tier;

// test files, one module each
mod cavitation;
mod dissipation;
mod exponential_law;
mod fig4c_lambda6;
mod fuzz;
mod hertz;
mod load_control;
mod map;
mod maugis_smooth;
mod no_contact;
mod periodic_jkr;
mod profile_table;
mod rough_profiles;
mod scales;
mod tamaas_reference;
mod transition;
