//! Time budgets (`maugis::budget`): a request whose cost estimate passes the
//! budget is refused at once with `Error::TooExpensive` naming the estimate; a
//! loop that reaches the budget stops with `Error::BudgetSpent` naming what it
//! reached; and the budget never changes an answer. No assertion is on wall
//! time (speed is measured in benches and docs/fuzzing.md): the refusals below
//! are decided by cost estimates, or by budgets far below one evaluation.

use maugis::ball::Decimal;
use maugis::budget::Budget;
use maugis::contact::displacement::quadrature::u_wave_quad_mp;
use maugis::error::Reached;
use maugis::registry::{self, Answer, Arg};
use maugis::rug::Float;
use maugis::special::hyp1f2::hyp1f2_mp;
use maugis::Error;

fn f(x: f64) -> Float {
    Float::with_val(64, x)
}

fn dec(s: &str) -> Arg<Decimal> {
    Arg::Real(Decimal::parse(s).unwrap())
}

/// `1F2(1e12; 1.5, 2.5; 100)`: positive terms that grow until `n^3 ~ a z`,
/// about 4.6e4 of them (pfq's cost model proves at least 2.5e4 before summing).
fn big_1f2(prec: u32) -> maugis::Result<maugis::Ball> {
    hyp1f2_mp(&f(1e12), &f(1.5), &f(2.5), &f(100.0), prec)
}

#[test]
fn a_huge_parameter_with_a_tiny_budget_is_refused_naming_the_estimate() {
    let tiny = Budget::from_millis(1).unwrap();
    match tiny.run(|| big_1f2(64)) {
        Err(Error::TooExpensive { function, seconds, limit_seconds }) => {
            assert!(function.contains("series"), "{function}");
            assert!(limit_seconds <= 1e-3, "the limit is what is left of the budget: {limit_seconds}");
            // the estimate is named and it is past the limit: at least 1.6e4 terms
            // at pfq's estimated time per term (1.2 us)
            assert!(seconds > limit_seconds && seconds >= 0.02, "{seconds}");
            let msg = Error::TooExpensive { function, seconds, limit_seconds }.to_string();
            assert!(msg.contains("ms") && msg.contains("budget"), "{msg}");
        }
        other => panic!("expected TooExpensive, got {other:?}"),
    }
    // the same call without a budget (the default) answers, certified
    let b = big_1f2(64).expect("answers under the default budget");
    assert!(b.meets_rel(64) && b.mid().is_sign_positive(), "{b:?}");
    // and a generous budget gives the very same ball
    let again = Budget::from_secs_f64(60.0).unwrap().run(|| big_1f2(64)).unwrap();
    assert_eq!((again.mid(), again.rad()), (b.mid(), b.rad()));
}

#[test]
fn the_registry_takes_a_budget_and_it_never_changes_an_answer() {
    // one point per registry function inside its domain, and a huge-parameter one
    let points: &[(&str, &[&str])] = &[
        ("bessel_j", &["3", "2.5"]),
        ("hyp1f2", &["0.5", "1", "1.5", "-2"]),
        ("hyp2f1", &["1.5", "1000001", "24.741135219007653", "-0.5"]),
        ("meijer_g_k", &["0", "0.999999999999999"]),
        ("u_wave", &["1", "0.7", "0.1", "1.5"]),
        ("du_wave", &["1", "0.7", "0.1", "1.5"]),
        ("u_hertz", &["1", "2", "1.5"]),
        ("strip_ratio", &["1", "0.35", "1.125", "2"]),
    ];
    for (name, texts) in points {
        let func = registry::function(name).unwrap();
        let args: Vec<Arg<Decimal>> = func
            .params
            .iter()
            .zip(texts.iter())
            .map(|(p, t)| if p.kind == registry::ParamKind::Integer { Arg::Int(t.parse().unwrap()) } else { dec(t) })
            .collect();
        for prec in [12, 96] {
            let plain = func.eval_mp(&args, prec).unwrap_or_else(|e| panic!("{name} at {prec}: {e}"));
            let budgeted = func
                .eval_mp_with_budget(&args, prec, Budget::from_secs_f64(600.0).unwrap())
                .unwrap_or_else(|e| panic!("{name} at {prec}: {e}"));
            match (plain, budgeted) {
                (Answer::Ball(x), Answer::Ball(y)) => assert_eq!((x.mid(), x.rad()), (y.mid(), y.rad()), "{name}"),
                other => panic!("{name}: {other:?}"),
            }
        }
    }
    // the first request, huge parameter, through the registry with a tiny
    // budget: the 1F2 one is refused by its estimate
    let h = registry::function("hyp1f2").unwrap();
    let args = [dec("1e12"), dec("1.5"), dec("2.5"), dec("100")];
    let r = h.eval_mp_with_budget(&args, 64, Budget::from_millis(1).unwrap());
    assert!(matches!(r, Err(ref e @ Error::TooExpensive { .. }) if e.is_time_limit()), "{r:?}");
}

#[test]
fn a_loop_the_model_cannot_bound_stops_at_the_budget_with_what_it_reached() {
    // the MP quadrature estimate checks the budget at every outer node; one
    // outer node (a Bessel value and an inner tanh-sinh at 88 bits) takes far
    // more than a microsecond, so it stops at the second node
    let budget = Budget::from_secs_f64(1e-6).unwrap();
    let r = budget.run(|| u_wave_quad_mp(&f(1.0), &f(0.7), &f(0.1), &f(1.5), 64));
    match r {
        Err(ref e @ Error::BudgetSpent { reached: Reached::Evaluations { count }, elapsed_seconds, budget_seconds, .. }) => {
            assert!(elapsed_seconds > budget_seconds, "{e} ({count} evaluations)");
            assert!(e.is_time_limit() && e.to_string().contains("integrand evaluations"), "{e}");
        }
        other => panic!("expected BudgetSpent, got {other:?}"),
    }
}

#[test]
fn budgets_out_of_range_are_typed_errors() {
    assert!(matches!(Budget::from_secs_f64(0.0), Err(Error::OutOfRange { .. })));
    assert!(matches!(Budget::from_secs_f64(f64::NAN), Err(Error::NonFinite { .. })));
    assert!(matches!(Budget::from_millis(0), Err(Error::IntegerOutOfRange { arg: "budget_ms", .. })));
    assert_eq!(Budget::default().seconds(), 30.0);
}

#[test]
fn the_certified_quadrature_checks_the_budget_between_its_rounds() {
    use maugis::ball::Ball;
    use maugis::quad::certified::{integrate, Options};
    // int_0^30 sin(x^2) dx at 128 bits: a chirp the adaptive bisection cuts into many
    // pieces; under a microsecond the first check between rounds stops it
    let (a, b) = (Ball::from_i64(0, 128), Ball::from_i64(30, 128));
    let run = || integrate(|x| x.sqr().sin(), &a, &b, 128, &Options::new());
    match Budget::from_secs_f64(1e-6).unwrap().run(run) {
        Err(ref e @ Error::BudgetSpent { reached: Reached::Evaluations { .. }, .. }) => assert!(e.is_time_limit(), "{e}"),
        other => panic!("expected BudgetSpent, got {other:?}"),
    }
    // the budget never changes an answer: with room it is the answer without one
    let free = run().expect("answers without a budget");
    let roomy = Budget::from_secs_f64(600.0).unwrap().run(run).expect("answers in 600 s");
    assert!(free.goal_met && roomy.goal_met);
    assert_eq!(free.real().mid(), roomy.real().mid());
}

/// The wave series (Eq. 12) estimates its terms at the working precision its
/// cancellation needs (`1.44 D` guard bits, `D = 2 pi a / zeta`) before its first
/// round: issue 37's scan ran `u_wave_series(100001, 23.6, 0.5, 1.36e18, 916)`
/// (`D = 26 600`, 917 terms at 38 000 bits) and two more for 0.15-0.46 s under a
/// 100 ms budget once its Meijer constants no longer needed MPFR's Gamma (whose
/// estimate had refused them). Refused now by that estimate, at once; an ordinary
/// input still answers under the same budget.
#[test]
fn the_wave_series_is_refused_by_its_term_estimate() {
    let f = registry::function("u_wave_series").unwrap();
    let args = [dec("100001"), dec("23.60000516339597"), dec("0.5"), dec("1359272381516038712"), Arg::Int(916)];
    let r = f.eval_mp_with_budget(&args, 7, Budget::from_millis(100).unwrap());
    match r {
        Err(Error::TooExpensive { function, seconds, .. }) => assert!(function.contains("wave series") && seconds > 0.1, "{function}: {seconds}"),
        other => panic!("expected TooExpensive, got {other:?}"),
    }
    let ordinary = [dec("1"), dec("0.7"), dec("0.1"), dec("1.5"), Arg::Int(40)];
    for prec in [8, 64, 128] {
        let r = f.eval_mp_with_budget(&ordinary, prec, Budget::from_millis(100).unwrap());
        match r {
            Ok(Answer::SeriesBall { value, trunc }) => assert!(value.meets_rel(prec) && trunc.is_finite(), "{prec}: {value:?}"),
            other => panic!("{prec}: {other:?}"),
        }
    }
}

/// A direct call of the certified quadrature, and of the expression integrator,
/// refuses an expensive integral at the installed budget with a typed error naming
/// what it reached. `int_0^300 sin(x^2) dx` at 1000 bits: a chirp of about 2.9e4
/// half-periods, certified without a budget in 1.7 s (`maugis integrate 'sin(x^2)' 0
/// 300 --prec 1000`, debug build, 2026-11-29), 85 times the 20 ms given here. The default budget a direct
/// call runs under when none is installed is checked by a unit test in
/// `src/quad/certified/mod.rs` (it would take 30 s here).
#[test]
fn a_direct_call_of_an_expensive_integral_refuses_at_the_budget() {
    use maugis::ball::Ball;
    use maugis::quad::certified::{integrate, Options};
    use maugis::quad::expr::{integrate_range, End, Expr};
    let budget = Budget::from_millis(20).unwrap();
    let (a, b) = (Ball::from_i64(0, 1100), Ball::from_i64(300, 1100));
    let direct = budget.run(|| integrate(|x| x.sqr().sin(), &a, &b, 1000, &Options::new()));
    let f = Expr::parse("sin(x^2)").unwrap();
    let (lo, hi) = (End::parse("0").unwrap(), End::parse("300").unwrap());
    let parsed = budget.run(|| integrate_range(&f, &lo, &hi, None, None, 1000, &Options::new()));
    for (route, r) in [("integrate", direct), ("integrate_range", parsed)] {
        match r {
            Err(ref e @ Error::BudgetSpent { function, reached: Reached::Evaluations { count }, budget_seconds, elapsed_seconds, .. }) => {
                assert!(function.contains("certified quadrature") && count > 0, "{route}: {e}");
                assert!(budget_seconds <= 0.02 && elapsed_seconds >= budget_seconds, "{route}: {e}");
                assert!(e.is_time_limit(), "{route}: {e}");
            }
            other => panic!("{route}: expected BudgetSpent, got {other:?}"),
        }
    }
}
