//! lambda* (`maugis_solver::transition`) at one fixed resolution for several
//! Johnson parameters, under either adhesion law, with a grid check (the
//! search repeated at twice the cells and steps from the coarse scan bracket,
//! the whole scan again when that bracket does not hold at the finer grid) at
//! the Johnson parameters named in CHECK. Cheaper than the `transition`
//! example, which refines every parameter: for a shared machine.
//!
//! `cargo run --release -p maugis-solver --example lambda_star_coarse -- OUT.csv LAW BETA CHI,.. CELLS STEPS LMIN LMAX SCAN FRACTION [CHECK_CHI,..]`
//!
//! One thread per Johnson parameter (`transition::johnson_sweep`); a row per
//! parameter to stdout and to the CSV.

use maugis_solver::map::{Resolution, ResolutionRule};
use maugis_solver::profile::AdhesionLaw;
use maugis_solver::transition::{johnson_sweep, JohnsonRow, TransitionSpec};

fn list(s: &str) -> Vec<f64> {
    s.split(',').filter(|t| !t.is_empty()).map(|t| t.trim().parse().expect("a comma-separated list of numbers")).collect()
}

fn row(r: &JohnsonRow, scan: usize) -> String {
    let (spec, res) = (&r.spec, spec_resolution(&r.spec));
    let head = format!("{},{},{:.6},{},{},{}", r.chi, spec.beta, spec.alpha, spec.law.name(), res.cells, res.steps_per_leg);
    let tr = match &r.result {
        Ok(all) => &all[0],
        Err(e) => return format!("{head},,,,,,,,,\"error: {e}\",,,{:.0},,", r.seconds),
    };
    let (s, f) = (&tr.search, tr.refined.as_ref());
    let opt = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.6}"));
    let shift = match (f.and_then(|f| f.lambda_star), s.lambda_star) {
        (Some(lf), Some(l)) => Some((lf.ln() - l.ln()).abs()),
        _ => None,
    };
    let curve: Vec<String> = s.evaluations.iter().take(scan).map(|e| format!("{:.4}:{:.4}:{:.4}", e.lambda, e.w, e.w_smooth)).collect();
    let fine: Vec<String> = f.map_or(Vec::new(), |f| f.evaluations.iter().map(|e| format!("{:.4}:{:.4}:{:.4}", e.lambda, e.w, e.w_smooth)).collect());
    format!(
        "{head},{:.6},{:.6},{},{},{},{},{},{},{},{},{},{:.0},\"{}\",\"{}\"",
        tr.w_jkr,
        tr.threshold,
        opt(s.lambda_star),
        opt(s.bracket.map(|b| b.0)),
        opt(s.bracket.map(|b| b.1)),
        opt(s.bracket.map(|(lo, hi)| 0.5 * (hi / lo).ln())),
        opt(f.and_then(|f| f.lambda_star)),
        opt(shift),
        s.outside.or(f.and_then(|f| f.outside)).map_or("", |o| o.name()),
        s.non_monotone,
        s.evaluations.len() + f.map_or(0, |f| f.evaluations.len()),
        r.seconds,
        curve.join(" "),
        fine.join(" ")
    )
}

fn spec_resolution(spec: &TransitionSpec) -> Resolution {
    spec.resolution.at(spec.lambda_min)
}

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let num = |i: usize| a[i].parse::<f64>().expect("a number");
    let coarse = Resolution { cells: num(4) as usize, steps_per_leg: num(5) as usize };
    let (lmin, lmax, scan, fraction) = (num(6), num(7), num(8) as usize, num(9));
    let check = a.get(10).map_or(Vec::new(), |s| list(s));
    let template = TransitionSpec {
        alpha: 1.0,
        beta: num(2),
        amax: 6.0,
        lambda_min: lmin,
        lambda_max: lmax,
        scan,
        fraction,
        rel_tol: 0.03,
        resolution: ResolutionRule::Fixed(coarse),
        law: AdhesionLaw::from_name(&a[1]).expect("law: dugdale or exp"),
    };
    let rows: Vec<String> = johnson_sweep(template, &list(&a[3]), &[fraction], &|chi| check.contains(&chi)).iter().map(|r| row(r, scan)).collect();
    let header = "chi,beta,alpha,law,cells,steps,w_jkr,threshold,lambda_star,bracket_low,bracket_high,rel_bisection,lambda_star_fine,grid_shift,outside,non_monotone,evaluations,seconds,scan_lambda_w_wsmooth,fine_lambda_w_wsmooth";
    println!("{header}\n{}", rows.join("\n"));
    std::fs::write(&a[0], format!("{header}\n{}\n", rows.join("\n"))).expect("write the CSV");
}
