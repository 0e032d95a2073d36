//! No public entry point panics, on any input: fuzzing on the stable toolchain
//! with bolero's structured generators (issue 26, item 5), driven by a seeded
//! byte stream (`common/fuzz_inputs.rs`) instead of bolero's random engine.
//!
//! Each target draws structured inputs (f64 bit patterns mixed with values at and
//! next to the domain edges, huge and negative integers, precisions 0, 1, the
//! maximum and beyond, arbitrary text for the parsers) and calls the library.
//! A panic fails the test; so does an `Ok` that carries a non-finite number
//! (bad input must be an error, never a NaN).
//!
//! `./dev test` runs 250 inputs a target (`--long`: 1000, the same 250 first) from
//! the fixed seed `./dev` sets: the same inputs on every run and machine. A campaign:
//!
//! ```text
//! BOLERO_RANDOM_ITERATIONS=1000000 cargo test --release --features maugis/gmp-no-check --test it fuzz::
//! ```
//!
//! (docs/fuzzing.md records the campaigns run and their counts).

#[path = "common/fuzz_real.rs"]
mod fuzz_real;
#[path = "common/fuzz_inputs.rs"]
mod fuzz_inputs;

use maugis::budget::thread_cpu_seconds;
use fuzz_inputs::check;
use maugis::ball::Decimal;
use maugis::contact::curve::{load_area_curve, state, CurveOptions};
use maugis::contact::model::{ContactSize, Params};
use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_expr, Expr, UpperLimit};
use maugis::registry::{self, Answer, Arg, ParamKind, FUNCTIONS};
use maugis::MAX_PREC;

/// Values at and next to the edges of the functions' domains.
const EDGES: [f64; 24] = [
    0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 1.5, 2.0, 1e-300, -1e-300, 5e-324, 1e300, -1e300, f64::MAX, f64::MIN,
    f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e-6, 1e6, 1e4, 1e5, 1.0 - f64::EPSILON, 1.0 + f64::EPSILON,
];

/// An f64 from 64 random bits: a raw bit pattern, a domain edge, a small
/// multiple of 1/8, or a value of moderate size.
fn real(bits: u64) -> f64 {
    fuzz_real::real_with(bits, &EDGES)
}

/// Bits whose [`real`] is NaN, infinite or at most `1e4` in magnitude (larger
/// values are replaced by one in `[-10, 30)`).
fn moderate(bits: u64) -> u64 {
    let v = real(bits);
    if !v.is_finite() || v.abs() <= 1e4 {
        bits
    } else {
        // mode 3 of `real`: a value in [-10, 30)
        (3u64 << 62) | (bits >> 2)
    }
}

/// An integer from 64 random bits: raw, small, or at the i64 edges.
fn integer(bits: u64) -> i64 {
    match bits >> 62 {
        0 => bits as i64,
        1 => [i64::MIN, i64::MAX, 0, -1, 1, 1 << 24, (1 << 24) + 1, 100_000, 100_001, 1_000_001][(bits % 10) as usize],
        _ => (bits % 61) as i64 - 20,
    }
}

/// A precision: 0, 1 and the edges of the allowed range often, otherwise a small one.
fn precision(bits: u32) -> u32 {
    match bits % 8 {
        0 => [0, 1, 2, MAX_PREC + 1, u32::MAX][(bits / 8 % 5) as usize],
        _ => 2 + bits / 8 % 160,
    }
}

/// A decimal text from random bits: mostly well formed, sometimes not.
fn decimal_text(bits: u64) -> String {
    let v = real(bits);
    match bits % 7 {
        0 => format!("{v:e}"),
        1 => format!("{}", integer(bits.rotate_left(7))),
        2 => format!("{v}e{}", (bits >> 40) as i16),
        3 => ["nan", "inf", "-", "", "1e", ".", "0x10", "1.2.3", "1e999999999999", " 2.5 "][(bits % 10) as usize].to_string(),
        _ => format!("{v}"),
    }
}

/// 0, or `1e-30 <= |d| <= 1e4` (the magnitudes an MP fuzz run can afford for the
/// functions in [`MP_MODERATE_ONLY`]).
fn moderate_decimal(d: &Decimal) -> bool {
    let v = d.as_rational().to_f64().abs();
    v == 0.0 && d.as_rational().cmp0().is_eq() || (1e-30..=1e4).contains(&v)
}

fn finite_answer(name: &str, args: &dyn std::fmt::Debug, a: &Answer) {
    let ok = match a {
        Answer::F64(v) => v.is_finite(),
        // a tail bound may be +inf (true, and useless): never NaN or negative
        Answer::SeriesF64 { value, trunc } => value.is_finite() && *trunc >= 0.0,
        Answer::EstimateF64 { value, error_estimate } => value.is_finite() && error_estimate.is_finite(),
        Answer::Ball(b) | Answer::SeriesBall { value: b, .. } => b.mid().is_finite() && b.rad().is_finite(),
        Answer::EstimateMp { value, error_estimate } => value.is_finite() && error_estimate.is_finite(),
        _ => true,
    };
    assert!(ok, "{name}{args:?} answered a non-finite number: {a:?}");
}

#[test]
fn registry_f64_paths() {
    check().with_type::<(u8, [u64; 5])>().for_each(|(which, bits)| {
        let f = &FUNCTIONS[*which as usize % FUNCTIONS.len()];
        let args: Vec<Arg<f64>> = f
            .params
            .iter()
            .zip(bits)
            .map(|(p, &b)| match p.kind {
                // orders and term counts: huge values are quick errors, but a count of
                // 1e5 terms is valid and slow
                ParamKind::Integer => Arg::Int(integer(b) % 5000),
                ParamKind::Real => Arg::Real(real(moderate(b))),
            })
            .collect();
        // reals up to about 1e4 (NaN, infinities, subnormals and the edges below 1e4
        // kept): at parameters like 1e300 the f64 paths fall back to MP, which is
        // certified but can take minutes (docs/fuzzing.md), more than a fuzz run can spend
        let started = std::time::Instant::now();
        let answer = f.eval_f64(&args);
        let took = started.elapsed().as_secs_f64();
        if took > 0.5 {
            eprintln!("slow f64 input: {}{args:?} took {took:.1} s", f.name);
        }
        if let Ok(a) = answer {
            finite_answer(f.name, &args, &a);
        }
        if let Ok(b) = f.eval_bounded(&args) {
            assert!(b.value.is_finite() && b.err.is_finite() && b.err >= 0.0, "{}{args:?}: {b:?}", f.name);
        }
    });
}

/// The MP arguments of `f` from random bits (`None` when a decimal text does not
/// parse): orders within the domain's scale (a huge order is a quick error), and
/// reals as the decimal generator writes them, huge integers and exponents up to
/// +-32767 included, unless `moderate` keeps them to 0 and `1e-30 <= |x| <= 1e4`.
/// The texts of the arguments come second (for printing).
fn mp_args(f: &registry::Function, bits: &[u64; 5], moderate_only: bool) -> Option<(Vec<Arg<Decimal>>, Vec<String>)> {
    let (mut args, mut texts) = (Vec::new(), Vec::new());
    for (q, &b) in f.params.iter().zip(bits) {
        match q.kind {
            ParamKind::Integer => {
                let n = integer(b) % 2000;
                args.push(Arg::Int(n));
                texts.push(n.to_string());
            }
            ParamKind::Real => {
                let text = decimal_text(moderate(b));
                match Decimal::parse(&text) {
                    Ok(d) if !moderate_only || moderate_decimal(&d) => args.push(Arg::Real(d)),
                    _ => return None,
                }
                texts.push(text);
            }
        }
    }
    Some((args, texts))
}

#[test]
fn registry_mp_paths() {
    check().with_type::<(u8, [u64; 5], u32)>().for_each(|(which, bits, p)| {
        let f = &FUNCTIONS[*which as usize % FUNCTIONS.len()];
        let prec = precision(*p);
        // the generator's full range (huge integers, exponents up to +-32767: issue
        // 23h made MP hyp2f1 quick there), except for the wave's quadrature and
        // series, slow at any magnitude (docs/fuzzing.md)
        let Some((args, texts)) = mp_args(f, bits, MP_MODERATE_ONLY.contains(&f.name)) else { return };
        let started = std::time::Instant::now();
        let answer = f.eval_mp(&args, prec);
        let took = started.elapsed().as_secs_f64();
        SLOWEST_MP_MICROS.fetch_max((took * 1e6) as u64, std::sync::atomic::Ordering::Relaxed);
        if took > 0.5 {
            eprintln!("slow MP input: {}({}) at {prec} bits took {took:.1} s", f.name, texts.join(", "));
        }
        if let Ok(a) = answer {
            finite_answer(f.name, &args, &a);
        }
    });
    eprintln!("registry_mp_paths: slowest input {:.3} s", SLOWEST_MP_MICROS.load(std::sync::atomic::Ordering::Relaxed) as f64 * 1e-6);
}

/// Functions whose MP inputs [`registry_mp_paths`] keeps to 0 and `1e-30 <= |x| <=
/// 1e4` ([`moderate_decimal`]): the certified wave quadrature takes 2-15 s and more
/// at many inputs of any size (`u_wave_quad(22.7, 0.5, 29.9, 28.87)` at 64 bits: over
/// 15 s; 8.8 s at `zeta = 1.97e18`), the wave series at 10^4 terms over 15 s; a
/// slow corner of the contact functions (docs/fuzzing.md), not of the special
/// functions.
const MP_MODERATE_ONLY: [&str; 2] = ["u_wave_quad", "u_wave_series"];

/// The slowest MP input of [`registry_mp_paths`] (microseconds), for its report.
static SLOWEST_MP_MICROS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// The slow-input scan (issue 37 item 5, docs/fuzzing.md "Slow-input scan"): the
/// MP path of every registry function over the decimal generator's full range,
/// at the fuzzed precisions, each call under a time budget, from a fixed
/// splitmix64 stream. It fails on a non-finite answer and on a refusal that is
/// neither about the input (a domain or argument error), nor about time, nor a
/// method's cap (working precision, series terms, exponent range: printed and
/// counted, open in docs/fuzzing.md), and it prints per function the calls
/// answered and refused by kind, and the slowest call with its input.
///
/// The default tier runs 4 inputs a function; `./dev test --long` runs 2000 and
/// also fails on a call slower than `SCAN_LIMIT` seconds (default 2). Knobs:
/// `SCAN_N` (inputs a function), `SCAN_SEED` (default 1), `SCAN_BUDGET_MS`
/// (default 100), `SCAN_FN` (a comma list of names), `SCAN_FULL=0` (the
/// moderate range only). A watchdog prints an input still running after 2 s.
/// Each call's wall time is what the limit applies to; its thread CPU time is
/// printed beside it (on the shared 2-core machine, at load 10-14, a call gets
/// a third to a half of a core: the wall time over the CPU time is the share
/// it did not get).
#[test]
fn registry_mp_budget_scan() {
    use std::sync::{Arc, Mutex};
    let var = |k: &str| std::env::var(k).ok();
    let n: u64 = var("SCAN_N").and_then(|v| v.parse().ok()).unwrap_or(crate::tier::pick(4, 2000));
    let mut state: u64 = var("SCAN_SEED").and_then(|v| v.parse().ok()).unwrap_or(1);
    let budget_ms: u64 = var("SCAN_BUDGET_MS").and_then(|v| v.parse().ok()).unwrap_or(100);
    let limit: Option<f64> = var("SCAN_LIMIT").and_then(|v| v.parse().ok()).or(crate::tier::long().then_some(2.0));
    let full = var("SCAN_FULL").map_or(true, |v| v != "0");
    let only: Option<Vec<String>> =
        var("SCAN_FN").filter(|v| !v.is_empty()).map(|v| v.split(',').map(str::to_string).collect());
    let budget = maugis::Budget::from_millis(budget_ms).expect("SCAN_BUDGET_MS in 1 ..= 86 400 000");
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    };
    let current: Arc<Mutex<Option<(String, std::time::Instant, bool)>>> = Arc::new(Mutex::new(None));
    let watch = Arc::clone(&current);
    let stop = Arc::new(std::sync::atomic::AtomicBool::new(false));
    let stopped = Arc::clone(&stop);
    let watchdog = std::thread::spawn(move || {
        while !stopped.load(std::sync::atomic::Ordering::Relaxed) {
            std::thread::sleep(std::time::Duration::from_millis(200));
            if let Some((text, t0, told)) = watch.lock().unwrap().as_mut() {
                if !*told && t0.elapsed().as_secs_f64() > 2.0 {
                    eprintln!("still running after 2 s: {text}");
                    *told = true;
                }
            }
        }
    });
    eprintln!("| function | inputs | answered | refused for time | refused for the input | refused at a cap | slowest (s) | slowest input | most CPU (s) |");
    eprintln!("|---|---|---|---|---|---|---|---|---|");
    let mut wrong = Vec::new();
    let mut too_slow = Vec::new();
    for f in FUNCTIONS {
        if only.as_ref().is_some_and(|o| !o.iter().any(|s| s == f.name)) {
            continue;
        }
        let (mut count, mut answered, mut time, mut input, mut capped) = (0u64, 0u64, 0u64, 0u64, 0u64);
        let (mut worst, mut worst_text, mut worst_cpu) = (0.0f64, String::new(), 0.0f64);
        let mut draws = 0u64;
        while count < n && draws < 100 * n {
            draws += 1;
            let bits = [next(), next(), next(), next(), next()];
            let prec = precision(next() as u32);
            let Some((args, texts)) = mp_args(f, &bits, !full) else { continue };
            let text = format!("{}({}) at {prec} bits", f.name, texts.join(", "));
            *current.lock().unwrap() = Some((text.clone(), std::time::Instant::now(), false));
            let (started, cpu0) = (std::time::Instant::now(), thread_cpu_seconds());
            let answer = f.eval_mp_with_budget(&args, prec, budget);
            let (took, cpu) = (started.elapsed().as_secs_f64(), thread_cpu_seconds() - cpu0);
            *current.lock().unwrap() = None;
            count += 1;
            if took > worst {
                (worst, worst_text) = (took, text.clone());
            }
            worst_cpu = worst_cpu.max(cpu);
            if limit.is_some_and(|l| took > l) {
                eprintln!("over the limit: {text}: {took:.3} s (CPU {cpu:.3} s)");
                too_slow.push(format!("{text}: {took:.2} s (CPU {cpu:.3} s)"));
            }
            match answer {
                Ok(a) => {
                    finite_answer(f.name, &args, &a);
                    answered += 1;
                }
                Err(e) if e.is_time_limit() => time += 1,
                Err(e) if about_the_input(&e) => {
                    if let maugis::Error::ValueOutOfRange { log2_magnitude } = e {
                        // the value itself past the exponent range: counted with the
                        // input's refusals, printed so that a run can tell them apart
                        eprintln!("value out of range ({log2_magnitude}): {text}");
                    }
                    input += 1
                }
                // a working-precision cap, a series cap, an exponent overflow in a
                // step: the input may be answerable, the method gave up (counted,
                // printed, and listed in docs/fuzzing.md as open)
                Err(e @ (maugis::Error::PrecisionExhausted { .. } | maugis::Error::NoConvergence { .. } | maugis::Error::Overflow { .. })) => {
                    eprintln!("refused at a cap: {text}: {e:?}");
                    capped += 1;
                }
                Err(e) => wrong.push(format!("{text}: {e:?}")),
            }
        }
        let short = |t: &str| if t.len() > 120 { format!("{}...", &t[..120]) } else { t.to_string() };
        eprintln!("| `{}` | {count} | {answered} | {time} | {input} | {capped} | {worst:.3} | `{}` | {worst_cpu:.3} |", f.name, short(&worst_text));
    }
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    watchdog.join().unwrap();
    assert!(wrong.is_empty(), "refusals neither about the input nor about time:\n{}", wrong.join("\n"));
    assert!(too_slow.is_empty(), "calls over the scan's limit:\n{}", too_slow.join("\n"));
}

/// Whether a refusal is about the input as typed: outside the domain, an edge
/// inside the input ball, a precision or an integer out of range, a decimal
/// the parser or the function cannot take, a profile the model does not take (a
/// wave finer than `abar/beta = 1e5 / (2 pi)`: `ProfileError::WaveTooFine`, checked
/// before any work), a value itself outside the exponent range (no precision
/// represents it: `ValueOutOfRange`).
fn about_the_input(e: &maugis::Error) -> bool {
    use maugis::Error as E;
    e.is_domain()
        || matches!(
            e,
            E::NonFinite { .. }
                | E::Precision { .. }
                | E::IntegerOutOfRange { .. }
                | E::ArgumentKind { .. }
                | E::Arity { .. }
                | E::NotRepresentable { .. }
                | E::NonFiniteResult { .. }
                | E::ValueOutOfRange { .. }
                | E::Profile(_)
        )
}

#[test]
fn decimal_parser() {
    check().for_each(|bytes| {
        let text = String::from_utf8_lossy(bytes);
        if let Ok(d) = Decimal::parse(&text) {
            let b = d.to_ball(64);
            assert!(b.mid().is_finite() && b.rad().is_finite());
        }
    });
    check().with_type::<u64>().for_each(|bits| {
        let _ = Decimal::parse(&decimal_text(*bits));
    });
}

#[test]
fn registry_lookup() {
    check().for_each(|bytes| {
        let name = String::from_utf8_lossy(bytes);
        match registry::function(&name) {
            Ok(f) => assert_eq!(f.name, name),
            Err(e) => assert!(!e.to_string().is_empty()),
        }
    });
}

/// Pieces of the expression language, to build texts the parser mostly accepts.
const TOKENS: [&str; 32] = [
    "x", "x", "1", "2.5", "-", "+", "*", "/", "^", "(", ")", "sqrt(", "exp(", "log(", "sin(", "cos(", "tan(",
    "sinh(", "cosh(", "tanh(", "atan(", "besselj(", ",", "pi", "0", "1e400", "-3", "(x", ")^2", "1/x", "nan", "y",
];

#[test]
fn expression_parser_and_integrator() {
    check().for_each(|bytes| {
        let _ = Expr::parse(&String::from_utf8_lossy(bytes));
    });
    check().with_type::<(Vec<u8>, u64, u64)>().for_each(|(picks, a, b)| {
        let text: String = picks.iter().take(24).map(|&i| TOKENS[i as usize % TOKENS.len()]).collect();
        let Ok(expr) = Expr::parse(&text) else { return };
        // the f64 evaluation is an estimate: any value, NaN included, but no panic
        std::hint::black_box(expr.eval_f64(real(*a)));
        // a cheap certified integral over a short range: bounded work whatever the expression
        let (Ok(lo), Ok(hi)) = (Decimal::parse(&decimal_text(*a)), Decimal::parse(&decimal_text(*b))) else { return };
        let Ok(opts) = Options::new().max_evaluations(2_000).and_then(|o| o.max_working_prec(256)) else { return };
        if let Ok(r) = integrate_expr(&expr, &lo, &UpperLimit::Finite(hi), None, None, 32, &opts) {
            assert!(r.value.re().mid().is_finite() && r.value.re().rad().is_finite(), "{text}: {r:?}");
        }
    });
}

#[test]
fn model_entry_points() {
    check().with_type::<[u64; 4]>().for_each(|bits| {
        let [lambda, alpha, beta, abar] = bits.map(real);
        let Ok(params) = Params::new(lambda, alpha, beta) else { return };
        // large contacts are valid but slow (the wave series grows with abar/beta); keep runs short
        if abar.abs() > 50.0 || 2.0 * std::f64::consts::PI * abar / beta > 2e3 {
            // construction only (its checks are what large inputs meet first)
            std::hint::black_box(ContactSize::new(params, abar).is_ok());
            return;
        }
        if let Ok(s) = state(params, abar) {
            assert!(s.load.is_finite() && s.m.is_finite(), "{params:?} at {abar}: {s:?}");
        }
        let opts = CurveOptions { amax: abar, points: (bits[0] % 12) as usize, ..CurveOptions::default() };
        if let Ok(c) = load_area_curve(params, opts) {
            assert!(c.points.iter().all(|p| p.load.is_finite()));
        }
    });
}
