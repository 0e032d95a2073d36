//! Times `u_wave_quad_mp` (the Eq. 11a quadrature estimate in MP) at one input
//! and prints the certified `u_wave_mp` beside it (docs/fuzzing.md, issue 37).
//! `cargo run --example wave_quad_timing --features maugis/gmp-no-check -- A ZETA AMP X PREC`
use maugis::contact::displacement::quadrature::u_wave_quad_mp;
use maugis::rug::Float;
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let prec: u32 = args[4].parse().unwrap();
    let v: Vec<Float> = args[..4].iter().map(|s| Float::with_val(prec + 64, Float::parse(s).unwrap())).collect();
    let t = std::time::Instant::now();
    let r = u_wave_quad_mp(&v[0], &v[1], &v[2], &v[3], prec);
    let dt = t.elapsed().as_secs_f64();
    match r { Ok(q) => println!("{:.40} err {:.3e} evals {} in {:.4} s", q.value, q.error_estimate.to_f64(), q.evaluations, dt), Err(e) => println!("{e} in {dt:.3} s") }
    let c = maugis::contact::displacement::u_wave_mp(&v[0], &v[1], &v[2], &v[3], prec);
    println!("certified: {:?}", c.map(|b| b.to_f64()));
}
