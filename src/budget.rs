//! Time budgets: every MP call answers or refuses in bounded time.
//!
//! A [`Budget`] is the wall-clock time one call may take. It bounds the work in
//! two ways, and never changes an answer (a call either returns the same
//! certified ball it returns without a budget, or a typed refusal):
//!
//! * **Before the work**, a method whose cost its cost model bounds from below
//!   (the pFq series' term count, the working precision of a Gamma-based
//!   formula, the Bessel chooser's estimate) compares that estimate with what is
//!   left of the budget and with the method's own cap, and refuses at once with
//!   [`Error::TooExpensive`], which names the estimate and the limit.
//! * **Between the iterations** of a loop whose length no model bounds in
//!   advance (the Ziv loops that raise the working precision, the retries of
//!   [`crate::ball::eval_at_decimals`] at tighter input balls, the MP wave
//!   quadrature's outer nodes, the certified quadrature's bisection and attempts,
//!   the pFq, 2F1 and 1F2 model family series every
//!   `TERMS_BETWEEN_CHECKS` (8) terms,
//!   the wave series every term, the wave's Bessel form (Eq. 11a) before its
//!   `J_n` sequence and every 4096 terms of its sums, the model's f64
//!   strip-root scan every 64 samples), the time spent plus an estimate of the
//!   next iteration (a Ziv round: the last one's time times the precision ratio
//!   to the power 1.5) is compared with
//!   the budget; past it the loop stops with [`Error::BudgetSpent`], which names
//!   the time spent and what was reached ([`Reached`]).
//! * **One MPFR Gamma** (no loop to interrupt) is refused with
//!   [`Error::TooExpensive`] when its estimated time at the precision it would run
//!   at (the first call's, Bernoulli numbers included) passes the budget.
//!
//! # Setting a budget
//!
//! [`Budget::run`] runs a closure with the budget installed for the current
//! thread; every MP function called inside it, at any depth, sees it:
//!
//! ```
//! use maugis::budget::Budget;
//! use maugis::special::hyp1f2::hyp1f2_mp;
//! use maugis::rug::Float;
//!
//! let f = |x: f64| Float::with_val(64, x);
//! let budget = Budget::from_millis(1).unwrap();
//! // 1F2(1e12; 1.5, 2.5; 100) sums about 4.6e4 terms: estimated past 1 ms
//! let r = budget.run(|| hyp1f2_mp(&f(1e12), &f(1.5), &f(2.5), &f(100.0), 64));
//! assert!(matches!(r, Err(maugis::Error::TooExpensive { .. })));
//! ```
//!
//! The front ends take it per request: `"budget_ms"` in `maugis eval`,
//! `budget=` (seconds) in Python, [`crate::registry::Function::eval_mp_with_budget`].
//!
//! # The default
//!
//! A call made outside [`Budget::run`] runs under [`Budget::DEFAULT`] (30 s),
//! counted from its first Ziv loop or decimal-input loop, or from its entry for
//! the certified quadrature (every entry point of [`crate::quad::certified`], and
//! [`crate::quad::expr::integrate_range`] for all the pieces of one expression
//! integral together): the budget every library call, `maugis eval` request and
//! Python call has when none is given.
//! The methods' own caps ([`crate::special::pfq::MAX_SERIES_SECONDS`],
//! [`crate::special::hyp2f1::MAX_GAMMA_LOSS`],
//! [`crate::special::bessel_j::MAX_COST`]) stay in force under any budget: a
//! budget shortens them, never lengthens them.
//!
//! Nested budgets keep the earlier deadline. The budget is per thread: work a
//! call hands to other threads (none of the MP functions does) would run under
//! the default there.

use std::cell::Cell;
use std::time::{Duration, Instant};

use crate::error::{Error, Interval, Reached, Result};

/// The wall-clock time one call may take (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    limit: Duration,
}

/// The installed budget of the current thread: when it started and how long it lasts.
#[derive(Clone, Copy, Debug)]
struct Scope {
    start: Instant,
    limit: Duration,
}

impl Scope {
    fn deadline(&self) -> Instant {
        self.start + self.limit
    }

    fn elapsed_seconds(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    fn remaining_seconds(&self) -> f64 {
        (self.limit.as_secs_f64() - self.elapsed_seconds()).max(0.0)
    }
}

thread_local! {
    static SCOPE: Cell<Option<Scope>> = const { Cell::new(None) };
}

/// Terms between two budget checks in the series loops (pFq, 2F1 and its
/// logarithmic case, the 1F2 model family). A check is one clock read (tens of
/// nanoseconds) against terms of a microsecond and more; at 64 terms a parameter
/// held exactly at 10^5 bits (`1e31099` typed) made the stretch between checks
/// 15-20 ms of CPU, 55 ms of wall time at load 13 on 2 cores, and calls ended at
/// 0.155 s under a 0.1 s budget (issue 37's scan).
pub(crate) const TERMS_BETWEEN_CHECKS: u64 = 8;

/// Largest budget accepted: a day (a larger one is a mistake, not a wish).
pub const MAX_SECONDS: f64 = 86_400.0;

impl Budget {
    /// The budget of a call made without one: 30 seconds.
    pub const DEFAULT: Budget = Budget { limit: Duration::from_secs(30) };

    /// A budget of `seconds` (`0 < seconds <= `[`MAX_SECONDS`]), or
    /// [`Error::OutOfRange`] naming `budget`.
    pub fn from_secs_f64(seconds: f64) -> Result<Budget> {
        crate::error::finite(seconds, "budget")?;
        Interval::left_open(0.0, MAX_SECONDS).check("budget (seconds)", seconds)?;
        Ok(Budget { limit: Duration::from_secs_f64(seconds) })
    }

    /// A budget of `ms` milliseconds (`1 <= ms <= 86 400 000`).
    pub fn from_millis(ms: u64) -> Result<Budget> {
        if !(1..=(MAX_SECONDS as u64) * 1000).contains(&ms) {
            return Err(Error::IntegerOutOfRange {
                arg: "budget_ms",
                value: i64::try_from(ms).unwrap_or(i64::MAX),
                min: 1,
                max: (MAX_SECONDS as i64) * 1000,
            });
        }
        Ok(Budget { limit: Duration::from_millis(ms) })
    }

    /// The budget in seconds.
    pub fn seconds(&self) -> f64 {
        self.limit.as_secs_f64()
    }

    /// Runs `f` with this budget installed for the current thread, counted from
    /// now. Inside an outer budget the earlier deadline wins.
    pub fn run<T>(self, f: impl FnOnce() -> T) -> T {
        let now = Instant::now();
        let mut scope = Scope { start: now, limit: self.limit };
        let outer = SCOPE.with(Cell::get);
        if let Some(o) = outer {
            if o.deadline() < scope.deadline() {
                scope.limit = o.deadline().saturating_duration_since(now);
            }
        }
        let _restore = Restore(outer);
        SCOPE.with(|c| c.set(Some(scope)));
        f()
    }
}

impl Default for Budget {
    fn default() -> Self {
        Budget::DEFAULT
    }
}

/// Puts the outer scope back when a [`Budget::run`] ends (also on unwinding).
struct Restore(Option<Scope>);

impl Drop for Restore {
    fn drop(&mut self) {
        SCOPE.with(|c| c.set(self.0));
    }
}

/// Runs `f` under the installed budget, or under [`Budget::DEFAULT`] from now
/// when none is installed (the entry of every Ziv loop and decimal-input loop).
pub(crate) fn ensure<T>(f: impl FnOnce() -> T) -> T {
    if SCOPE.with(Cell::get).is_some() {
        f()
    } else {
        Budget::DEFAULT.run(f)
    }
}

/// The limit of the budget installed on this thread, if any (for the tests that
/// check that an entry point installs the default).
#[cfg(test)]
pub(crate) fn installed_limit() -> Option<Duration> {
    SCOPE.with(Cell::get).map(|s| s.limit)
}

/// The limit for a method estimated before its work: the smaller of the
/// method's own cap and what is left of the installed budget (seconds).
pub(crate) fn limit_seconds(method_cap: f64) -> f64 {
    match SCOPE.with(Cell::get) {
        Some(s) => method_cap.min(s.remaining_seconds()),
        None => method_cap,
    }
}

/// Refuses with [`Error::TooExpensive`] when the estimated `seconds` of the
/// work `function` is about to do pass [`limit_seconds`]`(method_cap)`.
pub(crate) fn check_estimate(function: &'static str, seconds: f64, method_cap: f64) -> Result<()> {
    let limit = limit_seconds(method_cap);
    if seconds > limit || seconds.is_nan() {
        return Err(Error::TooExpensive { function, seconds, limit_seconds: limit });
    }
    Ok(())
}

/// Between the iterations of a loop no model bounds in advance: refuses with
/// [`Error::BudgetSpent`] when the time spent plus `next_seconds` (the
/// estimated time of the next iteration) passes the installed budget.
pub(crate) fn check_elapsed(function: &'static str, next_seconds: f64, reached: Reached) -> Result<()> {
    let Some(s) = SCOPE.with(Cell::get) else { return Ok(()) };
    let elapsed = s.elapsed_seconds();
    let budget = s.limit.as_secs_f64();
    if elapsed + next_seconds.max(0.0) > budget {
        return Err(Error::BudgetSpent { function, elapsed_seconds: elapsed, next_seconds, budget_seconds: budget, reached });
    }
    Ok(())
}

/// The calling thread's CPU time in seconds (`clock_gettime` with
/// `CLOCK_THREAD_CPUTIME_ID`, nanosecond resolution). A measuring aid: on a
/// shared machine a call's wall time grows with the other processes' load, its
/// thread CPU time much less. The budget itself counts wall time (what a caller
/// waits). Used by the timing examples and the slow-input scan (tests/it/fuzz.rs).
///
/// ```
/// let t0 = maugis::budget::thread_cpu_seconds();
/// let spent = maugis::budget::thread_cpu_seconds() - t0;
/// assert!(spent >= 0.0);
/// ```
#[cfg(unix)]
pub fn thread_cpu_seconds() -> f64 {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `ts` is a valid, writable timespec, and the clock id is one POSIX
    // defines; the call writes nothing else. It fails (EINVAL) only for an
    // unknown clock, which this one is not.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

/// Seconds since `t` (for the next-iteration estimates of the loops).
pub(crate) fn since(t: Instant) -> f64 {
    t.elapsed().as_secs_f64()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_budgets_keep_the_earlier_deadline_and_restore_the_outer() {
        assert!(SCOPE.with(Cell::get).is_none());
        let outer = Budget::from_millis(50_000).unwrap();
        outer.run(|| {
            let inner = Budget::from_secs_f64(3600.0).unwrap();
            inner.run(|| {
                let s = SCOPE.with(Cell::get).unwrap();
                assert!(s.limit <= Duration::from_millis(50_000));
            });
            let s = SCOPE.with(Cell::get).unwrap();
            assert_eq!(s.limit, Duration::from_millis(50_000));
            // an estimate past the budget is refused, naming it and the limit
            match check_estimate("test work", 1.0e5, f64::INFINITY) {
                Err(Error::TooExpensive { seconds, limit_seconds, .. }) => {
                    assert_eq!(seconds, 1.0e5);
                    assert!(limit_seconds <= 50.0);
                }
                other => panic!("{other:?}"),
            }
            // the method's cap stays in force under a longer budget
            assert!(matches!(check_estimate("test work", 2.0, 1.0), Err(Error::TooExpensive { limit_seconds, .. }) if limit_seconds == 1.0));
            assert!(check_estimate("test work", 0.5, 1.0).is_ok());
            // an iteration estimated past what is left
            let r = check_elapsed("test loop", 1.0e5, Reached::WorkingPrecision { bits: 100, accuracy_bits: 3.0 });
            assert!(matches!(r, Err(Error::BudgetSpent { reached: Reached::WorkingPrecision { bits: 100, .. }, .. })), "{r:?}");
        });
        assert!(SCOPE.with(Cell::get).is_none());
        // without a budget the loops are not bounded here (ensure installs the default)
        assert!(check_elapsed("test loop", 1.0e9, Reached::Evaluations { count: 1 }).is_ok());
        ensure(|| assert_eq!(SCOPE.with(Cell::get).unwrap().limit, Budget::DEFAULT.limit));
    }

    #[test]
    fn bad_budgets_are_typed_errors() {
        for s in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e9] {
            assert!(Budget::from_secs_f64(s).is_err(), "{s}");
        }
        assert!(matches!(Budget::from_millis(0), Err(Error::IntegerOutOfRange { arg: "budget_ms", .. })));
        assert_eq!(Budget::from_millis(1500).unwrap().seconds(), 1.5);
        assert_eq!(Budget::default(), Budget::DEFAULT);
    }
}
