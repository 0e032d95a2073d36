//! Time per request by stage, printed to stderr at the end of `maugis eval`
//! when `MAUGIS_EVAL_PROFILE=1` (measurement only; off, it costs one branch per
//! stage). Stages: reading the line, the JSON parse, the arguments (decimal
//! text to `Decimal`/f64/integers), the evaluation, the response (ball to
//! decimal text, JSON object) and the output (serialising and writing).

use std::cell::Cell;
use std::sync::OnceLock;
use std::time::Instant;

pub const NAMES: [&str; 6] = ["read line", "JSON parse", "arguments", "evaluation", "response", "output"];
pub const READ: usize = 0;
pub const JSON: usize = 1;
pub const ARGS: usize = 2;
pub const EVAL: usize = 3;
pub const RESPONSE: usize = 4;
pub const OUTPUT: usize = 5;

thread_local! {
    static NANOS: Cell<[u64; 6]> = const { Cell::new([0; 6]) };
}

pub fn enabled() -> bool {
    static ON: OnceLock<bool> = OnceLock::new();
    *ON.get_or_init(|| std::env::var_os("MAUGIS_EVAL_PROFILE").is_some_and(|v| v == "1"))
}

/// Runs `f`, charging its time to `stage` (nested stages are subtracted by the caller).
#[inline]
pub fn timed<T>(stage: usize, f: impl FnOnce() -> T) -> T {
    if !enabled() {
        return f();
    }
    let t = Instant::now();
    let out = f();
    add(stage, t.elapsed().as_nanos() as i64);
    out
}

/// Adds `nanos` (may be negative, to move time between stages) to `stage`.
pub fn add(stage: usize, nanos: i64) {
    NANOS.with(|c| {
        let mut a = c.get();
        a[stage] = a[stage].wrapping_add(nanos as u64);
        c.set(a);
    });
}

pub fn get(stage: usize) -> u64 {
    NANOS.with(|c| c.get()[stage])
}

/// The per-request means, one line per stage.
pub fn report(requests: u64) {
    if !enabled() || requests == 0 {
        return;
    }
    let a = NANOS.with(|c| c.get());
    let total: u64 = a.iter().sum();
    eprintln!("maugis eval profile: {requests} requests, {:.3} us each", total as f64 / requests as f64 / 1e3);
    for (name, ns) in NAMES.iter().zip(a) {
        eprintln!("  {name:<11} {:>9.3} us  {:>5.1} %", ns as f64 / requests as f64 / 1e3, 100.0 * ns as f64 / total.max(1) as f64);
    }
}
