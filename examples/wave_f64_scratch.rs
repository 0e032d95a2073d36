use maugis::contact::displacement::{u_wave_bounded, WaveBessel};
use std::time::Instant;
fn main() {
    let a: f64 = 6.0;
    let xs: Vec<f64> = (0..64).map(|i| a * (1.0 + 2.0 * (i as f64 * 0.754877666246693).fract())).collect();
    let t0 = Instant::now();
    let mut s = 0.0;
    for _ in 0..100 { for &x in &xs { s += u_wave_bounded(a, 1.125, 1.0, x).unwrap().value; } }
    println!("scratch bounded {:.3} us/value", t0.elapsed().as_secs_f64() / 6400.0 * 1e6);
    let wb = WaveBessel::new(a, 1.125, 1.0).unwrap();
    wb.eval_bounded(a).unwrap();
    let t0 = Instant::now();
    for _ in 0..2000 { for &x in &xs { let r = wb.eval_bounded(x).unwrap(); s += r.0.value + r.0.err; } }
    println!("precomp bounded {:.3} us/value", t0.elapsed().as_secs_f64() / 128000.0 * 1e6);
    let r = wb.eval_bounded(a * 1.5).unwrap();
    println!("{:?} {s}", r);
}
