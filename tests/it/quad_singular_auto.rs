//! Finite integrals whose singular points are found from the expression, with no
//! declared weight (issue 40, items 1, 2 and 5): removable singularities, algebraic and
//! logarithmic endpoint singularities, poles as typed errors naming the point.
//! References: `reference/data/integrals_singular.csv`, written by
//! `reference/generate_finite_singular.py` (closed forms, mpmath).

use maugis::quad::certified::{IntegrationError, Options};
use maugis::ball::Decimal;
use maugis::quad::expr::{integrate_range, End, Expr, WeightSpec};
use maugis::rug::Float;

const CSV: &str = include_str!("../../reference/data/integrals_singular.csv");

fn fields(line: &str) -> Vec<String> {
    crate::common::csv_fields(line)
}

#[test]
fn table_integrals_are_certified_at_every_precision() {
    for line in CSV.lines().skip(1) {
        let f = fields(line);
        let (id, expr, a, b, value) = (&f[0], &f[2], &f[3], &f[4], &f[5]);
        let e = Expr::parse(expr).unwrap();
        let want = Float::with_val(1400, Float::parse(value).unwrap());
        // 1000 bits everywhere but x^x, whose end is mapped exponentially (11 s there,
        // the long tier; the others take at most 0.5 s: docs/quadrature.md)
        let slow = id == "x_pow_x";
        let precs: &[u32] = if slow && !crate::tier::long() { &[53, 64, 333] } else { &[53, 64, 333, 1000] };
        for &prec in precs {
            let r = integrate_range(&e, &End::parse(a).unwrap(), &End::parse(b).unwrap(), None, None, prec, &Options::new())
                .unwrap_or_else(|err| panic!("{id} at {prec} bits: {err}"));
            assert!(r.real().contains(&want), "{id} at {prec} bits: {:?} does not contain the reference", r.value);
            assert!(r.goal_met && r.real().meets_rel(prec), "{id} at {prec} bits: {:?} misses the goal", r.value);
        }
    }
}

#[test]
fn poles_are_typed_errors_that_name_the_point() {
    // a quotient by a square whose numerator does not vanish there: a double pole, not
    // the removable point of `(1 - cos x)/x^2`; a numerator whose derivatives vanish to
    // one order less than the power (`(e^x - 1)/x^2`, `(e^x - 1 - x)/x^3`): a simple
    // pole, not the removable points of `(e^x - 1 - x)/x^2` and `(cos x - 1 + x^2/2)/x^4`
    for (text, point) in [
        ("1/x", 0.0),
        ("1/(x-0.5)", 0.5),
        ("x^(-2)", 0.0),
        ("1/(1-x)", 1.0),
        ("1/x^2", 0.0),
        ("(1-cos(x))/(2*x-1)^2", 0.5),
        ("sin(x)/x^2", 0.0),
        ("(exp(x)-1)/x^2", 0.0),
        ("(exp(x)-1-x)/x^3", 0.0),
        ("(cos(x)-1+x^2/2)/x^5", 0.0),
        ("(exp(x-1)-x)/(x-1)^3", 1.0),
    ] {
        let e = Expr::parse(text).unwrap();
        match integrate_range(&e, &End::parse("0").unwrap(), &End::parse("1").unwrap(), None, None, 64, &Options::new()) {
            Err(maugis::Error::Integration(IntegrationError::NotIntegrable { near, .. })) => {
                assert!((near - point).abs() < 1e-12, "{text}: named {near}, want {point}")
            }
            other => panic!("{text}: {other:?}"),
        }
    }
}

/// The routes that make these integrals cheap, by their evaluation counts (deterministic,
/// unlike times): a removable point of a quotient is enclosed on every box, so
/// `sin(x)/x` and `(e^x - 1)/x` cost what an analytic integrand costs (47 178 and 29 055
/// evaluations at 333 bits when the point was mapped); `atan(1/x)` is `pi/2 - atan(x)` on
/// the segment (90 925 before); `log(x)` and `x^(-1/2) cos x` are weights, within 2x of
/// the same integral with the weight declared; `log(x) log(1-x)` is a weight at each end.
#[test]
fn found_singularities_cost_what_declared_ones_do() {
    let count = |f: &str, a: &str, b: &str, w: Option<WeightSpec>, prec: u32| {
        let r = integrate_range(&Expr::parse(f).unwrap(), &End::parse(a).unwrap(), &End::parse(b).unwrap(), w.as_ref(), None, prec, &Options::new())
            .unwrap_or_else(|e| panic!("{f}: {e}"));
        assert!(r.goal_met, "{f} at {prec} bits");
        r.evaluations
    };
    for prec in [64u32, 333] {
        for (f, a, b, most) in [("sin(x)/x", "-1", "1", 100), ("(exp(x)-1)/x", "0", "1", 100), ("sin(x-0.5)/(x-0.5)", "0", "1", 100), ("atan(1/x)", "0", "1", 200), ("log(x)*log(1-x)", "0", "1", 2500)] {
            let n = count(f, a, b, None, prec);
            assert!(n <= most, "{f} at {prec} bits: {n} evaluations, more than {most}");
        }
        let half = Some(Decimal::parse("-0.5").unwrap());
        for (found, declared, weight) in [
            ("log(x)", "1", WeightSpec { alpha: None, beta: None, log: 1 }),
            ("x^(-1/2)*cos(x)", "cos(x)", WeightSpec { alpha: half.clone(), beta: None, log: 0 }),
        ] {
            let (n, m) = (count(found, "0", "1", None, prec), count(declared, "0", "1", Some(weight), prec));
            assert!(n <= 2 * m, "{found} at {prec} bits: {n} evaluations against {m} declared");
        }
    }
}
