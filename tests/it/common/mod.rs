//! Shared pieces of the golden-table tests: the CSV loader, the enclosure check
//! and the per-region accuracy statistics.
//!
//! The tables come from `reference/generate.py` (mpmath, two precisions,
//! 50 significant digits). Nothing here is typed in by hand.

#![allow(dead_code)]

use std::collections::BTreeMap;
use std::path::PathBuf;

use maugis::Ball;
use rug::Float;

/// Precision of the MP golden checks: the references carry 50 significant
/// digits (~166 bits), so 170 bits makes the ball tighter than the reference.
pub const GOLDEN_PREC: u32 = 170;

/// Relative uncertainty of a 50-significant-digit reference value (rounding of
/// the last digit, plus the 52-digit agreement the generator demands).
pub const REF_REL_SLACK: f64 = 1e-49;

/// One row of a golden table: column name -> text.
pub type Row = BTreeMap<String, String>;

/// Loads `reference/data/<name>.csv` (comment lines start with `#`).
pub fn load(name: &str) -> Vec<Row> {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "reference", "data", &format!("{name}.csv")].iter().collect();
    let mut rdr = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_path(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e} (run python3 reference/generate.py)", path.display()));
    let headers = rdr.headers().expect("csv header").clone();
    rdr.records()
        .map(|r| {
            let r = r.expect("csv record");
            headers.iter().zip(r.iter()).map(|(h, v)| (h.to_string(), v.to_string())).collect()
        })
        .collect()
}

/// A column as f64 (inputs are written as exactly representable doubles).
pub fn col_f64(row: &Row, name: &str) -> f64 {
    row[name].parse::<f64>().unwrap_or_else(|_| panic!("column {name} = {:?} is not a double", row[name]))
}

/// A column as integer.
pub fn col_i64(row: &Row, name: &str) -> i64 {
    let t = &row[name];
    t.parse::<i64>().unwrap_or_else(|_| t.parse::<f64>().expect("integer column") as i64)
}

/// The reference value as a high-precision float.
pub fn reference(row: &Row) -> Float {
    Float::with_val(320, Float::parse(&row["value"]).expect("reference value parses"))
}

/// Whether `ball` contains the reference (up to the reference's own uncertainty).
pub fn encloses(ball: &Ball, reference: &Float) -> bool {
    let d = Float::with_val(400, ball.mid() - reference).abs();
    let slack = Float::with_val(400, reference.clone().abs() * REF_REL_SLACK);
    let allowed = Float::with_val(400, ball.rad() + &slack);
    d <= allowed
}

/// Accuracy statistics of one region, in units of f64 epsilon (2^-52).
#[derive(Default, Debug, Clone)]
pub struct Stats {
    pub count: usize,
    pub max: f64,
    pub sum_sq: f64,
    pub failures: Vec<String>,
}

impl Stats {
    pub fn add(&mut self, err_eps: f64) {
        self.count += 1;
        self.max = self.max.max(err_eps);
        self.sum_sq += err_eps * err_eps;
    }
    pub fn rms(&self) -> f64 {
        if self.count == 0 {
            0.0
        } else {
            (self.sum_sq / self.count as f64).sqrt()
        }
    }
}

/// Relative error of `v` against the reference, in units of f64 epsilon.
pub fn rel_err_eps(v: f64, reference: &Float) -> f64 {
    if reference.is_zero() {
        return if v == 0.0 { 0.0 } else { f64::INFINITY };
    }
    let d = Float::with_val(200, Float::with_val(200, v) - reference).abs();
    let r = Float::with_val(200, &d / reference.clone().abs());
    r.to_f64() / f64::EPSILON
}

/// Absolute error of `v` against the reference, in units of 2^-53.
pub fn abs_err_units(v: f64, reference: &Float) -> f64 {
    let d = Float::with_val(200, Float::with_val(200, v) - reference).abs();
    d.to_f64() / 2f64.powi(-53)
}

/// Prints the per-region table and returns it as Markdown rows.
pub fn report(function: &str, stats: &BTreeMap<String, Stats>, unit: &str) -> String {
    let mut out = String::new();
    for (region, s) in stats {
        out.push_str(&format!(
            "| {function} | {region} | {} | {:.3} | {:.3} | {unit} |\n",
            s.count,
            s.max,
            s.rms()
        ));
    }
    eprint!("{out}");
    out
}

/// Saves an accuracy report fragment under `target/accuracy/` for the docs.
pub fn save_report(function: &str, table: &str) {
    let dir: PathBuf = [env!("CARGO_MANIFEST_DIR"), "target", "accuracy"].iter().collect();
    let _ = std::fs::create_dir_all(&dir);
    let _ = std::fs::write(dir.join(format!("{function}.md")), table);
}

/// Precision of the decimal-input reference checks (the tables carry 100 digits).
pub const DECIMAL_REF_BITS: u32 = 400;

/// `|mid - ref| <= rad + 1e-99 max(|ref|, scale)`: the ball contains a
/// 100-digit reference of the decimal-input tables (`*_decimal.csv`), within its
/// last digit; `scale` is the function's natural size where it may vanish.
pub fn contains_decimal_ref(b: &Ball, r: &Float, scale: Option<&Float>) -> bool {
    let p = DECIMAL_REF_BITS;
    let diff = Float::with_val(p, b.mid() - r).abs();
    let mut size = Float::with_val(p, r.abs_ref());
    if let Some(s) = scale {
        size = size.max(s);
    }
    let slack = size * Float::with_val(p, 1e-99);
    diff <= Float::with_val(p, b.rad() + slack)
}

/// `|mid - ref| <= rad + 1e-38 |ref|`: the ball contains a 40-digit reference
/// (`hyp2f1_decimal_corners.csv`, `hyp2f1_large_param.csv`) within its last digit.
pub fn contains_40_digit_ref(b: &Ball, r: &Float) -> bool {
    let p = DECIMAL_REF_BITS;
    let diff = Float::with_val(p, b.mid() - r).abs();
    diff <= Float::with_val(p, b.rad() + Float::with_val(p, r.abs_ref()) * Float::with_val(p, 1e-38))
}

/// MP `2F1` at decimal strings, as `maugis eval` (and the registry's MP path) runs
/// `{"fn": "hyp2f1", ...}`.
pub fn hyp2f1_at_decimals(a: &str, b: &str, c: &str, z: &str, prec: u32) -> maugis::Result<Ball> {
    use maugis::ball::{eval_at_decimals, Decimal};
    let d: Vec<Decimal> = [a, b, c, z].iter().map(|s| Decimal::parse(s).expect("decimal parses")).collect();
    eval_at_decimals(&d, prec, |x| maugis::special::hyp2f1::hyp2f1_ball_mp(&x[0], &x[1], &x[2], &x[3], prec))
}

/// The fields of one line of the integral tables (`reference/data/integrals_*.csv`):
/// comma-separated, a field in double quotes may hold commas.
pub fn csv_fields(line: &str) -> Vec<String> {
    let mut fields = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    for ch in line.chars() {
        match ch {
            '"' => quoted = !quoted,
            ',' if !quoted => fields.push(std::mem::take(&mut cur)),
            c => cur.push(c),
        }
    }
    fields.push(cur);
    fields
}
