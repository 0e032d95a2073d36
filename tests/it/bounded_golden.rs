//! The `*_bounded` f64 functions against the golden tables: at every row the
//! reference must lie within the returned bound `err` of `value`.
//!
//! The reference carries 50 significant digits, so the check allows the
//! reference's own rounding (`REF_REL_SLACK |ref|`) on top of `err`. Also
//! reported: how tight the bounds are (max and median of `err / ulp(value)`),
//! since a bound that always holds but is huge is of no use to a solver.

use crate::common;

use common::*;
use maugis::special::{bessel_j, hyp1f2, hyp2f1, meijer_g};
use maugis::{Bounded, Result};
use rug::Float;

/// Largest accepted `err` in units of `ulp(value)` (a bound looser than this is
/// useless for f64 work and signals a broken error analysis).
const MAX_ERR_ULPS: f64 = 64.0;

fn check_table<F: Fn(&Row) -> Result<Bounded>>(name: &str, f: F) {
    let rows = load(name);
    assert!(rows.len() > 1000, "{name}: only {} rows", rows.len());
    let mut misses = Vec::new();
    let mut loose = Vec::new();
    let mut ulps: Vec<f64> = Vec::with_capacity(rows.len());
    for row in &rows {
        let r = reference(row);
        let b = match f(row) {
            Ok(b) => b,
            Err(e) => {
                misses.push(format!("error {e} at {row:?}"));
                continue;
            }
        };
        let dist = Float::with_val(256, Float::with_val(256, b.value) - &r).abs();
        let allowed = Float::with_val(256, Float::with_val(256, r.abs_ref()) * REF_REL_SLACK) + b.err;
        if dist > allowed {
            misses.push(format!("{} +/- {:e} misses {} at {row:?}", b.value, b.err, row["value"]));
        }
        let ulp = if b.value == 0.0 { f64::from_bits(1) } else { (b.value.abs() * f64::EPSILON).max(f64::from_bits(1)) };
        let u = b.err / ulp;
        ulps.push(u);
        // Near zeros of the function the bound is absolute; only judge rows where
        // the value is not tiny against the reference scale of the table.
        if u > MAX_ERR_ULPS && b.value.abs() > 1e-8 {
            loose.push(format!("err = {u:.1} ulp at {row:?}"));
        }
    }
    ulps.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let median = ulps.get(ulps.len() / 2).copied().unwrap_or(0.0);
    println!("{name}: {} rows, err/ulp median {median:.2}, max {:.2}", rows.len(), ulps.last().copied().unwrap_or(0.0));
    assert!(misses.is_empty(), "{name}: {} enclosure failures, first: {:#?}", misses.len(), &misses[..misses.len().min(5)]);
    assert!(loose.is_empty(), "{name}: {} loose bounds, first: {:#?}", loose.len(), &loose[..loose.len().min(5)]);
}

#[test]
fn bounded_bessel_j_encloses_golden() {
    check_table("bessel_j", |row| bessel_j::bessel_j_bounded(col_i64(row, "n"), col_f64(row, "x")));
}

#[test]
fn bounded_hyp1f2_encloses_golden() {
    check_table("hyp1f2", |row| {
        hyp1f2::hyp1f2_bounded(col_f64(row, "a"), col_f64(row, "b1"), col_f64(row, "b2"), col_f64(row, "z"))
    });
}

#[test]
fn bounded_hyp2f1_encloses_golden() {
    check_table("hyp2f1", |row| {
        hyp2f1::hyp2f1_bounded(col_f64(row, "a"), col_f64(row, "b"), col_f64(row, "c"), col_f64(row, "z"))
    });
}

#[test]
fn bounded_meijer_g_k_encloses_golden() {
    check_table("meijer_g_k", |row| meijer_g::meijer_g_k_bounded(col_i64(row, "k") as u32, col_f64(row, "y")));
}

#[test]
fn bounded_rejects_non_finite_input() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(bessel_j::bessel_j_bounded(3, bad).is_err());
        assert!(hyp1f2::hyp1f2_bounded(0.5, 1.0, 1.5, bad).is_err());
        assert!(hyp2f1::hyp2f1_bounded(1.0, 0.5, bad, 0.5).is_err());
        assert!(meijer_g::meijer_g_k_bounded(3, bad).is_err());
        assert!(maugis::contact::displacement::u_wave_bounded(1.0, 1.125, 0.1, bad).is_err());
        assert!(maugis::contact::displacement::du_wave_bounded(bad, 1.125, 0.1, 2.0).is_err());
    }
}
