//! Tests of the complex elementary functions: enclosure of high-precision references
//! at exact points and on random points of wide rectangles, branch cuts, poles and
//! overflow, and powers.

use super::*;
use rug::float::Constant;

/// Reference precision.
const RP: u32 = 2400;

type Pair = (Float, Float);

fn f(x: f64) -> Float {
    Float::with_val(RP, x)
}

/// Principal log of x + iy at RP bits (y = +0 on the cut gives Arg = pi).
fn rlog(x: &Float, y: &Float) -> Pair {
    let n = Float::with_val(RP, x * x) + Float::with_val(RP, y * y);
    (n.ln() / 2u32, Float::with_val(RP, y.atan2_ref(x)))
}

fn rexp(x: &Float, y: &Float) -> Pair {
    let e = Float::with_val(RP, x.exp_ref());
    (Float::with_val(RP, &e * Float::with_val(RP, y.cos_ref())), e * Float::with_val(RP, y.sin_ref()))
}

fn reference(name: &str, x: &Float, y: &Float) -> Pair {
    let (sx, cx) = (Float::with_val(RP, x.sin_ref()), Float::with_val(RP, x.cos_ref()));
    let (shx, chx) = (Float::with_val(RP, x.sinh_ref()), Float::with_val(RP, x.cosh_ref()));
    let (sy, cy) = (Float::with_val(RP, y.sin_ref()), Float::with_val(RP, y.cos_ref()));
    let (shy, chy) = (Float::with_val(RP, y.sinh_ref()), Float::with_val(RP, y.cosh_ref()));
    let m = |a: &Float, b: &Float| Float::with_val(RP, a * b);
    match name {
        "exp" => rexp(x, y),
        "sin" => (m(&sx, &chy), m(&cx, &shy)),
        "cos" => (m(&cx, &chy), -m(&sx, &shy)),
        "sinh" => (m(&shx, &cy), m(&chx, &sy)),
        "cosh" => (m(&chx, &cy), m(&shx, &sy)),
        "tan" => {
            let x2 = Float::with_val(RP, x * 2u32);
            let y2 = Float::with_val(RP, y * 2u32);
            let den = Float::with_val(RP, x2.cos_ref()) + Float::with_val(RP, y2.cosh_ref());
            (Float::with_val(RP, x2.sin_ref()) / &den, Float::with_val(RP, y2.sinh_ref()) / &den)
        }
        "tanh" => {
            let x2 = Float::with_val(RP, x * 2u32);
            let y2 = Float::with_val(RP, y * 2u32);
            let den = Float::with_val(RP, x2.cosh_ref()) + Float::with_val(RP, y2.cos_ref());
            (Float::with_val(RP, x2.sinh_ref()) / &den, Float::with_val(RP, y2.sin_ref()) / &den)
        }
        "log" => rlog(x, y),
        "sqrt" => {
            let a = (Float::with_val(RP, x * x) + Float::with_val(RP, y * y)).sqrt();
            let re = (Float::with_val(RP, &a + x) / 2u32).sqrt();
            let mut im = (Float::with_val(RP, &a - x) / 2u32).sqrt();
            if y.is_sign_negative() && !y.is_zero() {
                im = -im;
            }
            (re, im)
        }
        "atan" => {
            // (i/2)(log(1 - iz) - log(1 + iz)); 1 - iz = (1 + y) - ix, 1 + iz = (1 - y) + ix
            let mx = if x.is_zero() { Float::new(RP) } else { Float::with_val(RP, -x) };
            let (a1, b1) = rlog(&Float::with_val(RP, 1 + y), &mx);
            let (a2, b2) = rlog(&Float::with_val(RP, 1 - y), x);
            ((b2 - b1) / 2u32, (a1 - a2) / 2u32)
        }
        _ => unreachable!(),
    }
}

fn eval(name: &str, z: &CBall) -> CBall {
    match name {
        "exp" => z.exp(),
        "sin" => z.sin(),
        "cos" => z.cos(),
        "sinh" => z.sinh(),
        "cosh" => z.cosh(),
        "tan" => z.tan(),
        "tanh" => z.tanh(),
        "log" => z.log(),
        "log_a" => z.log_analytic(),
        "sqrt" => z.sqrt(),
        "sqrt_a" => z.sqrt_analytic(),
        "atan" => z.atan(),
        "atan_a" => z.atan_analytic(),
        _ => unreachable!(),
    }
}

const ALL: [&str; 10] = ["exp", "sin", "cos", "sinh", "cosh", "tan", "tanh", "log", "sqrt", "atan"];

/// Points where every function is finite (exact f64 inputs).
const POINTS: [(f64, f64); 18] = [
    (0.5, 0.25),
    (-1.5, 2.0),
    (3.0, -0.7),
    (1e-30, 1e-30),
    (1e-300, -1e-300),
    (-2.0, 1e-20),
    (-2.0, -1e-20),
    (0.75, 0.0),
    (-0.75, 0.0),
    (0.0, 0.5),
    (0.0, -3.0),
    (1.0, 1e-25),
    (1.0 + 1e-15, 1e-9),
    (0.6, 0.8),
    (-20.0, 30.0),
    (std::f64::consts::FRAC_PI_2, 0.0),
    (1e-5, 1.5),
    (-1e-5, -1.5),
];

fn hyp(a: &Pair) -> Float {
    Float::with_val(RP, a.0.hypot_ref(&a.1))
}

#[test]
fn exact_points_enclose_and_carry_digits() {
    let p = 128;
    for name in ALL {
        for &(x, y) in &POINTS {
            let z = CBall::from_f64s(x, y, p);
            let (xr, yr) = (f(x), f(y));
            if name == "atan" && x == 0.0 && y.abs() >= 1.0 {
                continue; // on the cut: checked separately
            }
            let r = reference(name, &xr, &yr);
            let b = eval(name, &z);
            assert!(b.is_finite(), "{name}({x}, {y}) = {b:?}");
            assert!(b.contains(&r.0, &r.1), "{name}({x}, {y}) = {b:?}, want {} {}", r.0, r.1);
            let bound = Mag::from_float_down(&hyp(&r)).mul_2exp(-120);
            assert!(b.rad_mag().le(&bound), "{name}({x}, {y}): {b:?} radius too big");
            // each part separately, unless it is tiny against the modulus
            for (part, val) in [(b.re(), &r.0), (b.im(), &r.1)] {
                let rel = Mag::from_float_down(val).mul_2exp(-118);
                let abs_ok = Mag::from_float_down(val).le(&Mag::from_float_down(&hyp(&r)).mul_2exp(-1000));
                assert!(abs_ok || part.rad_mag().le(&rel), "{name}({x}, {y}): part {part:?} vs {val}");
            }
        }
    }
}

#[test]
fn analytic_forms_agree_off_the_cut() {
    let p = 96;
    for &(x, y) in &POINTS {
        let z = CBall::from_f64s(x, y, p);
        let off_log_cut = x > 0.0 || y != 0.0;
        assert_eq!(z.log_analytic().is_finite(), off_log_cut, "log_a({x},{y})");
        if off_log_cut {
            assert_eq!(z.log_analytic(), z.log());
            assert_eq!(z.sqrt_analytic(), z.sqrt());
        }
        if !(x == 0.0 && y.abs() >= 1.0) {
            assert_eq!(z.atan_analytic(), z.atan());
        }
    }
}

#[test]
fn branch_cuts() {
    let p = 128;
    let pi = Float::with_val(RP, Constant::Pi);
    // on the cut (-inf, 0]: analytic indeterminate, principal from above
    for z in [CBall::from_f64s(-2.0, 0.0, p), CBall::from_real(Ball::from_i64(-2, p)).conj()] {
        assert!(!z.log_analytic().is_finite() && !z.sqrt_analytic().is_finite());
        assert!(!z.pow_analytic(&CBall::from_f64s(0.3, 0.1, p)).is_finite());
        let l = z.log();
        assert!(l.contains(&f(2.0).ln(), &pi), "{l:?}");
        let s = z.sqrt();
        assert!(s.contains(&Float::new(RP), &f(2.0).sqrt()), "{s:?}");
    }
    // just above and below: continuous from above, jump of 2 pi below
    let above = CBall::from_f64s(-2.0, 1e-30, p).log();
    let below = CBall::from_f64s(-2.0, -1e-30, p).log();
    assert!(above.im().mid().to_f64() > 3.1 && below.im().mid().to_f64() < -3.1);
    // a rectangle straddling the cut: the principal form encloses every value
    let mut z = CBall::from_f64s(-1.0, 0.0, p);
    z.add_error_mag(Mag::from_f64(0.25));
    assert!(!z.log_analytic().is_finite() && !z.sqrt_analytic().is_finite());
    check_rectangle(&z, "log", 1);
    check_rectangle(&z, "sqrt", 2);
    let l = z.log();
    assert!(l.contains(&f(1.0).ln(), &pi) && l.contains(&f(1.0).ln(), &Float::with_val(RP, -&pi)));
    // a rectangle touching the cut from above, [-1.25, -0.75] x [0, 0.5]
    let t = CBall::new(Ball::from_f64(-1.0, p).unwrap(), Ball::from_f64(0.25, p).unwrap());
    let mut t = t;
    t.add_error_mag(Mag::from_f64(0.25));
    assert!(!t.log_analytic().is_finite());
    check_rectangle(&t, "log", 3);
    assert!(t.log().contains(&f(1.0).ln(), &pi));
    // log and sqrt of a rectangle around 0
    let mut o = CBall::zero(p);
    o.add_error_mag(Mag::from_f64(1e-3));
    assert!(!o.log().is_finite());
    let s0 = o.sqrt();
    assert!(s0.is_finite() && s0.contains(&Float::new(RP), &Float::new(RP)));
    check_rectangle(&o, "sqrt", 4);
    assert!(CBall::zero(p).sqrt().is_exact());
    // atan: cuts on the imaginary axis beyond +-i
    let h = Float::with_val(RP, &pi / 2u32);
    let ln3_2 = f(3.0).ln() / 2u32;
    let up = CBall::from_f64s(0.0, 2.0, p);
    assert!(!up.atan_analytic().is_finite());
    assert!(up.atan().contains(&h, &ln3_2), "{:?}", up.atan());
    let dn = CBall::from_f64s(0.0, -2.0, p);
    assert!(dn.atan().contains(&Float::with_val(RP, -&h), &Float::with_val(RP, -&ln3_2)), "{:?}", dn.atan());
    // continuity: upper cut from the right, lower from the left
    assert!(CBall::from_f64s(1e-30, 2.0, p).atan().re().mid().to_f64() > 1.5);
    assert!(CBall::from_f64s(-1e-30, 2.0, p).atan().re().mid().to_f64() < -1.5);
    assert!(CBall::from_f64s(-1e-30, -2.0, p).atan().re().mid().to_f64() < -1.5);
    // +-i are singular
    assert!(!CBall::i(p).atan().is_finite() && !CBall::i(p).neg().atan().is_finite());
    // rectangle straddling the upper cut
    let mut a = CBall::from_f64s(0.0, 2.0, p);
    a.add_error_mag(Mag::from_f64(0.5));
    assert!(!a.atan_analytic().is_finite());
    check_rectangle(&a, "atan", 5);
}

#[test]
fn tan_poles_and_overflow() {
    let p = 128;
    let half_pi = CBall::from_real(Ball::pi(p).mul_pow2(-1));
    assert!(!half_pi.tan().is_finite());
    assert!(!half_pi.mul_i().tanh().is_finite());
    let mut q = CBall::from_real(Ball::pi(p).mul_pow2(-1));
    q.add_error_mag(Mag::from_f64(1e-10));
    assert!(!q.tan().is_finite());
    // large imaginary parts: tan tends to +-i, no overflow
    let t = CBall::from_f64s(1.0, 1e10, p).tan();
    assert!(t.contains(&Float::new(RP), &f(1.0)) && t.rad_mag().le(&Mag::pow2(-100)), "{t:?}");
    let t = CBall::from_f64s(1.0, -1e10, p).tan();
    assert!(t.contains(&Float::new(RP), &f(-1.0)), "{t:?}");
    let t = CBall::from_f64s(1e10, 1.0, p).tanh();
    assert!(t.contains(&f(1.0), &Float::new(RP)), "{t:?}");
    // overflow is indeterminate
    for name in ["exp", "sin", "cos", "sinh", "cosh"] {
        let z = CBall::from_f64s(1e10, 1e10, p);
        let b = eval(name, &z);
        assert!(!b.is_finite(), "{name}: {b:?}");
        assert!(b.re().mid().is_nan());
    }
    // underflow of exp is a tiny finite ball
    let u = CBall::from_f64s(-1e10, 1.0, p).exp();
    assert!(u.is_finite() && u.contains(&Float::new(RP), &Float::new(RP)));
    // non-finite input
    for name in ALL {
        assert!(!eval(name, &CBall::indeterminate(p)).is_finite());
    }
    // moderate |y| on both tan forms: y = 1 +- small hits both branches
    for &(x, y) in &[(0.3, 0.999), (0.3, 1.001), (0.3, -1.001), (2.0, 5.0), (-2.0, -40.0)] {
        let z = CBall::from_f64s(x, y, p);
        let r = reference("tan", &f(x), &f(y));
        let b = z.tan();
        assert!(b.contains(&r.0, &r.1), "tan({x},{y}) {b:?}");
        assert!(b.rad_mag().le(&Mag::from_float_down(&hyp(&r)).mul_2exp(-120)));
    }
}

/// Checks that `name(z)` contains the reference at 20 pseudo-random points of z.
fn check_rectangle(z: &CBall, name: &str, seed: u64) {
    let b = eval(name, z);
    assert!(b.is_finite(), "{name} {z:?}");
    let mut s = seed.wrapping_mul(0x9E3779B97F4A7C15) | 1;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for k in 0..22 {
        // corners and edges too
        let (u, v) = match k {
            0 => (1.0, 1.0),
            1 => (-1.0, -1.0),
            _ => (next(), next()),
        };
        let x = Float::with_val(RP, z.re().mid() + Float::with_val(RP, z.re().rad() * u));
        let y = Float::with_val(RP, z.im().mid() + Float::with_val(RP, z.im().rad() * v));
        let r = reference(name, &x, &y);
        assert!(b.contains(&r.0, &r.1), "{name} on {z:?} at ({x}, {y}): {b:?} misses {} {}", r.0, r.1);
    }
}

#[test]
fn wide_rectangles_enclose_random_points() {
    let p = 64;
    let mut seed = 1;
    for name in ALL {
        for &(x, y, rx, ry) in &[
            (0.5, 0.25, 0.1, 0.2),
            (-1.5, 2.0, 1.0, 0.5),
            (3.0, -0.7, 0.01, 0.3),
            (2.0, 0.5, 0.5, 0.4),
            (0.2, -0.3, 1e-6, 1e-8),
            (-3.0, 5.0, 2.0, 2.0),
        ] {
            let mut z = CBall::from_f64s(x, y, p);
            let (mut re, mut im) = z.into_parts();
            re.add_error_mag(Mag::from_f64(rx));
            im.add_error_mag(Mag::from_f64(ry));
            z = CBall::new(re, im);
            if !eval(name, &z).is_finite() {
                // only allowed for tan/atan (poles, cut) and log/sqrt; none of these boxes
                // reach a pole or 0, but tan/tanh's denominators may widen past zero
                assert!(["tan", "tanh"].contains(&name), "{name} {z:?}");
                continue;
            }
            seed += 1;
            check_rectangle(&z, name, seed);
        }
    }
}

#[test]
fn powers() {
    let p = 128;
    let z = CBall::from_f64s(-1.5, 0.5, p);
    // exact integers: no cut
    let z3 = z.pow(&CBall::from_i64(3, p));
    assert_eq!(z3, z.pow_u64(3));
    assert!(z.pow_analytic(&CBall::from_i64(-2, p)).is_finite());
    assert!(!CBall::zero(p).pow(&CBall::from_i64(-1, p)).is_finite());
    // real positive base, real exponent: real
    let r = CBall::from_f64s(2.0, 0.0, p).pow(&CBall::from_f64s(0.5, 0.0, p));
    assert!(r.is_real() && r.contains(&f(2.0).sqrt(), &Float::new(RP)));
    // general: exp(w log z)
    for &(x, y, a, b) in &[(0.5, 0.25, 0.3, -1.2), (-1.5, 2.0, 2.5, 0.0), (-2.0, 0.0, 0.3, 0.1), (3.0, -0.7, -0.5, 4.0)] {
        let zb = CBall::from_f64s(x, y, p);
        let wb = CBall::from_f64s(a, b, p);
        let (l, t) = rlog(&f(x), &f(y));
        let er = Float::with_val(RP, &l * a) - Float::with_val(RP, &t * b);
        let ei = Float::with_val(RP, &t * a) + Float::with_val(RP, &l * b);
        let want = rexp(&er, &ei);
        let got = zb.pow(&wb);
        assert!(got.contains(&want.0, &want.1), "pow {got:?}");
        assert!(got.rad_mag().le(&Mag::from_float_down(&hyp(&want)).mul_2exp(-118)), "{got:?}");
    }
    // a disc around 0 with Re w > 0
    let mut o = CBall::zero(p);
    o.add_error_mag(Mag::from_f64(0.01));
    let w = CBall::from_f64s(0.5, 0.2, p);
    let g = o.pow(&w);
    assert!(g.is_finite() && g.abs_upper_mag().le(&Mag::from_f64(0.4)), "{g:?}");
    assert!(!o.pow_analytic(&w).is_finite());
}

#[test]
#[ignore = "timing; run with --ignored --nocapture"]
fn timing() {
    for p in [64u32, 128, 333] {
        let z = CBall::from_f64s(0.7, -0.3, p);
        let x = CBall::from_f64s(0.7, 0.0, p);
        for (name, zz) in [("complex", &z), ("real", &x)] {
            for fname in ["exp", "log", "sqrt", "sin", "tan", "atan"] {
                let n = 20000;
                let t0 = std::time::Instant::now();
                for _ in 0..n {
                    std::hint::black_box(eval(fname, std::hint::black_box(zz)));
                }
                let dt = t0.elapsed().as_nanos() as f64 / n as f64;
                println!("{p:4} bits {name:8} {fname:5}: {dt:8.0} ns");
            }
        }
    }
}
