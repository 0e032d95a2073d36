//! The library's integration tests: one test binary (`cargo test --test it`), one
//! module a file, so that the suite links the library once instead of once a file.
//!
//! A new test file goes in this folder as `tests/it/<name>.rs` and is listed below
//! as `mod <name>;`. Shared helpers are `crate::common` (golden tables, enclosure
//! checks) and `crate::wave_points` (`use crate::common;` in the file, not `mod
//! common;`). Run one file's tests with `cargo test --test it <name>::`.
//! What the default tier and `./dev test --long` run: docs/testing.md.

// shared helpers
mod common;
mod wave_points;
mod tier;

// test files, one module each
mod api_scheme;
mod ball_input_relative;
mod ball_inputs_decimal;
mod bessel_decimal;
mod bessel_f64;
mod bessel_large;
mod bessel_sequence_mp;
mod bounded_golden;
mod budget;
mod edges_low_precision;
mod certified_golden;
mod certified_quad;
mod certified_quad_proptest;
mod fuzz;
mod golden;
mod hyp2f1_decimal;
mod hyp2f1_decimal_corners;
mod hyp2f1_exponent_range;
mod hyp2f1_f64;
mod hyp2f1_large_param;
mod identities;
mod import_cycles;
mod jkr_limit;
mod large_lambda;
mod maugis_model;
mod meijer_g_f64_routes;
mod model_decimal;
mod model_rough;
mod model_tiny_contact;
mod model_waves;
mod model_waves_decimal;
mod multiscale_envelope;
mod no_panic;
mod paths_dissipation;
mod precision_edges;
mod quadrature;
mod wave_bounded;
mod wave_certified;
mod wave_crosscheck;
mod wave_scratch;
mod wave_value;
mod quad_infinite;
mod quad_singular_auto;
mod quad_spelling;
mod quad_oscillatory_proptest;
mod hankel_bound;
mod quad_zero;
mod quad_precision_sweep;
mod sweep_waves;
