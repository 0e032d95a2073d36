//! Reproducible fuzz inputs: the same inputs on every run and every machine.
//!
//! bolero 0.13's random engine (`bolero::check!()` under `cargo test`) draws each
//! input from a generator seeded by the operating system's entropy:
//! `BOLERO_RANDOM_SEED` adds one input (the replay of a reported failure), it does
//! not seed the sequence. Two runs of a target therefore saw different inputs, and
//! took different times (the solver's simulation target: 168 s, 487 s and over
//! 25 min for the same 250 inputs a target; docs/testing.md).
//!
//! [`check`] keeps bolero's structured generators (`with_type::<T>()`, the same
//! types the targets drew before) and replaces its engine: input `i` of a target is
//! generated from a fixed stream of bytes, splitmix64 of the seed and `i`, through
//! bolero's byte-slice driver (the way a coverage fuzzer's bytes become a value).
//! The inputs are
//!
//! - `BOLERO_RANDOM_SEED` (default [`SEED`]) picks the sequence;
//! - `BOLERO_RANDOM_ITERATIONS` (default [`ITERATIONS`]) inputs are run, the first of
//!   the sequence, so a shorter run's inputs are the first of a longer one's
//!   (`./dev test`: 250, `./dev test --long`: 1000);
//! - `BOLERO_RANDOM_TEST_TIME_MS`, when set, runs the sequence until that time is up
//!   instead (a campaign; it prints how many inputs it ran).
//!
//! A failing input is reported with its index, the seed and its value, and so is
//! one that runs longer than 2 s; rerun it alone with `FUZZ_INPUT=<index>`.
//!
//! One file for the library's, the solver's and the CLI's targets (included by path).

#![allow(dead_code)]

use bolero::generator::bolero_generator::driver::{ByteSliceDriver, Options};
use bolero::generator::TypeGenerator;
use std::fmt::Debug;
use std::marker::PhantomData;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

/// The seed when `BOLERO_RANDOM_SEED` is not set (the one `./dev` sets).
pub const SEED: u64 = 20261126;
/// Inputs a target when `BOLERO_RANDOM_ITERATIONS` is not set (the default tier's).
pub const ITERATIONS: usize = 250;
/// An input that runs longer than this is named on stderr (it passes: a fuzz
/// target checks answers, the benches and the budget scans check time).
const SLOW: Duration = Duration::from_secs(2);
/// Bytes behind one input (bolero's default maximum input length).
const BYTES: usize = 4096;

/// A fuzz target over values of type `T` (raw bytes unless [`Target::with_type`]
/// says otherwise): the drop-in for `bolero::check!()`.
pub fn check() -> Target<Vec<u8>> {
    Target(PhantomData)
}

pub struct Target<T>(PhantomData<T>);

impl Target<Vec<u8>> {
    /// Draw values of type `U` (any bolero `TypeGenerator`).
    pub fn with_type<U>(self) -> Target<U> {
        Target(PhantomData)
    }
}

fn env<T: std::str::FromStr>(name: &str) -> Option<T> {
    std::env::var(name).ok().and_then(|v| v.parse().ok())
}

/// splitmix64: the `n`-th word of the stream that `seed` names.
fn splitmix(seed: u64, n: u64) -> u64 {
    let mut z = seed.wrapping_add(n.wrapping_add(1).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The bytes of input `index` of the sequence `seed`.
fn input_bytes(seed: u64, index: u64, out: &mut [u8]) {
    let stream = splitmix(seed, index);
    for (k, chunk) in out.chunks_mut(8).enumerate() {
        let w = splitmix(stream, k as u64).to_le_bytes();
        chunk.copy_from_slice(&w[..chunk.len()]);
    }
}

impl<T: TypeGenerator + Debug> Target<T> {
    /// Runs `test` on each input of the sequence (see the module's docs). A panic
    /// fails the test, naming the input.
    pub fn for_each(self, test: impl Fn(&T)) {
        let seed = env("BOLERO_RANDOM_SEED").unwrap_or(SEED);
        let deadline = env::<u64>("BOLERO_RANDOM_TEST_TIME_MS").map(|ms| Instant::now() + Duration::from_millis(ms));
        let indices: Box<dyn Iterator<Item = u64>> = match (env::<u64>("FUZZ_INPUT"), deadline) {
            (Some(i), _) => Box::new(std::iter::once(i)),
            (None, Some(_)) => Box::new(0..),
            (None, None) => Box::new(0..env("BOLERO_RANDOM_ITERATIONS").unwrap_or(ITERATIONS) as u64),
        };
        let options = Options::default();
        let mut bytes = vec![0u8; BYTES];
        let mut ran = 0u64;
        for i in indices {
            if deadline.is_some_and(|d| Instant::now() >= d) {
                break;
            }
            input_bytes(seed, i, &mut bytes);
            let Some(value) = T::generate(&mut ByteSliceDriver::new(&bytes, &options)) else { continue };
            let start = Instant::now();
            if let Err(panic) = catch_unwind(AssertUnwindSafe(|| test(&value))) {
                eprintln!("fuzz input {i} of seed {seed} failed (rerun it alone with FUZZ_INPUT={i}): {value:?}");
                resume_unwind(panic);
            }
            let took = start.elapsed();
            if took >= SLOW {
                eprintln!("fuzz input {i} of seed {seed} took {:.1} s (FUZZ_INPUT={i}): {value:?}", took.as_secs_f64());
            }
            ran += 1;
        }
        if deadline.is_some() {
            eprintln!("fuzz: {ran} inputs of seed {seed} in the time given");
        }
    }
}
