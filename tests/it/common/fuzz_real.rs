//! The f64 generator shared by the fuzz targets of the library (tests/it/fuzz.rs)
//! and of the solver (solver/tests/it/fuzz.rs, which includes this file by path):
//! an f64 from 64 random bits.

/// A raw bit pattern, one of `edges` (values at and next to the domain edges of
/// the functions under test), a small multiple of 1/8, or a value in `[-10, 30)`,
/// chosen by the top two bits.
pub fn real_with(bits: u64, edges: &[f64]) -> f64 {
    match bits >> 62 {
        0 => f64::from_bits(bits),
        1 => edges[(bits % edges.len() as u64) as usize],
        2 => ((bits % 4001) as f64 - 2000.0) / 8.0,
        _ => (bits >> 11) as f64 / (1u64 << 53) as f64 * 40.0 - 10.0,
    }
}
