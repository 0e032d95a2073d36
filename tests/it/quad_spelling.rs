//! The same integrand in another spelling costs about the same (issue 36, item 5):
//! `Expr::canonical` rewrites `1/cosh(u)^k` to `sech(u)^k`, `exp(a) exp(b)` to
//! `exp(a + b)` and `a*a` to `a^2` before integrating.

use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_range, End, Expr};

fn run(text: &str, a: &str, b: &str, prec: u32) -> maugis::quad::certified::Integral {
    let f = Expr::parse(text).unwrap();
    integrate_range(&f, &End::parse(a).unwrap(), &End::parse(b).unwrap(), None, None, prec, &Options::new())
        .unwrap_or_else(|e| panic!("{text}: {e}"))
}

#[test]
fn spellings_cost_within_twice_the_best() {
    let pairs = [
        ("sech(10*(x-0.2))^2 + sech(100*(x-0.4))^4 + sech(1000*(x-0.6))^6", "1/cosh(10*(x-0.2))^2 + 1/cosh(100*(x-0.4))^4 + 1/cosh(1000*(x-0.6))^6", "0", "1"),
        ("exp(-2*x)", "exp(-x)*exp(-x)", "0", "3"),
        ("x^2*sin(x)", "x*x*sin(x)", "0", "2"),
        ("sech(x)", "cosh(x)^-1", "-2", "2"),
    ];
    for (best, other, a, b) in pairs {
        for prec in [64u32, 333] {
            let (r1, r2) = (run(best, a, b, prec), run(other, a, b, prec));
            assert!(r1.goal_met && r2.goal_met, "{best} / {other} at {prec}: {:?} {:?}", r1.value, r2.value);
            assert!(r1.real().overlaps(r2.real()), "{best} / {other} at {prec}");
            let (e1, e2) = (r1.evaluations, r2.evaluations);
            eprintln!("spelling at {prec} bits: {best}: {e1} evaluations; {other}: {e2}");
            assert!(e2 <= 2 * e1 && e1 <= 2 * e2, "{best}: {e1} evaluations, {other}: {e2} at {prec} bits");
        }
    }
    // the example: at most 2000 evaluations in both spellings at 64 bits
    for text in [pairs[0].0, pairs[0].1] {
        let r = run(text, "0", "1", 64);
        assert!(r.evaluations <= 2000, "{text}: {} evaluations", r.evaluations);
    }
}
