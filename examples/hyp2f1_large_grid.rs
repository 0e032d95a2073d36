//! Times MP `2F1` with one large parameter over the grid of
//! `reference/data/hyp2f1_large_param.csv` (issue 37 item 2) through the path
//! `maugis eval` takes (decimal strings, `eval_at_decimals` + `hyp2f1_ball_mp`),
//! at 2, 64 and 256 bits: the first call and the best of five warm calls per
//! point, the slowest point, and the count over 50 ms. Times are the thread's
//! CPU time (CLOCK_THREAD_CPUTIME_ID): on the shared 2-core machine wall times
//! swing severalfold with the other builds' load.
//! `cargo run --release --example hyp2f1_large_grid --features maugis/gmp-no-check`
use maugis::budget::thread_cpu_seconds;
use maugis::ball::{eval_at_decimals, Decimal};
use maugis::special::hyp2f1::hyp2f1_ball_mp;

fn main() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reference/data/hyp2f1_large_param.csv");
    let mut rdr = csv::ReaderBuilder::new().comment(Some(b'#')).from_path(path).expect("run reference/hyp2f1_large_param.py");
    let rows: Vec<Vec<String>> = rdr.records().map(|r| r.unwrap().iter().take(4).map(str::to_string).collect()).collect();
    for prec in [2u32, 64, 256] {
        let (mut worst, mut worst_at, mut over, mut sum, mut errors) = (0.0f64, String::new(), 0, 0.0, 0);
        for r in &rows {
            let d: Vec<Decimal> = r.iter().map(|s| Decimal::parse(s).unwrap()).collect();
            let call = || eval_at_decimals(&d, prec, |x| hyp2f1_ball_mp(&x[0], &x[1], &x[2], &x[3], prec));
            let t = thread_cpu_seconds();
            let first = call();
            let first_t = thread_cpu_seconds() - t;
            let mut best = f64::INFINITY;
            for _ in 0..5 {
                let t = thread_cpu_seconds();
                let _ = call();
                best = best.min(thread_cpu_seconds() - t);
            }
            if first.is_err() {
                errors += 1;
                println!("{prec} bits: 2F1({}) -> {:?}", r.join(", "), first);
            }
            let t = first_t.max(best);
            sum += best;
            if t > 0.05 {
                over += 1;
            }
            if t > worst {
                worst = t;
                worst_at = r.join(", ");
            }
            if std::env::var("VERBOSE").is_ok() {
                println!("{prec:>4} {:<50} first {:>8.2} ms warm {:>8.2} ms", r.join(", "), first_t * 1e3, best * 1e3);
            }
        }
        println!(
            "{prec:>4} bits: {} points, mean warm {:.2} ms, slowest {:.2} ms (first call or warm) at 2F1({worst_at}), {over} over 50 ms, {errors} errors",
            rows.len(),
            sum / rows.len() as f64 * 1e3,
            worst * 1e3
        );
    }
}
