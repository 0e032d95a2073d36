//! Issue 26: every public function that takes a working precision answers a precision
//! of 0 (which rug cannot take), 1, or beyond the cap (`MAX_WORKING_PREC + 1` and
//! `u32::MAX`, which would allocate gigabytes) with a typed error, never a panic; each
//! call is also made at 64 bits, where it must answer.

use maugis::ball::Ball;
use maugis::contact::displacement::{self, quadrature as wave_quadrature, quadrature_ball as wave_certified};
use maugis::contact::{model::Params, model_mp, traction_mp};
use maugis::special::{bessel_j, hyp1f2, meijer_g};
use rug::Float;

/// `f` at precision 0, 1 and beyond the cap: a typed error, no panic; at 64 bits:
/// an answer. The failures are collected in `bad`.
fn check<T, E: std::fmt::Debug>(bad: &mut Vec<String>, what: &str, f: impl Fn(u32) -> Result<T, E> + std::panic::RefUnwindSafe) {
    for p in [0u32, 1, maugis::MAX_WORKING_PREC + 1, u32::MAX] {
        match std::panic::catch_unwind(|| f(p).is_err()) {
            Ok(true) => {}
            Ok(false) => bad.push(format!("{what} at precision {p}: an answer instead of an error")),
            Err(_) => bad.push(format!("{what} at precision {p}: panicked")),
        }
    }
    if let Err(e) = f(64) {
        bad.push(format!("{what} at 64 bits: {e:?}"));
    }
}

fn fl(x: f64) -> Float {
    Float::with_val(64, x)
}

fn ball(x: f64) -> Ball {
    Ball::from_f64(x, 64).unwrap()
}

#[test]
fn special_functions_refuse_precision_zero_and_beyond_the_cap() {
    let mut bad = Vec::new();
    check(&mut bad, "hyp1f2_model_ball", |p| hyp1f2::hyp1f2_model_ball(2, &ball(3.0), p));
    check(&mut bad, "hyp1f2_model_family", |p| hyp1f2::hyp1f2_model_family(3, &ball(3.0), p));
    check(&mut bad, "hyp1f2_mp", |p| hyp1f2::hyp1f2_mp(&fl(0.5), &fl(1.0), &fl(1.5), &fl(-3.0), p));
    check(&mut bad, "hyp1f2_ball_mp", |p| hyp1f2::hyp1f2_ball_mp(&ball(0.5), &ball(1.0), &ball(1.5), &ball(-3.0), p));
    check(&mut bad, "hyp1f2_mp_f64", |p| hyp1f2::hyp1f2_mp_f64(0.5, 1.0, 1.5, -3.0, p));
    check(&mut bad, "MeijerConstants::new", |p| meijer_g::MeijerConstants::new(3, p));
    check(&mut bad, "meijer_g_k_direct", |p| meijer_g::meijer_g_k_direct(3, &fl(0.5), p));
    check(&mut bad, "meijer_g_k_near_one", |p| meijer_g::meijer_g_k_near_one(3, &fl(0.99), p));
    check(&mut bad, "meijer_g_k_at_one", |p| meijer_g::meijer_g_k_at_one(3, p));
    check(&mut bad, "direct_sums_sweep", |p| meijer_g::direct_sums_sweep(3, &ball(0.5), p));
    check(&mut bad, "near_one_sums_sweep", |p| meijer_g::near_one_sums_sweep(3, &ball(0.01), p));
    check(&mut bad, "bessel_j_series", |p| bessel_j::bessel_j_series(3, &fl(2.5), p));
    check(&mut bad, "bessel_j_series_pfq", |p| bessel_j::bessel_j_series_pfq(3, &fl(2.5), p));
    check(&mut bad, "bessel_j_sequence_mp", |p| bessel_j::bessel_j_sequence_mp(3, &fl(2.5), p));
    check(&mut bad, "bessel_j_sequence_three_term", |p| bessel_j::bessel_j_sequence_three_term(8, &fl(2.5), p));
    check(&mut bad, "bessel_j_three_term", |p| {
        let (j0, j1) = (bessel_j::bessel_j_mp(0, &fl(2.5), 64).unwrap(), bessel_j::bessel_j_mp(1, &fl(2.5), 64).unwrap());
        bessel_j::bessel_j_three_term(3, &fl(2.5), &j0, &j1, p)
    });
    check(&mut bad, "bessel_j_hankel", |p| bessel_j::bessel_j_hankel(3, &fl(250.5), p));
    check(&mut bad, "MeijerConstants::cached", |p| meijer_g::MeijerConstants::cached(3, p));
    let consts = meijer_g::MeijerConstants::new(3, 64).unwrap();
    check(&mut bad, "meijer_g_k_direct_ball", |p| meijer_g::meijer_g_k_direct_ball(&consts, &ball(0.5), p));
    check(&mut bad, "meijer_g_k_near_one_ball", |p| meijer_g::meijer_g_k_near_one_ball(&consts, &ball(0.01), p));
    check(&mut bad, "meijer_g33_slater_mp", |p| meijer_g::meijer_g33_slater_mp([0.3, 0.6, 0.9], [0.2, 0.7, 1.1], -0.5, p));
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn contact_functions_refuse_precision_zero_and_beyond_the_cap() {
    let mut bad = Vec::new();
    let params = Params::new(1.0, 0.35, 1.125).unwrap();
    check(&mut bad, "u_wave_ball_mp", |p| displacement::u_wave_ball_mp(&ball(2.0), &ball(1.125), &ball(0.35), &ball(6.0), p));
    check(&mut bad, "u_wave_series_mp", |p| displacement::u_wave_series_mp(&fl(2.0), &fl(1.125), &fl(0.35), &fl(6.0), 40, p));
    check(&mut bad, "u_wave_quad_mp", |p| wave_quadrature::u_wave_quad_mp(&fl(2.0), &fl(1.125), &fl(0.35), &fl(6.0), p));
    check(&mut bad, "u_wave_quad_ball", |p| wave_certified::u_wave_quad_ball(&ball(2.0), &ball(1.125), &ball(0.35), &ball(3.0), p));
    check(&mut bad, "strip_residual_mp", |p| model_mp::strip_residual_mp(params, 3.0, &fl(1.5), p));
    let inputs = model_mp::ModelBalls::exact(params, 3.0).unwrap();
    check(&mut bad, "strip_residual_ball_mp", |p| model_mp::strip_residual_ball_mp(&inputs, &ball(0.5), p));
    check(&mut bad, "load_mp", |p| model_mp::load_mp(params, 3.0, &ball(1.5), p));
    check(&mut bad, "traction_mp", |p| traction_mp::traction_mp(params, 3.0, &ball(1.5), 1.0, p));
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
