//! Time per call for the example timing loops: `f` is called until 20 ms have
//! passed (at least once); returns the last result and the mean time per call in
//! microseconds, by the wall clock ([`per_call`]) or by the thread's CPU time
//! ([`per_call_cpu`], from `/proc/thread-self/schedstat`: on the shared 2-core
//! machine wall times swing with the other processes' load).

use std::time::Instant;

/// `(last result, microseconds per call)` of `f` run for at least 20 ms of wall time.
#[allow(dead_code)]
pub fn per_call<T>(f: impl FnMut() -> T) -> (T, f64) {
    let t0 = Instant::now();
    timed(f, move || t0.elapsed().as_secs_f64())
}

/// [`per_call`] by the calling thread's CPU time (20 ms of it).
#[allow(dead_code)]
pub fn per_call_cpu<T>(f: impl FnMut() -> T) -> (T, f64) {
    let cpu = || -> f64 {
        let stat = std::fs::read_to_string("/proc/thread-self/schedstat").unwrap_or_default();
        stat.split_whitespace().next().and_then(|v| v.parse::<f64>().ok()).unwrap_or(0.0) * 1e-9
    };
    let t0 = cpu();
    timed(f, move || cpu() - t0)
}

fn timed<T>(mut f: impl FnMut() -> T, elapsed: impl Fn() -> f64) -> (T, f64) {
    let mut calls = 1u32;
    let mut res = f();
    while elapsed() < 0.02 {
        res = f();
        calls += 1;
    }
    (res, elapsed() * 1e6 / calls as f64)
}
