//! Times the slow corners of issue 23 item 5 (docs/fuzzing.md): f64 hyp2f1 at
//! huge or tiny parameters, MP hyp1f2 at a parameter ~1e18.
//! `cargo run --example slow_corners --features maugis/gmp-no-check -- [case]`
use maugis::special::{exact, hyp1f2, hyp2f1};
use std::time::Instant;

fn main() {
    let which: String = std::env::args().nth(1).unwrap_or_default();
    if which == "one" {
        let v: Vec<f64> = std::env::args().skip(2).map(|s| s.parse().unwrap()).collect();
        let t = Instant::now();
        let r = hyp2f1::hyp2f1(v[0], v[1], v[2], v[3]);
        println!("hyp2f1({:e}, {:e}, {:e}, {}) = {r:?}  [{:.3} s]", v[0], v[1], v[2], v[3], t.elapsed().as_secs_f64());
        return;
    }
    if which == "grid" {
        // every call of a grid over huge, tiny and moderate parameters, printed before it runs
        let vals = [1e300, -1e300, 1e10, 1e5, -99999.5, 2.5, -2.5, 1e-300, 2e-225];
        let zs = [-10.0, -0.9, 0.3, 0.7, 0.95, 0.999];
        let skip: usize = std::env::args().nth(2).and_then(|s| s.parse().ok()).unwrap_or(0);
        let mut i = 0usize;
        for &a in &vals {
            for &b in &vals {
                for &c in &vals {
                    for &z in &zs {
                        i += 1;
                        if i != skip {
                            continue;
                        }
                        let t = Instant::now();
                        let r = hyp2f1::hyp2f1(a, b, c, z);
                        let dt = t.elapsed().as_secs_f64();
                        println!("{i} hyp2f1({a:e}, {b:e}, {c:e}, {z}) = {r:?} [{dt:.3} s]");
                        return;
                    }
                }
            }
        }
        return;
    }
    let f64_cases: &[(f64, f64, f64, f64)] = &[
        (1e300, 2.0, 3.0, 0.5),
        (1.5, 1e300, 1e300, 0.5),
        (1.5, 2.5, 1e300, 0.5),
        (1e300, -1e300, 3.0, 0.5),
        (1e300, 1e300, 1e300, 0.9),
        (-1e300, 2.5, 3.5, -0.5),
        (1e300, 2.5, -1e300, 0.25),
        (0.5, 0.25, 2e-225, 0.999),
        (0.5, 0.25, 2e-225, 1.0),
        (1.5, 2.25, 2e-225, 0.99999),
        (-0.5, 0.25, -2e-225, 0.999),
        (1.5, 2.25, 2e-225, -0.99999),
        (1.5, 2.25, 2e-225, 1.0),
        (1e5, 1e5, 1e5, -10.0),
        (1e5, 1e5, 2.5, -0.9),
        (1e5, -99999.5, 2.5, 0.95),
        (1e5, 2.5, 1e5, 0.999),
        (-99999.5, 2.5, 1e-300, 0.999),
        (1e5, 1e5, -99999.5, 0.3),
        (1e5, 2.5, -2.5, -10.0),
        (-99999.5, -99999.5, 1e5, 0.7),
        (2e-225, 1e5, 2e-225, 0.999),
        (0.5, 1e5, 2e-225, -0.999),
    ];
    for (i, &(a, b, c, z)) in f64_cases.iter().enumerate() {
        if !which.is_empty() && which != format!("f{i}") {
            continue;
        }
        let t = Instant::now();
        let r = hyp2f1::hyp2f1(a, b, c, z);
        println!("f{i} hyp2f1({a:e}, {b:e}, {c:e}, {z}) = {r:?}  [{:.3} s]", t.elapsed().as_secs_f64());
    }
    if which.is_empty() || which == "m0" {
        let t = Instant::now();
        let r = hyp1f2::hyp1f2_mp(&exact(3.7e18), &exact(20.03), &exact(-179.875), &exact(23.7), 98);
        println!("m0 hyp1f2_mp(3.7e18, 20.03, -179.875, 23.7; 98) = {:?}  [{:.3} s]", r.map(|b| b.to_f64()), t.elapsed().as_secs_f64());
    }
}
