//! Finite integrals whose singular points are found from the expression, with no
//! declared weight (issue 40, items 1, 2 and 5): removable singularities, algebraic and
//! logarithmic endpoint singularities, poles as typed errors naming the point.
//! References: `reference/data/integrals_singular.csv`, written by
//! `reference/generate_finite_singular.py` (closed forms, mpmath).

use maugis::quad::certified::{IntegrationError, Options};
use maugis::quad::expr::{integrate_range, End, Expr};
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
        // 1000 bits for the ends found as weights (milliseconds); the mapped ends
        // (removable points, logs) take seconds there (docs/quadrature.md)
        let fast = ["rsqrt", "sqrt", "rsqrt_cos", "rsqrt_both"].contains(&id.as_str());
        let precs: &[u32] = if fast { &[53, 64, 333, 1000] } else { &[53, 64, 333] };
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
    for (text, point) in [("1/x", 0.0), ("1/(x-0.5)", 0.5), ("x^(-2)", 0.0), ("1/(1-x)", 1.0)] {
        let e = Expr::parse(text).unwrap();
        match integrate_range(&e, &End::parse("0").unwrap(), &End::parse("1").unwrap(), None, None, 64, &Options::new()) {
            Err(maugis::Error::Integration(IntegrationError::NotIntegrable { near, .. })) => {
                assert!((near - point).abs() < 1e-12, "{text}: named {near}, want {point}")
            }
            other => panic!("{text}: {other:?}"),
        }
    }
}
