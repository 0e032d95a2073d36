//! The two test tiers (docs/testing.md). `./dev test` runs every test with its
//! inputs sized to run in seconds; `./dev test --long` sets `MAUGIS_TEST_TIER=long`
//! and the same tests run at campaign size. A test that sizes its inputs with
//! [`pick`] runs its short form in the default tier, never nothing.
//!
//! One file for the three test binaries: `solver/tests/it/main.rs` and
//! `cli/tests/it/main.rs` include it by path.

#![allow(dead_code)]

/// True under `./dev test --long` (`MAUGIS_TEST_TIER=long`).
pub fn long() -> bool {
    std::env::var("MAUGIS_TEST_TIER").is_ok_and(|v| v == "long")
}

/// `short` in the default tier, `long` under `./dev test --long`.
pub fn pick<T>(short: T, long: T) -> T {
    if self::long() {
        long
    } else {
        short
    }
}
