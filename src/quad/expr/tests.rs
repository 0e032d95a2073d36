use super::*;
use crate::ball::Decimal;
use crate::special::bessel_j::bessel_j;

fn p(text: &str) -> Expr {
    match Expr::parse(text) {
        Ok(e) => e,
        Err(e) => panic!("{text:?} should parse: {e}"),
    }
}

fn err(text: &str) -> ExprError {
    match Expr::parse(text) {
        Err(crate::Error::Expression(e)) => e,
        other => panic!("{text:?} should be an expression error, got {other:?}"),
    }
}

fn num(text: &str) -> Box<Expr> {
    Box::new(Expr::Number(Decimal::parse(text).unwrap()))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 4.0 * f64::EPSILON * b.abs().max(1e-300)
}

#[test]
fn precedence_and_associativity() {
    let x = || Box::new(Expr::X);
    assert_eq!(p("-x^2"), Expr::Neg(Box::new(Expr::PowInt(x(), 2))));
    assert_eq!(p("(-x)^2"), Expr::PowInt(Box::new(Expr::Neg(x())), 2));
    assert_eq!(p("1 - x - 2"), Expr::Sub(Box::new(Expr::Sub(num("1"), x())), num("2")));
    assert_eq!(p("x/2/3"), Expr::Div(Box::new(Expr::Div(x(), num("2"))), num("3")));
    assert_eq!(p("1 + 2*x"), Expr::Add(num("1"), Box::new(Expr::Mul(num("2"), x()))));
    // ^ is right-associative; only a literal integer exponent is an integer power
    assert_eq!(p("2^3^2"), Expr::Pow(num("2"), Box::new(Expr::PowInt(num("3"), 2))));
    assert_eq!(p("x^-2"), Expr::PowInt(x(), -2));
    assert_eq!(p("x^(-2)"), Expr::PowInt(x(), -2));
    assert_eq!(p("x ^ +3"), Expr::PowInt(x(), 3));
    assert_eq!(p("x^2.0"), Expr::PowInt(x(), 2));
    assert_eq!(p("x^1e2"), Expr::PowInt(x(), 100));
    assert_eq!(p("x^0.5"), Expr::Pow(x(), num("0.5")));
    assert_eq!(p("x^(1/2)"), Expr::Pow(x(), Box::new(Expr::Div(num("1"), num("2")))));
    // the minus in an exponent takes a power, not a product: 2^-x*3 = (2^-x)*3
    assert_eq!(p("2^-x*3"), Expr::Mul(Box::new(Expr::Pow(num("2"), Box::new(Expr::Neg(x())))), num("3")));
    assert_eq!(p("--x"), Expr::X);
    assert_eq!(p("- + -x"), Expr::X);
    assert_eq!(p("x*-1"), Expr::Mul(x(), Box::new(Expr::Neg(num("1")))));
    let f64_cases: [(&str, f64); 8] = [
        ("-2^2", -4.0),
        ("(-2)^2", 4.0),
        ("2^3^2", 512.0),
        ("2^-1*3", 1.5),
        ("1 - 2 - 3", -4.0),
        ("8/2/2", 2.0),
        ("2*3 + 4*5", 26.0),
        ("-3^-2", -1.0 / 9.0),
    ];
    for (text, want) in f64_cases {
        assert!(close(p(text).eval_f64(0.0), want), "{text}");
    }
}

#[test]
fn literals_and_names() {
    for (text, want) in [("0.1", "1/10"), (".5", "1/2"), ("2.", "2"), ("2.5e-3", "1/400"), ("1E6", "1000000"), ("7e+1", "70")] {
        match p(text) {
            Expr::Number(d) => assert_eq!(d.as_rational().to_string(), want, "{text}"),
            other => panic!("{text}: {other:?}"),
        }
    }
    assert_eq!(p("pi"), Expr::Pi);
    assert_eq!(p("π"), Expr::Pi);
    assert_eq!(p(" \t x \n"), Expr::X);
    assert!(!p("pi*2 + sin(1)").depends_on_x());
    assert!(p("besselj(0, 1 + x)").depends_on_x());
    assert_eq!(p("besselj(-3, x)"), Expr::BesselJ(-3, Box::new(Expr::X)));
    assert_eq!(p("besselj( +2 , x)"), Expr::BesselJ(2, Box::new(Expr::X)));
    assert_eq!(p("besselj(1, besselj(2, x))").size(), 3);
    assert_eq!("sqrt(x)".parse::<Expr>().unwrap(), Expr::Call(Function::Sqrt, Box::new(Expr::X)));
}

#[test]
fn printing_parses_back_to_the_same_tree() {
    let cases = [
        "-x^2",
        "(-x)^2",
        "1 - (x - 2)",
        "1 - x - 2",
        "x/(2*x)",
        "x/2*x",
        "2^3^2",
        "(2^3)^2",
        "x^-2",
        "x^(1/2)",
        "x^-x",
        "2^-x*3",
        "-(x*2)",
        "-x*2",
        "x + -1",
        "x - -1",
        "x*-(-x)",
        "-sin(x)^2",
        "sqrt(x)*cos(x)",
        "exp(-x^2)/(1 + x^2)",
        "besselj(-2, 3*x)*log(1 + x)",
        "atan(tanh(sinh(cosh(tan(x)))))",
        "0.1 + .5 + 2.5e-3 + 1E6 + 3e-40 + 1e99999 + 12345.678",
        "pi*x",
        "((x))",
    ];
    for text in cases {
        let e = p(text);
        let printed = e.to_string();
        assert_eq!(p(&printed), e, "{text} printed as {printed}");
    }
    assert_eq!(p("-x^2").to_string(), "-x^2");
    assert_eq!(p("(-x)^2").to_string(), "(-x)^2");
    assert_eq!(p("1-(x-2)").to_string(), "1 - (x - 2)");
    assert_eq!(p("x^(-1/2)*cos(x)").to_string(), "x^(-1/2)*cos(x)");
    assert_eq!(p("0.10 + 2.5e-3 + 1E6 + 3e-40").to_string(), "0.1 + 0.0025 + 1000000 + 3e-40");
    // a hand-made double negation prints with parentheses and parses back
    let nn = Expr::Neg(Box::new(Expr::Neg(Box::new(Expr::X))));
    assert_eq!(nn.to_string(), "-(-x)");
    assert_eq!(p(&nn.to_string()), nn);
}

#[test]
fn each_function_in_f64() {
    let x = 0.7_f64;
    let cases: [(&str, f64); 15] = [
        ("sqrt(x)", x.sqrt()),
        ("exp(x)", x.exp()),
        ("log(x)", x.ln()),
        ("sin(x)", x.sin()),
        ("cos(x)", x.cos()),
        ("tan(x)", x.tan()),
        ("sinh(x)", x.sinh()),
        ("cosh(x)", x.cosh()),
        ("tanh(x)", x.tanh()),
        ("sech(x)", 1.0 / x.cosh()),
        ("atan(x)", x.atan()),
        ("besselj(0, x)", bessel_j(0, x).unwrap()),
        ("besselj(3, 2*x)", bessel_j(3, 2.0 * x).unwrap()),
        ("besselj(-1, x)", -bessel_j(1, x).unwrap()),
        ("x^(1/3) + x^-3 + pi", x.powf(1.0 / 3.0) + x.powi(-3) + std::f64::consts::PI),
    ];
    for (text, want) in cases {
        assert!(close(p(text).eval_f64(x), want), "{text}: {} vs {want}", p(text).eval_f64(x));
    }
    assert!(p("sqrt(x)").eval_f64(-1.0).is_nan());
    assert!(p("log(x)").eval_f64(-1.0).is_nan());
}

#[test]
fn error_cases_are_typed_and_say_what_to_fix() {
    assert_eq!(err(""), ExprError::Empty);
    assert_eq!(err("   \t\n"), ExprError::Empty);
    assert!(matches!(err("(((("), ExprError::Syntax { position: 4, .. }));
    assert!(matches!(err("x^"), ExprError::Syntax { position: 2, .. }));
    assert!(matches!(err("x +"), ExprError::Syntax { position: 3, .. }));
    assert!(matches!(err("x + * 2"), ExprError::Syntax { position: 4, .. }));
    assert!(matches!(err("(x"), ExprError::Syntax { position: 2, .. }));
    assert!(matches!(err("x)"), ExprError::Syntax { position: 1, .. }));
    assert!(matches!(err("2x"), ExprError::Syntax { position: 1, .. }));
    assert!(matches!(err("2e"), ExprError::Syntax { position: 1, .. }));
    assert!(matches!(err("."), ExprError::Syntax { position: 0, .. }));
    assert!(matches!(err("1..2"), ExprError::Syntax { position: 2, .. }));
    assert!(matches!(err("sin x"), ExprError::Syntax { position: 4, .. }));
    assert!(matches!(err("x²"), ExprError::Syntax { position: 1, .. }));
    assert!(matches!(err("é + x"), ExprError::Syntax { position: 0, .. }));
    assert!(matches!(err("x + é"), ExprError::Syntax { position: 4, .. }));
    assert!(matches!(err("1e99999999"), ExprError::BadNumber { position: 0, .. }));
    assert_eq!(err("foo(x)"), ExprError::UnknownFunction { name: "foo".into(), position: 0 });
    assert_eq!(err("1 + ln(((("), ExprError::UnknownFunction { name: "ln".into(), position: 4 });
    assert_eq!(err("y+1"), ExprError::UnknownVariable { name: "y".into(), position: 0 });
    assert_eq!(err("NaN"), ExprError::UnknownVariable { name: "NaN".into(), position: 0 });
    assert_eq!(err("inf*x"), ExprError::UnknownVariable { name: "inf".into(), position: 0 });
    assert_eq!(err("besselj(x)"), ExprError::WrongArity { name: "besselj".into(), expected: 2, got: 1, position: 0 });
    assert_eq!(err("sin(x, 2)"), ExprError::WrongArity { name: "sin".into(), expected: 1, got: 2, position: 0 });
    assert_eq!(err("cos()"), ExprError::WrongArity { name: "cos".into(), expected: 1, got: 0, position: 0 });
    assert_eq!(err("besselj(1.5, x)"), ExprError::BadBesselOrder { text: "1.5".into(), position: 8 });
    assert_eq!(err("besselj( x , x)"), ExprError::BadBesselOrder { text: "x".into(), position: 9 });
    assert_eq!(err("besselj(100001, x)"), ExprError::BadBesselOrder { text: "100001".into(), position: 8 });
    assert!(matches!(err(&"x+".repeat(3000)), ExprError::TooLong { chars: 6000 }));
    assert!(matches!(err(&format!("{}x{}", "(".repeat(200), ")".repeat(200))), ExprError::TooDeep { .. }));
    assert!(matches!(err(&"x^".repeat(150)), ExprError::TooDeep { .. }));
    assert!(matches!(err(&format!("{}x", "sin(".repeat(150))), ExprError::TooDeep { .. }));

    // the messages name the problem and the way out
    let m = crate::Error::from(err("foo(x)")).to_string();
    assert!(m.contains("'foo'") && m.contains("sqrt, exp, log, sin, cos, tan, sinh, cosh, tanh, sech, atan and besselj(n, x)"), "{m}");
    let m = err("x^").to_string();
    assert!(m.contains("character 3") && m.contains("the end of the expression"), "{m}");
    let m = err("2x").to_string();
    assert!(m.contains("expected an operator") && m.contains("'x'"), "{m}");
    let m = err("y+1").to_string();
    assert!(m.contains("'y'") && m.contains("variable is x"), "{m}");
    let m = err("besselj(1.5, x)").to_string();
    assert!(m.contains("integer") && m.contains("'1.5'"), "{m}");
}

#[test]
fn nothing_panics_on_odd_input() {
    let long_ok = format!("{}x", "x+".repeat(2000));
    let deep_ok = format!("{}x{}", "(".repeat(MAX_DEPTH - 1), ")".repeat(MAX_DEPTH - 1));
    let odd = [
        "",
        " ",
        "((((",
        "))))",
        "x^",
        "^x",
        "*x",
        "x**2",
        "x^^2",
        "1e99999999",
        "1e-99999999",
        "1e",
        "e5",
        ".e5",
        "nan",
        "NaN(x)",
        "∞",
        "x\u{0}",
        "🦀",
        "besselj",
        "besselj(",
        "besselj(1",
        "besselj(1,",
        "besselj(1, x",
        "besselj(,x)",
        "besselj(1.5, x)",
        "besselj(x)",
        "besselj(1, 2, x)",
        "besselj(99999999999999999999999, x)",
        "x^99999999999999999999999",
        "sqrt",
        "sqrt()",
        "foo(x)",
        "y+1",
        "x,",
        "(,)",
        "1 2",
        &long_ok,
        &deep_ok,
        &"-".repeat(4000),
        &format!("{}x", "-".repeat(4000)),
        &"(".repeat(5000),
        &"9".repeat(4096),
    ];
    for text in odd {
        let r = std::panic::catch_unwind(|| Expr::parse(text).map(|e| (e.eval_f64(0.5), e.to_string())));
        assert!(r.is_ok(), "{text:?} panicked");
    }
    // the longest accepted input and the deepest nesting evaluate and print
    assert_eq!(p(&long_ok).eval_f64(1.0), 2001.0);
    assert_eq!(p(&deep_ok).eval_f64(1.5), 1.5);
    assert_eq!(p(&format!("{}x", "-".repeat(4000))), Expr::X);
}

/// Random trees in the shapes the parser builds (an integer-literal exponent is
/// always a `PowInt`).
fn tree() -> impl proptest::strategy::Strategy<Value = Expr> {
    use proptest::prelude::*;
    let leaf = prop_oneof![
        Just(Expr::X),
        Just(Expr::Pi),
        (0u32..100_000, 0u32..6, -5i32..5).prop_map(|(m, point, e)| {
            let text = format!("{}e{}", f64::from(m) / 10f64.powi(point as i32), e);
            Expr::Number(Decimal::parse(&text).unwrap())
        }),
    ];
    leaf.prop_recursive(6, 48, 2, |inner| {
        let b = |e: Expr| Box::new(e);
        prop_oneof![
            inner.clone().prop_map(move |a| Expr::Neg(b(a))),
            (inner.clone(), inner.clone()).prop_map(move |(a, c)| Expr::Add(b(a), b(c))),
            (inner.clone(), inner.clone()).prop_map(move |(a, c)| Expr::Sub(b(a), b(c))),
            (inner.clone(), inner.clone()).prop_map(move |(a, c)| Expr::Mul(b(a), b(c))),
            (inner.clone(), inner.clone()).prop_map(move |(a, c)| Expr::Div(b(a), b(c))),
            (inner.clone(), -4i64..5).prop_map(move |(a, n)| Expr::PowInt(b(a), n)),
            (inner.clone(), inner.clone()).prop_map(move |(a, c)| match parse::integer_literal(&c) {
                Some(n) => Expr::PowInt(b(a), n),
                None => Expr::Pow(b(a), b(c)),
            }),
            (inner.clone(), 0usize..10).prop_map(move |(a, k)| Expr::Call(Function::ALL[k], b(a))),
            (inner, -3i64..4).prop_map(move |(a, n)| Expr::BesselJ(n, b(a))),
        ]
    })
}

proptest::proptest! {
    #![proptest_config(proptest::test_runner::Config::with_cases(512))]
    #[test]
    fn random_trees_print_and_parse_back(e in tree()) {
        let printed = e.to_string();
        let back = Expr::parse(&printed);
        proptest::prop_assert!(back.as_ref().is_ok_and(|b| *b == e), "{:?} printed as {} parsed as {:?}", e, printed, back);
    }
}

mod complex_balls {
    use super::*;
    use crate::ball::{Ball, CBall};
    use rug::{Float, Rational};

    fn real(x: f64, prec: u32) -> CBall {
        CBall::from_real(Ball::from_f64(x, prec).unwrap())
    }

    /// The ball contains the f64 value within a few ulps of it and is tight.
    fn encloses(b: &CBall, want: f64, what: &str) {
        assert!(b.is_finite() && b.im().contains(&Float::new(53)), "{what}: {b}");
        let mid = b.re().mid().to_f64();
        assert!(close(mid, want), "{what}: {mid} vs {want}");
        assert!(b.re().rad().to_f64() <= 1e-30 * want.abs().max(1.0), "{what}: {b}");
    }

    #[test]
    fn decimal_is_enclosed_at_the_working_precision() {
        let x = real(0.0, 128);
        let tenth = p("0.1").eval(&x);
        let q = Rational::from((1, 10));
        assert!(tenth.re().contains(&Float::with_val(1024, &q)));
        assert!(tenth.is_real());
        let rad = tenth.re().rad();
        assert!(rad <= Float::with_val(64, Float::i_exp(1, -127)), "{rad}");
        // and a binary fraction is exact
        assert!(p("2.5e-1").eval(&x).is_exact());
        // at 1000 bits the same tree gives a 1000-bit ball
        let fine = p("0.1").eval(&real(0.0, 1000));
        assert!(fine.re().rad() <= Float::with_val(64, Float::i_exp(1, -999)));
    }

    #[test]
    fn each_function_agrees_with_f64() {
        let x0 = 0.7;
        let x = real(x0, 128);
        for text in [
            "sqrt(x)",
            "exp(x)",
            "log(x)",
            "sin(x)",
            "cos(x)",
            "tan(x)",
            "sinh(x)",
            "cosh(x)",
            "tanh(x)",
            "atan(x)",
            "besselj(0, x)",
            "besselj(3, 2*x)",
            "besselj(-1, x)",
            "x^(1/3) + x^-3 + pi",
            "x^x",
            "-x^2/(1 + x)",
            "1/(2 + x) - 1.0/x",
        ] {
            let e = p(text);
            encloses(&e.eval(&x), e.eval_f64(x0), text);
        }
    }

    #[test]
    fn branch_cuts_give_non_finite_balls_and_integer_powers_do_not() {
        let neg = real(-0.5, 64);
        for text in ["sqrt(x)", "log(x)", "x^0.5", "x^(1/3)", "(x - 1)^pi"] {
            assert!(!p(text).eval(&neg).is_finite(), "{text}");
        }
        // x^-2 and x^3 by integer powering: finite on the negative axis
        for (text, want) in [("x^-2", 4.0), ("x^3", -0.125), ("x^2.0", 0.25)] {
            let v = p(text).eval(&neg);
            assert!(v.re().contains(&Float::with_val(53, want)) && v.is_finite(), "{text}: {v}");
        }
        // atan's cuts are on the imaginary axis beyond +-i
        let z = CBall::new(Ball::from_f64(0.0, 64).unwrap(), Ball::from_f64(2.0, 64).unwrap());
        assert!(!p("atan(x)").eval(&z).is_finite());
        assert!(p("atan(x)").eval(&real(5.0, 64)).is_finite());
    }
}

mod integrals {
    use super::*;
    use crate::quad::certified::{integrate, HoloBall, Options};
    use rug::Float;

    fn d(text: &str) -> Decimal {
        Decimal::parse(text).unwrap()
    }

    fn run(f: &str, a: &str, b: &str, w: Option<&WeightSpec>, decay: Option<&DecaySpec>, prec: u32) -> crate::quad::certified::Integral {
        let b = UpperLimit::parse(b).unwrap();
        match integrate_range(&p(f), &End::parse(a).unwrap(), &b, w, decay, prec, &Options::new()) {
            Ok(r) => r,
            Err(e) => panic!("{f} over [{a}, {b:?}]: {e}"),
        }
    }

    #[test]
    fn sqrt_over_one_to_four_contains_fourteen_thirds_every_way() {
        let exact = Float::with_val(512, 14) / 3u32;
        let (a, b) = (crate::Ball::from_i64(1, 128), crate::Ball::from_i64(4, 128));
        let direct = integrate(|x: &HoloBall| p("sqrt(x)").eval(x), &a, &b, 128, &Options::new()).unwrap();
        assert!(direct.real().contains(&exact) && direct.goal_met);
        for f in ["sqrt(x)", "x^0.5", "x^(1/2)", "exp(log(x)/2)", "x/sqrt(x)"] {
            let r = run(f, "1", "4", None, None, 128);
            assert!(r.real().contains(&exact), "{f}: {:?}", r.value);
            assert!(r.goal_met && r.real().meets_rel(128), "{f}: {:?}", r.value);
        }
    }

    #[test]
    fn endpoint_weights_and_infinite_ranges() {
        // x^(-1/2) cos(x) over [0, 1] = sqrt(2 pi) C(sqrt(2/pi))
        let w = WeightSpec { alpha: Some(d("-0.5")), ..WeightSpec::default() };
        let r = run("cos(x)", "0", "1", Some(&w), None, 64);
        // the value: reference/data/integrals.csv, row Xcos_rsqrt (mpmath, 3500 digits)
        let table = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/reference/data/integrals.csv")).unwrap();
        let want = table.lines().find(|l| l.starts_with("Xcos_rsqrt,")).unwrap().rsplit(',').next().unwrap();
        let want = Float::with_val(256, Float::parse(want).unwrap());
        assert!(r.goal_met && r.real().contains(&want) && r.real().meets_rel(64), "{:?}", r.value);
        // x log x over [0, 1] = -1/4, as a weight
        let w = WeightSpec { log: 1, ..WeightSpec::default() };
        let r = run("x", "0", "1", Some(&w), None, 64);
        assert!(r.real().contains(&Float::with_val(64, -0.25)), "{:?}", r.value);
        // exp(-x^2) over [0, inf) = sqrt(pi)/2, with |f| <= e^(1/4) e^(-x)
        let decay = DecaySpec::Exponential { rate: d("1"), bound: d("1.2841") };
        let r = run("exp(-x^2)", "0", "inf", None, Some(&decay), 64);
        let exact = Float::with_val(128, rug::float::Constant::Pi).sqrt() / 2u32;
        assert!(r.goal_met && r.real().contains(&exact), "{:?}", r.value);
    }

    #[test]
    fn bad_requests_are_errors() {
        let e = |f: &str, b: &str, decay: Option<&DecaySpec>| {
            integrate_range(&p(f), &End::parse("1").unwrap(), &End::parse(b).unwrap(), None, decay, 64, &Options::new())
        };
        use crate::error::IntegrationError as I;
        assert!(matches!(e("exp(exp(x))", "inf", None), Err(crate::Error::Integration(I::MissingDecay))));
        assert!(matches!(e("1/x", "inf", None), Err(crate::Error::Integration(I::NotAbsolutelyIntegrable { .. }))));
        let decay = DecaySpec::Exponential { rate: d("1"), bound: d("1") };
        assert!(matches!(e("exp(-x)", "2", Some(&decay)), Err(crate::Error::Integration(I::DecayWithFiniteEnd))));
        assert_eq!(UpperLimit::parse("-inf").unwrap(), End::MinusInfinity);
        match UpperLimit::parse("x") {
            Err(crate::Error::Integration(I::UpperEnd { text })) => assert_eq!(text, "x"),
            other => panic!("{other:?}"),
        }
        assert_eq!(UpperLimit::parse(" +Infinity ").unwrap(), UpperLimit::Infinity);
        let w = WeightSpec { alpha: Some(d("-1")), ..WeightSpec::default() };
        let r = integrate_range(&p("1"), &End::parse("0").unwrap(), &UpperLimit::parse("1").unwrap(), Some(&w), None, 64, &Options::new());
        assert!(matches!(r, Err(crate::Error::Integration(_))));
    }
}

/// The evaluation on a piece mapped at an end (`mapped.rs`): the same values on the
/// real axis, and finite boxes far up in `Im s`, where `x` turns around the end.
mod mapped_end {
    use super::*;
    use crate::ball::{Ball, CBall};
    use crate::quad::certified::{HoloBall, MappedEnd, Mode};
    use rug::{Float, Rational};

    const P: u32 = 128;

    /// `x = e + sign d e^{-s}` carrying its end, for `s` the ball `re + i im`.
    fn mapped_x(e: i64, sign: i64, d: f64, s: CBall, mode: Mode) -> (HoloBall, HoloBall) {
        let s = HoloBall::new(s, mode);
        let dd = Ball::from_f64(d, P).unwrap();
        let log_t = s.real(dd.ln().unwrap()) - &s;
        let t = s.real(dd) * (-&s).exp();
        let x = if sign > 0 {
            s.real(Ball::from_i64(e, P)) + &t
        } else {
            s.real(Ball::from_i64(e, P)) - &t
        };
        let plain = HoloBall::new(x.inner_ref().clone(), mode);
        let end = MappedEnd {
            e: Some(Rational::from(e)),
            sign,
            t: t.into_inner(),
            log_t: log_t.into_inner(),
        };
        (x.with_end(end), plain)
    }

    fn ball(lo: f64, hi: f64) -> Ball {
        Ball::hull(&Float::with_val(P, lo), &Float::with_val(P, hi), P)
    }

    const CASES: [(&str, i64, i64); 10] = [
        ("x^x", 0, 1),
        ("log(x)*log(1-x)", 0, 1),
        ("x^(-1/2)*cos(x)", 0, 1),
        ("sqrt(3*x)/(2*x)", 0, 1),
        ("x^-2*(1 - cos(x))", 0, 1),
        ("log(x/3)^2 + exp(x)", 0, 1),
        ("(1-x)^0.3*log(1-x)", 1, -1),
        ("(2 - 2*x)^(-1/3)", 1, -1),
        ("log(x - 1)*x^x", 1, 1),
        ("sqrt(x)*atan(x)", 0, 1),
    ];

    #[test]
    fn the_same_values_on_the_real_axis() {
        for (text, e, sign) in CASES {
            let f = p(text);
            for s in [0.0, 0.5, 3.0, 40.0] {
                let (x, plain) = mapped_x(
                    e,
                    sign,
                    0.25,
                    CBall::from_real(Ball::from_f64(s, P).unwrap()),
                    Mode::Point,
                );
                let (v, w) = (f.eval(&x), f.eval(&plain));
                assert!(v.is_finite() && w.is_finite(), "{text} at s = {s}");
                assert!(
                    v.inner_ref().overlaps(w.inner_ref()),
                    "{text} at s = {s}: {:?} vs {:?}",
                    v.inner_ref(),
                    w.inner_ref()
                );
                // a real segment of s, too
                let seg = CBall::from_real(ball(s, s + 0.5));
                let (x, _) = mapped_x(e, sign, 0.25, seg, Mode::Point);
                assert!(
                    f.eval(&x).inner_ref().overlaps(w.inner_ref()),
                    "{text} on [{s}, {}]",
                    s + 0.5
                );
            }
        }
    }

    #[test]
    fn boxes_that_reach_around_the_end_stay_finite() {
        // Im s in [-4, 4]: x = e + sign e^{-s}/4 goes around e, where log(x - e) has a cut
        for (text, e, sign) in CASES {
            let f = p(text);
            let s = CBall::new(ball(20.0, 24.0), ball(-4.0, 4.0));
            let (x, plain) = mapped_x(e, sign, 0.25, s, Mode::Analytic);
            assert!(f.eval(&x).is_finite(), "{text}");
            assert!(!f.eval(&plain).is_finite(), "{text}: finite from x alone");
        }
    }
}
