use maugis::special::bessel_j::*;
use rug::Float;
fn cpu() -> f64 { let s = std::fs::read_to_string("/proc/self/stat").unwrap(); let f: Vec<&str> = s.rsplit(')').next().unwrap().split_whitespace().collect(); (f[11].parse::<f64>().unwrap() + f[12].parse::<f64>().unwrap()) / 100.0 }
fn t<F: FnMut()>(mut f: F) -> f64 { let c0 = cpu(); let mut c = 0; while cpu() - c0 < 0.3 { f(); c += 1; } (cpu() - c0) * 1e6 / c as f64 }
fn main() {
    for &(n, x) in &[(10000u64, 99999.5), (2000, 99999.5), (2000, 20000.5), (10000, 20000.5), (500, 5000.25), (2000, 5000.25), (60, 150.5), (500, 999.5), (2000, 999.5), (10000, 5000.25), (10000, 999.5), (500, 150.5)] {
        for wp in [100u32, 180, 560] {
            let xf = Float::with_val(53, x);
            let costs = algorithm_costs(n, x, wp);
            let guard = |a: Algorithm| costs.iter().find(|c| c.0 == a).map(|c| c.1);
            let j0 = bessel_j_mp(0, &xf, wp).unwrap(); let j1 = bessel_j_mp(1, &xf, wp).unwrap();
            let tr = t(|| { bessel_j_three_term(n, &xf, &j0, &j1, wp + 40).unwrap(); }) + t(|| { bessel_j_mp(0, &xf, wp).unwrap(); bessel_j_mp(1, &xf, wp).unwrap(); });
            let th = if guard(Algorithm::Hankel).is_some_and(|c| c < 2e7) { t(|| { let _ = bessel_j_hankel(n, &xf, wp + 40).unwrap(); }) } else { f64::NAN };
            let ts = if guard(Algorithm::PowerSeries).is_some_and(|c| c < 2e7) { let loss = (1.45 * x.min(n as f64 * 0.0 + x)) as u32; let _ = loss; t(|| { bessel_j_mp(n as i64, &xf, wp).unwrap(); }) } else { f64::NAN };
            println!("n={n} x={x} wp={wp}: rec {tr:.0} us hankel {th:.0} mp(chosen {:?}) {ts:.0} | model {:?}", choose_algorithm(n, x, wp), costs.iter().map(|c| (c.0, (c.1/1e3).round())).collect::<Vec<_>>());
        }
    }
}
