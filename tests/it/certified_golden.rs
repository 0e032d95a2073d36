//! Golden set for the certified integrator (issue 22, item 7): the integrals of
//! F. Johansson's Arb example `examples/integrals.c` that have a closed form in the
//! integrator's functions, plus four extras used by the speed comparison against Arb.
//!
//! The reference values come from `reference/generate_integrals.py` (mpmath closed forms
//! at 3500 digits, `reference/data/integrals.csv`); each integrand is written here next
//! to its id. Every result must contain the reference value, meet the relative goal
//! `2^-prec`, and have an imaginary part containing 0.
//!
//! Left out of the set (no closed form, or not analytic on the range, or a function
//! the integrator does not offer): I4 (sin(x + e^x), no closed form; it is in the
//! benchmark), I5/I6/I16/I27 (floor, |.|), I7/I21/I22/I28/I35 (complex contours, zeta,
//! Weierstrass p), I8/I9/I30 (essential singularities), I11/I36 (gamma), I23 (Lambert W),
//! I25 (erf), I26/I32 (Airy), I29 (complex integrand), I33/I34 (Bessel I).

use std::collections::HashMap;
use std::time::Instant;

use maugis::ball::Ball;
use maugis::quad::certified::{integrate, integrate_to_infinity, integrate_weighted, Decay, HoloBall, Integral, Options, Weight};
use maugis::rug::Float;

const CSV: &str = include_str!("../../reference/data/integrals.csv");

fn reference() -> HashMap<String, String> {
    let mut rdr = csv::Reader::from_reader(CSV.as_bytes());
    rdr.records()
        .map(|r| {
            let r = r.unwrap();
            (r[0].to_string(), r[2].to_string())
        })
        .collect()
}

fn int(n: i64, p: u32) -> Ball {
    Ball::from_i64(n, p)
}

/// The result of one golden integral: the real enclosure (after the closed form's
/// scaling, e.g. the factor 4 of I1), whether every integration met its goal, whether
/// every imaginary part contains 0, and the evaluations spent.
struct Outcome {
    re: Ball,
    goal_met: bool,
    im_zero: bool,
    evaluations: u64,
}

fn one(r: Integral) -> Outcome {
    let im_zero = r.value.im().contains_zero();
    Outcome { re: r.real().clone(), goal_met: r.goal_met, im_zero, evaluations: r.evaluations }
}

fn sum(a: Integral, b: Integral) -> Outcome {
    let (x, y) = (one(a), one(b));
    Outcome { re: x.re.add(&y.re), goal_met: x.goal_met && y.goal_met, im_zero: x.im_zero && y.im_zero, evaluations: x.evaluations + y.evaluations }
}

fn scaled(mut o: Outcome, k: i64) -> Outcome {
    o.re = o.re.mul_i64(k);
    o
}

/// The ids of the golden set, in the CSV's order.
const IDS: [&str; 20] = [
    "I0", "I1", "I2", "I3", "I10", "I12", "I13", "I14", "I15", "I17", "I18", "I19", "I20", "I24", "I31", "Xexp", "Xsqrt", "XxJ0", "Xatan",
    "Xcos_rsqrt",
];

/// Run at 3333 bits by default: the integrals that take at most a few seconds there
/// (measured in release, 2026-11-25, on a loaded 2-core machine: I0 3.9 s, I1 0.1 s,
/// I12 4.1 s, I13 4.1 s with the node computation, I14 1.0 s, I24 0.2 s, e^x 1.5 s,
/// sqrt 0.04 s, x J0 0.1 s, atan 0.9 s). The others pass at 3333 bits in
/// `golden_3333_all` (ignored for time: I3 14 s, I10 17 s, I15 67 s, I17 9 s, I18 8 s,
/// I19 14 s, I20 14 s, I31 8 s on 2026-11-26), I2 included since 2026-11-26: its
/// algebraic decay x^-2 is mapped by x = e^s and cut at S ~ 2310, and 1/(1+x^2) on the
/// rectangle of e^(box) reached a pole unless the pieces in s were about 0.1 wide (an
/// estimate of 10^7 evaluations at 3333 bits). The ellipse boxes are now covered by
/// sub-boxes one period high (`quad/certified/cover.rs`): I2 at 3333 bits took
/// 2.45 million evaluations, 67 s CPU (194 s wall at load 20, test profile). The eight
/// others, run on 2026-11-26 23:00 with the covers: 0 failures, 116 s CPU (1280 s wall
/// at load 14-20).
const IDS_3333: [&str; 10] = ["I0", "I1", "I12", "I13", "I14", "I24", "Xexp", "Xsqrt", "XxJ0", "Xatan"];

fn compute(id: &str, p: u32) -> Outcome {
    let o = Options::new();
    let (zero, one_) = (int(0, p), int(1, p));
    match id {
        // int_0^100 sin x
        "I0" => one(integrate(|x| x.sin(), &zero, &int(100, p), p, &o).unwrap()),
        // 4 int_0^1 1/(1+x^2)
        "I1" => scaled(one(integrate(|x| (x.sqr() + x.int(1)).recip(), &zero, &one_, p, &o).unwrap()), 4),
        // 2 int_0^inf 1/(1+x^2): [0, 1] plus [1, inf) with |f| <= x^-2
        "I2" => {
            let f = |x: &HoloBall| (x.sqr() + x.int(1)).recip();
            let d = Decay::algebraic(int(2, p), int(1, p)).unwrap();
            scaled(sum(integrate(f, &zero, &one_, p, &o).unwrap(), integrate_to_infinity(f, &one_, None, &d, p, &o).unwrap()), 2)
        }
        // 4 int_0^1 sqrt(1-x^2) = 4 int_0^1 (1-x)^(1/2) sqrt(1+x)
        "I3" => {
            let w = Weight::new(Ball::zero(p), Ball::from_ratio(1, 2, p), 0).unwrap();
            scaled(one(integrate_weighted(|x| (x + x.int(1)).sqrt(), &zero, &one_, &w, p, &o).unwrap()), 4)
        }
        // int_0^10000 x^1000 e^-x
        "I10" => one(integrate(|x| x.powi(1000) * (-x).exp(), &zero, &int(10000, p), p, &o).unwrap()),
        // int_{-10}^{10} sin x + e^(-200-x^2) = 2.6e-87, far below 2^-prec int |f| at
        // every precision of this set: with the default absolute tolerance a ball around
        // 0 meets the goal (as in Arb under the absolute tolerance 2^-prec of its
        // examples/integrals.c). The golden set asks for the relative goal, which the
        // caller must then ask for.
        "I12" => {
            let o = Options::new().relative_only();
            one(integrate(|x| x.sin() + (-(x.sqr() + x.int(200))).exp(), &int(-10, p), &int(10, p), p, &o).unwrap())
        }
        // int_{-1020}^{-1010} e^x
        "I13" => one(integrate(|x| x.exp(), &int(-1020, p), &int(-1010, p), p, &o).unwrap()),
        // int_0^inf e^(-x^2), |f| <= e^(1 - 2x) <= 3 e^(-2x)
        "I14" => {
            let d = Decay::exponential(int(2, p), int(3, p)).unwrap();
            one(integrate_to_infinity(|x| (-x.sqr()).exp(), &zero, None, &d, p, &o).unwrap())
        }
        // int_0^1 sech(10(x-1/5))^2 + sech(100(x-2/5))^4 + sech(1000(x-3/5))^6
        "I15" => one(
            integrate(
                |x| {
                    // sech, as Arb's f_spike writes it (acb_sech): 1/cosh would make the
                    // rectangles of cosh on wide boxes contain 0
                    let a = (x * x.int(10) - x.int(2)).sech().sqr();
                    let b = (x * x.int(100) - x.int(40)).sech().powi(4);
                    let c = (x * x.int(1000) - x.int(600)).sech().powi(6);
                    a + b + c
                },
                &zero,
                &one_,
                p,
                &o,
            )
            .unwrap(),
        ),
        // int_0^inf sech x, |f| <= 2 e^-x
        "I17" => {
            let d = Decay::exponential(int(1, p), int(2, p)).unwrap();
            one(integrate_to_infinity(|x| x.sech(), &zero, None, &d, p, &o).unwrap())
        }
        // int_0^inf sech^3 x, |f| <= 8 e^(-3x)
        "I18" => {
            let d = Decay::exponential(int(3, p), int(8, p)).unwrap();
            one(integrate_to_infinity(|x| x.sech().powi(3), &zero, None, &d, p, &o).unwrap())
        }
        // int_0^1 -log(x)/(1+x): weight log x, g = -1/(1+x)
        "I19" => {
            let w = Weight::new(Ball::zero(p), Ball::zero(p), 1).unwrap();
            one(integrate_weighted(|x| -(x + x.int(1)).recip(), &zero, &one_, &w, p, &o).unwrap())
        }
        // int_0^inf x e^-x / (1 + e^-x), |f| <= x e^-x <= (2/e) e^(-x/2) <= e^(-x/2)
        "I20" => {
            let d = Decay::exponential(Ball::from_ratio(1, 2, p), int(1, p)).unwrap();
            one(integrate_to_infinity(|x| x * (-x).exp() / ((-x).exp() + x.int(1)), &zero, None, &d, p, &o).unwrap())
        }
        // int_0^pi max(sin x, cos x) = int_0^(pi/4) cos x + int_(pi/4)^pi sin x
        "I24" => {
            // endpoints at 2p bits: a ball endpoint of radius 2^-p alone costs the goal
            let (pi, q) = (Ball::pi(2 * p), Ball::pi(2 * p).mul_pow2(-2));
            sum(integrate(|x| x.cos(), &zero, &q, p, &o).unwrap(), integrate(|x| x.sin(), &q, &pi, p, &o).unwrap())
        }
        // int_0^pi x sin x / (1 + cos^2 x)
        "I31" => one(integrate(|x| x * x.sin() / (x.cos().sqr() + x.int(1)), &zero, &Ball::pi(p), p, &o).unwrap()),
        // int_0^1 e^x
        "Xexp" => one(integrate(|x| x.exp(), &zero, &one_, p, &o).unwrap()),
        // int_1^4 sqrt x
        "Xsqrt" => one(integrate(|x| x.sqrt(), &one_, &int(4, p), p, &o).unwrap()),
        // int_0^1 x J_0(x)
        "XxJ0" => one(integrate(|x| x * x.besselj(0), &zero, &one_, p, &o).unwrap()),
        // int_0^1 atan x
        "Xatan" => one(integrate(|x| x.atan(), &zero, &one_, p, &o).unwrap()),
        // int_0^1 x^(-1/2) cos x: weight x^(-1/2), g = cos
        "Xcos_rsqrt" => {
            let w = Weight::new(Ball::from_ratio(-1, 2, p), Ball::zero(p), 0).unwrap();
            one(integrate_weighted(|x| x.cos(), &zero, &one_, &w, p, &o).unwrap())
        }
        _ => panic!("no integrand for {id}"),
    }
}

/// Runs `ids` at `prec`; returns the failures (and prints one line per integral).
fn run(ids: &[&str], prec: u32) {
    let refs = reference();
    let mut failures = Vec::new();
    for &id in ids {
        let text = refs.get(id).unwrap_or_else(|| panic!("{id} missing from integrals.csv"));
        // all the digits of the reference (3500): a ball can be far tighter than its goal
        // (I12 at 64 bits comes back with 400 bits after the escalation)
        let exact = Float::with_val(12_000, Float::parse(text).unwrap());
        let t = Instant::now();
        let r = match std::panic::catch_unwind(|| compute(id, prec)) {
            Ok(r) => r,
            Err(_) => {
                failures.push(format!("{id} at {prec}: the integration returned an error (see the panic above)"));
                continue;
            }
        };
        let ms = t.elapsed().as_secs_f64() * 1e3;
        eprintln!("{id} at {prec}: {ms:.1} ms, {} evaluations, {:.1} bits", r.evaluations, r.re.rel_accuracy_bits());
        if !r.goal_met {
            failures.push(format!("{id} at {prec}: goal not met: {:?}", r.re));
        }
        if !r.re.contains(&exact) {
            failures.push(format!("{id} at {prec}: {:?} does not contain the reference", r.re));
        }
        if !r.re.meets_rel(prec) {
            failures.push(format!("{id} at {prec}: radius above 2^-{prec} |mid|: {:?}", r.re));
        }
        if !r.im_zero {
            failures.push(format!("{id} at {prec}: imaginary part excludes 0"));
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn every_reference_row_has_an_integrand() {
    let refs = reference();
    assert_eq!(refs.len(), IDS.len());
    for id in IDS {
        assert!(refs.contains_key(id), "{id}");
    }
}

#[test]
fn golden_64() {
    run(&IDS, 64);
}

#[test]
fn golden_333() {
    run(&IDS, 333);
}

#[test]
fn golden_3333() {
    run(&IDS_3333, 3333);
}

#[test]
#[ignore = "slow: every golden integral at 3333 bits"]
fn golden_3333_all() {
    let rest: Vec<&str> = IDS.iter().copied().filter(|id| !IDS_3333.contains(id)).collect();
    run(&rest, 3333);
}
