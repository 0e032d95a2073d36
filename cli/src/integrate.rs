//! `maugis integrate 'EXPR' A B`: a certified integral of an expression in x.
//!
//! ```text
//! $ maugis integrate 'sqrt(x)' 1 4 --prec 128
//! mid: 4.66666666666666666666666666666666666666667
//! rad: 2.0e-40
//! ```
//!
//! The result is a ball (`mid` +/- `rad`) that contains the integral, computed by
//! the certified integrator ([`maugis::quad::certified`]) on the expression
//! parsed by [`maugis::quad::expr`]; `im_mid` and `im_rad` follow when the
//! imaginary part may be larger than `rad` (an integrand that is complex
//! somewhere, such as `sqrt(x)` for `x < 0`), and `abs_tol` when the ball contains 0
//! and met the goal by the default absolute tolerance, `2^-P` times a bound of `int |f|`
//! (a zero integral, `sin(x)` on `[-1, 1]`; docs/quadrature.md). The endpoints and the exponents are decimals
//! taken as balls that contain them; `A` may be `-inf` and `B` `inf` (the tail bound
//! derived from the expression, oscillatory tails recognised, or a decay declared with
//! `--decay-*`). `--alpha AL --beta BE --log K` multiply the integrand by
//! `(x-A)^AL (B-x)^BE log^K(x-A)`, certified without truncation. `--budget-ms MS`
//! bounds the time (default 30 s, [`maugis::budget`]): past it the command stops with
//! code 2, naming the evaluations reached.
//!
//! Everything typed is checked while the command line is parsed, so a bad
//! expression or number exits with code 2 and one line on stderr before any
//! work. An integral that cannot be done (a pole, an undeclared endpoint
//! singularity, an infinite range without a tail bound, the budget spent) also exits with code 2, and nothing
//! is printed on stdout. A result that stopped at a limit before its goal is
//! printed (it still encloses the integral), with a warning on stderr.

use clap::Args;

use maugis::ball::Decimal;
use maugis::quad::certified::{Integral, Options};
use maugis::quad::expr::{abs_tol_text, integrate_range, shortfall, significant_imaginary, DecaySpec, End, Expr, WeightSpec};
use maugis::{Budget, MAX_PREC};

use crate::output::print_stdout;

/// Flags of `maugis integrate`.
#[derive(Args, Debug)]
pub struct IntegrateArgs {
    /// The integrand in x: + - * / ^, sqrt exp log sin cos tan sinh cosh tanh sech atan,
    /// besselj(n, x), pi and decimals, e.g. 'exp(-x^2)' or 'x^(-1/2)*cos(x)'.
    #[arg(value_name = "EXPR", value_parser = expression, allow_hyphen_values = true)]
    pub f: Expr,
    /// Lower end, a decimal or -inf.
    #[arg(value_name = "A", value_parser = end, allow_hyphen_values = true)]
    pub a: End,
    /// Upper end, a decimal or inf (the tail bound is derived from the expression, or
    /// declared with --decay-*).
    #[arg(value_name = "B", value_parser = end, allow_hyphen_values = true)]
    pub b: End,
    /// Precision in bits: the goal is rad <= 2^-P |mid|.
    #[arg(long, value_name = "P", default_value = "53", value_parser = prec)]
    pub prec: u32,
    /// Endpoint weight (x-A)^AL, AL > -1.
    #[arg(long, value_name = "AL", value_parser = decimal, allow_negative_numbers = true)]
    pub alpha: Option<Decimal>,
    /// Endpoint weight (B-x)^BE, BE > -1 (B finite).
    #[arg(long, value_name = "BE", value_parser = decimal, allow_negative_numbers = true)]
    pub beta: Option<Decimal>,
    /// Endpoint weight log^K(x-A).
    #[arg(long, value_name = "K", default_value = "0")]
    pub log: u32,
    /// For B = inf: |f(x)| <= M e^(-C x) for x >= A (with --decay-bound M).
    #[arg(long, value_name = "C", value_parser = decimal, requires = "decay_bound", conflicts_with = "decay_power")]
    pub decay_rate: Option<Decimal>,
    /// For B = inf: |f(x)| <= M x^(-P) for x >= A > 0, P > 1 (with --decay-bound M).
    #[arg(long, value_name = "P", value_parser = decimal, requires = "decay_bound")]
    pub decay_power: Option<Decimal>,
    /// The constant M of the declared decay.
    #[arg(long, value_name = "M", value_parser = decimal)]
    pub decay_bound: Option<Decimal>,
    /// Time budget in milliseconds (default 30000, the library's `Budget::DEFAULT`):
    /// past it the integral stops at once with a refusal that names what it reached.
    #[arg(long, value_name = "MS", value_parser = budget_ms, allow_negative_numbers = true)]
    pub budget_ms: Option<Budget>,
}

fn expression(s: &str) -> Result<Expr, String> {
    Expr::parse(s).map_err(|e| e.to_string())
}

fn decimal(s: &str) -> Result<Decimal, String> {
    Decimal::parse(s).map_err(|e| e.to_string())
}

fn end(s: &str) -> Result<End, String> {
    End::parse(s).map_err(|e| e.to_string())
}

fn budget_ms(s: &str) -> Result<Budget, String> {
    let ms = s.trim().parse::<u64>().map_err(|_| "use a whole number of milliseconds, at least 1".to_string())?;
    Budget::from_millis(ms).map_err(|e| e.to_string())
}

fn prec(s: &str) -> Result<u32, String> {
    match s.trim().parse::<u32>() {
        Ok(p) if (2..=MAX_PREC).contains(&p) => Ok(p),
        _ => Err(format!("use a whole number of bits in 2 ..= {MAX_PREC}")),
    }
}

/// Decimal digits printed for a ball at `prec` bits: `ceil(prec log10 2) + 3`.
pub fn digits_for(prec: u32) -> usize {
    (prec as f64 * std::f64::consts::LOG10_2).ceil() as usize + 3
}

/// The printed text of an integral's ball at `prec` bits: `mid` and `rad` of the real
/// part, `im_mid` and `im_rad` when the imaginary part may exceed `rad`
/// ([`significant_imaginary`]), `abs_tol` when the ball contains 0 and met the goal by
/// the absolute tolerance ([`abs_tol_text`]).
pub struct BallText {
    pub mid: String,
    pub rad: String,
    /// `im_mid`, `im_rad`.
    pub im: Option<(String, String)>,
    pub abs_tol: Option<String>,
}

impl BallText {
    /// The text of `r` at `prec` bits.
    pub fn of(r: &Integral, prec: u32) -> BallText {
        let digits = digits_for(prec);
        let (mid, rad) = r.value.re().to_decimal(digits);
        BallText { mid, rad, im: significant_imaginary(r).map(|im| im.to_decimal(digits)), abs_tol: abs_tol_text(r) }
    }

    /// The fields in the order `maugis integrate` prints them: `mid`, `rad`, then
    /// `im_mid`, `im_rad` and `abs_tol` where present.
    pub fn fields(self) -> Vec<(&'static str, String)> {
        let mut fields = vec![("mid", self.mid), ("rad", self.rad)];
        if let Some((im_mid, im_rad)) = self.im {
            fields.extend([("im_mid", im_mid), ("im_rad", im_rad)]);
        }
        fields.extend(self.abs_tol.map(|t| ("abs_tol", t)));
        fields
    }
}

/// The declared decay, from the flags.
fn decay(args: &IntegrateArgs) -> Option<DecaySpec> {
    let bound = args.decay_bound.clone()?;
    match (&args.decay_rate, &args.decay_power) {
        (Some(rate), _) => Some(DecaySpec::Exponential { rate: rate.clone(), bound }),
        (None, Some(power)) => Some(DecaySpec::Algebraic { power: power.clone(), bound }),
        (None, None) => None,
    }
}

/// Runs `maugis integrate`.
pub fn run(args: IntegrateArgs) -> Result<(), String> {
    if args.decay_bound.is_some() && args.decay_rate.is_none() && args.decay_power.is_none() {
        return Err("--decay-bound needs --decay-rate or --decay-power".into());
    }
    let weight = WeightSpec { alpha: args.alpha.clone(), beta: args.beta.clone(), log: args.log };
    let decay = decay(&args);
    let budget = args.budget_ms.unwrap_or(Budget::DEFAULT);
    let r = budget
        .run(|| integrate_range(&args.f, &args.a, &args.b, Some(&weight), decay.as_ref(), args.prec, &Options::new()))
        .map_err(|e| e.to_string())?;
    let text: String = BallText::of(&r, args.prec).fields().iter().map(|(k, v)| format!("{k}: {v}\n")).collect();
    print_stdout(&text)?;
    if let Some(note) = shortfall(&r) {
        eprintln!("maugis: warning: {note}");
    }
    Ok(())
}
