//! Exact powers of two: scale factors that introduce no rounding.

/// 2^`exponent`, exactly, for a normal exponent (−1022 ≤ `exponent` ≤ 1023).
pub(crate) const fn pow2(exponent: i32) -> f64 {
    f64::from_bits(((exponent + 1023) as u64) << 52)
}

/// The power of two nearest below `max` (1 for zero or a non-finite
/// `max`), at least 2⁻¹⁰²² so that it is normal: dividing by it brings
/// numbers of largest magnitude `max` near 1, exactly.
pub(crate) fn power_of_two_near(max: f64) -> f64 {
    if max > 0.0 && max.is_finite() {
        pow2((max.log2().floor() as i32).clamp(-1022, 1023))
    } else {
        1.0
    }
}
