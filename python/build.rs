//! Empty: it exists so that `[build-dependencies]` in Cargo.toml is resolved with
//! the build-time crates (the features it requests let the wheel's build reuse the
//! test build's `maugis`, Cargo.toml and docs/testing.md).
fn main() {}
