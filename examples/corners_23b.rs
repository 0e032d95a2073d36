//! Times two slow corners of issue 23: MP hyp1f2 at a parameter ~3.7e18, and
//! `strip_ratio` at decimal inputs with beta "0.001".
//! `cargo run --profile test --example corners_23b --features maugis/gmp-no-check -- [hyp|strip|trace|load|resid|resid192] [prec]`
use maugis::ball::Decimal;
use maugis::ball::eval_at_decimals;
use maugis::contact::model_mp::{load_at_decimals, solve_m_ball_mp, strip_ratio_at_decimals, ModelBalls};
use maugis::special::{exact, hyp1f2};
use std::time::Instant;

fn main() {
    let which: String = std::env::args().nth(1).unwrap_or_default();
    let prec: u32 = std::env::args().nth(2).and_then(|s| s.parse().ok()).unwrap_or(53);
    let t = Instant::now();
    if which == "hyp" {
        let r = hyp1f2::hyp1f2_mp(&exact(3.7e18), &exact(20.03), &exact(-179.875), &exact(23.7), prec);
        println!("hyp1f2_mp(3.7e18, 20.03, -179.875, 23.7; {prec}) = {r:?}  [{:.3} s]", t.elapsed().as_secs_f64());
    } else if which == "resid" {
        use maugis::contact::model::Params;
        use maugis::contact::model_mp::strip_residual_mp;
        let p = Params::new(2.5, 2.5, 0.001).unwrap();
        for &e in &[6.5325e-5] {
            for wp in [85u32, 1000, 4000, 6000, 8000, 10000] {
                let m = maugis::rug::Float::with_val(200, 1.0 + e);
                let t1 = Instant::now();
                let r = strip_residual_mp(p, 1.0, &m, wp);
                println!("e {e:e} wp {wp}: {r:?} [{:.3} s]", t1.elapsed().as_secs_f64());
            }
        }
    } else if which == "load" {
        let d = |s: &str| Decimal::parse(s).unwrap();
        let r = load_at_decimals(&[d("2.5"), d("2.5"), d("0.001"), d("1")], prec);
        println!("load(2.5, 2.5, \"0.001\", 1; {prec}) = {r:?}  [{:.3} s]", t.elapsed().as_secs_f64());
    } else if which == "resid192" {
        use maugis::contact::model_mp::strip_residual_ball_mp;
        use maugis::Ball;
        let d = |s: &str, p: u32| Decimal::parse(s).unwrap().to_ball(p);
        for ip in [117u32, 192, 400] {
            let mid = |b: Ball| Ball::from_float(b.mid(), b.prec());
            for (name, beta) in [("ball", d("0.001", ip)), ("mid", mid(d("0.001", ip)))] {
                let m = ModelBalls::new(d("2.5", ip), d("2.5", ip), beta, d("1", ip)).unwrap();
                let e = Ball::from_f64(6.5325e-5, 53).unwrap();
                let r = strip_residual_ball_mp(&m, &e, 6824);
                println!("input prec {ip} {name}: {r:?}");
            }
        }
    } else if which == "trace" {
        // each call of eval_at_decimals' closure: input precision, result, time
        let d = |s: &str| Decimal::parse(s).unwrap();
        let r = eval_at_decimals(&[d("2.5"), d("2.5"), d("0.001"), d("1")], prec, |b| {
            let t1 = Instant::now();
            let r = ModelBalls::new(b[0].clone(), b[1].clone(), b[2].clone(), b[3].clone()).and_then(|m| solve_m_ball_mp(&m, prec));
            println!("  input prec {} -> {r:?} [{:.3} s]", b[2].prec(), t1.elapsed().as_secs_f64());
            r
        });
        println!("strip_ratio trace {prec}: {r:?} [{:.3} s]", t.elapsed().as_secs_f64());
    } else {
        let d = |s: &str| Decimal::parse(s).unwrap();
        let r = strip_ratio_at_decimals(&[d("2.5"), d("2.5"), d("0.001"), d("1")], prec);
        println!("strip_ratio(2.5, 2.5, \"0.001\", 1; {prec}) = {r:?}  [{:.3} s]", t.elapsed().as_secs_f64());
    }
}
