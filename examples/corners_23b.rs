//! Times slow corners of issue 23: MP hyp1f2 at a parameter ~3.7e18, `strip_ratio`
//! and `load` at decimal inputs with beta "0.001" (or as given), and the radius of
//! the two certified J_n sequences against D (`seqrad`).
//! `cargo run --profile test --example corners_23b --features maugis/gmp-no-check -- [hyp|strip|trace|load|loadtrace|resid|resid192|seqrad|seqtime|seqone|wave|wavef64] [prec] [beta]`
use maugis::ball::Decimal;
use maugis::ball::eval_at_decimals;
use maugis::contact::model_mp::{load_at_decimals, solve_m_ball_mp, strip_ratio_at_decimals, ModelBalls};
use maugis::special::{exact, hyp1f2};
use std::time::Instant;

fn main() {
    let which: String = std::env::args().nth(1).unwrap_or_default();
    let prec: u32 = std::env::args().nth(2).and_then(|s| s.parse().ok()).unwrap_or(53);
    // beta as typed (load, strip, trace, loadtrace); "0.001" unless given
    let beta_text: String = std::env::args().nth(3).unwrap_or_else(|| "0.001".to_string());
    let beta = beta_text.as_str();
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
    } else if which == "seqrad" {
        // radius of the ball downward recurrence against D and wp (issue 23j item 1)
        use maugis::special::bessel_j::{bessel_j_sequence_mp, bessel_j_sequence_three_term};
        for d in [10.0f64, 100.0, 1000.0, 2000.0, 6283.185307179586] {
            for wp in [128u32, 512, 2048] {
                let x = maugis::rug::Float::with_val(53, d);
                let nmax = d as u64 + 60;
                let t1 = Instant::now();
                let seq = bessel_j_sequence_mp(nmax, &x, wp);
                let secs = t1.elapsed().as_secs_f64();
                let Ok(seq) = seq else { println!("D {d} wp {wp}: {seq:?}"); continue };
                let lr = |b: &maugis::Ball| b.rad_mag().log2();
                let worst = seq.iter().map(lr).fold(f64::NEG_INFINITY, f64::max);
                println!("D {d:7.1} wp {wp:5}: log2 rad at n=0 {:8.1}, n=D/2 {:8.1}, n=nmax {:8.1}; max {:8.1}; (max + wp)/D = {:.3}  [{secs:.3} s]",
                    lr(&seq[0]), lr(&seq[(d / 2.0) as usize]), lr(&seq[nmax as usize]), worst, (worst + wp as f64) / d);
                let t2 = Instant::now();
                let new = bessel_j_sequence_three_term(nmax, &x, wp).unwrap();
                let secs = t2.elapsed().as_secs_f64();
                let worst = new.iter().map(lr).fold(f64::NEG_INFINITY, f64::max);
                let apart = seq.iter().zip(&new).filter(|(a, b)| !a.overlaps(b)).count();
                println!("    midpoint route: n=0 {:8.1}, n=D/2 {:8.1}, n=nmax {:8.1}; max {:8.1} (max + wp = {:.1}); disjoint from ball route at {apart}  [{secs:.3} s]",
                    lr(&new[0]), lr(&new[(d / 2.0) as usize]), lr(&new[nmax as usize]), worst, worst + wp as f64);
            }
        }
    } else if which == "seqtime" {
        // CPU per call of the two certified sequences at the wave's nmax (D + 2 (D/2)^{1/3} wp^{2/3}-ish)
        use maugis::special::bessel_j::{bessel_j_sequence_mp, bessel_j_sequence_three_term};
        for d in [0.5f64, 2.5, 10.0, 75.0, 628.0, 6283.185307179586] {
            let x = maugis::rug::Float::with_val(53, d);
            let nmax = (d * 1.1) as u64 + 40;
            let reps = (2000.0 / (d + 10.0)).ceil() as u32;
            let t1 = Instant::now();
            for _ in 0..reps {
                std::hint::black_box(bessel_j_sequence_mp(nmax, &x, prec).unwrap());
            }
            let old = t1.elapsed().as_secs_f64() / reps as f64;
            let t2 = Instant::now();
            for _ in 0..reps {
                std::hint::black_box(bessel_j_sequence_three_term(nmax, &x, prec).unwrap());
            }
            let new = t2.elapsed().as_secs_f64() / reps as f64;
            println!("D {d:9.3} nmax {nmax:5} wp {prec}: ball route {:9.1} us, midpoint route {:9.1} us (ratio {:.2})", old * 1e6, new * 1e6, new / old);
        }
    } else if which == "seqone" {
        // one route 200 times at D (args: prec, D, "ball" or "mid"), for callgrind
        use maugis::special::bessel_j::{bessel_j_sequence_mp, bessel_j_sequence_three_term};
        let d: f64 = std::env::args().nth(3).and_then(|s| s.parse().ok()).unwrap_or(75.0);
        let ball = std::env::args().nth(4).is_some_and(|s| s == "ball");
        let x = maugis::rug::Float::with_val(53, d);
        let nmax = (d * 1.1) as u64 + 40;
        for _ in 0..200 {
            if ball {
                std::hint::black_box(bessel_j_sequence_mp(nmax, &x, prec).unwrap());
            } else {
                std::hint::black_box(bessel_j_sequence_three_term(nmax, &x, prec).unwrap());
            }
        }
    } else if which == "wavef64" {
        // the f64 routes at large D, and whether they fell back to MP
        use maugis::contact::displacement::{du_wave_bounded, u_wave_bounded};
        for zeta in [0.01, 0.001, 0.0002, 0.0001] {
            let before = maugis::special::fallback_counts();
            let t1 = Instant::now();
            let u = u_wave_bounded(1.0, zeta, 2.5, 1.5);
            let du = du_wave_bounded(1.0, zeta, 2.5, 1.5);
            let f = maugis::special::fallback_counts().since(&before);
            println!("zeta {zeta}: u {u:?} du {du:?} [{:.3} s] fallbacks {f:?}", t1.elapsed().as_secs_f64());
        }
    } else if which == "wave" {
        // u_w and du_w at decimal inputs a = 1, zeta = beta, amp = 2.5, x = 1.5 (D = 2 pi/beta)
        use maugis::contact::displacement::wave_at_decimals;
        let d = |s: &str| Decimal::parse(s).unwrap();
        for gradient in [false, true] {
            let t1 = Instant::now();
            let r = wave_at_decimals(&[d("1"), d(beta), d("2.5"), d("1.5")], prec, gradient);
            println!("wave(gradient {gradient}; 1, \"{beta}\", 2.5, 1.5; {prec}) = {r:?}  [{:.3} s]", t1.elapsed().as_secs_f64());
        }
    } else if which == "load" {
        let d = |s: &str| Decimal::parse(s).unwrap();
        let r = load_at_decimals(&[d("2.5"), d("2.5"), d(beta), d("1")], prec);
        println!("load(2.5, 2.5, \"{beta}\", 1; {prec}) = {r:?}  [{:.3} s]", t.elapsed().as_secs_f64());
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
    } else if which == "loadtrace" {
        // each call of load_at_decimals' closure: input precision, root ball, load ball, time
        use maugis::contact::model_mp::load_ball_mp;
        let d = |s: &str| Decimal::parse(s).unwrap();
        let r = eval_at_decimals(&[d("2.5"), d("2.5"), d(beta), d("1")], prec, |b| {
            let t1 = Instant::now();
            let inputs = ModelBalls::new(b[0].clone(), b[1].clone(), b[2].clone(), b[3].clone())?;
            let m = solve_m_ball_mp(&inputs, prec + 32);
            let tm = t1.elapsed().as_secs_f64();
            let r = m.clone().and_then(|m| load_ball_mp(&inputs, &m, prec));
            println!("  input prec {} -> m {m:?} [{tm:.3} s], load {r:?} [{:.3} s]", b[2].prec(), t1.elapsed().as_secs_f64());
            r
        });
        println!("load trace {prec}: {r:?} [{:.3} s]", t.elapsed().as_secs_f64());
    } else if which == "trace" {
        // each call of eval_at_decimals' closure: input precision, result, time
        let d = |s: &str| Decimal::parse(s).unwrap();
        let r = eval_at_decimals(&[d("2.5"), d("2.5"), d(beta), d("1")], prec, |b| {
            let t1 = Instant::now();
            let r = ModelBalls::new(b[0].clone(), b[1].clone(), b[2].clone(), b[3].clone()).and_then(|m| solve_m_ball_mp(&m, prec));
            println!("  input prec {} -> {r:?} [{:.3} s]", b[2].prec(), t1.elapsed().as_secs_f64());
            r
        });
        println!("strip_ratio trace {prec}: {r:?} [{:.3} s]", t.elapsed().as_secs_f64());
    } else {
        let d = |s: &str| Decimal::parse(s).unwrap();
        let r = strip_ratio_at_decimals(&[d("2.5"), d("2.5"), d(beta), d("1")], prec);
        println!("strip_ratio(2.5, 2.5, \"{beta}\", 1; {prec}) = {r:?}  [{:.3} s]", t.elapsed().as_secs_f64());
    }
}
