//! The parser: `winnow` combinators over the text, with winnow's Pratt
//! [`expression`] for the left-associative `+ - * /`.
//!
//! Grammar (white space allowed between tokens):
//!
//! ```text
//! sum     := product (('+' | '-') product)*       Pratt, binding powers 1 and 3
//! product := signed (('*' | '/') signed)*
//! signed  := ('+' | '-')* power                    -x^2 = -(x^2), 2^-x*3 = (2^(-x))*3
//! power   := atom ('^' signed)?                    right-associative: 2^3^2 = 2^9
//! atom    := number | 'x' | 'pi' | 'π' | name '(' sum (',' sum)* ')' | '(' sum ')'
//! number  := (digits ['.' digits*] | '.' digits) [('e' | 'E') ['+' | '-'] digits]
//! ```
//!
//! Every failure is a cut carrying the final [`ExprError`], so nothing backtracks
//! past the point where the text went wrong, and its position is exact.
//! Recursion (parentheses, calls, the exponent of `^`) is counted in the stream's
//! state and stops at [`MAX_DEPTH`], so no input can exhaust the stack.

use winnow::ascii::{digit0, digit1, multispace0};
use winnow::combinator::{expression, opt, Infix};
use winnow::error::{ErrMode, ModalResult, ParserError};
use winnow::stream::{Stateful, Stream};
use winnow::token::{one_of, take_while};
use winnow::Parser;

use super::error::ExprError;
use super::tree::{Expr, Function};
use super::{MAX_BESSEL_ORDER, MAX_DEPTH, MAX_LEN};
use crate::ball::Decimal;

/// What the parser carries along: the whole text (for positions) and the depth.
#[derive(Clone, Copy, Debug)]
struct State<'a> {
    text: &'a str,
    depth: usize,
}

type Input<'a> = Stateful<&'a str, State<'a>>;

/// A parse failure: where it happened (bytes into the text) and, for every
/// failure this module raises, the error to report.
#[derive(Debug)]
struct Failure {
    at: usize,
    error: Option<ExprError>,
}

impl<'a> ParserError<Input<'a>> for Failure {
    type Inner = Self;

    fn from_input(input: &Input<'a>) -> Self {
        Failure { at: offset(input), error: None }
    }

    fn into_inner(self) -> Result<Self, Self> {
        Ok(self)
    }
}

type PResult<O> = ModalResult<O, Failure>;

/// What may start an operand, for messages.
const OPERAND: &str = "a number, x, pi, a function call or '('";

/// Byte offset of the parser's position in the text.
fn offset(i: &Input<'_>) -> usize {
    i.state.text.len() - i.input.len()
}

/// Character position of byte offset `at`.
fn chars_before(text: &str, at: usize) -> usize {
    text.get(..at).map_or(0, |s| s.chars().count())
}

/// A cut (no backtracking) carrying `error`.
fn fail<O>(i: &Input<'_>, error: ExprError) -> PResult<O> {
    Err(ErrMode::Cut(Failure { at: offset(i), error: Some(error) }))
}

/// The token at byte offset `at`, quoted, for "found ..." in messages.
fn found_at(text: &str, at: usize) -> String {
    let rest = text.get(at..).unwrap_or("");
    let word: String = rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '.').take(24).collect();
    match rest.chars().next() {
        None => "the end of the expression".to_string(),
        Some(c) if word.is_empty() => format!("'{c}'"),
        Some(_) => format!("'{word}'"),
    }
}

/// The syntax error "expected ..., found ..." at byte offset `at`.
fn syntax_error(text: &str, at: usize, expected: &str) -> ExprError {
    ExprError::Syntax { position: chars_before(text, at), found: found_at(text, at), expected: expected.into() }
}

/// A syntax error at byte offset `at`.
fn syntax_at<O>(i: &Input<'_>, at: usize, expected: &str) -> PResult<O> {
    fail(i, syntax_error(i.state.text, at, expected))
}

/// A syntax error at the parser's position.
fn syntax<O>(i: &Input<'_>, expected: &str) -> PResult<O> {
    syntax_at(i, offset(i), expected)
}

fn ws(i: &mut Input<'_>) -> PResult<()> {
    multispace0.void().parse_next(i)
}

/// Whether the next character (after white space) is `c`; consumes it if so.
fn eat(i: &mut Input<'_>, c: char) -> PResult<bool> {
    ws(i)?;
    Ok(opt(c).parse_next(i)?.is_some())
}

/// Runs `f` one nesting level deeper, refusing past [`MAX_DEPTH`].
fn nested<'a, O>(i: &mut Input<'a>, f: impl FnOnce(&mut Input<'a>) -> PResult<O>) -> PResult<O> {
    if i.state.depth >= MAX_DEPTH {
        let position = chars_before(i.state.text, offset(i));
        return fail(i, ExprError::TooDeep { position });
    }
    i.state.depth += 1;
    let out = f(i);
    i.state.depth -= 1;
    out
}

/// `sum`: the Pratt loop over `+ - * /`.
fn sum(i: &mut Input<'_>) -> PResult<Expr> {
    expression(signed).infix(infix).parse_next(i)
}

type Fold<'a> = Infix<Input<'a>, Expr, ErrMode<Failure>>;

fn infix<'a>(i: &mut Input<'a>) -> PResult<Fold<'a>> {
    ws(i)?;
    let op = one_of(['+', '-', '*', '/']).parse_next(i)?;
    Ok(match op {
        '+' => Infix::Left(1, |_, x, y| Ok(Expr::Add(Box::new(x), Box::new(y)))),
        '-' => Infix::Left(1, |_, x, y| Ok(Expr::Sub(Box::new(x), Box::new(y)))),
        '*' => Infix::Left(3, |_, x, y| Ok(Expr::Mul(Box::new(x), Box::new(y)))),
        _ => Infix::Left(3, |_, x, y| Ok(Expr::Div(Box::new(x), Box::new(y)))),
    })
}

/// `signed`: signs, then a power. An odd number of minus signs is one negation.
fn signed(i: &mut Input<'_>) -> PResult<Expr> {
    ws(i)?;
    let signs = take_while(0.., |c: char| c == '+' || c == '-' || c.is_ascii_whitespace()).parse_next(i)?;
    let p = power(i)?;
    Ok(if signs.matches('-').count() % 2 == 1 { Expr::Neg(Box::new(p)) } else { p })
}

/// `power`: an atom, then `^` and a signed exponent (integer literals give
/// [`Expr::PowInt`]).
fn power(i: &mut Input<'_>) -> PResult<Expr> {
    let base = atom(i)?;
    let before = i.checkpoint();
    if !eat(i, '^')? {
        i.reset(&before);
        return Ok(base);
    }
    let exponent = nested(i, signed)?;
    Ok(match integer_literal(&exponent) {
        Some(n) => Expr::PowInt(Box::new(base), n),
        None => Expr::Pow(Box::new(base), Box::new(exponent)),
    })
}

/// The value of an integer literal, possibly negated (`3`, `-2`, `2.0`, `1e3`).
pub(super) fn integer_literal(e: &Expr) -> Option<i64> {
    match e {
        Expr::Number(d) if *d.as_rational().denom() == 1 => d.as_rational().numer().to_i64(),
        Expr::Neg(a) => integer_literal(a)?.checked_neg(),
        _ => None,
    }
}

fn atom(i: &mut Input<'_>) -> PResult<Expr> {
    ws(i)?;
    let start = offset(i);
    match i.input.chars().next() {
        Some('(') => {
            '('.parse_next(i)?;
            let e = nested(i, sum)?;
            if !eat(i, ')')? {
                return syntax(i, "an operator (+ - * / ^) or ')'");
            }
            Ok(e)
        }
        Some('π') => {
            'π'.parse_next(i)?;
            Ok(Expr::Pi)
        }
        Some(c) if c.is_ascii_digit() || c == '.' => number(i, start),
        Some(c) if c.is_ascii_alphabetic() || c == '_' => {
            let name = take_while(1.., |c: char| c.is_ascii_alphanumeric() || c == '_').parse_next(i)?;
            let position = chars_before(i.state.text, start);
            match name {
                "x" => Ok(Expr::X),
                "pi" => Ok(Expr::Pi),
                _ => {
                    let before = i.checkpoint();
                    if eat(i, '(')? {
                        return call(i, name, position);
                    }
                    i.reset(&before);
                    if name == "besselj" || Function::from_name(name).is_some() {
                        ws(i)?;
                        return syntax(i, &format!("'(' after the function name {name}"));
                    }
                    fail(i, ExprError::UnknownVariable { name: name.into(), position })
                }
            }
        }
        _ => syntax(i, OPERAND),
    }
}

/// A decimal literal, kept exact; `start` is its byte offset.
fn number(i: &mut Input<'_>, start: usize) -> PResult<Expr> {
    let mantissa = (digit0, opt(('.', digit0))).take().parse_next(i)?;
    if !mantissa.bytes().any(|b| b.is_ascii_digit()) {
        return syntax_at(i, start, OPERAND);
    }
    opt((one_of(['e', 'E']), opt(one_of(['+', '-'])), digit1)).parse_next(i)?;
    let text = &i.state.text[start..offset(i)];
    match Decimal::parse(text) {
        Ok(d) => Ok(Expr::Number(d)),
        Err(e) => {
            let position = chars_before(i.state.text, start);
            let shown: String = text.chars().take(40).collect();
            fail(i, ExprError::BadNumber { text: shown, position, reason: e.to_string() })
        }
    }
}

/// `name(args)`, the opening parenthesis consumed; `position` is the name's.
fn call(i: &mut Input<'_>, name: &str, position: usize) -> PResult<Expr> {
    let function = Function::from_name(name);
    if function.is_none() && name != "besselj" {
        return fail(i, ExprError::UnknownFunction { name: name.into(), position });
    }
    // The arguments, each with the text it was written as.
    let mut args: Vec<(Expr, usize, usize)> = Vec::new();
    let before = i.checkpoint();
    if !eat(i, ')')? {
        i.reset(&before);
        loop {
            ws(i)?;
            let from = offset(i);
            let arg = nested(i, sum)?;
            args.push((arg, from, offset(i)));
            if eat(i, ',')? {
                continue;
            }
            if eat(i, ')')? {
                break;
            }
            return syntax(i, "an operator (+ - * / ^), ',' or ')'");
        }
    }
    let (expected, got) = (if function.is_some() { 1 } else { 2 }, args.len());
    let mut args = args.into_iter();
    match (function, args.next(), args.next()) {
        (Some(f), Some((arg, ..)), None) if got == 1 => Ok(Expr::Call(f, Box::new(arg))),
        (None, Some((order, from, to)), Some((arg, ..))) if got == 2 => {
            match integer_literal(&order).filter(|n| n.unsigned_abs() <= MAX_BESSEL_ORDER) {
                Some(n) => Ok(Expr::BesselJ(n, Box::new(arg))),
                None => {
                    let text = i.state.text;
                    let written: String = text.get(from..to).unwrap_or("").trim().chars().take(40).collect();
                    fail(i, ExprError::BadBesselOrder { text: written, position: chars_before(text, from) })
                }
            }
        }
        _ => fail(i, ExprError::WrongArity { name: name.into(), expected, got, position }),
    }
}

/// Parses `text` (see the module docs for the grammar).
pub(super) fn parse(text: &str) -> Result<Expr, ExprError> {
    if text.trim().is_empty() {
        return Err(ExprError::Empty);
    }
    let chars = text.chars().count();
    if chars > MAX_LEN {
        return Err(ExprError::TooLong { chars });
    }
    let mut i = Input { input: text, state: State { text, depth: 0 } };
    let e = sum(&mut i).map_err(|e| match e {
        ErrMode::Backtrack(f) | ErrMode::Cut(f) => f.error.unwrap_or_else(|| syntax_error(text, f.at, OPERAND)),
        ErrMode::Incomplete(_) => syntax_error(text, text.len(), OPERAND),
    })?;
    // White space cannot fail to parse; what follows it must be the end.
    ws(&mut i).ok();
    if !i.input.is_empty() {
        return Err(syntax_error(text, offset(&i), "an operator (+ - * / ^) or the end of the expression"));
    }
    Ok(e)
}
