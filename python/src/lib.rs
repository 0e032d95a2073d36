//! `maugis._maugis`: the compiled half of the `maugis` Python package.
//!
//! A thin layer: no numerics live here. The Python half (`python/maugis/`)
//! broadcasts and converts the arguments to flat, contiguous `int64`/`float64`
//! arrays of one length; the functions here run the library over them element
//! by element and hand back flat arrays, which Python reshapes.
//!
//! * f64 loops release the GIL ([`Python::detach`]) and run on rayon's pool
//!   once an array has `PARALLEL_MIN_LEN` elements.
//! * Arbitrary precision (`eval_mp`) takes exact binary inputs (`man * 2^exp`)
//!   or decimal strings (each a ball that contains the decimal as typed, as in
//!   `maugis eval`), and returns each certified ball either as exact binary
//!   pairs (for `mpmath.mpf`) or as decimal strings whose radius still encloses.
//! * `integrate_mp`: a certified integral of an expression in x
//!   ([`maugis::quad::expr`]) with the same inputs and outputs.
//! * Every library [`maugis::Error`] becomes a Python `ValueError` carrying the
//!   library's message and the arguments of the element that failed.

mod simulate;

use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use rayon::prelude::*;

use maugis::contact::curve::{self, CurveOptions};
use maugis::contact::located::At;
use maugis::contact::profile::WavyProfile;
use maugis::contact::summary::{load_area_curves, load_area_curves_profile, RunSummary};
use maugis::contact::sweep::{run_sweep, SweepGrid};
use maugis::contact::model::Params;
use maugis::contact::state_profile::{sample_state, sample_state_at, ProfileSample};
use maugis::ball::Decimal;
use maugis::registry::{self, Answer, Arg, Function, ParamKind};
use maugis::quad::certified::Options;
use maugis::quad::expr::{abs_tol_text, integrate_range, shortfall, significant_imaginary, DecaySpec, End, Expr, WeightSpec};
use maugis::rug::{Float, Integer, Rational};
use maugis::special::hyp1f2::hyp1f2_model_family_f64;
use maugis::special::meijer_g::meijer_g_k_family_f64;
use maugis::{Ball, Bounded, Budget, Error};

/// Arrays shorter than this are evaluated on the calling thread: below it,
/// handing chunks to rayon costs more than it saves for the cheapest
/// functions (a few hundred ns per element).
const PARALLEL_MIN_LEN: usize = 2048;

/// Smallest chunk rayon hands to one worker (amortises the task overhead).
const PARALLEL_MIN_CHUNK: usize = 256;

/// A failed element: its flat index and the library's error.
struct ElementError {
    index: usize,
    error: Error,
}

/// Runs `f` over `0..len`, in parallel for long inputs. The first error (in
/// the order rayon meets them) stops the loop.
fn map_elements<T, F>(len: usize, f: F) -> Result<Vec<T>, ElementError>
where
    T: Send,
    F: Fn(usize) -> maugis::Result<T> + Sync + Send,
{
    let one = |i: usize| f(i).map_err(|error| ElementError { index: i, error });
    if len < PARALLEL_MIN_LEN {
        (0..len).map(one).collect()
    } else {
        (0..len).into_par_iter().with_min_len(PARALLEL_MIN_CHUNK).map(one).collect()
    }
}

/// Turns a failed element into a `ValueError`: `"bessel_j(n=3, x=nan): <library message>"`.
fn element_error(e: ElementError, describe: impl Fn(usize) -> String) -> PyErr {
    let msg = format!("{}: {}", describe(e.index), e.error);
    if e.error.is_time_limit() {
        return TimeLimitError::new_err(msg);
    }
    PyValueError::new_err(msg)
}

fn lib_error(e: Error) -> PyErr {
    if e.is_time_limit() {
        return TimeLimitError::new_err(e.to_string());
    }
    PyValueError::new_err(e.to_string())
}

pyo3::create_exception!(
    _maugis,
    TimeLimitError,
    PyValueError,
    "A certified call refused for time: its cost estimate, or its loops, passed the call's budget \
     (`budget=`, default 30 s). The input is fine; a larger budget or a lower precision may answer it."
);

/// Flat input slices; Python guarantees contiguity and equal lengths.
fn slice<'a, T: numpy::Element>(a: &'a PyReadonlyArray1<'_, T>, name: &str) -> PyResult<&'a [T]> {
    a.as_slice().map_err(|_| PyValueError::new_err(format!("internal: argument {name} is not contiguous")))
}

fn same_len(lens: &[usize]) -> PyResult<usize> {
    let n = lens.first().copied().unwrap_or(0);
    if lens.iter().any(|&l| l != n) {
        return Err(PyValueError::new_err("internal: arguments of different lengths after broadcasting"));
    }
    Ok(n)
}

/// `kmax` of a model family: a non-negative integer that fits `u32`.
fn order_u32(k: i64) -> maugis::Result<u32> {
    u32::try_from(k).map_err(|_| Error::IntegerOutOfRange { arg: "kmax", value: k, min: 0, max: u32::MAX as i64 })
}

/// Evaluates `value` (or `bounded`) over `len` elements with the GIL released
/// and returns one float64 array, or the `(value, err)` pair of arrays.
fn run_f64<'py, V, B, D>(py: Python<'py>, len: usize, want_bound: bool, value: V, bounded: B, describe: D) -> PyResult<Bound<'py, PyAny>>
where
    V: Fn(usize) -> maugis::Result<f64> + Sync + Send,
    B: Fn(usize) -> maugis::Result<Bounded> + Sync + Send,
    D: Fn(usize) -> String,
{
    if want_bound {
        let out = py.detach(|| map_elements(len, &bounded)).map_err(|e| element_error(e, &describe))?;
        let (v, err): (Vec<f64>, Vec<f64>) = out.into_iter().map(|b| (b.value, b.err)).unzip();
        let pair = PyTuple::new(py, [PyArray1::from_vec(py, v).into_any(), PyArray1::from_vec(py, err).into_any()])?;
        Ok(pair.into_any())
    } else {
        let out = py.detach(|| map_elements(len, &value)).map_err(|e| element_error(e, &describe))?;
        Ok(PyArray1::from_vec(py, out).into_any())
    }
}

/// One flat argument column of an f64 call: int64 for integer parameters, float64 for reals.
enum Column<'py> {
    Int(PyReadonlyArray1<'py, i64>),
    Real(PyReadonlyArray1<'py, f64>),
}

/// The parameters of a registry function as `[(name, "int" | "real")]`: Python
/// converts and broadcasts its arguments by them.
#[pyfunction]
fn signature(function: &str) -> PyResult<Vec<(&'static str, &'static str)>> {
    let f = registry::function(function).map_err(lib_error)?;
    Ok(f.params
        .iter()
        .map(|p| (p.name, if p.kind == ParamKind::Integer { "int" } else { "real" }))
        .collect())
}

/// The repeated group of a registry function ([`maugis::registry::Repeated`]) as
/// `(list name, names in one group, most groups)`, or `None`: Python passes the
/// groups' columns after the fixed parameters' (`lambda, abar, alpha_1, beta_1, ...`).
#[pyfunction]
fn repeated(function: &str) -> PyResult<Option<(&'static str, Vec<&'static str>, usize)>> {
    let f = registry::function(function).map_err(lib_error)?;
    Ok(f.repeated.map(|r| (r.list, r.names.to_vec(), r.max)))
}

/// The kind of argument `i` of `f`: a fixed parameter's, or real (a repeated group).
fn kind_at(f: &Function, i: usize) -> ParamKind {
    f.params.get(i).map_or(ParamKind::Real, |p| p.kind)
}

/// The name of argument `i` of `f`: a fixed parameter's, or `alpha_2` (the group's
/// name and its number, from 1).
fn name_at(f: &Function, i: usize) -> String {
    match (f.params.get(i), f.repeated) {
        (Some(p), _) => p.name.to_string(),
        (None, Some(r)) => {
            let k = i - f.params.len();
            format!("{}_{}", r.names[k % r.names.len()], k / r.names.len() + 1)
        }
        (None, None) => "?".to_string(),
    }
}

/// Checks the number of argument columns: the registry checks the rest (kinds, whole
/// groups, at most the most groups) with its typed errors.
fn check_columns(f: &Function, got: usize) -> PyResult<()> {
    let fixed = f.params.len();
    let fits = if f.repeated.is_some() { got >= fixed && got <= MAX_COLUMNS } else { got == fixed };
    if fits {
        Ok(())
    } else if let (Some(r), true) = (f.repeated, got > MAX_COLUMNS) {
        let count = (got - fixed) / r.names.len();
        Err(lib_error(Error::Profile(maugis::error::ProfileError::TooManyWaves { count, max: r.max })))
    } else {
        Err(lib_error(Error::Arity { function: f.name, expected: fixed, got }))
    }
}

/// A registry function ([`maugis::registry`]) over flat argument columns (one
/// per parameter, int64 for integers and float64 for reals, all of one length;
/// a repeated group's columns after the fixed ones): a float64 array, or with
/// `bounded` the `(value, err)` pair of arrays.
#[pyfunction]
fn eval_f64<'py>(py: Python<'py>, function: &str, columns: Vec<Bound<'py, PyAny>>, bounded: bool) -> PyResult<Bound<'py, PyAny>> {
    let f = registry::function(function).map_err(lib_error)?;
    check_columns(f, columns.len())?;
    let cols = columns
        .iter()
        .enumerate()
        .map(|(i, c)| {
            Ok(match kind_at(f, i) {
                ParamKind::Integer => Column::Int(c.extract()?),
                ParamKind::Real => Column::Real(c.extract()?),
            })
        })
        .collect::<PyResult<Vec<Column>>>()?;
    let names: Vec<String> = (0..cols.len()).map(|i| name_at(f, i)).collect();
    let slices = cols
        .iter()
        .zip(&names)
        .map(|(c, n)| {
            Ok(match c {
                Column::Int(a) => ColumnSlice::Int(slice(a, n)?),
                Column::Real(a) => ColumnSlice::Real(slice(a, n)?),
            })
        })
        .collect::<PyResult<Vec<ColumnSlice>>>()?;
    let len = same_len(&slices.iter().map(ColumnSlice::len).collect::<Vec<_>>())?;
    let describe = |i: usize| {
        let args: Vec<String> = names.iter().zip(&slices).map(|(n, c)| format!("{n}={}", show_arg(&c.at(i)))).collect();
        format!("{function}({})", args.join(", "))
    };
    run_f64(
        py,
        len,
        bounded,
        |i| f64_value(f, &slices, i),
        |i| {
            let mut buf = [Arg::Int(0); MAX_COLUMNS];
            f.eval_bounded(row(&slices, i, &mut buf))
        },
        describe,
    )
}

/// More parameters than any registry function has: the two fixed parameters of
/// `strip_ratio_waves` and two for each of up to `MAX_WAVES` waves.
const MAX_COLUMNS: usize = 2 + 2 * maugis::contact::profile::MAX_WAVES;

/// Row `i` of the columns, in `buf` (no allocation per element).
fn row<'b>(columns: &[ColumnSlice<'_>], i: usize, buf: &'b mut [Arg<f64>; MAX_COLUMNS]) -> &'b [Arg<f64>] {
    let n = columns.len().min(MAX_COLUMNS);
    for (slot, c) in buf.iter_mut().zip(columns) {
        *slot = c.at(i);
    }
    &buf[..n]
}

/// The f64 value of `f` at row `i` (functions whose f64 answer is a plain value).
fn f64_value(f: &Function, columns: &[ColumnSlice<'_>], i: usize) -> maugis::Result<f64> {
    let mut buf = [Arg::Int(0); MAX_COLUMNS];
    match f.eval_f64(row(columns, i, &mut buf))? {
        Answer::F64(v) => Ok(v),
        _ => Err(Error::NoBoundedPath { function: f.name }),
    }
}

/// A borrowed column.
enum ColumnSlice<'a> {
    Int(&'a [i64]),
    Real(&'a [f64]),
}

impl ColumnSlice<'_> {
    fn len(&self) -> usize {
        match self {
            ColumnSlice::Int(s) => s.len(),
            ColumnSlice::Real(s) => s.len(),
        }
    }

    fn at(&self, i: usize) -> Arg<f64> {
        match self {
            ColumnSlice::Int(s) => Arg::Int(s[i]),
            ColumnSlice::Real(s) => Arg::Real(s[i]),
        }
    }
}

fn show_arg(a: &Arg<f64>) -> String {
    match a {
        Arg::Int(v) => v.to_string(),
        Arg::Real(v) => format!("{v:?}"),
    }
}

/// A model family over `k = 0..=kmax` at one argument (`"hyp1f2"`: the
/// `1F2(1/2; k+1, k+3/2; z)` family; `"meijer_g_k"`: `G(k, y)`), as the
/// `(value, err)` pair of float64 arrays, with the GIL released.
#[pyfunction]
fn family_f64<'py>(py: Python<'py>, function: &str, kmax: i64, arg: f64) -> PyResult<Bound<'py, PyAny>> {
    let kmax = order_u32(kmax).map_err(lib_error)?;
    let family = match function {
        "hyp1f2" => hyp1f2_model_family_f64,
        "meijer_g_k" => meijer_g_k_family_f64,
        _ => return Err(PyValueError::new_err(format!("unknown family {function:?}"))),
    };
    let out = py.detach(|| family(kmax, arg)).map_err(lib_error)?;
    let (v, err): (Vec<f64>, Vec<f64>) = out.into_iter().map(|b| (b.value, b.err)).unzip();
    let pair = PyTuple::new(py, [PyArray1::from_vec(py, v).into_any(), PyArray1::from_vec(py, err).into_any()])?;
    Ok(pair.into_any())
}

// ---------------------------------------------------------------- arbitrary precision

/// One MP argument as Python sends it: exact `man * 2^exp`, or a decimal string.
/// Both become a [`Decimal`] (Arb's convention, as in `maugis eval`): the
/// certified ball contains the function at the number given, an exact binary
/// value or the decimal as typed.
#[derive(Clone, Debug)]
enum MpArg {
    Exact { man: String, exp: i64 },
    Decimal(String),
}

impl<'a, 'py> FromPyObject<'a, 'py> for MpArg {
    type Error = PyErr;

    fn extract(ob: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok((man, exp)) = ob.extract::<(String, i64)>() {
            return Ok(MpArg::Exact { man, exp });
        }
        Ok(MpArg::Decimal(ob.extract::<String>()?))
    }
}

impl MpArg {
    fn to_decimal(&self, what: &'static str) -> maugis::Result<Decimal> {
        match self {
            MpArg::Exact { man, exp } => {
                let bad = || Error::NotANumber { arg: what, text: self.to_string(), expected: "a number (its mantissa is not an integer)" };
                let m: Integer = man.parse().map_err(|_| bad())?;
                let e = i32::try_from(*exp).map_err(|_| Error::Overflow { what: format!("the exponent of {what}") })?;
                let q = if e >= 0 { Rational::from(m << e as u32) } else { Rational::from((m, Integer::from(1) << e.unsigned_abs())) };
                Ok(Decimal::from_rational(q))
            }
            MpArg::Decimal(s) => Decimal::parse(s).map_err(|e| match e {
                // unparseable text: say which argument; other errors (exponent or
                // length out of range) carry their own message
                Error::NotADecimal { .. } => Error::NotANumber {
                    arg: what,
                    text: format!("{s:?}"),
                    expected: "a number (expected a decimal such as 2.5, -0.125 or 3.8317e-2)",
                },
                other => other,
            }),
        }
    }

    fn to_float(&self, what: &'static str, prec: u32) -> maugis::Result<Float> {
        let v = Float::with_val(prec.max(64), self.to_decimal(what)?.as_rational());
        if !v.is_finite() {
            return Err(Error::NonFinite { what });
        }
        Ok(v)
    }

    fn to_i64(&self, what: &'static str) -> maugis::Result<i64> {
        let v = self.to_float(what, 64)?;
        v.to_integer()
            .filter(|_| v.is_integer())
            .and_then(|i| i.to_i64())
            .ok_or_else(|| Error::NotANumber { arg: what, text: self.to_string(), expected: "an integer" })
    }
}

impl std::fmt::Display for MpArg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MpArg::Exact { man, exp } if *exp == 0 => write!(f, "{man}"),
            MpArg::Exact { man, exp } => write!(f, "{man}*2^{exp}"),
            MpArg::Decimal(s) => write!(f, "{s:?}"),
        }
    }
}

/// One certified ball of the registry function `f` at the arguments `args`, at
/// `prec` bits (balls that contain the numbers given, or rounded inputs, as
/// [`maugis::registry::MpInputs`] says for `f`); answers that are not certified
/// balls (estimates) are refused.
fn mp_one(f: &Function, args: &[MpArg], prec: u32, budget: Budget) -> maugis::Result<Ball> {
    let values = args
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let name = f.params.get(i).map_or("a wave", |p| p.name);
            Ok(match kind_at(f, i) {
                ParamKind::Integer => Arg::Int(a.to_i64(name)?),
                ParamKind::Real => Arg::Real(a.to_decimal(name)?),
            })
        })
        .collect::<maugis::Result<Vec<_>>>()?;
    match f.eval_mp_with_budget(&values, prec, budget)? {
        Answer::Ball(b) => Ok(b),
        Answer::SeriesBall { mut value, trunc } => {
            value.add_error(&trunc);
            Ok(value)
        }
        _ => Err(Error::NoBoundedPath { function: f.name }),
    }
}

/// An exact binary float as `(mantissa as decimal text, exponent)`; zero is `("0", 0)`.
fn exact_pair(x: &Float) -> (String, i64) {
    match x.to_integer_exp() {
        Some((m, e)) => (m.to_string(), e as i64),
        None => ("0".to_string(), 0),
    }
}

/// A ball as Python receives it.
enum MpOut {
    /// `((mid_man, mid_exp), (rad_man, rad_exp))`, exact.
    Exact((String, i64), (String, i64)),
    /// `(mid, rad)` decimal strings; the decimal ball encloses the binary one.
    Decimal(String, String),
}

/// A ball's midpoint and radius as Python receives them (see [`MpOut`]).
fn ball_out(ball: &Ball, digits: Option<usize>) -> MpOut {
    match digits {
        None => MpOut::Exact(exact_pair(ball.mid()), exact_pair(&ball.rad())),
        Some(d) => {
            let (m, r) = ball.to_decimal(d);
            MpOut::Decimal(m, r)
        }
    }
}

impl<'py> IntoPyObject<'py> for MpOut {
    type Target = PyTuple;
    type Output = Bound<'py, PyTuple>;
    type Error = PyErr;

    fn into_pyobject(self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        match self {
            MpOut::Exact(m, r) => (m, r).into_pyobject(py),
            MpOut::Decimal(m, r) => (m, r).into_pyobject(py),
        }
    }
}

/// Certified balls of `function` over argument columns (one list per argument,
/// all of one length), at `prec` bits. `digits = None` returns exact binary
/// pairs, `Some(d)` decimal strings with `d` significant digits. `budget` is
/// each element's time budget in seconds ([`maugis::budget`]; `None`: the
/// default, 30 s); a refusal for time raises `TimeLimitError`.
#[pyfunction]
#[pyo3(signature = (function, columns, prec, digits=None, budget=None))]
fn eval_mp<'py>(
    py: Python<'py>,
    function: &str,
    columns: Vec<Vec<MpArg>>,
    prec: u32,
    digits: Option<usize>,
    budget: Option<f64>,
) -> PyResult<Bound<'py, PyList>> {
    let budget = budget.map_or(Ok(Budget::DEFAULT), Budget::from_secs_f64).map_err(lib_error)?;
    let f = registry::function(function).map_err(lib_error)?;
    check_columns(f, columns.len())?;
    let names: Vec<String> = (0..columns.len()).map(|i| name_at(f, i)).collect();
    maugis::error::check_prec(prec).map_err(lib_error)?;
    let len = same_len(&columns.iter().map(Vec::len).collect::<Vec<_>>())?;
    let row = |i: usize| columns.iter().map(|c| c[i].clone()).collect::<Vec<_>>();
    let out = py
        .detach(|| {
            // MP evaluations are expensive: parallel from two elements on.
            (0..len)
                .into_par_iter()
                .map(|i| {
                    let ball = mp_one(f, &row(i), prec, budget).map_err(|error| ElementError { index: i, error })?;
                    Ok(ball_out(&ball, digits))
                })
                .collect::<Result<Vec<MpOut>, ElementError>>()
        })
        .map_err(|e| {
            element_error(e, |i| {
                let args: Vec<String> = names.iter().zip(row(i)).map(|(n, a)| format!("{n}={a}")).collect();
                format!("{function}({}, prec={prec})", args.join(", "))
            })
        })?;
    let list = PyList::empty(py);
    for o in out {
        list.append(o)?;
    }
    Ok(list)
}

// ---------------------------------------------------------------- certified integrals

/// `int_a^b w(x) f(x) dx` for the expression `f` in x ([`maugis::quad::expr`]),
/// certified at `prec` bits ([`integrate_expr`]). `b = None` is `+inf`; `"inf"` and
/// `"-inf"` are infinite ends (the tail bound derived from the expression); the weight is `(x-a)^alpha (b-x)^beta log^log(x-a)`.
/// Returns a dict: `re` and `im` (`None` when it is a ball around 0 no wider than
/// `re`'s radius), each `(mid, rad)` as exact pairs or decimal strings like
/// [`eval_mp`], `evaluations`, `warning` (`None`, or why the goal was not met), and
/// `abs_tol` (`None`, or, as a decimal string, the absolute tolerance `2^-prec` times a
/// certified bound of `int |f|` that a ball containing 0 met: a zero integral).
/// `budget` is the integral's time budget in seconds ([`maugis::budget`]; `None`:
/// [`Budget::DEFAULT`]); past it the call raises `TimeLimitError`.
#[pyfunction]
#[pyo3(signature = (f, a, b, prec, alpha=None, beta=None, log=0, decay_rate=None, decay_power=None, decay_bound=None, digits=None, budget=None))]
#[allow(clippy::too_many_arguments)]
fn integrate_mp<'py>(
    py: Python<'py>,
    f: &str,
    a: MpArg,
    b: Option<MpArg>,
    prec: u32,
    alpha: Option<MpArg>,
    beta: Option<MpArg>,
    log: u32,
    decay_rate: Option<MpArg>,
    decay_power: Option<MpArg>,
    decay_bound: Option<MpArg>,
    digits: Option<usize>,
    budget: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let budget = budget.map_or(Ok(Budget::DEFAULT), Budget::from_secs_f64).map_err(lib_error)?;
    let expr = Expr::parse(f).map_err(lib_error)?;
    let opt = |v: &Option<MpArg>, what: &'static str| v.as_ref().map(|v| v.to_decimal(what)).transpose();
    let end = |v: &MpArg, what: &'static str| -> maugis::Result<End> {
        match v {
            MpArg::Decimal(s) if matches!(s.trim(), "inf" | "-inf") => End::parse(s),
            _ => v.to_decimal(what).map(End::Finite),
        }
    };
    let a = end(&a, "a").map_err(lib_error)?;
    let b = match &b {
        None => End::Infinity,
        Some(b) => end(b, "b").map_err(lib_error)?,
    };
    let weight = WeightSpec { alpha: opt(&alpha, "alpha").map_err(lib_error)?, beta: opt(&beta, "beta").map_err(lib_error)?, log };
    let bound = opt(&decay_bound, "decay_bound").map_err(lib_error)?;
    let decay = match (opt(&decay_rate, "decay_rate").map_err(lib_error)?, opt(&decay_power, "decay_power").map_err(lib_error)?, bound) {
        (None, None, None) => None,
        (Some(rate), None, Some(bound)) => Some(DecaySpec::Exponential { rate, bound }),
        (None, Some(power), Some(bound)) => Some(DecaySpec::Algebraic { power, bound }),
        _ => {
            return Err(PyValueError::new_err(
                "declare a decay with decay_bound and one of decay_rate (exponential) and decay_power (algebraic)",
            ))
        }
    };
    let r = py
        .detach(|| budget.run(|| integrate_range(&expr, &a, &b, Some(&weight), decay.as_ref(), prec, &Options::new())))
        .map_err(lib_error)?;
    let out = PyDict::new(py);
    out.set_item("re", ball_out(r.value.re(), digits))?;
    out.set_item("im", significant_imaginary(&r).map(|im| ball_out(im, digits)))?;
    out.set_item("evaluations", r.evaluations)?;
    out.set_item("warning", shortfall(&r))?;
    out.set_item("abs_tol", abs_tol_text(&r))?;
    Ok(out)
}

// ---------------------------------------------------------------- the model
//
// The model's results cross as JSON text of the library's own serde schema
// (`maugis::contact::summary`, the object `maugis curve --format json` prints);
// Python turns its record lists into columns of NumPy arrays. The bindings thus
// follow the schema as it grows, and the tests compare with the CLI's output.

fn params(lam: f64, alpha: f64, beta: f64) -> PyResult<Params> {
    Params::new(lam, alpha, beta).map_err(lib_error)
}

/// The profile of `waves` (`(amplitude, wavelength)` pairs, normalised), checked by the
/// library (an error names the wave and the field); `None`: the one wave `(alpha, beta)`.
fn profile_of(alpha: f64, beta: f64, waves: Option<Vec<(f64, f64)>>) -> PyResult<WavyProfile> {
    match waves {
        None => {
            // the one-wave checks and messages of Params::new
            Params::new(1.0, alpha, beta).map_err(lib_error)?;
            WavyProfile::one_wave(alpha, beta).map_err(lib_error)
        }
        Some(w) => WavyProfile::from_pairs(&w).map_err(|e| PyValueError::new_err(format!("waves: {e}"))),
    }
}

fn to_json<T: serde::Serialize>(value: &T) -> PyResult<String> {
    serde_json::to_string(value).map_err(|e| PyValueError::new_err(format!("internal: could not format JSON: {e}")))
}

/// The run summary of `maugis curve --format json` for the given Maugis
/// parameters (in this order; the first is the M-DMT limit's lambda), as JSON text.
/// `waves` (`(amplitude, wavelength)` pairs) replaces `(alpha, beta)` by a profile of
/// many waves.
#[pyfunction]
#[pyo3(signature = (lams, alpha, beta, amax, points, datum, waves=None))]
#[allow(clippy::too_many_arguments)]
fn curve_summary_json(
    py: Python<'_>,
    lams: Vec<f64>,
    alpha: f64,
    beta: f64,
    amax: f64,
    points: usize,
    datum: f64,
    waves: Option<Vec<(f64, f64)>>,
) -> PyResult<String> {
    let opts = CurveOptions { amax, points, datum };
    let one_wave = waves.is_none();
    let profile = profile_of(alpha, beta, waves)?;
    let curves = py
        .detach(|| if one_wave { load_area_curves(&lams, alpha, beta, opts, || ()) } else { load_area_curves_profile(&lams, &profile, opts, || ()) })
        .map_err(|e| match e.at {
            At::Curve { lambda } => PyValueError::new_err(format!("lambda = {lambda:?}: {}", e.error)),
            _ => lib_error(e.error),
        })?;
    let summary = RunSummary::for_profile(&profile, opts, &curves, |_| None);
    to_json(&summary)
}

/// A `maugis sweep` over the grid given as JSON text of the library's
/// `SweepGrid`; returns the JSON text of the `Sweep`.
#[pyfunction]
fn sweep_json(py: Python<'_>, grid: &str) -> PyResult<String> {
    let grid: SweepGrid = serde_json::from_str(grid).map_err(|e| PyValueError::new_err(format!("sweep grid: {e}")))?;
    let out = py.detach(|| run_sweep(grid, None, || ())).map_err(lib_error)?;
    to_json(&out)
}

/// Solved states over flat `(lam, alpha, beta, abar)` arrays: JSON text of the
/// list of the library's `CurvePoint`s.
#[pyfunction]
fn states_json(
    py: Python<'_>,
    lam: PyReadonlyArray1<'_, f64>,
    alpha: PyReadonlyArray1<'_, f64>,
    beta: PyReadonlyArray1<'_, f64>,
    abar: PyReadonlyArray1<'_, f64>,
) -> PyResult<String> {
    let (l, al, be, ab) = (slice(&lam, "lam")?, slice(&alpha, "alpha")?, slice(&beta, "beta")?, slice(&abar, "abar")?);
    let len = same_len(&[l.len(), al.len(), be.len(), ab.len()])?;
    // Each state is a root solve plus two extremum searches: parallel from two on.
    let pts = py
        .detach(|| {
            (0..len)
                .into_par_iter()
                .map(|i| Params::new(l[i], al[i], be[i]).and_then(|p| curve::state(p, ab[i])).map_err(|error| ElementError { index: i, error }))
                .collect::<Result<Vec<_>, _>>()
        })
        .map_err(|e| element_error(e, |i| format!("state(lam={:?}, alpha={:?}, beta={:?}, abar={:?})", l[i], al[i], be[i], ab[i])))?;
    to_json(&pts)
}

/// Solved states of the profile `waves` (`(amplitude, wavelength)` pairs, normalised)
/// over flat `(lam, abar)` arrays: JSON text of the list of the library's `CurvePoint`s,
/// as [`states_json`] (a bad wave is an error naming the wave and the field).
#[pyfunction]
fn states_waves_json(py: Python<'_>, lam: PyReadonlyArray1<'_, f64>, abar: PyReadonlyArray1<'_, f64>, waves: Vec<(f64, f64)>) -> PyResult<String> {
    let (l, ab) = (slice(&lam, "lam")?, slice(&abar, "abar")?);
    let len = same_len(&[l.len(), ab.len()])?;
    let profile = WavyProfile::from_pairs(&waves).map_err(|e| PyValueError::new_err(format!("waves: {e}")))?;
    let pts = py
        .detach(|| {
            (0..len)
                .into_par_iter()
                .map(|i| Params::with_profile(l[i], profile).and_then(|p| curve::state(p, ab[i])).map_err(|error| ElementError { index: i, error }))
                .collect::<Result<Vec<_>, _>>()
        })
        .map_err(|e| element_error(e, |i| format!("state(lam={:?}, abar={:?}, waves={} waves)", l[i], ab[i], waves.len())))?;
    to_json(&pts)
}

/// One state and its traction, displacement, gap and surface depth at `x`, or
/// (`x` None) on the library's default grid of `points` positions
/// ([`sample_state`]): the fields of `maugis profile --format json`, samples as columns.
#[pyfunction]
#[pyo3(signature = (lam, alpha, beta, abar, x, points, waves=None))]
#[allow(clippy::too_many_arguments)]
fn profile_dict<'py>(
    py: Python<'py>,
    lam: f64,
    alpha: f64,
    beta: f64,
    abar: f64,
    x: Option<PyReadonlyArray1<'py, f64>>,
    points: usize,
    waves: Option<Vec<(f64, f64)>>,
) -> PyResult<Bound<'py, PyDict>> {
    let many = waves.is_some();
    let p = if many { Params::with_profile(lam, profile_of(alpha, beta, waves)?).map_err(lib_error)? } else { params(lam, alpha, beta)? };
    let xs = x.as_ref().map(|x| slice(x, "x")).transpose()?;
    let state = py
        .detach(|| match xs {
            Some(xs) => sample_state_at(p, abar, xs),
            None => sample_state(p, abar, None, points),
        })
        .map_err(|e| match e.at {
        At::Sample { xbar } => PyValueError::new_err(format!("profile at xbar={xbar:?}: {}", e.error)),
        _ => lib_error(e.error),
    })?;
    let (m, load, v) = (state.m, state.load, state.validity);
    let column = |f: fn(&ProfileSample) -> f64| state.samples.iter().map(f).collect::<Vec<f64>>();
    let [pbar, ubar, gbar, hbar] = [column(|s| s.pbar), column(|s| s.ubar), column(|s| s.gbar), column(|s| s.hbar)];
    let out = PyDict::new(py);
    for (key, value) in [("lambda", lam), ("alpha", p.alpha()), ("beta", p.beta()), ("abar", abar), ("m", m), ("load", load)] {
        out.set_item(key, value)?;
    }
    if many {
        let pairs: Vec<(f64, f64)> = p.profile().waves().iter().map(|w| (w.alpha(), w.beta())).collect();
        out.set_item("waves", pairs)?;
    }
    out.set_item("valid", v.valid)?;
    out.set_item("min_strip_gap", v.min_strip_gap)?;
    out.set_item("min_strip_gap_at", v.min_strip_gap_at)?;
    out.set_item("max_traction", v.max_traction)?;
    out.set_item("max_traction_at", v.max_traction_at)?;
    let samples = PyDict::new(py);
    samples.set_item("xbar", PyArray1::from_vec(py, column(|s| s.xbar)))?;
    for (key, col) in [("pbar", pbar), ("ubar", ubar), ("gbar", gbar), ("hbar", hbar)] {
        samples.set_item(key, PyArray1::from_vec(py, col))?;
    }
    out.set_item("samples", samples)?;
    Ok(out)
}

// ---------------------------------------------------------------- timing aid

/// Seconds taken by a plain serial Rust loop of `function` over the given flat
/// arrays (no NumPy, no GIL, no rayon): the baseline of
/// `python/benchmarks/timing.py`. Not part of the public API.
#[pyfunction]
fn _native_loop_seconds(py: Python<'_>, function: &str, n: PyReadonlyArray1<'_, i64>, x: PyReadonlyArray1<'_, f64>) -> PyResult<f64> {
    let f = registry::function(function).map_err(lib_error)?;
    let columns = [ColumnSlice::Int(slice(&n, "n")?), ColumnSlice::Real(slice(&x, "x")?)];
    let len = same_len(&[columns[0].len(), columns[1].len()])?;
    py.detach(|| {
        let t = std::time::Instant::now();
        let mut acc = 0.0;
        for i in 0..len {
            acc += f64_value(f, &columns, i)?;
        }
        std::hint::black_box(acc);
        Ok::<f64, Error>(t.elapsed().as_secs_f64())
    })
    .map_err(lib_error)
}

/// The compiled module.
/// How many times each f64 route fell back to the certified MP path since the
/// process started (`maugis::special::fallback_counts`), as a dict of ints.
#[pyfunction]
fn fallback_counts(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let c = maugis::special::fallback_counts();
    let out = PyDict::new(py);
    for (key, n) in [
        ("bessel_j", c.bessel_j),
        ("hyp1f2", c.hyp1f2),
        ("hyp2f1", c.hyp2f1),
        ("meijer_g_k", c.meijer_g_k),
        ("wave_bounded", c.wave_bounded),
        ("wave_bounded_mp_contacts", c.wave_bounded_mp_contacts),
    ] {
        out.set_item(key, n)?;
    }
    Ok(out)
}

#[pymodule]
fn _maugis(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(signature, m)?)?;
    m.add_function(wrap_pyfunction!(repeated, m)?)?;
    m.add_function(wrap_pyfunction!(eval_f64, m)?)?;
    m.add_function(wrap_pyfunction!(family_f64, m)?)?;
    m.add_function(wrap_pyfunction!(eval_mp, m)?)?;
    m.add("TimeLimitError", m.py().get_type::<TimeLimitError>())?;
    m.add_function(wrap_pyfunction!(integrate_mp, m)?)?;
    m.add_function(wrap_pyfunction!(curve_summary_json, m)?)?;
    m.add_function(wrap_pyfunction!(states_json, m)?)?;
    m.add_function(wrap_pyfunction!(states_waves_json, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_json, m)?)?;
    m.add_function(wrap_pyfunction!(profile_dict, m)?)?;
    m.add_function(wrap_pyfunction!(fallback_counts, m)?)?;
    simulate::register(m)?;
    m.add_function(wrap_pyfunction!(_native_loop_seconds, m)?)?;
    m.add("PARALLEL_MIN_LEN", PARALLEL_MIN_LEN)?;
    m.add("MAX_PREC", maugis::MAX_PREC)?;
    m.add("DEFAULT_DATUM", curve::DEFAULT_DATUM)?;
    m.add("FIG4C_ALPHA", maugis::contact::paper::FIG_4C.alpha)?;
    m.add("FIG4C_BETA", maugis::contact::paper::FIG_4C.beta)?;
    Ok(())
}
