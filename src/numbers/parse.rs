//! Reading numbers from scene files: decimals, fractions and powers of ten,
//! exactly, with bounds against absurd input.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use super::*;

/// Why a piece of text is not a number zsim accepts.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NumberError {
    /// Not a decimal, an integer or a fraction `p/q`.
    NotANumber(String),
    /// A fraction with denominator zero.
    ZeroDenominator(String),
    /// Too many digits or too large an exponent to hold exactly.
    TooLarge(String),
    /// More digits or a larger power of ten than a vertex coordinate may
    /// have (`MAX_BIG_DIGITS`).
    TooLong(String),
}

impl NumberError {
    /// What is wrong and the text that failed, as a fact a serde visitor
    /// carries to where it is worded ([`crate::words::fact`]).
    pub fn fact(&self) -> String {
        let max = MAX_BIG_DIGITS.to_string();
        match self {
            NumberError::NotANumber(text) => crate::words::fact("number-not-a-number", &[("text", text)]),
            NumberError::ZeroDenominator(text) => crate::words::fact("number-zero-denominator", &[("text", text)]),
            NumberError::TooLarge(text) => crate::words::fact("number-too-large", &[("text", text)]),
            NumberError::TooLong(text) => crate::words::fact("number-too-long", &[("text", text), ("max", &max)]),
        }
    }

    /// The message in `lang`, one line.
    pub fn message(&self, lang: crate::words::Lang) -> String {
        crate::words::json_reason(lang, &self.fact())
    }
}

/// Reads an integer, a decimal (`-2.125`, `1e3`, `2.5E-2`) or a fraction of
/// two integers (`5/2`, `-7/3`) exactly. Decimals never pass through binary
/// floating point: `2.1` is `21/10`.
///
/// ```
/// use zsim::{parse_number, Q};
/// assert_eq!(parse_number("2.1").unwrap(), Q::new(21, 10));
/// assert_eq!(parse_number("-5/2").unwrap(), Q::new(-5, 2));
/// assert!(parse_number("1/0").is_err());
/// ```
pub fn parse_number(text: &str) -> Result<Q, NumberError> {
    let trimmed = text.trim();
    // Most scene numbers are plain integers: no fraction to reduce.
    if trimmed.len() <= 18
        && !trimmed.is_empty()
        && trimmed.bytes().enumerate().all(|(i, b)| b.is_ascii_digit() || (i == 0 && b == b'-' && trimmed.len() > 1))
        && let Ok(value) = trimmed.parse::<i64>()
    {
        return Ok(Q::from_integer(i128::from(value)));
    }
    if let Some((num, den)) = trimmed.split_once('/') {
        let num = parse_decimal(num.trim(), text)?;
        let den = parse_decimal(den.trim(), text)?;
        if *den.numer() == 0 {
            return Err(NumberError::ZeroDenominator(text.to_string()));
        }
        return checked_div(num, den).ok_or_else(|| NumberError::TooLarge(text.to_string()));
    }
    parse_decimal(trimmed, text)
}

/// Most significant digits a decimal may have: 10^30 < 2^100 leaves room for
/// the exponent and the common denominators built later.
const MAX_DIGITS: usize = 30;

/// A decimal as written: its sign, its significant digits (no leading
/// zeros) and the power of ten they are scaled by.
struct Decimal {
    negative: bool,
    significant: String,
    scale: i64,
}

/// Reads `-12.5e3`: sign, digits with an optional point, an optional exponent.
fn read_decimal(text: &str, whole: &str) -> Result<Decimal, NumberError> {
    let not_a_number = || NumberError::NotANumber(whole.to_string());
    let (negative, rest) = match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    let (mantissa, exponent) = match rest.find(['e', 'E']) {
        Some(at) => {
            let exponent: i32 = rest[at + 1..].parse().map_err(|_| not_a_number())?;
            (&rest[..at], exponent)
        }
        None => (rest, 0),
    };
    let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if int_part.is_empty() && frac_part.is_empty() {
        return Err(not_a_number());
    }
    if !int_part.bytes().all(|b| b.is_ascii_digit()) || !frac_part.bytes().all(|b| b.is_ascii_digit()) {
        return Err(not_a_number());
    }
    let digits = format!("{int_part}{frac_part}");
    let significant = digits.trim_start_matches('0').to_string();
    Ok(Decimal { negative, significant, scale: i64::from(exponent) - frac_part.len() as i64 })
}

fn parse_decimal(text: &str, whole: &str) -> Result<Q, NumberError> {
    let too_large = || NumberError::TooLarge(whole.to_string());
    let Decimal { negative, significant, scale } = read_decimal(text, whole)?;
    if significant.len() > MAX_DIGITS {
        return Err(too_large());
    }
    let mut numer: i128 = if significant.is_empty() { 0 } else { significant.parse().map_err(|_| too_large())? };
    let mut denom: i128 = 1;
    if numer != 0 {
        let power = u32::try_from(scale.unsigned_abs())
            .ok()
            .filter(|power| *power <= 36)
            .and_then(|power| 10i128.checked_pow(power))
            .ok_or_else(too_large)?;
        if scale >= 0 {
            numer = numer.checked_mul(power).ok_or_else(too_large)?;
        } else {
            denom = power;
        }
    }
    if negative {
        numer = -numer;
    }
    Ok(Q::new(numer, denom))
}

/// Most significant digits, and largest power of ten, a vertex coordinate
/// may be written with: far beyond any homework (a double printed in full
/// has 17 digits), and far enough below what would exhaust memory or time.
/// Coordinates past [`crate::geometry::plane::MAX_SCALED_BITS`] are refused later.
pub const MAX_BIG_DIGITS: usize = 1000;

/// Reads a number as [`parse_number`] does, of any size up to
/// `MAX_BIG_DIGITS` digits and powers of ten: a 128-bit fraction where it
/// fits, a big one where not (for vertex coordinates).
///
/// ```
/// use zsim::{parse_exact, Exact, Q};
/// assert_eq!(parse_exact("2.5").unwrap(), Exact::Word(Q::new(5, 2)));
/// assert!(parse_exact("0.1234567890123456789012345678901234567890").unwrap().word().is_none());
/// ```
pub fn parse_exact(text: &str) -> Result<Exact, NumberError> {
    match parse_number(text) {
        Err(NumberError::TooLarge(_)) => {}
        other => return other.map(Exact::Word),
    }
    let trimmed = text.trim();
    let big = |part: &str| {
        let Decimal { negative, significant, scale } = read_decimal(part.trim(), text)?;
        let too_long = || NumberError::TooLong(text.to_string());
        if significant.len() > MAX_BIG_DIGITS || scale.unsigned_abs() > MAX_BIG_DIGITS as u64 {
            return Err(too_long());
        }
        let digits: BigInt =
            if significant.is_empty() { BigInt::zero() } else { significant.parse().map_err(|_| too_long())? };
        let digits = if negative { -digits } else { digits };
        let power = BigInt::from(10).pow(scale.unsigned_abs() as u32);
        Ok(if scale >= 0 { BigRational::from_integer(digits * power) } else { BigRational::new(digits, power) })
    };
    let value = match trimmed.split_once('/') {
        Some((num, den)) => {
            let (num, den) = (big(num)?, big(den)?);
            if den.is_zero() {
                return Err(NumberError::ZeroDenominator(text.to_string()));
            }
            num / den
        }
        None => big(trimmed)?,
    };
    Ok(Exact::from(value))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_are_read_exactly() {
        assert_eq!(parse_number("2.1").unwrap(), Q::new(21, 10));
        assert_eq!(parse_number("-0.125").unwrap(), Q::new(-1, 8));
        assert_eq!(parse_number("1e3").unwrap(), Q::from_integer(1000));
        assert_eq!(parse_number("2.5E-2").unwrap(), Q::new(1, 40));
        assert_eq!(parse_number(".5").unwrap(), Q::new(1, 2));
        assert_eq!(parse_number("7/-2").unwrap(), Q::new(-7, 2));
    }

    #[test]
    fn fractions_are_read_and_reduced() {
        assert_eq!(parse_number("10/4").unwrap(), Q::new(5, 2));
        assert_eq!(parse_number(" -7/3 ").unwrap(), Q::new(-7, 3));
        assert_eq!(parse_number("1/0").unwrap_err(), NumberError::ZeroDenominator("1/0".into()));
    }

    #[test]
    fn non_numbers_are_refused() {
        for text in ["abc", "", "-", "1.2.3", "1/2/3", "1e", "0x10", "1 2"] {
            assert!(parse_number(text).is_err(), "{text:?} was accepted");
        }
        assert!(matches!(parse_number("1234567890123456789012345678901"), Err(NumberError::TooLarge(_))));
        assert!(matches!(parse_number("1e40"), Err(NumberError::TooLarge(_))));
    }

    /// A vertex coordinate may have up to MAX_BIG_DIGITS significant digits
    /// and powers of ten; past that (memory and time, not exactness) it is
    /// refused, as settings are past 30 digits.
    #[test]
    fn vertex_coordinates_may_have_up_to_a_thousand_digits() {
        let sevens = |n: usize| format!("0.{}", "7".repeat(n));
        let long = parse_exact(&sevens(1000)).unwrap();
        assert_eq!(
            long.to_big(),
            BigRational::new(BigInt::from(7) * (BigInt::from(10).pow(1000) - 1) / 9, BigInt::from(10).pow(1000))
        );
        assert!(matches!(parse_exact(&sevens(1001)), Err(NumberError::TooLong(_))));
        assert!(matches!(parse_number(&sevens(31)), Err(NumberError::TooLarge(_))));
        assert_eq!(parse_exact("1e1000").unwrap(), Exact::integer(BigInt::from(10).pow(1000)));
        assert!(matches!(parse_exact("1e1001"), Err(NumberError::TooLong(_))));
        assert!(matches!(parse_exact("1e-1001"), Err(NumberError::TooLong(_))));
        let third = "1234567890123456789012345678901234567890/3";
        assert_eq!(
            parse_exact(third).unwrap().to_big(),
            BigRational::new("1234567890123456789012345678901234567890".parse().unwrap(), BigInt::from(3))
        );
        assert_eq!(parse_exact("-2.5").unwrap(), Exact::Word(Q::new(-5, 2)));
        assert!(matches!(parse_exact("1/0.000"), Err(NumberError::ZeroDenominator(_))));
        assert!(matches!(parse_exact("1.2.3"), Err(NumberError::NotANumber(_))));
    }
}
