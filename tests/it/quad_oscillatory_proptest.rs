//! Random rational `g` in certified oscillatory integrals to infinity (issue 36): the
//! balls must contain the closed forms
//! `int_0^inf cos(w x)/(x^2 + c^2) dx = pi e^{-w c}/(2c)` and
//! `int_0^inf x sin(w x)/(x^2 + c^2) dx = pi e^{-w c}/2` (`w, c > 0`; Gradshteyn-Ryzhik
//! 3.723.2 and 3.723.3), the second only conditionally convergent; and sums whose
//! oscillatory factor belongs to a term (`quad/expr/oscillatory_sum.rs`):
//! `int_0^inf (1 - cos(w x))/x^2 dx = pi w/2` and `int_0^inf (k + cos(w x))/(x^2 + c^2) dx
//! = pi (k + e^{-w c})/(2c)` (the same 3.723.2 and `int_0^inf dx/(x^2 + c^2) = pi/(2c)`).

use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_range, End, Expr};
use maugis::rug::Float;
use proptest::prelude::*;

fn closed(w: (u32, u32), c: (u32, u32), with_x: bool) -> Float {
    let p = 512;
    let w = Float::with_val(p, w.0) / w.1;
    let c = Float::with_val(p, c.0) / c.1;
    let pi = Float::with_val(p, maugis::rug::float::Constant::Pi);
    let e = Float::with_val(p, -(w * &c)).exp();
    if with_x {
        pi * e / 2u32
    } else {
        pi * e / (c * 2u32)
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]
    #[test]
    fn lorentzian_fourier_integrals_are_enclosed(wn in 1u32..8, wd in 1u32..4, cn in 1u32..6, cd in 1u32..4, with_x: bool) {
        let text = if with_x {
            format!("x*sin({wn}/{wd}*x)/(x^2 + ({cn}/{cd})^2)")
        } else {
            format!("cos({wn}/{wd}*x)/(x^2 + ({cn}/{cd})^2)")
        };
        let f = Expr::parse(&text).unwrap();
        let r = integrate_range(&f, &End::parse("0").unwrap(), &End::Infinity, None, None, 64, &Options::new()).unwrap();
        let want = closed((wn, wd), (cn, cd), with_x);
        prop_assert!(r.real().contains(&want), "{}: {:?} vs {}", text, r.value, want);
        prop_assert!(r.goal_met, "{}: {:?}", text, r.value);
    }
}

fn ratio(n: u32, d: u32) -> Float {
    Float::with_val(512, n) / d
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]
    #[test]
    fn sums_with_an_oscillatory_term_are_enclosed(wn in 1u32..8, wd in 1u32..4, cn in 1u32..6, cd in 1u32..4, k in 0u32..4, removable: bool) {
        let pi = Float::with_val(512, maugis::rug::float::Constant::Pi);
        let (text, want) = if removable {
            (format!("(1 - cos({wn}/{wd}*x))/x^2"), pi * ratio(wn, wd) / 2u32)
        } else {
            let e = Float::with_val(512, -(ratio(wn, wd) * ratio(cn, cd))).exp();
            (format!("({k} + cos({wn}/{wd}*x))/(x^2 + ({cn}/{cd})^2)"), pi * (e + k) / (ratio(cn, cd) * 2u32))
        };
        let f = Expr::parse(&text).unwrap();
        let r = integrate_range(&f, &End::parse("0").unwrap(), &End::Infinity, None, None, 64, &Options::new()).unwrap();
        prop_assert!(r.real().contains(&want), "{}: {:?} vs {}", text, r.value, want);
        prop_assert!(r.goal_met, "{}: {:?}", text, r.value);
    }
}
