//! No public entry point of the solver panics, on any input: fuzzing on the
//! stable toolchain with bolero's structured generators, driven by a seeded byte
//! stream (`tests/it/common/fuzz_inputs.rs`; issue 26, item 5; the
//! library's targets are in the workspace's `tests/it/fuzz.rs`, this file follows
//! their style).
//!
//! Each target draws structured inputs (f64 bit patterns mixed with values at
//! and next to the domain edges, huge and degenerate grid sizes and step
//! counts, arbitrary text and near-valid `x,h` tables for the profile parser)
//! and calls the solver. A panic fails the test; so does an `Ok` that carries a
//! non-finite number (bad input must be an error, never a NaN). The simulations
//! run at the smallest grids (64 and 128 cells) and 2-4 steps per leg, so each
//! input is cheap; the validation paths see every size.
//!
//! `./dev test` runs 250 inputs a target (`--long`: 1000, the same 250 first),
//! the same inputs on every run. A campaign, with a time per target (or
//! `BOLERO_RANDOM_ITERATIONS` for a count):
//!
//! ```text
//! BOLERO_RANDOM_TEST_TIME_MS=600000 cargo test --features maugis/gmp-no-check -p maugis-solver --test it fuzz:: -- --nocapture
//! ```
//!
//! Campaign of 2026-11-26 (test profile, 240 s a target, one thread, at
//! 7b960b0): building blocks 75 038 753 inputs, profile tables 101 938 439
//! raw-text plus 4 471 661 near-valid tables, simulations 67 365 inputs (5 571
//! of them simulated to the end); 0 failures, with
//! `BOLERO_RANDOM_TEST_TIME_MS=240000` and `-- --test-threads=1`.
//!
//! Found and fixed before it: a subnormal domain half-width (cell width 0), a
//! subnormal `beta` (a NaN profile), table rows too close for their rise (a NaN
//! slope), and `ProfileTable::depth_at(NaN)` (an index underflow: a panic).

#[path = "../../../tests/it/common/fuzz_real.rs"]
mod fuzz_real;
#[path = "../../../tests/it/common/fuzz_inputs.rs"]
mod fuzz_inputs;

use fuzz_inputs::check;
use maugis_solver::contact::State;
use maugis_solver::elastic::HalfPlane;
use maugis_solver::grid::Grid;
use maugis_solver::profile::{Adhesion, Profile};
use maugis_solver::profile_file::ProfileTable;
use maugis_solver::run::{simulate_with, Domain, SimulationOptions, SimulationSpec};

/// Values at and next to the edges of the solver's domains.
const EDGES: [f64; 22] = [
    0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, 5e-324, 1e300, f64::MAX, f64::MIN, f64::NAN, f64::INFINITY,
    f64::NEG_INFINITY, 1e-6, 1e6, 1e4, 1e4 + 1.0, 0.9, 3.0, 6.0, 1.0 - f64::EPSILON, 1.0 + f64::EPSILON,
];

/// An f64 from 64 random bits: a raw bit pattern, a domain edge, a small
/// multiple of 1/8, or a value of moderate size.
fn real(bits: u64) -> f64 {
    fuzz_real::real_with(bits, &EDGES)
}

/// A positive parameter of moderate size (the physical range), or an edge.
fn param(bits: u64) -> f64 {
    match bits % 4 {
        0 => real(bits >> 2),
        _ => 0.05 + (bits >> 11) as f64 / (1u64 << 53) as f64 * 3.0,
    }
}

/// A size: the edges of the accepted ranges, huge values, or raw bits.
fn size(bits: u64, edges: &[usize]) -> usize {
    match bits % 4 {
        0 => bits as usize,
        _ => edges[(bits >> 2) as usize % edges.len()],
    }
}

const CELLS: [usize; 9] = [0, 1, 63, 64, 65, 100, 128, 1 << 25, usize::MAX];
/// Grids small enough to simulate.
const SMALL_CELLS: [usize; 2] = [64, 128];
const STEPS: [usize; 7] = [0, 1, 2, 3, 4, 100_001, usize::MAX];

/// A decimal text from random bits: mostly well formed, sometimes not.
fn decimal_text(bits: u64) -> String {
    let v = real(bits);
    match bits % 7 {
        0 => format!("{v:e}"),
        1 => format!("{}", bits as i64),
        2 => format!("{v}e{}", (bits >> 40) as i16),
        3 => ["nan", "inf", "-", "", "1e", ".", "0x10", "1.2.3", "1e999999999999", " 2.5 "][(bits % 10) as usize].to_string(),
        _ => format!("{v}"),
    }
}

/// A near-valid profile table: the header (sometimes broken), then rows with
/// increasing `x` over `[-span, span]` (sometimes not increasing, sometimes a
/// field from [`decimal_text`], sometimes a missing or extra field).
fn table_text(rows: &[u64], span: f64) -> String {
    let mut t = String::new();
    match rows.first().map_or(0, |r| r % 16) {
        0 => t.push_str("x;h\n"),
        1 => {}
        _ => t.push_str("x,h\n"),
    }
    let n = rows.len().max(1) as f64;
    for (i, &r) in rows.iter().enumerate() {
        let x = -span + 2.0 * span * i as f64 / (n - 1.0).max(1.0);
        let h = x * x / 2.0 + (r >> 8) as f64 / (1u64 << 56) as f64;
        let line = match r % 32 {
            0 => format!("{},{h}", decimal_text(r >> 5)),
            1 => format!("{x},{}", decimal_text(r >> 5)),
            2 => format!("{x}"),
            3 => format!("{x},{h},{h}"),
            4 => format!("{},{h}", -x),
            5 => String::new(),
            _ => format!("{x},{h}"),
        };
        t.push_str(&line);
        t.push('\n');
    }
    t
}

/// Every number a state reports is finite.
fn finite_state(s: &State) -> bool {
    [s.approach, s.load, s.abar, s.elastic_energy, s.adhesion_energy].iter().all(|v| v.is_finite())
        && s.contact.iter().chain(&s.zone).all(|&(a, b)| a.is_finite() && b.is_finite())
}

#[test]
fn profile_table_from_text() {
    check().for_each(|bytes| {
        let text = String::from_utf8_lossy(bytes);
        if let Ok(t) = ProfileTable::parse(&text) {
            assert!(t.x().iter().chain(t.h()).all(|v| v.is_finite()), "{text:?}");
        }
    });
    check().with_type::<(Vec<u64>, u64, [u64; 3])>().for_each(|(rows, span, probes)| {
        let text = table_text(rows, real(*span).abs());
        if let Ok(t) = ProfileTable::parse(&text) {
            for &p in probes {
                let x = real(p);
                let d = t.depth_at(x);
                assert!(d.is_finite() || x.is_nan(), "{text:?} at x = {x}: {d}");
            }
            let _ = t.check_covers(real(span.rotate_left(17)));
        }
    });
}

#[test]
fn building_blocks() {
    check().with_type::<[u64; 5]>().for_each(|bits| {
        let cells = size(bits[0], &CELLS);
        let half_width = real(bits[1]);
        if let Ok(g) = Grid::new(cells, half_width) {
            assert!(g.dx().is_finite() && g.dx() > 0.0, "{g:?}");
            // a half-plane's FFT plans cost O(cells); only small grids are built
            if g.cells() <= 128 {
                let datum = if bits[4] % 2 == 0 { None } else { Some(real(bits[4] >> 1)) };
                let _ = HalfPlane::new(g, datum);
                let _ = HalfPlane::periodic(g, datum);
            }
            for p in [Profile::wavy_cylinder(real(bits[2]), real(bits[3])), Profile::sinusoid(real(bits[2]), real(bits[3]))]
                .into_iter()
                .flatten()
                .filter(|_| g.cells() <= 1 << 12)
            {
                if let Ok(h) = p.sample(&g) {
                    assert!(h.iter().all(|v| v.is_finite()), "{p:?} on {g:?}");
                }
            }
        }
        if let Ok(a) = Adhesion::dugdale(real(bits[2])) {
            let (s, r) = a.strength_and_range();
            assert!(s.is_finite() && r.is_finite(), "{a:?}");
        }
    });
}

#[test]
fn simulation_spec_and_options() {
    let simulated = std::sync::atomic::AtomicUsize::new(0);
    check().with_type::<([u64; 8], Vec<u64>)>().for_each(|(bits, rows)| {
        // small grids and a few steps simulate cheaply; other sizes exercise validation
        let cells = if bits[4] % 4 == 0 { size(bits[4] >> 2, &CELLS) } else { SMALL_CELLS[(bits[4] >> 2) as usize % 2] };
        let steps = if bits[5] % 4 == 0 { size(bits[5] >> 2, &STEPS) } else { 2 + (bits[5] >> 2) as usize % 3 };
        let spec = SimulationSpec {
            lambda: param(bits[0]),
            alpha: param(bits[1]) * 0.5,
            beta: param(bits[2]),
            amax: param(bits[3]),
            cells,
            steps_per_leg: steps,
        };
        let half_width = if bits[6] % 2 == 0 { None } else { Some(real(bits[6] >> 1)) };
        let domain = if bits[7] % 2 == 0 { Domain::Free } else { Domain::Periodic };
        let profile = if bits[7] % 3 == 0 {
            ProfileTable::parse(&table_text(rows, real(bits[7] >> 2).abs())).ok()
        } else {
            None
        };
        let options = SimulationOptions { profile, half_width, domain, ..SimulationOptions::default() };
        if let Ok(sim) = simulate_with(spec, options, &mut |_, _| ()) {
            simulated.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let c = &sim.cycle;
            assert!(sim.half_width.is_finite() && sim.datum.is_finite() && c.step.is_finite() && c.stiff_work.is_finite(), "{spec:?}");
            for s in c.loading.iter().chain(&c.unloading).chain(&c.reloading) {
                assert!(finite_state(s), "{spec:?}: {s:?}");
            }
            let report = sim.report();
            assert!(report.states.iter().all(|r| r.load.is_finite() && r.approach.is_finite()), "{spec:?}");
        }
    });
    // how many inputs reached a whole simulation (the rest were refused)
    eprintln!("simulation_spec_and_options: {} inputs simulated", simulated.into_inner());
}
