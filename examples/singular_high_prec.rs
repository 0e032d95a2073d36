//! Issue 40's singular integrals at high precision, one call each (the sweep's costly
//! rows): id, prec, CPU s of the call (the calling thread's, [`maugis::budget::thread_cpu_seconds`]:
//! the machine is shared), evaluations, goal met, reference enclosed.
//!
//! `cargo run --release --example singular_high_prec [-- PREC... [--only ID,ID]]`
//! (default precisions 512 1024 2048; ids from `reference/data/integrals_singular.csv`
//! and `reference/data/integrals_infinite.csv`)

use maugis::ball::{Ball, Mag};
use maugis::budget::thread_cpu_seconds as cpu;
use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_range, End, Expr};
use maugis::rug::ops::Pow;
use maugis::rug::Float;

const SINGULAR: &str = include_str!("../reference/data/integrals_singular.csv");
const INFINITE: &str = include_str!("../reference/data/integrals_infinite.csv");

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let only: Vec<String> = match args.iter().position(|a| a == "--only") {
        Some(i) => args[i + 1].split(',').map(String::from).collect(),
        None => vec![
            "x_pow_x".into(),
            "log_log1m".into(),
            "rsqrt_cos".into(),
            "rsqrt_cube".into(),
        ],
    };
    let precs: Vec<u32> = args
        .iter()
        .take_while(|a| !a.starts_with("--"))
        .map(|p| p.parse().expect("prec"))
        .collect();
    let precs = if precs.is_empty() {
        vec![512, 1024, 2048]
    } else {
        precs
    };
    let mut rows = Vec::new();
    for table in [SINGULAR, INFINITE] {
        for r in csv::Reader::from_reader(table.as_bytes()).records() {
            let r = r.expect("a row of the table");
            if only.iter().any(|id| id == &r[0]) {
                rows.push(r);
            }
        }
    }
    println!("id\tprec\tcpu_s\tevaluations\tgoal_met\tencloses");
    for &prec in &precs {
        for r in &rows {
            let (e, a, b) = (
                Expr::parse(&r[2]).expect("expr"),
                End::parse(&r[3]).expect("a"),
                End::parse(&r[4]).expect("b"),
            );
            // the reference as a ball: its decimal digits, +- one unit of the last
            let digits = r[5]
                .trim_start_matches('-')
                .chars()
                .filter(char::is_ascii_digit)
                .count() as i32;
            let mut want = Ball::from_float(
                &Float::with_val(14_000, Float::parse(&r[5]).expect("value")),
                14_000,
            );
            let ulp = Float::with_val(64, Float::parse(&r[5]).expect("value")).abs()
                * Float::with_val(64, 10f64).pow(2 - digits);
            want.add_error_mag(Mag::from_float_up(&ulp));
            let t = cpu();
            let out = integrate_range(&e, &a, &b, None, None, prec, &Options::new());
            let s = cpu() - t;
            match out {
                Ok(v) => println!(
                    "{}\t{prec}\t{s:.3}\t{}\t{}\t{}",
                    &r[0],
                    v.evaluations,
                    v.goal_met,
                    v.real().overlaps(&want)
                ),
                Err(err) => println!("{}\t{prec}\t{s:.3}\terror: {err}", &r[0]),
            }
        }
    }
}
