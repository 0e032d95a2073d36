use maugis::special::hyp2f1;
use std::hint::black_box;
use std::time::Instant;
fn main() {
    let mut state: u64 = 0x2f1_5c1;
    let mut uniform = |lo: f64, hi: f64| { state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407); lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64) };
    let pts: Vec<[f64; 4]> = (0..20000).map(|_| [uniform(-3.0, 3.0), uniform(-3.0, 3.0), uniform(0.5, 6.0), uniform(-5.0, 0.9)]).collect();
    let lo: f64 = std::env::args().nth(1).unwrap().parse().unwrap();
    let hi: f64 = std::env::args().nth(2).unwrap().parse().unwrap();
    let mut ts: Vec<(f64, [f64; 4])> = pts.iter().filter(|p| p[3] >= lo && p[3] < hi).map(|p| {
        let mut best = f64::INFINITY;
        for _ in 0..5 { let t = Instant::now(); for _ in 0..20 { black_box(hyp2f1::hyp2f1(p[0], p[1], p[2], black_box(p[3])).unwrap()); } best = best.min(t.elapsed().as_secs_f64() / 20.0); }
        (best * 1e9, *p)
    }).collect();
    ts.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap());
    let n = ts.len();
    let total: f64 = ts.iter().map(|t| t.0).sum();
    for q in [0.1, 0.25, 0.5, 0.75, 0.85, 0.9, 0.95, 0.99] { println!("q{q}: {:.0} ns", ts[(q * n as f64) as usize].0); }
    let mut acc = 0.0;
    for (i, t) in ts.iter().enumerate().rev() { acc += t.0; if acc > 0.5 * total { println!("top {} points ({:.1}%) take half the time", n - i, (n - i) as f64 / n as f64 * 100.0); break; } }
    println!("mean {:.0} ns", total / n as f64);
    for t in ts.iter().rev().take(12) { let p = t.1; println!("{:.0} ns a={:.4} b={:.4} c={:.4} z={:.4} a-b={:.4}", t.0, p[0], p[1], p[2], p[3], p[0]-p[1]); }
}
