//! W of the closed in-contact cycle from the solver next to the model's.
//!
//! `cargo run --release -p maugis-solver --example dissipation -- LAMBDA ALPHA BETA AMAX CELLS STEPS [dugdale|exp]`
//!
//! Prints the solver's W and W_d (datum 100), the model's at the same amax
//! (600 points), their differences, the wall time and the stiff-cycle work.

use std::time::Instant;

use maugis::contact::curve::{load_area_curve, CurveOptions};
use maugis::contact::model::Params;
use maugis_solver::profile::AdhesionLaw;
use maugis_solver::run::{simulate_with, SimulationOptions, SimulationSpec};

fn main() {
    let law = std::env::args().nth(7).map_or(AdhesionLaw::Dugdale, |n| AdhesionLaw::from_name(&n).expect("law"));
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .take(6)
        .map(|s| s.parse().expect("numbers"))
        .collect();
    let (lambda, alpha, beta, amax, cells, steps) =
        (a[0], a[1], a[2], a[3], a[4] as usize, a[5] as usize);
    let t = Instant::now();
    let sim = simulate_with(
        SimulationSpec {
            lambda,
            alpha,
            beta,
            amax,
            cells,
            steps_per_leg: steps,
        },
        SimulationOptions { law, ..SimulationOptions::default() },
        &mut |_, _| {},
    )
    .unwrap();
    let secs = t.elapsed().as_secs_f64();
    let d = sim.dissipation().unwrap();
    let curve = load_area_curve(
        Params::new(lambda, alpha, beta).unwrap(),
        CurveOptions {
            amax,
            ..CurveOptions::default()
        },
    )
    .unwrap();
    let (w, wd) = (
        d.load_control.dissipation.total,
        d.displacement_control.dissipation.total,
    );
    let (mw, mwd) = (
        curve.load_control.dissipation.total,
        curve.displacement_control.dissipation.total,
    );
    println!(
        "lambda {lambda} alpha {alpha} beta {beta} amax {amax} cells {cells} steps {steps}: {secs:.2} s, {} states\n  \
         W   solver {w:.5} model {mw:.5} diff {:+.2e} ({:+.3} %), loops {} vs {}, model invalid {:.3e}\n  \
         W_d solver {wd:.5} model {mwd:.5} diff {:+.2e} ({:+.3} %), loops {} vs {}\n  \
         pull-off solver {:.5} model {:?}; stiff-cycle work {:.4}; single interval {}",
        sim.cycle.loading.len() + sim.cycle.unloading.len() + sim.cycle.reloading.len(),
        w - mw,
        100.0 * (w - mw) / mw.abs().max(1e-300),
        d.load_control.loops.len(),
        curve.load_control.loops.len(),
        curve.load_control.dissipation.invalid,
        wd - mwd,
        100.0 * (wd - mwd) / mwd.abs().max(1e-300),
        d.displacement_control.loops.len(),
        curve.displacement_control.loops.len(),
        d.load_control.end.load,
        curve.pull_off.map(|p| p.load),
        sim.cycle.stiff_work,
        d.load_control.single_interval,
    );
    if std::env::var("DUMP").is_ok() {
        for (leg, v) in [("L", &sim.cycle.loading), ("U", &sim.cycle.unloading), ("R", &sim.cycle.reloading)] {
            for st in v.iter() {
                let dm =
                    maugis_solver::path::approach_on_model_datum(st.approach, st.load, sim.datum);
                println!("D {leg} {:.6} {:.6} {:.6}", st.abar, st.load, dm);
            }
        }
    }
    if std::env::var("PATHS").is_ok() {
        for n in &d.load_control.reloading {
            println!("R {:.6} {:.6} {:.6}", n.abar, n.load, n.approach);
        }
        for n in &d.load_control.unloading {
            println!("U {:.6} {:.6} {:.6}", n.abar, n.load, n.approach);
        }
    }
    if std::env::var("LOOPS").is_ok() {
        for (name, a, b) in [
            ("load", &d.load_control.loops, &curve.load_control.loops),
            (
                "disp",
                &d.displacement_control.loops,
                &curve.displacement_control.loops,
            ),
        ] {
            for l in a.iter() {
                println!(
                    "  {name} solver: y [{:.4}, {:.4}] abar [{:.4}, {:.4}] W {:.5}",
                    l.control_low, l.control_high, l.abar_low, l.abar_high, l.dissipation
                );
            }
            for l in b.iter() {
                println!(
                    "  {name} model : y [{:.4}, {:.4}] abar [{:.4}, {:.4}] W {:.5}",
                    l.control_low, l.control_high, l.abar_low, l.abar_high, l.dissipation
                );
            }
        }
    }
}
