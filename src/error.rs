//! The crate's error type.
//!
//! Every public function that can fail on user input returns [`Result`]. No
//! public function panics on any input: out-of-domain arguments, non-finite
//! numbers and precision requests past the cap all come back as an [`Error`]
//! whose message says what to change.

use std::fmt;

/// Everything that can go wrong in `maugis`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// An argument is NaN or infinite.
    NonFinite {
        /// Which argument.
        what: &'static str,
    },
    /// An argument lies outside the function's documented domain. The library no
    /// longer builds this variant (every domain error is one of the structured
    /// variants below, with fields); it stays so that code matching on it compiles.
    Domain {
        /// What is wrong and what is allowed.
        what: String,
    },
    /// The requested precision is below 2 bits or above [`crate::MAX_PREC`].
    Precision {
        /// The precision that was asked for.
        requested: u64,
    },
    /// The Ziv loop reached [`crate::MAX_WORKING_PREC`] without certifying the
    /// requested accuracy (extreme cancellation or a value too close to zero).
    PrecisionExhausted {
        /// The function.
        function: &'static str,
        /// The working precision reached.
        working_prec: u32,
    },
    /// A series needed more terms than its cap.
    NoConvergence {
        /// The function.
        function: &'static str,
        /// Terms summed.
        terms: u64,
    },
    /// A divisor ball contained zero.
    DivisionByZero,
    /// A value overflowed the exponent range.
    Overflow {
        /// Where.
        what: String,
    },
    /// The value itself lies outside MPFR's exponent range (magnitudes from
    /// `2^-(2^30)` to `2^(2^30)`): no precision can represent it. Factors past
    /// that range whose product is inside it are answered
    /// ([`crate::ball::Scaled`]); this is the product's own size.
    ValueOutOfRange {
        /// `log2 |value|`, an estimate or a proven bound, as a decimal
        /// `mantissa * 10^exp10`: the logarithm can itself pass f64's range
        /// (`(1 - 4.26e-273)^(9.5e14123)` is about `2^(-5.8e13851)`).
        log2_magnitude: Log2Magnitude,
    },
    /// An integrand expression that does not parse ([`crate::quad::expr`]).
    Expression(crate::quad::expr::error::ExprError),
    /// A certified integral that cannot be done as asked ([`crate::quad::certified`]).
    Integration(IntegrationError),
    /// A real argument outside its allowed interval (NaN included).
    OutOfRange {
        /// The argument.
        arg: &'static str,
        /// The value given.
        value: f64,
        /// The values allowed.
        allowed: Interval,
    },
    /// The adhesive strip's end was not found within the range searched.
    NoStripEnd {
        /// Which model (e.g. `"Eq. 15b"`, `"M-DMT, E.43b"`).
        model: &'static str,
        /// The largest strip width `c - a` (or `c`) searched.
        limit: f64,
    },
    /// A result of the model that is not a finite f64 (the parameters are too
    /// extreme for f64 arithmetic).
    NotRepresentable {
        /// The quantity (`"load"`, `"approach"`).
        quantity: &'static str,
        /// The contact half-width `abar` at which it arose.
        abar: f64,
    },
    /// An f64 routine whose result is not a finite f64 at these arguments
    /// (extreme scales); the MP path answers there.
    NonFiniteResult {
        /// The function.
        function: &'static str,
    },
    /// A function evaluated at one of its poles.
    Pole {
        /// The function.
        function: &'static str,
        /// The pole (approximate).
        at: f64,
    },
    /// A named argument given as text (a decimal, or a mantissa of a mantissa and
    /// binary exponent pair) that is not a number of the kind the parameter takes.
    NotANumber {
        /// The argument.
        arg: &'static str,
        /// The text given.
        text: String,
        /// What the parameter takes (for example "a decimal such as 2.5, -0.125 or 3.8317e-2").
        expected: &'static str,
    },
    /// Text that is not a plain decimal number (`[+-]digits[.digits][e[+-]digits]`).
    NotADecimal {
        /// The text given.
        text: String,
    },
    /// A decimal with more than `max_digits` digits or an exponent beyond
    /// `±max_exponent` (the limits of `ball::Decimal`).
    DecimalTooLarge {
        /// The text given (its first 24 characters).
        text: String,
        /// The most digits accepted.
        max_digits: usize,
        /// The largest |decimal exponent| accepted.
        max_exponent: i64,
    },
    /// A regime-map grid or shard that cannot be run or merged ([`crate::contact::sweep`]).
    Sweep(SweepError),
    /// A profile that cannot be built: a bad wave, too many waves, a bad harmonics
    /// table ([`crate::contact::profile`]).
    Profile(ProfileError),
    /// A ball argument that reaches outside its allowed interval: the function is
    /// not defined (or not supported) over the whole ball. A decimal input whose
    /// ball straddles an edge is retried tighter by
    /// [`crate::ball::eval_at_decimals`].
    BallOutOfRange {
        /// The argument.
        arg: &'static str,
        /// The ball's lower end (rounded down to f64).
        lower: f64,
        /// The ball's upper end (rounded up to f64).
        upper: f64,
        /// The values allowed.
        allowed: Interval,
    },
    /// A function name that [`crate::registry`] does not know.
    UnknownFunction {
        /// The name given.
        name: String,
        /// The names it knows.
        known: Vec<&'static str>,
    },
    /// A call through [`crate::registry`] with the wrong number of arguments.
    Arity {
        /// The function.
        function: &'static str,
        /// How many it takes.
        expected: usize,
        /// How many were given.
        got: usize,
    },
    /// A call through [`crate::registry`] of a function that takes a group of
    /// parameters any number of times (the waves of a profile, `alpha_j, beta_j`)
    /// whose last group is incomplete.
    IncompleteGroup {
        /// The function.
        function: &'static str,
        /// What one group is, e.g. `"wave"`.
        group: &'static str,
        /// The names in one group, e.g. `["alpha", "beta"]`.
        names: &'static [&'static str],
        /// How many arguments come before the groups.
        fixed: usize,
        /// How many were given.
        got: usize,
    },
    /// An integer given where a real is wanted, or the reverse.
    ArgumentKind {
        /// The function.
        function: &'static str,
        /// The parameter.
        arg: &'static str,
        /// What it takes.
        expected: ParamKind,
    },
    /// An integer argument outside `min ..= max`.
    IntegerOutOfRange {
        /// The parameter.
        arg: &'static str,
        /// The value given.
        value: i64,
        /// The smallest allowed.
        min: i64,
        /// The largest allowed.
        max: i64,
    },
    /// The function has no f64 path with a proven bound (an estimating rule, a truncated series).
    NoBoundedPath {
        /// The function.
        function: &'static str,
    },
    /// An internal invariant failed. This is a bug; please report it.
    Internal {
        /// What failed.
        what: String,
    },
    /// An internal invariant failed, with the numbers that show how ([`Invariant`]).
    /// This is a bug; please report it.
    Invariant(Invariant),
    /// A lower (denominator) parameter of a hypergeometric function at a
    /// non-positive integer that the series reaches (a pole), or a parameter ball
    /// that contains one.
    ParameterPole {
        /// The function (`"2F1"`, `"pFq"`).
        function: &'static str,
        /// The parameter (`"c"`, `"b1"`, ...).
        arg: &'static str,
        /// The non-positive integer.
        pole: f64,
        /// The parameter's lower end (equal to `upper` for a point).
        lower: f64,
        /// The parameter's upper end.
        upper: f64,
    },
    /// The function diverges at these arguments (or may, somewhere in the input balls).
    Divergent {
        /// The function and where (`"2F1(a, b; c; 1)"`).
        function: &'static str,
        /// The condition convergence needs (`"c - a - b > 0"`).
        needs: &'static str,
        /// The value that breaks it (an end of its ball, for ball inputs).
        value: f64,
    },
    /// A ball input too wide for the method's bound.
    BallTooWide {
        /// The argument.
        arg: &'static str,
        /// The ball's lower end (rounded down to f64).
        lower: f64,
        /// The ball's upper end (rounded up to f64).
        upper: f64,
        /// What the ball must satisfy.
        needs: &'static str,
    },
    /// An interval too narrow for the quadrature nodes at this working precision
    /// (its midpoint rounds onto an endpoint).
    IntervalTooNarrow {
        /// The working precision of the nodes.
        prec: u32,
    },
    /// The wave displacement asked inside the contact: it is defined for `x >= a`.
    InsideContact {
        /// The point given (rounded to f64).
        x: f64,
        /// The contact half-width (rounded to f64).
        a: f64,
    },
    /// Input balls over which `x - a` reaches below zero: inside the contact
    /// (`upper < 0`), or the contact edge `x = a` within the balls, where `u_w` is
    /// defined on one side only and `du_w/dx` is one-sided. Give `x = a` exactly,
    /// or balls that keep `x - a > 0`.
    ContactEdgeInBall {
        /// The function.
        function: &'static str,
        /// The lower end of `x - a` over the balls (rounded down to f64).
        lower: f64,
        /// The upper end of `x - a` over the balls (rounded up to f64).
        upper: f64,
    },
    /// A route whose precision is capped below [`crate::MAX_PREC`] (a double
    /// integral, whose cost grows too fast beyond the cap).
    RoutePrecision {
        /// The route.
        route: &'static str,
        /// The precision asked for.
        requested: u32,
        /// The largest precision the route takes.
        max: u32,
    },
    /// A scale of the material (`l_h`, `l_v`, the load or stress scale) that is not
    /// a finite positive f64.
    ScaleNotRepresentable {
        /// The scale.
        scale: &'static str,
        /// `E*` in Pa.
        e_star: f64,
        /// `R` in m.
        radius: f64,
        /// The work of adhesion in J/m^2.
        dgamma: f64,
    },
    /// An evaluation whose cheapest method would run past the time limit.
    TooExpensive {
        /// The function and arguments (`"J_n(x)"`).
        function: &'static str,
        /// The estimated run time in seconds.
        seconds: f64,
        /// The limit in seconds.
        limit_seconds: f64,
    },
    /// A loop whose length no cost model bounds in advance (a Ziv loop, the
    /// retries at tighter input balls, a quadrature's nodes) stopped at the
    /// call's time budget ([`crate::budget`]): the time spent plus the next
    /// iteration's estimate passed it.
    BudgetSpent {
        /// The function or loop.
        function: &'static str,
        /// Seconds spent when it stopped.
        elapsed_seconds: f64,
        /// Estimated seconds of the next iteration (0 when the budget was already spent).
        next_seconds: f64,
        /// The budget in seconds.
        budget_seconds: f64,
        /// How far the loop got.
        reached: Reached,
    },
    /// A root of the model (the strip ratio of Eq. 15b) that the certified
    /// bracketing could not separate: the residual's balls stay too wide around it.
    RootNotCertified {
        /// The quantity.
        quantity: &'static str,
        /// The f64 root it was searched around.
        near: f64,
        /// Whether the inputs were balls (then tighter inputs may separate it).
        input_balls: bool,
    },
    /// Parameters at a degenerate position the method does not cover.
    Degenerate {
        /// The function or method.
        function: &'static str,
        /// What the parameters must satisfy.
        needs: &'static str,
    },
    /// An output slice whose length differs from the input slice's.
    LengthMismatch {
        /// How many inputs.
        inputs: usize,
        /// Room for how many results.
        outputs: usize,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NonFinite { what } => write!(f, "{what} must be a finite number (got NaN or infinity)"),
            Error::Domain { what } => write!(f, "argument out of domain: {what}"),
            Error::NotANumber { arg, text, expected } => write!(f, "{arg} = {text} is not {expected}"),
            Error::Precision { requested } => write!(
                f,
                "precision {requested} bits is out of range: use 2 ..= {} bits",
                crate::MAX_PREC
            ),
            Error::PrecisionExhausted { function, working_prec } => write!(
                f,
                "{function}: could not certify the requested accuracy below the working-precision cap \
                 ({working_prec} bits); ask for fewer bits or move the argument away from the zero/singularity"
            ),
            Error::NoConvergence { function, terms } => {
                write!(f, "{function}: series did not converge within {terms} terms")
            }
            Error::DivisionByZero => write!(f, "division by a ball containing zero"),
            Error::Overflow { what } => write!(f, "overflow in {what}: the result exceeds the exponent range"),
            Error::ValueOutOfRange { log2_magnitude } => write!(
                f,
                "the value is {log2_magnitude}, outside the exponent range 2^-(2^30) .. 2^(2^30): no precision can represent it"
            ),
            Error::Expression(e) => write!(f, "{e}"),
            Error::Integration(e) => write!(f, "{e}"),
            Error::Sweep(e) => write!(f, "{e}"),
            Error::Profile(e) => write!(f, "{e}"),
            Error::NotADecimal { text } => {
                write!(f, "{text:?} is not a decimal number (expected e.g. 2.5, -0.125, 3.8317e-2)")
            }
            Error::DecimalTooLarge { text, max_digits, max_exponent } => write!(
                f,
                "the decimal {text:?} is too large: at most {max_digits} digits and exponents up to ±{max_exponent} are accepted"
            ),
            Error::Pole { function, at } => write!(f, "{function} at its pole {at}"),
            Error::NonFiniteResult { function } => write!(
                f,
                "{function}: the f64 result is not finite at these arguments (extreme scales); use the MP path"
            ),
            Error::NotRepresentable { quantity, abar } => write!(
                f,
                "the {quantity} at abar = {abar:e} is not a finite f64: the parameters are too extreme for the f64 model (use the MP path)"
            ),
            Error::NoStripEnd { model, limit } => {
                write!(f, "no end of the adhesive strip ({model}) within {limit:e}: the parameters are too extreme")
            }
            Error::BallOutOfRange { arg, lower, upper, allowed } => {
                if lower == upper {
                    write!(f, "{arg} must lie in {allowed} (got {lower:?})")
                } else {
                    write!(f, "{arg} must lie in {allowed} over its whole input ball (got [{lower:e}, {upper:e}])")
                }
            }
            Error::OutOfRange { arg, value, allowed } => write!(f, "{arg} must lie in {allowed} (got {value:?})"),
            Error::UnknownFunction { name, known } => write!(f, "unknown function {name:?}; known: {}", known.join(", ")),
            Error::Arity { function, expected, got } => {
                write!(f, "{function} takes {expected} arguments, got {got}")
            }
            Error::IncompleteGroup { function, group, names, fixed, got } => {
                let size = names.len().max(1);
                let index = got.saturating_sub(*fixed) / size + 1;
                write!(
                    f,
                    "{function} takes {fixed} arguments and then ({}) for each {group}: {got} arguments leave {group} {index} incomplete",
                    names.join(", ")
                )
            }
            Error::ArgumentKind { function, arg, expected } => {
                write!(f, "{function}: {arg} must be {}", expected.describe())
            }
            Error::IntegerOutOfRange { arg, value, min, max } => {
                if *max == i64::MAX {
                    write!(f, "{arg} must be an integer >= {min} (got {value})")
                } else {
                    write!(f, "{arg} must be an integer in {min} ..= {max} (got {value})")
                }
            }
            Error::NoBoundedPath { function } => {
                write!(f, "{function} has no f64 path with a proven bound; use the certified (MP) path")
            }
            Error::Internal { what } => write!(f, "internal error (please report): {what}"),
            Error::Invariant(i) => write!(f, "internal error (please report): {i}"),
            Error::ParameterPole { function, arg, pole, lower, upper } => {
                if lower == upper {
                    write!(
                        f,
                        "{function}: {arg} = {pole} is a non-positive integer, a pole of the series (defined there only \
                         when a numerator parameter is a non-positive integer of no larger magnitude: a terminating series)"
                    )
                } else {
                    write!(
                        f,
                        "{function}: the pole {arg} = {pole} (a non-positive integer) lies within the input ball \
                         [{lower:e}, {upper:e}] of {arg}; give {arg} exactly or away from the poles"
                    )
                }
            }
            Error::Divergent { function, needs, value } => {
                write!(f, "{function} diverges here: it needs {needs} (here {value:e})")
            }
            Error::BallTooWide { arg, lower, upper, needs } => write!(
                f,
                "the input ball [{lower:e}, {upper:e}] of {arg} is too wide: it must lie {needs}; give {arg} with fewer \
                 uncertain digits"
            ),
            Error::IntervalTooNarrow { prec } => write!(
                f,
                "the interval is too narrow for {prec}-bit nodes (its midpoint rounds onto an endpoint); \
                 use a higher precision or integrate over the complement"
            ),
            Error::InsideContact { x, a } => write!(f, "the wave displacement is for x >= a (got x = {x:?} < a = {a:?})"),
            Error::ContactEdgeInBall { function, lower, upper } => {
                if *upper < 0.0 {
                    write!(f, "{function}: the wave displacement is for x >= a (x - a lies in [{lower:e}, {upper:e}])")
                } else {
                    write!(
                        f,
                        "{function}: the contact edge x = a lies within the input balls (x - a in [{lower:e}, {upper:e}]): \
                         u_w is defined for x >= a only and du_w/dx is one-sided there; give x = a exactly or balls with x - a > 0"
                    )
                }
            }
            Error::RoutePrecision { route, requested, max } => {
                write!(f, "{route} takes prec <= {max} bits (got {requested})")
            }
            Error::ScaleNotRepresentable { scale, e_star, radius, dgamma } => write!(
                f,
                "{scale} of E* = {e_star:e} Pa, R = {radius:e} m, dgamma = {dgamma:e} J/m^2 is not a finite positive f64 \
                 (overflow or underflow): the material values are too extreme"
            ),
            Error::TooExpensive { function, seconds, limit_seconds } => write!(
                f,
                "{function} would take about {} with the cheapest method, past the limit of {} (the method's cap \
                 or what is left of the time budget); lower the precision or raise the budget",
                Seconds(*seconds),
                Seconds(*limit_seconds)
            ),
            Error::BudgetSpent { function, elapsed_seconds, next_seconds, budget_seconds, reached } => write!(
                f,
                "{function} stopped at its time budget of {} after {} (next step about {}), having reached {reached}; \
                 raise the budget or lower the precision",
                Seconds(*budget_seconds),
                Seconds(*elapsed_seconds),
                Seconds(*next_seconds)
            ),
            Error::RootNotCertified { quantity, near, input_balls } => {
                write!(f, "could not certify the root {quantity} near {near:e}: the residual's balls stay too wide")?;
                if *input_balls {
                    write!(f, " over the input balls (give the inputs with more digits, or exactly)")
                } else {
                    write!(f, " (the parameters are too extreme for the certified solver)")
                }
            }
            Error::Degenerate { function, needs } => write!(f, "{function} needs {needs} (a degenerate position)"),
            Error::LengthMismatch { inputs, outputs } => {
                write!(f, "{inputs} points but room for {outputs} results (make the lengths equal)")
            }
        }
    }
}

impl std::error::Error for Error {}

impl Error {
    /// An internal routine called outside the arguments it covers: the chooser
    /// guarantees them, so reaching this is a bug ([`Error::Internal`]).
    pub(crate) fn precondition(what: &'static str) -> Error {
        Error::Invariant(Invariant::Precondition { what })
    }

    /// Whether this is a refusal for time ([`Error::TooExpensive`] or
    /// [`Error::BudgetSpent`]): the input is fine, and a larger budget (or a
    /// lower precision) may answer it.
    pub fn is_time_limit(&self) -> bool {
        matches!(self, Error::TooExpensive { .. } | Error::BudgetSpent { .. })
    }

    /// Whether the error says that an argument lies outside the function's domain
    /// ([`Error::Domain`], [`Error::OutOfRange`], [`Error::BallOutOfRange`],
    /// [`Error::ParameterPole`], [`Error::Divergent`], [`Error::BallTooWide`],
    /// [`Error::InsideContact`], [`Error::ContactEdgeInBall`]): the
    /// errors a tighter input ball may avoid.
    pub fn is_domain(&self) -> bool {
        matches!(
            self,
            Error::Domain { .. }
                | Error::OutOfRange { .. }
                | Error::BallOutOfRange { .. }
                | Error::ParameterPole { .. }
                | Error::Divergent { .. }
                | Error::BallTooWide { .. }
                | Error::InsideContact { .. }
                | Error::ContactEdgeInBall { .. }
                | Error::RootNotCertified { input_balls: true, .. }
        )
    }
}

/// Which field of a wave ([`ProfileError::Wave`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WaveField {
    /// The amplitude `alpha_j`.
    Amplitude,
    /// The wavelength `beta_j`.
    Wavelength,
}

impl fmt::Display for WaveField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            WaveField::Amplitude => "amplitude",
            WaveField::Wavelength => "wavelength",
        })
    }
}

/// What can be wrong with a profile of many waves ([`crate::contact::profile`]).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ProfileError {
    /// Wave `wave` (1-based) has a `field` outside `allowed` (NaN and infinities included).
    Wave {
        /// Which wave, counting from 1 in the order given.
        wave: usize,
        /// Which field.
        field: WaveField,
        /// The value given.
        value: f64,
        /// The values allowed.
        allowed: Interval,
    },
    /// More waves than a profile carries.
    TooManyWaves {
        /// How many were given (0 for a Weierstrass profile of no scale).
        count: usize,
        /// The most allowed.
        max: usize,
    },
    /// A Weierstrass parameter (`gamma` or `H`) outside its range.
    Weierstrass {
        /// `"gamma"` or `"H"`.
        arg: &'static str,
        /// The value given.
        value: f64,
        /// The values allowed.
        allowed: Interval,
    },
    /// A line of a harmonics table that is not `amplitude,wavelength`.
    HarmonicsLine {
        /// The line, counting from 1.
        line: usize,
        /// How many comma-separated columns it has.
        columns: usize,
        /// The column (1 or 2) that is not a number, when there are two.
        bad_column: Option<usize>,
    },
    /// A harmonics table without a single wave.
    NoHarmonics,
    /// Wave `wave` (1-based) is too fine for the contact: its Bessel length
    /// `D = 2 pi abar/beta` exceeds `max` (the wave terms' cost and cancellation grow
    /// with `D`; a refusal at once, at any precision).
    WaveTooFine {
        /// Which wave, counting from 1 in the order given.
        wave: usize,
        /// Its wavelength `beta`.
        beta: f64,
        /// The contact half-width `abar`.
        abar: f64,
        /// The most `D` allowed.
        max: f64,
    },
    /// Serialized parameters with neither `alpha` and `beta` (one wave) nor `waves`, or both.
    ParamsFields,
}

impl fmt::Display for ProfileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProfileError::Wave { wave, field, value, allowed } => {
                if value.is_finite() {
                    write!(f, "wave {wave}: {field} = {value} is out of range: allowed {allowed}")
                } else {
                    write!(f, "wave {wave}: {field} must be a finite number (got {value}); allowed {allowed}")
                }
            }
            ProfileError::TooManyWaves { count, max } => {
                write!(f, "{count} waves: a profile carries 1 to {max} waves")
            }
            ProfileError::Weierstrass { arg, value, allowed } => {
                write!(f, "Weierstrass profile: {arg} = {value} is out of range: allowed {allowed}")
            }
            ProfileError::HarmonicsLine { line, columns, bad_column } => match bad_column {
                Some(c) => write!(
                    f,
                    "harmonics table, line {line}: column {c} is not a number (expected `amplitude,wavelength`)"
                ),
                None => write!(
                    f,
                    "harmonics table, line {line}: {columns} columns, expected 2 (`amplitude,wavelength`)"
                ),
            },
            ProfileError::ParamsFields => write!(
                f,
                "the parameters need `lambda` with either `alpha` and `beta` (one wave) or `waves` (a list of {{alpha, beta}}), not both"
            ),
            ProfileError::WaveTooFine { wave, beta, abar, max } => write!(
                f,
                "wave {wave}: wavelength = {beta} is too fine for the contact abar = {abar}: 2 pi abar/beta = {:.6e} exceeds {max:e} (use a smaller abar or drop the wave)",
                2.0 * std::f64::consts::PI * abar / beta
            ),
            ProfileError::NoHarmonics => {
                write!(f, "the harmonics table has no wave (expected lines `amplitude,wavelength`)")
            }
        }
    }
}

/// What can be wrong with a regime-map grid, a shard, or a set of shards to merge.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SweepError {
    /// The lambda range is not `0 < min <= max`.
    LambdaRange {
        /// Its lower end.
        min: f64,
        /// Its upper end.
        max: f64,
    },
    /// An axis has no values.
    EmptyAxis,
    /// The second axis has `max < min`.
    AxisOrder {
        /// Its lower end.
        min: f64,
        /// Its upper end.
        max: f64,
    },
    /// The second axis starts below its smallest allowed value.
    AxisStart {
        /// The axis (`"alpha"`, `"beta"` or `"johnson"`).
        axis: &'static str,
        /// Its lower end.
        min: f64,
        /// Whether 0 itself is allowed (`alpha`) or not.
        zero_allowed: bool,
    },
    /// A shard that is not `s/n` with `1 <= s <= n`.
    Shard {
        /// The shard's number.
        s: usize,
        /// The number of shards.
        n: usize,
    },
    /// Nothing was given to merge.
    NothingToMerge,
    /// The shards were computed on different grids.
    DifferentGrids,
    /// The shards were computed for different base profiles (the `amplitude` axis'
    /// profile, or one of them on a one-wave axis).
    DifferentProfiles {
        /// The first shard's profile ([`crate::contact::profile::WavyProfile::describe`],
        /// or `"one wave"` for a one-wave axis).
        first: String,
        /// The differing shard's.
        other: String,
    },
    /// The `amplitude` axis without a base profile (or with one of no wave) to scale.
    NoBaseProfile,
    /// A base profile given with a one-wave axis (`alpha`, `beta`, `johnson`), which
    /// builds its wave from `fixed`: sweep a profile on the `amplitude` axis.
    ProfileOnOneWaveAxis {
        /// The axis.
        axis: &'static str,
        /// The profile's number of waves.
        waves: usize,
    },
    /// A grid point appears in two shards.
    DuplicatePoint {
        /// The point's index.
        index: usize,
    },
    /// A point's index lies outside the grid.
    PointOutsideGrid {
        /// The point's index.
        index: usize,
    },
    /// Points of the grid are missing from the shards.
    MissingPoints {
        /// How many are missing.
        missing: usize,
        /// How many the grid has.
        total: usize,
    },
}

impl fmt::Display for SweepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SweepError::LambdaRange { min, max } => {
                write!(f, "the lambda range must satisfy 0 < min <= max (got {min} .. {max})")
            }
            SweepError::EmptyAxis => write!(f, "sweep grids need at least one value per axis"),
            SweepError::AxisOrder { min, max } => write!(f, "the second axis needs min <= max (got {min} .. {max})"),
            SweepError::AxisStart { axis, min, zero_allowed } => {
                write!(f, "the {axis} axis must be {} (got min = {min})", if *zero_allowed { ">= 0" } else { "> 0" })
            }
            SweepError::Shard { s, n } => write!(f, "shard must be s/n with 1 <= s <= n (got {s}/{n})"),
            SweepError::NothingToMerge => write!(f, "nothing to merge"),
            SweepError::DifferentGrids => write!(f, "the shards belong to different grids"),
            SweepError::DifferentProfiles { first, other } => {
                write!(f, "the shards belong to different profiles ({first}; {other})")
            }
            SweepError::NoBaseProfile => {
                write!(f, "the amplitude axis scales a profile: give the grid a profile of at least one wave")
            }
            SweepError::ProfileOnOneWaveAxis { axis, waves } => write!(
                f,
                "the {axis} axis builds one wave from the fixed parameter, but a profile of {waves} wave(s) was given: sweep it on the amplitude axis"
            ),
            SweepError::DuplicatePoint { index } => write!(f, "grid point {index} appears in two shards"),
            SweepError::PointOutsideGrid { index } => write!(f, "grid point {index} lies outside the grid"),
            SweepError::MissingPoints { missing, total } => {
                write!(f, "{missing} of {total} grid points are missing: merge every shard")
            }
        }
    }
}

/// An interval of allowed values: its ends and whether each belongs to it
/// (an infinite end is always open).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The lower end.
    pub lo: f64,
    /// The upper end.
    pub hi: f64,
    /// Whether `lo` is allowed.
    pub lo_closed: bool,
    /// Whether `hi` is allowed.
    pub hi_closed: bool,
}

impl Interval {
    /// `[lo, hi]`.
    pub const fn closed(lo: f64, hi: f64) -> Interval {
        Interval { lo, hi, lo_closed: true, hi_closed: true }
    }

    /// `(lo, hi]`.
    pub const fn left_open(lo: f64, hi: f64) -> Interval {
        Interval { lo, hi, lo_closed: false, hi_closed: true }
    }

    /// `(lo, +inf)`.
    pub const fn above(lo: f64) -> Interval {
        Interval { lo, hi: f64::INFINITY, lo_closed: false, hi_closed: false }
    }

    /// `[lo, +inf)`.
    pub const fn at_least(lo: f64) -> Interval {
        Interval { lo, hi: f64::INFINITY, lo_closed: true, hi_closed: false }
    }

    /// `(-inf, hi]`.
    pub const fn at_most(hi: f64) -> Interval {
        Interval { lo: f64::NEG_INFINITY, hi, lo_closed: false, hi_closed: true }
    }

    /// Whether `x` lies in the interval (never for NaN).
    pub fn contains(&self, x: f64) -> bool {
        let above_lo = if self.lo_closed { x >= self.lo } else { x > self.lo };
        let below_hi = if self.hi_closed { x <= self.hi } else { x < self.hi };
        above_lo && below_hi
    }

    /// `value` if it lies in the interval, else [`Error::OutOfRange`] naming `arg`.
    pub fn check(&self, arg: &'static str, value: f64) -> Result<f64> {
        if self.contains(value) {
            Ok(value)
        } else {
            Err(Error::OutOfRange { arg, value, allowed: *self })
        }
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let end = |x: f64| {
            if x.is_infinite() {
                if x > 0.0 { "inf".to_string() } else { "-inf".to_string() }
            } else if x != 0.0 && (x.abs() >= 1e5 || x.abs() < 1e-3) {
                format!("{x:e}")
            } else {
                format!("{x}")
            }
        };
        let open = if self.lo_closed { '[' } else { '(' };
        let close = if self.hi_closed { ']' } else { ')' };
        write!(f, "{open}{}, {}{close}", end(self.lo), end(self.hi))
    }
}

/// What kind of value a parameter takes ([`crate::registry`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// An integer (an order, a number of terms).
    Integer,
    /// A real number.
    Real,
}

impl ParamKind {
    /// `"an integer"` or `"a real number"`.
    pub fn describe(self) -> &'static str {
        match self {
            ParamKind::Integer => "an integer",
            ParamKind::Real => "a real number",
        }
    }
}

/// What can go wrong in an integration, beyond the crate's common errors.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum IntegrationError {
    /// The integrand could not be bounded on a piece next to `near`: a pole, a
    /// non-integrable singularity, or an endpoint singularity that was not declared
    /// with a weight.
    NotIntegrable {
        /// A point of the piece that could not be bounded (approximate), in the
        /// integration variable `x` (mapped back from the variable of a substituted
        /// piece: next to a weighted endpoint, or on an algebraic decay to infinity).
        near: f64,
        /// Evaluations spent.
        evaluations: u64,
    },
    /// An exponent of a weight is not `> -1` (the weight is not integrable).
    WeightExponent {
        /// `"alpha"` or `"beta"`.
        which: &'static str,
        /// The value given.
        value: f64,
    },
    /// The power of the logarithm in a weight is above `max`
    /// ([`Weight::MAX_LOG_POWER`](crate::quad::certified::Weight::MAX_LOG_POWER)).
    LogPower {
        /// The value given.
        value: u32,
        /// The largest allowed.
        max: u32,
    },
    /// A decay parameter is out of range.
    Decay {
        /// Which parameter, and what it must be.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// The endpoints are not ordered `a < b` where the integral needs it (weights
    /// and semi-infinite ranges).
    Endpoints {
        /// The left endpoint (approximate).
        a: f64,
        /// The right endpoint (approximate).
        b: f64,
    },
    /// An option is out of range.
    Option {
        /// Which option, and what it must be.
        what: &'static str,
    },
    /// The upper end is `-inf`, which is not supported: integrate `f(-x)` from `-b`
    /// to `inf` instead.
    NegativeInfinity,
    /// An end is neither a decimal nor `inf` / `-inf`.
    UpperEnd {
        /// The text given.
        text: String,
    },
    /// A decay was declared for a finite upper end; it applies only to `b = inf`.
    DecayWithFiniteEnd,
    /// An infinite end without a declared decay, and no decay class follows from the
    /// expression.
    MissingDecay,
    /// The expression's class at an infinite end is `|f(x)| <= C |x|^power` with
    /// `power >= -1` (or a growth), and it is not an oscillatory integral the
    /// integrator recognises: it is not absolutely integrable there.
    NotAbsolutelyIntegrable {
        /// The power of `|x|` of the class (approximate).
        power: f64,
        /// `+1` for `+inf`, `-1` for `-inf`.
        end: f64,
    },
}

impl fmt::Display for IntegrationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IntegrationError::NotIntegrable { near, evaluations } => write!(
                f,
                "the integrand is not bounded near x = {near:.6e} (after {evaluations} evaluations): a pole, a \
                 non-integrable singularity, or an endpoint singularity; declare endpoint behaviour with a weight \
                 (alpha, beta, log) or split the interval there"
            ),
            IntegrationError::WeightExponent { which, value } => {
                write!(f, "weight exponent {which} = {value} must be > -1 (otherwise the integral diverges)")
            }
            IntegrationError::LogPower { value, max } => {
                write!(f, "log power {value} is too large: use 0 ..= {max}")
            }
            IntegrationError::Decay { what, value } => write!(f, "decay: {what} (got {value})"),
            IntegrationError::Endpoints { a, b } => {
                write!(f, "this integral needs a < b (got a = {a}, b = {b})")
            }
            IntegrationError::Option { what } => write!(f, "integration option: {what}"),
            IntegrationError::NegativeInfinity => {
                write!(f, "the upper end -inf is not supported: integrate f(-x) from -b to inf instead")
            }
            IntegrationError::UpperEnd { text } => {
                write!(f, "the end '{text}' is not a decimal number; write a decimal, or inf / -inf for an infinite end")
            }
            IntegrationError::DecayWithFiniteEnd => {
                write!(f, "a decay is declared only for an infinite upper end (b = inf)")
            }
            IntegrationError::MissingDecay => write!(
                f,
                "no tail bound follows from the expression at the infinite end; declare a decay of the integrand: \
                 |f(x)| <= m e^(-c x) (decay rate c and bound m) or |f(x)| <= m x^(-p) (decay power p > 1 and \
                 bound m) for x >= a"
            ),
            IntegrationError::NotAbsolutelyIntegrable { power, end } => write!(
                f,
                "the integrand is not absolutely integrable at {}inf: it decays no faster than |x|^{power:.4} \
                 (an integral to infinity needs a power below -1, an exponential decay, or a recognised \
                 oscillatory factor sin(w x + c), cos(w x + c) or besselj(n, w x))",
                if *end < 0.0 { "-" } else { "+" }
            ),
        }
    }
}



/// `Result` with [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that an f64 argument is finite.
pub fn finite(x: f64, what: &'static str) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::NonFinite { what })
    }
}

/// Checks a requested output precision.
pub fn check_prec(prec: u32) -> Result<()> {
    if prec < 2 || prec > crate::MAX_PREC {
        Err(Error::Precision { requested: prec as u64 })
    } else {
        Ok(())
    }
}

/// Checks a *working* precision (what the building blocks take: the requested
/// precision plus guard bits, raised by escalation): `2 ..= MAX_WORKING_PREC` bits.
/// rug panics on 0, so every public function that takes one checks it first.
pub fn check_working_prec(wp: u32) -> Result<()> {
    if wp < 2 || wp > crate::MAX_WORKING_PREC {
        Err(Error::Precision { requested: wp as u64 })
    } else {
        Ok(())
    }
}

/// The expression parser's own error, taken into the crate's at the edge
/// ([`Expr::parse`](crate::quad::expr::Expr::parse), the registry). It is
/// defined in `quad/expr/error.rs`, which depends on nothing that depends on this
/// file, so the dependency points one way.
impl From<crate::quad::expr::error::ExprError> for Error {
    fn from(e: crate::quad::expr::error::ExprError) -> Error {
        Error::Expression(e)
    }
}

/// An internal invariant that failed ([`Error::Invariant`]): each variant names
/// the routine's own quantities, so a report carries what is needed to reproduce
/// it. None of these is reachable from a valid call; all are bugs.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Invariant {
    /// An internal routine was called outside the arguments it covers.
    Precondition {
        /// The violated condition.
        what: &'static str,
    },
    /// A ball routine that needs an exact (zero-radius) argument got a wide one.
    InexactArgument {
        /// The routine.
        function: &'static str,
    },
    /// The f64 Newton iteration for a Gauss-Legendre node did not converge.
    GaussLegendreNewton {
        /// Degree of the rule.
        degree: usize,
        /// Index of the node.
        node: usize,
    },
    /// A certified Gauss-Legendre node does not lie inside `(0, 1)`.
    GaussLegendreNodeOutside {
        /// Degree of the rule.
        degree: usize,
        /// Index of the node.
        node: usize,
    },
    /// Two certified Gauss-Legendre nodes overlap (`node` and `node - 1`).
    GaussLegendreNodesOverlap {
        /// Degree of the rule.
        degree: usize,
        /// Index of the second node.
        node: usize,
    },
    /// No sign change of `P_n` could enclose a root to the target accuracy.
    LegendreRootNotCertified {
        /// Degree of the polynomial.
        degree: usize,
        /// Target radius, as bits (`2^-target_bits`).
        target_bits: u32,
    },
    /// The model's strip residual is not finite at a point of the root scan.
    StripResidualNotFinite {
        /// `m - 1` at that point.
        m_minus_1: f64,
    },
    /// The root of the strip equation came out at `m - 1 <= 0`.
    StripRootNotPositive {
        /// The root found.
        m_minus_1: f64,
    },
    /// A jump target's bracket holds a contact size whose state cannot be computed.
    JumpTargetNotComputable {
        /// Lower end of the bracket (abar).
        lo: f64,
        /// Upper end of the bracket (abar).
        hi: f64,
    },
}

impl fmt::Display for Invariant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Invariant::Precondition { what } => write!(f, "precondition violated: {what}"),
            Invariant::InexactArgument { function } => write!(f, "{function} needs an exact argument"),
            Invariant::GaussLegendreNewton { degree, node } => {
                write!(f, "Gauss-Legendre Newton iteration failed (n = {degree}, i = {node})")
            }
            Invariant::GaussLegendreNodeOutside { degree, node } => {
                write!(f, "Gauss-Legendre node {node} of degree {degree} left (0, 1)")
            }
            Invariant::GaussLegendreNodesOverlap { degree, node } => {
                write!(f, "Gauss-Legendre nodes {node} and {} of degree {degree} overlap", node - 1)
            }
            Invariant::LegendreRootNotCertified { degree, target_bits } => {
                write!(f, "could not certify a root of P_{degree} to {target_bits} bits")
            }
            Invariant::StripResidualNotFinite { m_minus_1 } => {
                write!(f, "strip residual not finite at m - 1 = {m_minus_1}")
            }
            Invariant::StripRootNotPositive { m_minus_1 } => write!(f, "strip root m - 1 = {m_minus_1:?} is not > 0"),
            Invariant::JumpTargetNotComputable { lo, hi } => {
                write!(f, "jump target: state not computable in [{lo}, {hi}]")
            }
        }
    }
}

/// How far a loop stopped by its time budget got ([`Error::BudgetSpent`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Reached {
    /// A Ziv loop: the last working precision and the relative accuracy its ball had.
    WorkingPrecision {
        /// The working precision of the last evaluation (bits).
        bits: u32,
        /// Its relative accuracy (bits; `-inf` for a ball that contains 0).
        accuracy_bits: f64,
    },
    /// The retries of a decimal-input evaluation: the input balls' precision.
    InputPrecision {
        /// The precision of the last input balls (bits).
        bits: u32,
    },
    /// A quadrature: the integrand evaluations done.
    Evaluations {
        /// How many.
        count: u64,
    },
    /// A series: the terms summed.
    Terms {
        /// How many.
        count: u64,
    },
}

impl fmt::Display for Reached {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Reached::WorkingPrecision { bits, accuracy_bits } => {
                write!(f, "{accuracy_bits:.0} correct bits at a working precision of {bits} bits")
            }
            Reached::InputPrecision { bits } => write!(f, "input balls of {bits} bits"),
            Reached::Evaluations { count } => write!(f, "{count} integrand evaluations"),
            Reached::Terms { count } => write!(f, "{count} terms"),
        }
    }
}

/// What a [`Log2Magnitude`] states about `log2 |value|`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Log2Relation {
    /// An estimate (the value's enclosure lies wholly past the range; its
    /// midpoint's logarithm is printed).
    About,
    /// A proven lower bound: `log2 |value| >= ` the number.
    AtLeast,
    /// A proven upper bound: `log2 |value| <= ` the number.
    AtMost,
}

/// `log2 |value|` of a value outside MPFR's exponent range
/// ([`Error::ValueOutOfRange`]), as `mantissa * 10^exp10` with `1 <= |mantissa|
/// < 10` (or both 0). A decimal exponent of its own, because the logarithm
/// itself passes f64's range (`2^(-5.8e13851)`), where an `f64` would read
/// `-inf`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Log2Magnitude {
    /// The signed significand, `1 <= |mantissa| < 10` (0 for 0).
    pub mantissa: f64,
    /// The power of ten.
    pub exp10: i64,
    /// Whether the number is an estimate or a bound.
    pub relation: Log2Relation,
}

impl Log2Magnitude {
    /// `mantissa * 10^exp10`, normalized (`mantissa` finite).
    pub fn new(mantissa: f64, exp10: i64, relation: Log2Relation) -> Log2Magnitude {
        if mantissa == 0.0 || !mantissa.is_finite() {
            return Log2Magnitude { mantissa: 0.0, exp10: 0, relation };
        }
        let shift = mantissa.abs().log10().floor();
        let mut m = mantissa / 10f64.powf(shift);
        let mut e = exp10.saturating_add(shift as i64);
        // the division can land a hair outside [1, 10)
        if m.abs() >= 10.0 {
            m /= 10.0;
            e = e.saturating_add(1);
        } else if m.abs() < 1.0 {
            m *= 10.0;
            e = e.saturating_sub(1);
        }
        Log2Magnitude { mantissa: m, exp10: e, relation }
    }

    /// An estimate from a finite `f64`.
    pub fn about(log2: f64) -> Log2Magnitude {
        Log2Magnitude::new(log2, 0, Log2Relation::About)
    }

    /// The number as an `f64` (`+-inf` past its range).
    pub fn to_f64(&self) -> f64 {
        if self.exp10 > 400 {
            return self.mantissa * f64::INFINITY;
        }
        if self.exp10 < -400 {
            return 0.0;
        }
        self.mantissa * 10f64.powi(self.exp10 as i32)
    }

    /// Whether the value is below the range (`log2 |value| < 0`).
    pub fn is_negative(&self) -> bool {
        self.mantissa < 0.0
    }

    /// Order of the numbers (not of the relations).
    pub fn cmp_number(&self, other: &Log2Magnitude) -> std::cmp::Ordering {
        use std::cmp::Ordering;
        let sign = |m: f64| if m > 0.0 { 1 } else if m < 0.0 { -1 } else { 0 };
        let (s1, s2) = (sign(self.mantissa), sign(other.mantissa));
        if s1 != s2 || s1 == 0 {
            return s1.cmp(&s2);
        }
        let abs = (self.exp10, self.mantissa.abs()).partial_cmp(&(other.exp10, other.mantissa.abs())).unwrap_or(Ordering::Equal);
        if s1 > 0 {
            abs
        } else {
            abs.reverse()
        }
    }
}

impl fmt::Display for Log2Magnitude {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let word = match self.relation {
            Log2Relation::About => "about",
            Log2Relation::AtLeast => "at least",
            Log2Relation::AtMost => "at most",
        };
        write!(f, "{word} 2^({:.4}e{})", self.mantissa, self.exp10)
    }
}

/// Seconds for a message: `1.2 ms`, `35 s`.
struct Seconds(f64);

impl fmt::Display for Seconds {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = self.0;
        if !s.is_finite() {
            write!(f, "{s} s")
        } else if s < 1e-3 {
            write!(f, "{:.0} us", s * 1e6)
        } else if s < 1.0 {
            write!(f, "{:.1} ms", s * 1e3)
        } else {
            write!(f, "{s:.1} s")
        }
    }
}
