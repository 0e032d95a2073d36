//! lambda* (`maugis_solver::transition`) at one fixed resolution for several
//! Johnson parameters, under either adhesion law, with a grid check (the
//! search repeated at twice the cells and steps from the coarse scan bracket)
//! at the Johnson parameters named in CHECK. Cheaper than the `transition`
//! example, which refines every parameter: for a shared machine.
//!
//! `cargo run --release -p maugis-solver --example lambda_star_coarse -- OUT.csv LAW BETA CHI,.. CELLS STEPS LMIN LMAX SCAN FRACTION [CHECK_CHI,..]`
//!
//! One thread per Johnson parameter; a row per parameter to stdout (as it
//! finishes) and to the CSV.

use std::time::Instant;

use maugis_solver::map::{Resolution, ResolutionRule};
use maugis_solver::profile::AdhesionLaw;
use maugis_solver::transition::{search, w_jkr, Cache, TransitionSpec};

fn list(s: &str) -> Vec<f64> {
    s.split(',').filter(|t| !t.is_empty()).map(|t| t.trim().parse().expect("a comma-separated list of numbers")).collect()
}

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let out = &a[0];
    let law = AdhesionLaw::from_name(&a[1]).expect("law: dugdale or exp");
    let beta: f64 = a[2].parse().expect("beta");
    let chis = list(&a[3]);
    let num = |i: usize| a[i].parse::<f64>().expect("a number");
    let coarse = Resolution { cells: num(4) as usize, steps_per_leg: num(5) as usize };
    let (lmin, lmax, scan, fraction) = (num(6), num(7), num(8) as usize, num(9));
    let check = a.get(10).map_or(Vec::new(), |s| list(s));
    let fine = Resolution { cells: 2 * coarse.cells, steps_per_leg: 2 * coarse.steps_per_leg };
    let rows: Vec<String> = std::thread::scope(|sc| {
        let handles: Vec<_> = chis
            .iter()
            .map(|&chi| {
                let check = check.contains(&chi);
                sc.spawn(move || {
                    let t = Instant::now();
                    let spec = TransitionSpec {
                        alpha: beta.sqrt() / chi,
                        beta,
                        amax: 6.0,
                        lambda_min: lmin,
                        lambda_max: lmax,
                        scan,
                        fraction,
                        rel_tol: 0.03,
                        resolution: ResolutionRule::Fixed(coarse),
                        law,
                    };
                    let run = || -> Result<String, maugis_solver::SolverError> {
                        let wj = w_jkr(spec.alpha, beta, spec.amax)?;
                        let threshold = fraction * wj;
                        let mut cache = Cache::new();
                        let s = search(&spec, threshold, &|_| coarse, None, &mut cache, &mut |_| {})?;
                        let f = if check && s.scan_bracket.is_some() {
                            Some(search(&spec, threshold, &|_| fine, s.scan_bracket, &mut cache, &mut |_| {})?)
                        } else {
                            None
                        };
                        let bis = s.bracket.map(|(lo, hi)| 0.5 * (hi / lo).ln());
                        let shift = match (&f, s.lambda_star) {
                            (Some(f), Some(l)) => f.lambda_star.map(|lf| (lf.ln() - l.ln()).abs()),
                            _ => None,
                        };
                        let opt = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.6}"));
                        let curve: Vec<String> = s.evaluations.iter().take(scan).map(|e| format!("{:.4}:{:.4}:{:.4}", e.lambda, e.w, e.w_smooth)).collect();
                        Ok(format!(
                            "{chi},{beta},{:.6},{},{},{},{:.6},{:.6},{},{},{},{},{},{},{},{},{},{:.0},\"{}\"",
                            spec.alpha,
                            law.name(),
                            coarse.cells,
                            coarse.steps_per_leg,
                            wj,
                            threshold,
                            opt(s.lambda_star),
                            opt(s.bracket.map(|b| b.0)),
                            opt(s.bracket.map(|b| b.1)),
                            opt(bis),
                            opt(f.as_ref().and_then(|f| f.lambda_star)),
                            opt(shift),
                            s.outside.map_or("", |o| o.name()),
                            s.non_monotone,
                            s.evaluations.len() + f.as_ref().map_or(0, |f| f.evaluations.len()),
                            t.elapsed().as_secs_f64(),
                            curve.join(" ")
                        ))
                    };
                    let row = run().unwrap_or_else(|e| format!("{chi},{beta},{:.6},{},{},{},,,,,,,,,\"error: {e}\",,,,", spec.alpha, law.name(), coarse.cells, coarse.steps_per_leg));
                    println!("{row}");
                    row
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().expect("a search thread")).collect()
    });
    let mut csv = String::from(
        "chi,beta,alpha,law,cells,steps,w_jkr,threshold,lambda_star,bracket_low,bracket_high,rel_bisection,lambda_star_fine,grid_shift,outside,non_monotone,evaluations,seconds,scan_lambda_w_wsmooth\n",
    );
    for r in rows {
        csv.push_str(&r);
        csv.push('\n');
    }
    std::fs::write(out, csv).expect("write the CSV");
}
