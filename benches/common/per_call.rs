//! Wall time per call for the example timing loops: `f` is called until 20 ms
//! have passed (at least once); returns the last result and the mean time per
//! call in microseconds.

use std::time::Instant;

/// `(last result, microseconds per call)` of `f` run for at least 20 ms.
pub fn per_call<T>(mut f: impl FnMut() -> T) -> (T, f64) {
    let t0 = Instant::now();
    let mut calls = 1u32;
    let mut res = f();
    while t0.elapsed().as_secs_f64() < 0.02 {
        res = f();
        calls += 1;
    }
    (res, t0.elapsed().as_secs_f64() * 1e6 / calls as f64)
}
