//! Integrals to infinity without a declared decay (issue 36): the tail bound comes
//! from the expression (decay classes) or, for oscillatory integrands, from the
//! rotated contour. References: `reference/data/integrals_infinite.csv`, written by
//! `reference/generate_infinite_integrals.py` (closed forms, mpmath).

use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_range, End, Expr};
use maugis::rug::Float;

const CSV: &str = include_str!("../../reference/data/integrals_infinite.csv");

struct Row {
    id: String,
    expr: String,
    a: String,
    b: String,
    value: String,
}

fn rows() -> Vec<Row> {
    let mut out = Vec::new();
    for line in CSV.lines().skip(1) {
        // id,description,expression,a,b,value with optional "quoted" fields
        let fields = crate::common::csv_fields(line);
        assert_eq!(fields.len(), 6, "{line}");
        out.push(Row { id: fields[0].clone(), expr: fields[2].clone(), a: fields[3].clone(), b: fields[4].clone(), value: fields[5].clone() });
    }
    out
}

fn check(ids: &[&str], precs: &[u32]) {
    let rows = rows();
    for id in ids {
        let row = rows.iter().find(|r| r.id == *id).unwrap_or_else(|| panic!("{id} missing from the csv"));
        let f = Expr::parse(&row.expr).unwrap();
        let (a, b) = (End::parse(&row.a).unwrap(), End::parse(&row.b).unwrap());
        let want = Float::with_val(1400, Float::parse(&row.value).unwrap());
        for &prec in precs {
            let r = integrate_range(&f, &a, &b, None, None, prec, &Options::new())
                .unwrap_or_else(|e| panic!("{id} at {prec} bits: {e}"));
            assert!(r.real().contains(&want), "{id} at {prec} bits: {:?} does not contain the reference", r.value);
            assert!(r.goal_met && r.real().meets_rel(prec), "{id} at {prec} bits: {:?} misses the goal", r.value);
        }
    }
}

#[test]
fn absolutely_integrable_tails_need_no_declaration() {
    check(&["exp_over_1px", "x2_gauss", "lorentz_half", "x_exp_sin", "gauss_left", "sech2", "rsqrt_cube", "exp_sqrt"], &[64, 333]);
}

/// A removable point or a `log` at `a` before an exponential tail: `[a, R]` by the
/// finite route, which finds them.
#[test]
fn removable_points_before_a_decaying_tail() {
    check(&["exp_sinc", "exp_log", "exp_one_minus_cos"], &[64, 333]);
}

#[test]
fn oscillatory_tails_by_contour_rotation() {
    check(&["cos_lorentz", "j0", "hankel_k0.5", "hankel_k1", "hankel_k5"], &[64, 333]);
}

#[test]
fn oscillatory_with_endpoint_behaviour() {
    check(&["sinc", "j1_rsqrt"], &[64, 333]);
}

#[test]
fn not_absolutely_integrable_and_not_oscillatory_is_a_typed_error() {
    use maugis::quad::certified::IntegrationError as I;
    // with an oscillatory term, the rest still decides (`1/x`, `1`: no decay)
    for text in ["1/x", "1/sqrt(x)", "x", "exp(x)/x^2", "1/x + sin(x)/x", "1 - cos(x)/x^2", "(1 - cos(x))/x"] {
        let f = Expr::parse(text).unwrap();
        match integrate_range(&f, &End::parse("1").unwrap(), &End::Infinity, None, None, 64, &Options::new()) {
            Err(maugis::Error::Integration(I::NotAbsolutelyIntegrable { .. } | I::MissingDecay)) => {}
            other => panic!("{text}: {other:?}"),
        }
    }
}

/// Sums where the oscillatory factor belongs to a term, not to the whole integrand
/// (`quad/expr/oscillatory_sum.rs`): `(1 - cos x)/x^2` is `1/x^2 - cos(x)/x^2` past the
/// split point, the first term by its decay class and the second by contour rotation,
/// with the removable point at 0 left to the whole integrand's finite part;
/// `sin(x)^2 = 1/2 - cos(2x)/2`; and `int_-inf^inf`, whose reflected sum `f(x) + f(-x)`
/// has two oscillatory terms.
#[test]
fn sums_with_oscillatory_terms() {
    check(&["one_minus_cos_sq", "x_minus_sin_cube", "sinc_plus_lorentz", "one_minus_cos_full", "sin2_sq", "sin2_lorentz", "cos_lorentz_full"], &[64, 333]);
}
