//! lambda* against the Johnson parameter (issue 24, item 3): for each
//! `chi = sqrt(beta/alpha^2)` at fixed `beta` (`alpha = sqrt(beta)/chi`) and each
//! threshold fraction of `W_JKR`, the bisection of `maugis_solver::transition`.
//!
//! `cargo run --release -p maugis-solver --example transition -- OUT.csv BETA CHI,.. FRACTION,.. [LMIN LMAX SCAN [LAW [CELLS STEPS]]]`
//!
//! `LAW`: `dugdale` (default) or `exp`; `CELLS STEPS`: one fixed coarse
//! resolution (the refined search doubles both) instead of the map's rule.
//!
//! The Johnson parameters run in parallel (threads, one per chi); a row per
//! (chi, fraction) goes to stdout and the CSV.

use maugis_solver::map::{Resolution, ResolutionRule};
use maugis_solver::profile::AdhesionLaw;
use maugis_solver::transition::{johnson_sweep, JohnsonRow, TransitionSpec};

fn list(s: &str) -> Vec<f64> {
    s.split(',').map(|t| t.trim().parse().expect("a comma-separated list of numbers")).collect()
}

/// One row per threshold fraction.
fn rows(r: &JohnsonRow, fractions: &[f64], scan: usize) -> Vec<String> {
    let (chi, spec) = (r.chi, &r.spec);
    fractions
        .iter()
        .enumerate()
        .map(|(k, &fraction)| match &r.result {
            Ok(all) => {
                let tr = &all[k];
                let best = tr.refined.as_ref().unwrap_or(&tr.search);
                let evals = tr.search.evaluations.len() + tr.refined.as_ref().map_or(0, |r| r.evaluations.len());
                let curve: Vec<String> = tr.search.evaluations.iter().take(scan).map(|e| format!("{:.4}:{:.4}", e.lambda, e.excess())).collect();
                format!(
                    "{chi},{},{},{fraction},{},{},{},{},{},{},{},{},{},{},{evals},{:.0},\"{}\"",
                    spec.beta,
                    spec.alpha,
                    tr.w_jkr,
                    tr.threshold,
                    tr.lambda_star().map_or(String::new(), |v| v.to_string()),
                    tr.search.lambda_star.map_or(String::new(), |v| v.to_string()),
                    tr.relative_uncertainty().map_or(String::new(), |v| v.to_string()),
                    tr.refined.is_some(),
                    best.bracket.map_or(String::new(), |b| b.0.to_string()),
                    best.bracket.map_or(String::new(), |b| b.1.to_string()),
                    tr.search.outside.or(best.outside).map_or("", |o| o.name()),
                    tr.search.non_monotone || best.non_monotone,
                    r.seconds,
                    curve.join(" ")
                )
            }
            Err(e) => format!("{chi},{},{},{fraction},,,,,,,,,\"error: {e}\",,,,", spec.beta, spec.alpha),
        })
        .collect()
}

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let (out, beta, chis, fractions) = (&a[0], a[1].parse::<f64>().expect("beta"), list(&a[2]), list(&a[3]));
    let num = |i: usize, d: f64| a.get(i).map_or(d, |s| s.parse().expect("a number"));
    let (lmin, lmax, scan) = (num(4, 0.1), num(5, 10.0), num(6, 9.0) as usize);
    let law = a.get(7).map_or(AdhesionLaw::Dugdale, |n| AdhesionLaw::from_name(n).expect("law: dugdale or exp"));
    let resolution = match (a.get(8), a.get(9)) {
        (Some(c), Some(s)) => ResolutionRule::Fixed(Resolution { cells: c.parse().expect("cells"), steps_per_leg: s.parse().expect("steps") }),
        _ => ResolutionRule::Auto,
    };
    let template = TransitionSpec { alpha: 1.0, beta, amax: 6.0, lambda_min: lmin, lambda_max: lmax, scan, fraction: fractions[0], rel_tol: 0.03, resolution, law };
    let rows: Vec<String> = johnson_sweep(template, &chis, &fractions, &|_| true).iter().flat_map(|r| rows(r, &fractions, scan)).collect();
    let header = "chi,beta,alpha,fraction,w_jkr,threshold,lambda_star,lambda_star_coarse,rel_uncertainty,refined,bracket_low,bracket_high,outside,non_monotone,evaluations,seconds,scan_excess";
    println!("{header}\n{}", rows.join("\n"));
    std::fs::write(out, format!("{header}\n{}\n", rows.join("\n"))).expect("write the CSV");
}
