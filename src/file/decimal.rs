//! Decimal numbers written in a file, scaled by an exact ratio (or by π
//! times one) and rounded once: "80.3" millimetres become the f64 nearest
//! to 80.3/1000 (the number read as `80.3e-3`), not the product of two
//! rounded numbers; "30" degrees the f64 nearest to π/6.

/// Significant digits of a quotient past which a non-zero remainder is
/// marked by one more digit: every midpoint between two adjacent f64 has
/// fewer significant decimal digits than this (at most 767), so the digits
/// kept and the mark are on the same side of every rounding boundary as the
/// exact quotient, and the parser's one rounding is the exact quotient's.
const QUOTIENT_DIGITS: usize = 800;

/// π's first 250 digits, truncated: π lies between this × 10^-249 and one
/// more in the last place (mpmath, at 320 digits).
const PI_DIGITS: &str = "3141592653589793238462643383279502884197169399375105820974944592307816406286208998628034825342117067982148086513282306647093844609550582231725359408128481117450284102701938521105559644622948954930381964428810975665933446128475648233786783165271201909";
/// The power of ten of π's last digit in [`PI_DIGITS`].
const PI_EXPONENT: i64 = -249;

/// A decimal number as written: its sign, its significant digits (no
/// leading zeros) and the power of ten they are multiplied by.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Decimal {
    negative: bool,
    digits: Vec<u8>,
    exponent: i64,
}

impl Decimal {
    /// `[+-]digits[.digits][(e|E)[+-]digits]`, or `.digits` for the
    /// integer part; `None` for anything else.
    fn parse(text: &str) -> Option<Decimal> {
        let bytes = text.as_bytes();
        let mut k = 0;
        let negative = match bytes.first() {
            Some(b'-') => {
                k = 1;
                true
            }
            Some(b'+') => {
                k = 1;
                false
            }
            _ => false,
        };
        let mut digits = Vec::new();
        let mut exponent: i64 = 0;
        let mut seen_digit = false;
        while let Some(&b) = bytes.get(k).filter(|b| b.is_ascii_digit()) {
            digits.push(b - b'0');
            seen_digit = true;
            k += 1;
        }
        if bytes.get(k) == Some(&b'.') {
            k += 1;
            while let Some(&b) = bytes.get(k).filter(|b| b.is_ascii_digit()) {
                digits.push(b - b'0');
                exponent = exponent.saturating_sub(1);
                seen_digit = true;
                k += 1;
            }
        }
        if !seen_digit {
            return None;
        }
        if matches!(bytes.get(k), Some(b'e' | b'E')) {
            k += 1;
            let sign: i64 = match bytes.get(k) {
                Some(b'-') => {
                    k += 1;
                    -1
                }
                Some(b'+') => {
                    k += 1;
                    1
                }
                _ => 1,
            };
            let start = k;
            let mut written: i64 = 0;
            while let Some(&b) = bytes.get(k).filter(|b| b.is_ascii_digit()) {
                written = written
                    .saturating_mul(10)
                    .saturating_add(i64::from(b - b'0'));
                k += 1;
            }
            if k == start {
                return None;
            }
            exponent = exponent.saturating_add(sign * written);
        }
        if k != bytes.len() {
            return None;
        }
        let first = digits.iter().position(|&d| d != 0).unwrap_or(digits.len());
        digits.drain(..first);
        Some(Decimal {
            negative,
            digits,
            exponent,
        })
    }

    /// Times another decimal number, exactly.
    fn times_decimal(&self, other: &Decimal) -> Decimal {
        let mut product = vec![0u64; self.digits.len() + other.digits.len()];
        // A place's sum is at most 81 times the shorter number's length:
        // no overflow; carried once at the end.
        for (i, &a) in self.digits.iter().enumerate() {
            for (j, &b) in other.digits.iter().enumerate() {
                product[i + j + 1] += u64::from(a) * u64::from(b);
            }
        }
        for k in (1..product.len()).rev() {
            product[k - 1] += product[k] / 10;
            product[k] %= 10;
        }
        let mut digits: Vec<u8> = product.into_iter().map(|d| d as u8).collect();
        let first = digits.iter().position(|&d| d != 0).unwrap_or(digits.len());
        digits.drain(..first);
        Decimal {
            negative: self.negative != other.negative,
            digits,
            exponent: self.exponent.saturating_add(other.exponent),
        }
    }

    /// Times a whole number, exactly.
    fn times(mut self, factor: u64) -> Decimal {
        let mut carry: u128 = 0;
        for d in self.digits.iter_mut().rev() {
            let x = u128::from(*d) * u128::from(factor) + carry;
            *d = (x % 10) as u8;
            carry = x / 10;
        }
        let mut head = Vec::new();
        while carry > 0 {
            head.push((carry % 10) as u8);
            carry /= 10;
        }
        head.reverse();
        head.extend_from_slice(&self.digits);
        self.digits = head;
        let first = self
            .digits
            .iter()
            .position(|&d| d != 0)
            .unwrap_or(self.digits.len());
        self.digits.drain(..first);
        self
    }

    /// Divided by a whole number (not 0): the quotient's digits up to
    /// [`QUOTIENT_DIGITS`] significant ones, then one more non-zero digit
    /// if anything is left over.
    fn over(self, divisor: u64) -> Decimal {
        if divisor == 1 || self.digits.is_empty() {
            return self;
        }
        let divisor = u128::from(divisor);
        let mut quotient = Vec::with_capacity(self.digits.len() + 8);
        let mut remainder: u128 = 0;
        let mut exponent = self.exponent;
        let mut k = 0;
        loop {
            let next = match self.digits.get(k) {
                Some(&d) => d,
                None if remainder == 0 => break,
                None => {
                    exponent = exponent.saturating_sub(1);
                    0
                }
            };
            k += 1;
            let x = remainder * 10 + u128::from(next);
            let q = (x / divisor) as u8;
            remainder = x % divisor;
            // Leading zeros are dropped: the last digit's place alone
            // fixes the value.
            if q != 0 || !quotient.is_empty() {
                quotient.push(q);
            }
            if quotient.len() >= QUOTIENT_DIGITS && k >= self.digits.len() {
                if remainder != 0 {
                    quotient.push(1);
                    exponent = exponent.saturating_sub(1);
                }
                break;
            }
        }
        // The last digit produced stands for 10^exponent.
        Decimal {
            negative: self.negative,
            digits: quotient,
            exponent,
        }
    }

    /// The nearest f64 (Rust's parser rounds once, correctly).
    fn to_f64(&self) -> f64 {
        if self.digits.is_empty() {
            return if self.negative { -0.0 } else { 0.0 };
        }
        let mut text = String::with_capacity(self.digits.len() + 24);
        if self.negative {
            text.push('-');
        }
        text.extend(self.digits.iter().map(|&d| char::from(b'0' + d)));
        text.push('e');
        text.push_str(&self.exponent.to_string());
        // Digits and an exponent, as built above: always a number.
        text.parse().unwrap_or(f64::NAN)
    }
}

/// Whether `text` is a decimal number this module reads.
pub(super) fn is_decimal(text: &str) -> bool {
    Decimal::parse(text).is_some()
}

/// The decimal `text` times `numerator / denominator`, rounded once to the
/// nearest f64; `None` if `text` is not a decimal number or the
/// denominator is 0.
pub(super) fn scaled(text: &str, numerator: u64, denominator: u64) -> Option<f64> {
    if denominator == 0 {
        return None;
    }
    let decimal = Decimal::parse(text)?;
    Some(decimal.times(numerator).over(denominator).to_f64())
}

/// The decimal `text` times π·`numerator`/`denominator`, rounded once to
/// the nearest f64; `None` if `text` is not a decimal number or the
/// denominator is 0.
///
/// π is known to 250 digits, so the exact product lies between the two
/// bounds of [`pi_bounds`], 10^-249 (relative) apart; when both round to
/// the same f64 — always, short of a product within 10^-249 of a midpoint
/// between two f64 — that is the correctly rounded result (rounding is
/// monotonic). The lower bound's rounding is returned.
pub(super) fn scaled_by_pi(text: &str, numerator: u64, denominator: u64) -> Option<f64> {
    pi_bounds(text, numerator, denominator).map(|(low, _)| low)
}

/// The roundings of `text`·π·`numerator`/`denominator` with π truncated
/// to [`PI_DIGITS`] and one more in its last place.
fn pi_bounds(text: &str, numerator: u64, denominator: u64) -> Option<(f64, f64)> {
    if denominator == 0 {
        return None;
    }
    let decimal = Decimal::parse(text)?.times(numerator);
    let truncated = Decimal {
        negative: false,
        digits: PI_DIGITS.bytes().map(|b| b - b'0').collect(),
        exponent: PI_EXPONENT,
    };
    let mut above = truncated.clone();
    // One more in the last place (…909 → …910: the carry stops at once).
    for d in above.digits.iter_mut().rev() {
        *d += 1;
        if *d < 10 {
            break;
        }
        *d = 0;
    }
    let bound = |pi: &Decimal| decimal.times_decimal(pi).over(denominator).to_f64();
    Some((bound(&truncated), bound(&above)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn reads_what_a_person_writes() {
        assert_eq!(scaled("80", 1, 1), Some(80.0));
        assert_eq!(scaled("-0.5", 1, 1), Some(-0.5));
        assert_eq!(scaled("+.25", 1, 1), Some(0.25));
        assert_eq!(scaled("1e3", 1, 1), Some(1000.0));
        assert_eq!(scaled("2.5E-1", 1, 1), Some(0.25));
        for bad in [
            "", "-", ".", "1e", "1e+", "1.2.3", "0x10", "1_000", " 1", "inf", "nan",
        ] {
            assert_eq!(scaled(bad, 1, 1), None, "{bad:?}");
        }
    }

    #[test]
    fn a_power_of_ten_shifts_the_exponent() {
        // 9.81 mm: the number read as 9.81e-3, not 9.81 × 0.001 (one
        // rounding, not three).
        assert_eq!(scaled("9.81", 1, 1000), Some(0.00981));
        assert_eq!(9.81 * 0.001, 0.009810000000000001);
        assert_eq!(scaled("80.3", 1, 1000), Some("80.3e-3".parse().unwrap()));
        assert_eq!(scaled("0.08", 1000, 1), Some(80.0));
        assert_eq!(scaled("7", 1, 1000), Some(0.007));
    }

    #[test]
    fn other_ratios_round_once() {
        // An inch is 254/10000 m; 5 mm in inches is 50/254, whose nearest
        // f64 Python's fractions give: float(Fraction(50, 254)).
        assert_eq!(scaled("1", 254, 10000), Some(0.0254));
        assert_eq!(scaled("5", 10, 254), Some(0.1968503937007874));
        // A third: 1/3 to the last bit, and 2/3 too.
        assert_eq!(scaled("1", 1, 3), Some(1.0 / 3.0));
        assert_eq!(scaled("2", 1, 3), Some(2.0 / 3.0));
        assert_eq!(scaled("0", 7, 3), Some(0.0));
        assert_eq!(scaled("-0", 1, 1), Some(-0.0));
    }

    #[test]
    fn extremes_overflow_and_underflow_as_the_parser_does() {
        assert_eq!(scaled("1e400", 1, 1), Some(f64::INFINITY));
        assert_eq!(scaled("1e-400", 1, 1), Some(0.0));
        assert_eq!(
            scaled("1e99999999999999999999999", 1, 1000),
            Some(f64::INFINITY)
        );
        assert_eq!(scaled("1e-99999999999999999999999", 3, 7), Some(0.0));
        assert_eq!(scaled("1", 1, 0), None);
    }

    #[test]
    fn pi_scales_round_once_too() {
        use std::f64::consts::{FRAC_PI_2, FRAC_PI_6, PI, TAU};
        // The nearest f64 to π/2, π, 2π are the constants.
        assert_eq!(scaled_by_pi("90", 1, 180), Some(FRAC_PI_2));
        assert_eq!(scaled_by_pi("180", 1, 180), Some(PI));
        assert_eq!(scaled_by_pi("1", 2, 1), Some(TAU));
        assert_eq!(scaled_by_pi("-360", 1, 180), Some(-TAU));
        assert_eq!(scaled_by_pi("0", 1, 180), Some(0.0));
        // π/6 to the last bit (std's constant, and mpmath's
        // float(mp.pi/6)), one ulp above both `PI / 6.0` and
        // `30f64.to_radians()`.
        assert_eq!(scaled_by_pi("30", 1, 180), Some(FRAC_PI_6));
        assert_eq!(FRAC_PI_6.to_bits(), (PI / 6.0).to_bits() + 1);
        // 73 rpm: float(73·2π/60) = 7.644542123735164 (mpmath).
        assert_eq!(scaled_by_pi("73", 2, 60), Some(7.644542123735164));
        assert_eq!(scaled_by_pi("1", 1, 0), None);
    }

    proptest! {
        /// The two bounds of π agree: the result is the correctly rounded
        /// product.
        #[test]
        fn pi_bounds_agree(mantissa in 0u64..100_000_000_000, point in 0u32..8, exponent in -30i32..30) {
            let text = format!("{}e{}", mantissa as f64 / 10f64.powi(point as i32), exponent);
            let (low, high) = pi_bounds(&text, 1, 180).unwrap();
            prop_assert_eq!(low.to_bits(), high.to_bits(), "{}", text);
            let (low, high) = pi_bounds(&text, 2, 60).unwrap();
            prop_assert_eq!(low.to_bits(), high.to_bits(), "{}", text);
        }

        /// A power of ten is an exponent shift: the result is the parser's
        /// reading of the shifted text.
        #[test]
        fn powers_of_ten_agree_with_the_parser(
            mantissa in 0u64..10_000_000_000,
            point in 0usize..12,
            shift in 0u32..7,
            negative in any::<bool>(),
        ) {
            let digits = mantissa.to_string();
            let point = point.min(digits.len());
            let text = format!(
                "{}{}.{}",
                if negative { "-" } else { "" },
                &digits[..digits.len() - point],
                &digits[digits.len() - point..],
            );
            let text = text.replace("-.", "-0.");
            let text = if text.starts_with('.') { format!("0{text}") } else { text };
            let expected: f64 = format!("{text}e-{shift}").parse().unwrap();
            prop_assert_eq!(scaled(&text, 1, 10u64.pow(shift)), Some(expected));
            let expected: f64 = format!("{text}e{shift}").parse().unwrap();
            prop_assert_eq!(scaled(&text, 10u64.pow(shift), 1), Some(expected));
        }

        /// A small whole number over a divisor is the nearest f64 to the
        /// quotient: the f64 division of two exact f64 is correctly
        /// rounded too.
        #[test]
        fn small_quotients_agree_with_division(a in 0u64..1 << 53, b in 1u64..1 << 20) {
            prop_assert_eq!(scaled(&a.to_string(), 1, b), Some(a as f64 / b as f64));
        }
    }
}
