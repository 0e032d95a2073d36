//! One table from a function's name to the library calls behind it.
//!
//! `maugis eval` (the JSON Lines calculator of the CLI) and the Python package
//! both dispatch through [`FUNCTIONS`]: a function added here is reachable from
//! both, with the same argument names, the same checks and the same error texts.
//! The front ends only parse their own input format into [`Arg`]s and present
//! the [`Answer`].
//!
//! Each [`Function`] has up to three paths:
//!
//! * [`Function::eval_f64`]: f64 arguments, an f64 answer within the function's
//!   documented tolerance (or, for the estimating rules, a value with an
//!   estimate that says so);
//! * [`Function::eval_bounded`]: f64 arguments, a [`Bounded`] value with a
//!   proven `|exact - value| <= err` (only where the library has one);
//! * [`Function::eval_mp`]: decimal arguments and a working precision. How the
//!   decimals are taken is the function's [`MpInputs`]: as balls that contain
//!   the decimal as typed ([`crate::ball::eval_at_decimals`]), or rounded to
//!   nearest at `max(prec, 53) + 64` bits, where the function has no
//!   ball-input form yet.
//!
//! Integer parameters (orders `n`, `k`, the truncation `kmax`) are
//! [`Arg::Int`]; giving a real where an integer is wanted, or the reverse, is the
//! typed error [`Error::ArgumentKind`].
//!
//! A function may take a group of reals any number of times after its fixed
//! parameters ([`Function::repeated`]): `strip_ratio_waves` and `load_waves` take
//! `lambda, abar` and then `alpha_j, beta_j` for each wave of the profile
//! (docs/model.md, "Many waves"). An incomplete last group is
//! [`Error::IncompleteGroup`], more than [`Repeated::max`] groups
//! [`crate::error::ProfileError::TooManyWaves`], a bad wave
//! [`crate::error::ProfileError::Wave`] naming the wave and the field.

use rug::Float;

use crate::ball::{eval_at_decimals, Decimal};
use crate::contact::model::{solve_load, ContactSize, Params};
use crate::contact::displacement::{self, quadrature as wave_quadrature};
use crate::contact::model_mp;
use crate::contact::profile::{WavyProfile, MAX_WAVES};
use crate::error::{Error, ProfileError, Result};
use crate::special::{bessel_j, hyp1f2, hyp2f1, meijer_g};
use crate::{Ball, Bounded, Budget};

pub use crate::error::ParamKind;

/// One parameter of a [`Function`]: its name (as the front ends spell it) and kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Param {
    /// The name, e.g. `"n"`, `"x"`, `"zeta"`.
    pub name: &'static str,
    /// Integer or real.
    pub kind: ParamKind,
}

/// An argument as a front end hands it over: an integer, or a real of type `R`
/// (`f64` for the f64 paths, [`Decimal`] for the MP path).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Arg<R> {
    /// An integer.
    Int(i64),
    /// A real number.
    Real(R),
}

/// How the MP path of a function takes its decimal arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum MpInputs {
    /// Each decimal is a ball that contains it as typed; the answer contains the
    /// function at the decimals ([`crate::ball::eval_at_decimals`]).
    Balls,
    /// Each decimal is rounded to nearest at `max(prec, 53) + 64` bits; the answer
    /// is for those binary numbers.
    Rounded,
}

/// What a function returns.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Answer {
    /// An f64 value.
    F64(f64),
    /// A certified ball.
    Ball(Ball),
    /// A truncated series in f64: the partial sum and a bound on the tail left out.
    SeriesF64 {
        /// The partial sum.
        value: f64,
        /// A bound on the tail.
        trunc: f64,
    },
    /// A truncated series in MP: the partial sum as a ball and a bound on the tail left out.
    SeriesBall {
        /// The partial sum (certified).
        value: Ball,
        /// A bound on the tail.
        trunc: Float,
    },
    /// An estimating rule in f64: the value and an error *estimate* (not a bound).
    EstimateF64 {
        /// The value.
        value: f64,
        /// The estimated error.
        error_estimate: f64,
    },
    /// An estimating rule in MP: the value and an error *estimate* (not a bound).
    EstimateMp {
        /// The value.
        value: Float,
        /// The estimated error.
        error_estimate: Float,
    },
}

/// A group of real parameters a function takes any number of times (`0..=max`)
/// after its fixed [`Function::params`]: the waves of a profile, each `(alpha, beta)`.
/// The arguments are flat: the fixed ones, then the first group's, the second's, ...
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Repeated {
    /// What one group is (errors name it), `"wave"`.
    pub group: &'static str,
    /// The front ends' name of the list of groups (`maugis eval`'s field, Python's
    /// keyword), `"waves"`.
    pub list: &'static str,
    /// The names in one group, in order, all reals: `["alpha", "beta"]`.
    pub names: &'static [&'static str],
    /// The most groups ([`MAX_WAVES`]; more is [`ProfileError::TooManyWaves`]).
    pub max: usize,
}

type F64Path = fn(&Args<'_, f64>) -> Result<Answer>;
type BoundedPath = fn(&Args<'_, f64>) -> Result<Bounded>;
type MpPath = fn(&Args<'_, Decimal>, u32) -> Result<Answer>;

/// A function the front ends can call by name.
pub struct Function {
    /// The name, as `maugis eval`'s `"fn"` and Python spell it.
    pub name: &'static str,
    /// The parameters, in call order.
    pub params: &'static [Param],
    /// How the MP path takes its decimals.
    pub mp_inputs: MpInputs,
    /// The group of reals taken any number of times after [`Function::params`], if any.
    pub repeated: Option<Repeated>,
    f64: F64Path,
    bounded: Option<BoundedPath>,
    mp: MpPath,
}

impl std::fmt::Debug for Function {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Function").field("name", &self.name).field("params", &self.params).finish_non_exhaustive()
    }
}

/// Arguments checked against a function's parameters (count and kinds).
pub struct Args<'a, R> {
    function: &'static str,
    params: &'static [Param],
    values: &'a [Arg<R>],
}

impl<'a, R> Args<'a, R> {
    /// The repeated groups after the fixed parameters, each as `N` reals (the count
    /// was checked by [`Function::check`]).
    fn groups<const N: usize>(&self) -> Result<Vec<[&'a R; N]>> {
        let tail = &self.values[self.params.len().min(self.values.len())..];
        tail.chunks(N)
            .map(|chunk| {
                let reals: Vec<&'a R> = chunk
                    .iter()
                    .map(|v| match v {
                        Arg::Real(r) => Ok(r),
                        Arg::Int(_) => Err(Error::ArgumentKind { function: self.function, arg: "a wave", expected: ParamKind::Real }),
                    })
                    .collect::<Result<_>>()?;
                reals.try_into().map_err(|_| Error::Arity { function: self.function, expected: self.params.len() + N, got: self.values.len() })
            })
            .collect()
    }
}

impl<R> Args<'_, R> {
    /// The integer at `i` ([`Error::ArgumentKind`] if a real was given there).
    fn int(&self, i: usize) -> Result<i64> {
        match self.values.get(i) {
            Some(Arg::Int(v)) => Ok(*v),
            _ => Err(self.kind_error(i, ParamKind::Integer)),
        }
    }

    /// The real at `i` ([`Error::ArgumentKind`] if an integer was given there).
    fn real(&self, i: usize) -> Result<&R> {
        match self.values.get(i) {
            Some(Arg::Real(v)) => Ok(v),
            _ => Err(self.kind_error(i, ParamKind::Real)),
        }
    }

    /// The reals at `i..i + N`, in order.
    fn reals<const N: usize>(&self, i: usize) -> Result<[&R; N]> {
        let mut out = Vec::with_capacity(N);
        for j in i..i + N {
            out.push(self.real(j)?);
        }
        out.try_into().map_err(|_| Error::Arity { function: self.function, expected: N, got: self.values.len() })
    }

    fn kind_error(&self, i: usize, expected: ParamKind) -> Error {
        Error::ArgumentKind { function: self.function, arg: self.params.get(i).map_or("?", |p| p.name), expected }
    }

    /// The integer at `i` as a non-negative `u32` (orders `k`).
    fn order_u32(&self, i: usize) -> Result<u32> {
        let v = self.int(i)?;
        u32::try_from(v).map_err(|_| Error::IntegerOutOfRange { arg: self.params[i].name, value: v, min: 0, max: u32::MAX as i64 })
    }

    /// The integer at `i` as a non-negative `u64` (term counts).
    fn count_u64(&self, i: usize) -> Result<u64> {
        let v = self.int(i)?;
        u64::try_from(v).map_err(|_| Error::IntegerOutOfRange { arg: self.params[i].name, value: v, min: 0, max: i64::MAX })
    }
}

/// The f64 reals at `i..i + N`, copied.
fn reals64<const N: usize>(a: &Args<'_, f64>, i: usize) -> Result<[f64; N]> {
    Ok(a.reals::<N>(i)?.map(|v| *v))
}

impl Function {
    /// Checks the arguments' number and kinds against [`Function::params`] (and
    /// [`Function::repeated`]: whole groups, at most `max`, all reals).
    fn check<'a, R>(&self, values: &'a [Arg<R>]) -> Result<Args<'a, R>> {
        let fixed = self.params.len();
        match self.repeated {
            None if values.len() != fixed => {
                return Err(Error::Arity { function: self.name, expected: fixed, got: values.len() });
            }
            None => {}
            Some(_) if values.len() < fixed => {
                return Err(Error::Arity { function: self.name, expected: fixed, got: values.len() });
            }
            Some(r) => {
                let size = r.names.len();
                if (values.len() - fixed) % size != 0 {
                    return Err(Error::IncompleteGroup { function: self.name, group: r.group, names: r.names, fixed, got: values.len() });
                }
                let count = (values.len() - fixed) / size;
                if count > r.max {
                    return Err(Error::Profile(ProfileError::TooManyWaves { count, max: r.max }));
                }
                for (i, v) in values[fixed..].iter().enumerate() {
                    if !matches!(v, Arg::Real(_)) {
                        return Err(Error::ArgumentKind { function: self.name, arg: r.names[i % size], expected: ParamKind::Real });
                    }
                }
            }
        }
        for (p, v) in self.params.iter().zip(values) {
            let ok = matches!((p.kind, v), (ParamKind::Integer, Arg::Int(_)) | (ParamKind::Real, Arg::Real(_)));
            if !ok {
                return Err(Error::ArgumentKind { function: self.name, arg: p.name, expected: p.kind });
            }
        }
        Ok(Args { function: self.name, params: self.params, values })
    }

    /// The parameter names, in call order.
    pub fn param_names(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.params.iter().map(|p| p.name)
    }

    /// Whether [`Function::eval_bounded`] is available.
    pub fn has_bounded(&self) -> bool {
        self.bounded.is_some()
    }

    /// The f64 path.
    pub fn eval_f64(&self, args: &[Arg<f64>]) -> Result<Answer> {
        (self.f64)(&self.check(args)?)
    }

    /// The f64 path with a proven error bound; [`Error::NoBoundedPath`] for the
    /// functions that have none (estimating rules, truncated series).
    pub fn eval_bounded(&self, args: &[Arg<f64>]) -> Result<Bounded> {
        let path = self.bounded.ok_or(Error::NoBoundedPath { function: self.name })?;
        path(&self.check(args)?)
    }

    /// The MP path at `prec` bits (`2 ..= MAX_PREC`), inputs as [`Function::mp_inputs`] says,
    /// under the default time budget ([`Budget::DEFAULT`]).
    pub fn eval_mp(&self, args: &[Arg<Decimal>], prec: u32) -> Result<Answer> {
        self.eval_mp_with_budget(args, prec, Budget::DEFAULT)
    }

    /// [`Function::eval_mp`] within `budget`: the same answer, or a prompt
    /// [`Error::TooExpensive`] (a cost estimate past the budget) or
    /// [`Error::BudgetSpent`] (a loop stopped at it); see [`crate::budget`].
    pub fn eval_mp_with_budget(&self, args: &[Arg<Decimal>], prec: u32, budget: Budget) -> Result<Answer> {
        crate::error::check_prec(prec)?;
        let args = self.check(args)?;
        budget.run(|| (self.mp)(&args, prec))
    }
}

/// The function called `name`, or [`Error::UnknownFunction`] (whose message lists the known names).
pub fn function(name: &str) -> Result<&'static Function> {
    FUNCTIONS.iter().find(|f| f.name == name).ok_or_else(|| Error::UnknownFunction { name: name.to_string(), known: names().collect() })
}

/// The names of [`FUNCTIONS`], in table order.
pub fn names() -> impl Iterator<Item = &'static str> {
    FUNCTIONS.iter().map(|f| f.name)
}

/// A decimal rounded to nearest at `max(prec, 53) + 64` bits ([`MpInputs::Rounded`]).
fn rounded(d: &Decimal, arg: &'static str, prec: u32) -> Result<Float> {
    let v = Float::with_val(prec.max(53) + 64, d.as_rational());
    if !v.is_finite() {
        return Err(Error::NonFinite { what: arg });
    }
    Ok(v)
}

/// The reals at `0..N` of a [`MpInputs::Rounded`] function, rounded.
fn rounded_reals<const N: usize>(a: &Args<'_, Decimal>, prec: u32) -> Result<[Float; N]> {
    let mut out: [Float; N] = std::array::from_fn(|_| Float::new(2));
    for (i, slot) in out.iter_mut().enumerate() {
        *slot = rounded(a.real(i)?, a.params[i].name, prec)?;
    }
    Ok(out)
}

/// The reals at `i..i + N` as owned decimals (for [`eval_at_decimals`]).
fn decimals<const N: usize>(a: &Args<'_, Decimal>, i: usize) -> Result<[Decimal; N]> {
    Ok(a.reals::<N>(i)?.map(Decimal::clone))
}

const fn int(name: &'static str) -> Param {
    Param { name, kind: ParamKind::Integer }
}

const fn real(name: &'static str) -> Param {
    Param { name, kind: ParamKind::Real }
}

/// The wave displacement's parameters (Eq. 12): half-width, wavelength, amplitude, position.
const WAVE: [Param; 4] = [real("a"), real("zeta"), real("amp"), real("x")];

/// The model's parameters (normalised, docs/model.md).
const MODEL: [Param; 4] = [real("lambda"), real("alpha"), real("beta"), real("abar")];

/// The model's parameters for a profile of many waves: `lambda`, `abar`, then
/// [`WAVES`] (`alpha_j, beta_j` for each wave).
const MODEL_WAVES: [Param; 2] = [real("lambda"), real("abar")];

/// The waves of `strip_ratio_waves` and `load_waves`.
const WAVES: Repeated = Repeated { group: "wave", list: "waves", names: &["alpha", "beta"], max: MAX_WAVES };

/// The model at one contact size in f64: the strip ratio `m` (Eq. 15b,
/// corrected) or the load at it (Eq. 14).
fn model_f64(a: &Args<'_, f64>, load: bool) -> Result<Answer> {
    let [lambda, alpha, beta, abar] = reals64::<4>(a, 0)?;
    state_f64(Params::new(lambda, alpha, beta)?, abar, load)
}

/// [`model_f64`] for a profile of many waves (`lambda, abar, alpha_1, beta_1, ...`).
fn model_waves_f64(a: &Args<'_, f64>, load: bool) -> Result<Answer> {
    let [lambda, abar] = reals64::<2>(a, 0)?;
    let pairs: Vec<(f64, f64)> = a.groups::<2>()?.into_iter().map(|[alpha, beta]| (*alpha, *beta)).collect();
    state_f64(Params::with_profile(lambda, WavyProfile::from_pairs(&pairs)?)?, abar, load)
}

/// `m`, or the load computed from the solver's strip end (`m - 1` to full relative
/// accuracy: the load from the rounded `m` lost it as `m -> 1`, 2.4e-5 relative at
/// lambda = 1e6, abar = 1).
fn state_f64(params: Params, abar: f64, load: bool) -> Result<Answer> {
    Ok(Answer::F64(if load { solve_load(params, abar)? } else { ContactSize::new(params, abar)?.solve_m()? }))
}

/// The certified `m` or load of a profile of many waves at decimals
/// (`lambda, abar, alpha_1, beta_1, ...`), each a ball that contains it.
fn model_waves_mp(a: &Args<'_, Decimal>, prec: u32, load: bool) -> Result<Answer> {
    let [lambda, abar] = decimals::<2>(a, 0)?;
    let waves: Vec<(Decimal, Decimal)> = a.groups::<2>()?.into_iter().map(|[alpha, beta]| (alpha.clone(), beta.clone())).collect();
    let at_decimals = if load { model_mp::load_waves_at_decimals } else { model_mp::strip_ratio_waves_at_decimals };
    Ok(Answer::Ball(at_decimals(&lambda, &abar, &waves, prec)?))
}

/// Every function the front ends can call, in the order `maugis eval` lists them.
pub static FUNCTIONS: &[Function] = &[
    Function {
        name: "bessel_j",
        params: &[int("n"), real("x")],
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| Ok(Answer::F64(bessel_j::bessel_j(a.int(0)?, *a.real(1)?)?)),
        bounded: Some(|a| bessel_j::bessel_j_bounded(a.int(0)?, *a.real(1)?)),
        mp: |a, p| {
            let n = a.int(0)?;
            Ok(Answer::Ball(eval_at_decimals(&decimals::<1>(a, 1)?, p, |b| bessel_j::bessel_j_ball_mp(n, &b[0], p))?))
        },
    },
    Function {
        name: "hyp1f2",
        params: &[real("a"), real("b1"), real("b2"), real("z")],
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| {
            let [x, b1, b2, z] = reals64::<4>(a, 0)?;
            Ok(Answer::F64(hyp1f2::hyp1f2(x, b1, b2, z)?))
        },
        bounded: Some(|a| {
            let [x, b1, b2, z] = reals64::<4>(a, 0)?;
            hyp1f2::hyp1f2_bounded(x, b1, b2, z)
        }),
        mp: |a, p| {
            let b = eval_at_decimals(&decimals::<4>(a, 0)?, p, |x| hyp1f2::hyp1f2_ball_mp(&x[0], &x[1], &x[2], &x[3], p))?;
            Ok(Answer::Ball(b))
        },
    },
    Function {
        name: "hyp2f1",
        params: &[real("a"), real("b"), real("c"), real("z")],
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| {
            let [x, b, c, z] = reals64::<4>(a, 0)?;
            Ok(Answer::F64(hyp2f1::hyp2f1(x, b, c, z)?))
        },
        bounded: Some(|a| {
            let [x, b, c, z] = reals64::<4>(a, 0)?;
            hyp2f1::hyp2f1_bounded(x, b, c, z)
        }),
        mp: |a, p| {
            let b = eval_at_decimals(&decimals::<4>(a, 0)?, p, |x| hyp2f1::hyp2f1_ball_mp(&x[0], &x[1], &x[2], &x[3], p))?;
            Ok(Answer::Ball(b))
        },
    },
    Function {
        name: "meijer_g_k",
        params: &[int("k"), real("y")],
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| Ok(Answer::F64(meijer_g::meijer_g_k(a.order_u32(0)?, *a.real(1)?)?)),
        bounded: Some(|a| meijer_g::meijer_g_k_bounded(a.order_u32(0)?, *a.real(1)?)),
        mp: |a, p| {
            let k = a.order_u32(0)?;
            Ok(Answer::Ball(eval_at_decimals(&decimals::<1>(a, 1)?, p, |b| meijer_g::meijer_g_k_ball_mp(k, &b[0], p))?))
        },
    },
    Function {
        name: "u_wave",
        params: &WAVE,
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| {
            let [x0, z, m, x] = reals64::<4>(a, 0)?;
            Ok(Answer::F64(displacement::u_wave(x0, z, m, x)?))
        },
        bounded: Some(|a| {
            let [x0, z, m, x] = reals64::<4>(a, 0)?;
            displacement::u_wave_bounded(x0, z, m, x)
        }),
        mp: |a, p| Ok(Answer::Ball(displacement::wave_at_decimals(&decimals::<4>(a, 0)?, p, false)?)),
    },
    Function {
        name: "u_wave_series",
        params: &[real("a"), real("zeta"), real("amp"), real("x"), int("kmax")],
        mp_inputs: MpInputs::Rounded,
        repeated: None,
        f64: |a| {
            let [x0, z, m, x] = reals64::<4>(a, 0)?;
            let (value, trunc) = displacement::u_wave_series(x0, z, m, x, a.count_u64(4)?)?;
            Ok(Answer::SeriesF64 { value, trunc })
        },
        bounded: None,
        mp: |a, p| {
            let kmax = a.count_u64(4)?;
            let [x0, z, m, x] = rounded_reals::<4>(a, p)?;
            let r = displacement::u_wave_series_mp(&x0, &z, &m, &x, kmax, p)?;
            Ok(Answer::SeriesBall { value: r.partial.clone(), trunc: r.trunc.clone() })
        },
    },
    Function {
        name: "du_wave",
        params: &WAVE,
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| {
            let [x0, z, m, x] = reals64::<4>(a, 0)?;
            Ok(Answer::F64(displacement::du_wave(x0, z, m, x)?))
        },
        bounded: Some(|a| {
            let [x0, z, m, x] = reals64::<4>(a, 0)?;
            displacement::du_wave_bounded(x0, z, m, x)
        }),
        mp: |a, p| Ok(Answer::Ball(displacement::wave_at_decimals(&decimals::<4>(a, 0)?, p, true)?)),
    },
    Function {
        name: "u_wave_quad",
        params: &WAVE,
        mp_inputs: MpInputs::Rounded,
        repeated: None,
        f64: |a| {
            let [x0, z, m, x] = reals64::<4>(a, 0)?;
            let q = wave_quadrature::u_wave_quad(x0, z, m, x)?;
            Ok(Answer::EstimateF64 { value: q.value, error_estimate: q.error_estimate })
        },
        bounded: None,
        mp: |a, p| {
            let [x0, z, m, x] = rounded_reals::<4>(a, p)?;
            let q = wave_quadrature::u_wave_quad_mp(&x0, &z, &m, &x, p)?;
            Ok(Answer::EstimateMp { value: q.value, error_estimate: q.error_estimate })
        },
    },
    Function {
        name: "u_hertz",
        params: &[real("a"), real("r"), real("x")],
        mp_inputs: MpInputs::Rounded,
        repeated: None,
        f64: |a| {
            let [x0, r, x] = reals64::<3>(a, 0)?;
            Ok(Answer::F64(displacement::u_hertz(x0, r, x)?))
        },
        bounded: None,
        mp: |a, p| {
            let [x0, r, x] = rounded_reals::<3>(a, p)?;
            Ok(Answer::Ball(displacement::u_hertz_mp(&x0, &r, &x, p)?))
        },
    },
    Function {
        name: "u_adhesive",
        params: &[real("a"), real("c"), real("sigma"), real("e_star"), real("x")],
        mp_inputs: MpInputs::Rounded,
        repeated: None,
        f64: |a| {
            let [x0, c, s, e, x] = reals64::<5>(a, 0)?;
            Ok(Answer::F64(displacement::u_adhesive(x0, c, s, e, x)?))
        },
        bounded: None,
        mp: |a, p| {
            let [x0, c, s, e, x] = rounded_reals::<5>(a, p)?;
            Ok(Answer::Ball(displacement::u_adhesive_mp(&x0, &c, &s, &e, &x, p)?))
        },
    },
    Function {
        name: "strip_ratio",
        params: &MODEL,
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| model_f64(a, false),
        bounded: None,
        mp: |a, p| Ok(Answer::Ball(model_mp::strip_ratio_at_decimals(&decimals::<4>(a, 0)?, p)?)),
    },
    Function {
        name: "load",
        params: &MODEL,
        mp_inputs: MpInputs::Balls,
        repeated: None,
        f64: |a| model_f64(a, true),
        bounded: None,
        mp: |a, p| Ok(Answer::Ball(model_mp::load_at_decimals(&decimals::<4>(a, 0)?, p)?)),
    },
    Function {
        name: "strip_ratio_waves",
        params: &MODEL_WAVES,
        mp_inputs: MpInputs::Balls,
        repeated: Some(WAVES),
        f64: |a| model_waves_f64(a, false),
        bounded: None,
        mp: |a, p| model_waves_mp(a, p, false),
    },
    Function {
        name: "load_waves",
        params: &MODEL_WAVES,
        mp_inputs: MpInputs::Balls,
        repeated: Some(WAVES),
        f64: |a| model_waves_f64(a, true),
        bounded: None,
        mp: |a, p| model_waves_mp(a, p, true),
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    fn dec(s: &str) -> Arg<Decimal> {
        Arg::Real(Decimal::parse(s).unwrap())
    }

    #[test]
    fn every_path_answers_at_a_point_of_its_domain() {
        // one point per function inside its domain; each path must answer
        let points: &[(&str, &[&str])] = &[
            ("bessel_j", &["3", "2.5"]),
            ("hyp1f2", &["0.5", "1", "1.5", "-2"]),
            ("hyp2f1", &["1", "0.5", "2", "0.25"]),
            ("meijer_g_k", &["2", "0.5"]),
            ("u_wave", &["1", "0.7", "0.1", "1.5"]),
            ("u_wave_series", &["1", "0.7", "0.1", "1.5", "40"]),
            ("du_wave", &["1", "0.7", "0.1", "1.5"]),
            ("u_wave_quad", &["1", "0.7", "0.1", "1.5"]),
            ("u_hertz", &["1", "2", "1.5"]),
            ("u_adhesive", &["1", "1.2", "0.5", "1", "1.5"]),
            ("strip_ratio", &["1", "0.35", "1.125", "2"]),
            ("load", &["1", "0.35", "1.125", "2"]),
            ("strip_ratio_waves", &["1", "2", "0.35", "1.125", "0.175", "0.375"]),
            ("load_waves", &["1", "2", "0.35", "1.125", "0.175", "0.375"]),
        ];
        assert_eq!(points.len(), FUNCTIONS.len(), "a point for every registered function");
        for (name, texts) in points {
            let f = function(name).unwrap();
            // the fixed parameters' kinds, then reals (a repeated group)
            let kind = |i: usize| f.params.get(i).map_or(ParamKind::Real, |p| p.kind);
            let f64_args: Vec<Arg<f64>> = texts
                .iter()
                .enumerate()
                .map(|(i, t)| match kind(i) {
                    ParamKind::Integer => Arg::Int(t.parse().unwrap()),
                    ParamKind::Real => Arg::Real(t.parse().unwrap()),
                })
                .collect();
            let mp_args: Vec<Arg<Decimal>> = texts
                .iter()
                .enumerate()
                .map(|(i, t)| match kind(i) {
                    ParamKind::Integer => Arg::Int(t.parse().unwrap()),
                    ParamKind::Real => dec(t),
                })
                .collect();
            let v = f.eval_f64(&f64_args).unwrap_or_else(|e| panic!("{name} f64: {e}"));
            let mp = f.eval_mp(&mp_args, 96).unwrap_or_else(|e| panic!("{name} mp: {e}"));
            // the f64 value and the MP answer describe the same number
            let f64_value = match v {
                Answer::F64(x) | Answer::SeriesF64 { value: x, .. } | Answer::EstimateF64 { value: x, .. } => x,
                other => panic!("{name}: f64 path answered {other:?}"),
            };
            let mp_value = match &mp {
                Answer::Ball(b) | Answer::SeriesBall { value: b, .. } => b.to_f64(),
                Answer::EstimateMp { value, .. } => value.to_f64(),
                other => panic!("{name}: MP path answered {other:?}"),
            };
            assert!((f64_value - mp_value).abs() <= 1e-9 * mp_value.abs().max(1e-300), "{name}: {f64_value} vs {mp_value}");
            if f.has_bounded() {
                let b = f.eval_bounded(&f64_args).unwrap();
                assert!((b.value - mp_value).abs() <= b.err + 1e-15 * mp_value.abs(), "{name}: bound does not cover");
            } else {
                assert!(matches!(f.eval_bounded(&f64_args), Err(Error::NoBoundedPath { .. })));
            }
        }
    }

    #[test]
    fn bad_calls_are_typed_errors() {
        assert!(matches!(function("besselj"), Err(Error::UnknownFunction { .. })));
        let msg = function("nope").unwrap_err().to_string();
        assert!(msg.contains("bessel_j") && msg.contains("load"), "{msg}");
        let j = function("bessel_j").unwrap();
        assert!(matches!(j.eval_f64(&[Arg::Real(1.0)]), Err(Error::Arity { expected: 2, got: 1, .. })));
        assert!(matches!(j.eval_f64(&[Arg::Real(1.0), Arg::Real(2.0)]), Err(Error::ArgumentKind { arg: "n", .. })));
        assert!(matches!(j.eval_f64(&[Arg::Int(1), Arg::Int(2)]), Err(Error::ArgumentKind { arg: "x", .. })));
        assert!(matches!(j.eval_f64(&[Arg::Int(1), Arg::Real(f64::NAN)]), Err(Error::NonFinite { .. })));
        let g = function("meijer_g_k").unwrap();
        assert!(matches!(
            g.eval_f64(&[Arg::Int(-1), Arg::Real(0.5)]),
            Err(Error::IntegerOutOfRange { arg: "k", value: -1, .. })
        ));
        assert!(matches!(j.eval_mp(&[Arg::Int(1), dec("2")], 0), Err(Error::Precision { .. })));
    }

    #[test]
    fn f64_load_keeps_the_accuracy_of_m_minus_1() {
        // m - 1 ~ 8e-13 at lambda = 1e6: the load from the rounded m was 2.4e-5 off
        for (name, args) in [("load", vec![1e6, 0.0, 1.0, 1.0]), ("load_waves", vec![1e6, 1.0, 0.0, 1.0]), ("load", vec![1e4, 0.35, 1.125, 2.2])] {
            let f = function(name).unwrap();
            let Answer::F64(v) = f.eval_f64(&args.iter().map(|x| Arg::Real(*x)).collect::<Vec<_>>()).unwrap() else { panic!() };
            let mp_args: Vec<Arg<Decimal>> = args.iter().map(|x| dec(&format!("{x:e}"))).collect();
            let Answer::Ball(b) = f.eval_mp(&mp_args, 64).unwrap() else { panic!() };
            assert!((v - b.to_f64()).abs() <= 1e-12 * b.to_f64().abs(), "{name} {args:?}: {v} vs {b:?}");
        }
    }

    #[test]
    fn bad_wave_lists_are_typed_errors() {
        let f = function("strip_ratio_waves").unwrap();
        let r = |v: f64| Arg::Real(v);
        // an odd count: the second wave has no wavelength
        let e = f.eval_f64(&[r(1.0), r(2.0), r(0.35), r(1.125), r(0.2)]).unwrap_err();
        assert!(matches!(e, Error::IncompleteGroup { group: "wave", fixed: 2, got: 5, .. }), "{e:?}");
        assert!(e.to_string().contains("wave 2 incomplete"), "{e}");
        let e = f.eval_mp(&[dec("1"), dec("2"), dec("0.35")], 64).unwrap_err();
        assert!(matches!(e, Error::IncompleteGroup { got: 3, .. }), "{e:?}");
        // fewer than the fixed parameters
        assert!(matches!(f.eval_f64(&[r(1.0)]), Err(Error::Arity { expected: 2, got: 1, .. })));
        // too many waves: refused before any evaluation
        let mut many = vec![dec("1"), dec("2")];
        for _ in 0..=MAX_WAVES {
            many.extend([dec("0.1"), dec("1")]);
        }
        let e = f.eval_mp(&many, 64).unwrap_err();
        assert!(matches!(e, Error::Profile(ProfileError::TooManyWaves { count, max: MAX_WAVES }) if count == MAX_WAVES + 1), "{e:?}");
        // an integer where a wave's real is wanted
        let e = f.eval_f64(&[r(1.0), r(2.0), r(0.35), Arg::Int(1)]).unwrap_err();
        assert!(matches!(e, Error::ArgumentKind { arg: "beta", .. }), "{e:?}");
        // a bad value names the wave and the field, on both paths
        use crate::error::WaveField;
        let e = f.eval_f64(&[r(1.0), r(2.0), r(0.35), r(1.125), r(-0.1), r(0.375)]).unwrap_err();
        assert!(matches!(e, Error::Profile(ProfileError::Wave { wave: 2, field: WaveField::Amplitude, .. })), "{e:?}");
        let e = f.eval_f64(&[r(1.0), r(2.0), r(0.35), r(f64::NAN)]).unwrap_err();
        assert!(matches!(e, Error::Profile(ProfileError::Wave { wave: 1, field: WaveField::Wavelength, .. })), "{e:?}");
        for prec in [12, 64] {
            let e = f.eval_mp(&[dec("1"), dec("2"), dec("0.35"), dec("1.125"), dec("0.2"), dec("0")], prec).unwrap_err();
            assert!(matches!(e, Error::Profile(ProfileError::Wave { wave: 2, field: WaveField::Wavelength, .. })), "{prec}: {e:?}");
            let e = function("load_waves").unwrap().eval_mp(&[dec("1"), dec("2"), dec("-0.35"), dec("1.125")], prec).unwrap_err();
            assert!(matches!(e, Error::Profile(ProfileError::Wave { wave: 1, field: WaveField::Amplitude, .. })), "{prec}: {e:?}");
        }
    }
}
