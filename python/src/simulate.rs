//! `maugis.simulate`: one cycle of the numerical solver (`maugis-solver`) with
//! every option of `maugis simulate`. Parsing and presenting only: the profile
//! table is read and checked by `maugis_solver::profile_file`, the run is
//! `maugis_solver::run::simulate_with`, and the result crosses as the JSON text
//! of the solver's `SimulationReport` (the object `maugis simulate --format
//! json` prints).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use maugis_solver::profile::AdhesionLaw;
use maugis_solver::profile_file::ProfileTable;
use maugis_solver::run::{simulate_with, Domain, SimulationOptions, SimulationSpec};
use maugis_solver::SolverError;

/// The profile argument: a CSV file's path, or the columns `x` and `h`.
fn table(path: Option<String>, columns: Option<(Vec<f64>, Vec<f64>)>) -> PyResult<Option<ProfileTable>> {
    let named = |what: &str, e: SolverError| PyValueError::new_err(format!("profile {what}: {e}"));
    match (path, columns) {
        (Some(_), Some(_)) => Err(PyValueError::new_err("profile: give a file or the columns (x, h), not both")),
        (Some(p), None) => {
            let text = std::fs::read_to_string(&p).map_err(|e| PyValueError::new_err(format!("profile {p}: {e}")))?;
            ProfileTable::parse(&text).map(Some).map_err(|e| named(&p, e))
        }
        (None, Some((x, h))) => {
            if x.len() != h.len() {
                return Err(PyValueError::new_err(format!("profile: x has {} values, h {}", x.len(), h.len())));
            }
            ProfileTable::new(x, h).map(Some).map_err(|e| match e {
                // A column's row k is line k + 2 of the same table as CSV text.
                SolverError::ProfileTable { line, fault } => {
                    PyValueError::new_err(format!("profile (x, h): row {} (from 0): {fault}", line.saturating_sub(2)))
                }
                e => named("(x, h)", e),
            })
        }
        (None, None) => Ok(None),
    }
}

/// One loading-unloading(-reloading) cycle of the numerical solver: JSON text
/// of the solver's `SimulationReport`.
#[pyfunction]
#[pyo3(signature = (lam, alpha, beta, amax, cells, steps, profile_path=None, profile_columns=None, half_width=None, periodic=false, law="dugdale", waves=None, without_model=false))]
#[allow(clippy::too_many_arguments)]
fn simulate_json(
    py: Python<'_>,
    lam: f64,
    alpha: f64,
    beta: f64,
    amax: f64,
    cells: usize,
    steps: usize,
    profile_path: Option<String>,
    profile_columns: Option<(Vec<f64>, Vec<f64>)>,
    half_width: Option<f64>,
    periodic: bool,
    law: &str,
    waves: Option<Vec<(f64, f64)>>,
    without_model: bool,
) -> PyResult<String> {
    let law = AdhesionLaw::from_name(law).map_err(|e| PyValueError::new_err(format!("law: {e}")))?;
    let spec = SimulationSpec { lambda: lam, alpha, beta, amax, cells, steps_per_leg: steps };
    let profile = table(profile_path, profile_columns)?;
    let waves = waves
        .map(|w| maugis::contact::profile::WavyProfile::from_pairs(&w))
        .transpose()
        .map_err(|e| PyValueError::new_err(format!("waves: {e}")))?;
    let options =
        SimulationOptions { profile, half_width, domain: if periodic { Domain::Periodic } else { Domain::Free }, law, waves, without_model };
    let sim = py.detach(|| simulate_with(spec, options, &mut |_, _| ())).map_err(|e| PyValueError::new_err(e.to_string()))?;
    serde_json::to_string(&sim.report()).map_err(|e| PyValueError::new_err(format!("internal: could not format JSON: {e}")))
}

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate_json, m)?)
}
