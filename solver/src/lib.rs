//! # maugis-solver: a numerical Dugdale-Maugis line-contact solver
//!
//! A rigid profile `h(x)` (by default the paper's wavy cylinder) presses on an
//! elastic half-plane in plane strain; the interface follows the Dugdale-Maugis
//! law (tensile traction `sigma0` where the gap is below `delta_c`). The solver
//! reaches the states the semi-analytical model of the `maugis` crate cannot
//! describe (cavitated contacts, several contact intervals) and checks the model
//! where it holds. It uses `maugis` as an ordinary dependency
//! (`default-features = false`).
//!
//! Units are those of the semi-analytical model: horizontal lengths by `l_h`,
//! vertical by `l_v`, load by `(E* dgamma^2 R)^(1/3)`, `E* = 1`,
//! `sigma0 = lambda`, `delta_c = 1/lambda`.
//!
//! The parts, each usable on its own:
//!
//! * [`grid::Grid`]: the uniform cell grid on `[-X, X]`;
//! * [`elastic::HalfPlane`]: the free-space (zero-padded FFT) half-plane
//!   operator, with the datum of the approach;
//! * [`profile::Profile`], [`profile::Adhesion`]: the geometry and the law;
//!   [`profile_file::ProfileTable`]: a profile read from `x,h` rows;
//! * [`contact::ContactSolver`]: one equilibrium at a given approach
//!   (Polonsky-Keer CG inside a Dugdale-zone fixed point), warm-started;
//! * [`path`]: displacement-controlled loading and unloading, the work of the
//!   stiff-machine cycle, and the comparison with the semi-analytical curve;
//! * [`dissipation`]: W of the closed in-contact cycle under load and
//!   displacement control, measured on a simulated cycle as the library
//!   measures it on the model;
//! * [`map`]: regime maps drawn by the solver, one cycle per grid point of the
//!   model's sweep grid, labelled next to the model (sharded, merged exactly;
//!   parallel with the `parallel` feature);
//! * [`transition`]: lambda*, below which the roughness-induced dissipation
//!   vanishes, by bisection in lambda with a grid uncertainty;
//! * [`scales`]: W and cavitation against the number of scales of a
//!   Weierstrass profile, with the single scales and the model beside them
//!   (sharded, merged exactly);
//! * [`run::simulate`]: one cycle from `(lambda, alpha, beta)`, set up as
//!   `maugis simulate` and the Python package run it.
//!
//! ```
//! use maugis_solver::{grid::Grid, profile::{Adhesion, Profile}, contact::{ContactSolver, SolveOptions}};
//! let grid = Grid::new(1024, 4.0)?;
//! let mut s = ContactSolver::new(grid, None, &Profile::wavy_cylinder(0.0, 1.0)?, Adhesion::NONE, SolveOptions::default())?;
//! let state = s.solve(2.0)?;
//! assert_eq!(state.contact_intervals(), 1);
//! # Ok::<(), maugis_solver::SolverError>(())
//! ```
//!
//! Method, validation and the mesh-convergence study: `docs/solver.md`.

pub mod contact;
pub mod dissipation;
pub mod elastic;
pub mod error;
pub mod grid;
pub mod map;
pub mod path;
pub mod profile;
pub mod profile_file;
pub mod run;
pub mod scales;
pub mod transition;

pub use error::{MergeFault, Result, SolverError, TableFault};
