//! Exact numbers written for people: reduced fractions, fixed decimals,
//! both side by side, in the reader's decimal convention.

use crate::words::Lang;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::*;

/// Formats a rational the way zsim prints exact values: reduced, `43/4`, or
/// `10` when whole (every digit, however large).
pub fn fraction(value: impl Into<Exact>) -> String {
    match value.into() {
        Exact::Word(q) if q.is_integer() => q.numer().to_string(),
        Exact::Word(q) => format!("{}/{}", q.numer(), q.denom()),
        Exact::Big(b) if b.is_integer() => b.numer().to_string(),
        Exact::Big(b) => format!("{}/{}", b.numer(), b.denom()),
    }
}

/// A big integer as a message prints it: whole up to 60 digits, beyond
/// that its first and last 12 digits and how many there are
/// (`123456789012…345678901234 (1304 digits)`), so a line stays readable.
pub fn big_integer(lang: Lang, value: &num_bigint::BigInt) -> String {
    let text = value.to_string();
    let (sign, digits) = text.strip_prefix('-').map_or(("", text.as_str()), |rest| ("-", rest));
    if digits.len() <= 60 {
        return text;
    }
    let count = words!(lang, "digits", count = digits.len().to_string());
    format!("{sign}{}…{} ({count})", &digits[..12], &digits[digits.len() - 12..])
}

/// A number as a student writes it: `12`, `12.5`, `5.375`, or a fraction
/// (`41/3`) when no decimal of at most four places is exact; the decimal
/// separator is the language's (`12,5` in Russian).
///
/// ```
/// use zsim::{Lang, Q, short};
/// let short = |q| short(Lang::En, q);
/// assert_eq!((short(Q::new(13, 2)), short(Q::new(43, 8)), short(Q::new(41, 3))), ("6.5".into(), "5.375".into(), "41/3".into()));
/// assert_eq!(zsim::short(Lang::Ru, Q::new(25, 2)), "12,5");
/// ```
pub fn short(lang: Lang, value: impl Into<Exact>) -> String {
    crate::words::localize_decimal(lang, short_in_files(value))
}

/// [`short`] with a point in every language: for files (scene files, JSON)
/// and for English text.
pub fn short_in_files(value: impl Into<Exact>) -> String {
    let value = value.into().to_big();
    (0..=4u32)
        .find(|places| (&value * BigInt::from(10).pow(*places)).is_integer())
        .map_or_else(|| fraction(value.clone()), |places| decimal(value.clone(), places))
}

/// The decimal approximation printed beside an exact value: always `places`
/// digits after the point, rounded half away from zero, computed exactly.
pub fn decimal(value: impl Into<Exact>, places: u32) -> String {
    let value = match value.into() {
        Exact::Word(q) => q,
        Exact::Big(big) => return big_decimal(&big, places),
    };
    let negative = *value.numer() < 0;
    let numer = value.numer().unsigned_abs();
    let denom = value.denom().unsigned_abs();
    let whole = numer / denom;
    let mut rem = numer % denom;
    let mut digits = Vec::with_capacity(places as usize + 1);
    for _ in 0..=places {
        // rem < denom < 2^127, so 10·rem may only overflow for denominators
        // above 2^123; fall back to one digit fewer of precision there.
        let scaled = rem.saturating_mul(10);
        digits.push((scaled / denom) as u8);
        rem = scaled % denom;
    }
    let round_up = digits.pop().unwrap_or(0) >= 5;
    let mut whole = whole;
    if round_up {
        let mut carry = true;
        for digit in digits.iter_mut().rev() {
            if *digit == 9 {
                *digit = 0;
            } else {
                *digit += 1;
                carry = false;
                break;
            }
        }
        if carry {
            whole += 1;
        }
    }
    let all_zero = whole == 0 && digits.iter().all(|&d| d == 0);
    let sign = if negative && !all_zero { "-" } else { "" };
    let frac: String = digits.iter().map(|d| char::from(b'0' + d)).collect();
    if places == 0 { format!("{sign}{whole}") } else { format!("{sign}{whole}.{frac}") }
}

/// [`decimal`] of a value beyond 128 bits, by one big division.
fn big_decimal(value: &BigRational, places: u32) -> String {
    let (numer, denom) = (value.numer().abs(), value.denom());
    let scale = BigInt::from(10).pow(places);
    // Rounded half away from zero: ⌊(2·|n|·10^p + d) / 2d⌋.
    let rounded: BigInt = (numer * &scale * 2 + denom) / (denom * 2);
    let digits = rounded.to_string();
    let digits = format!("{digits:0>width$}", width = places as usize + 1);
    let (whole, frac) = digits.split_at(digits.len() - places as usize);
    let sign = if value.is_negative() && !rounded.is_zero() { "-" } else { "" };
    if places == 0 { format!("{sign}{whole}") } else { format!("{sign}{whole}.{frac}") }
}

/// `43/4 ≈ 10.75`: the exact value and its decimal with 2 places, as zsim
/// shows depths and crossings. Whole numbers print once: `10`.
pub fn exact_and_decimal(lang: Lang, value: impl Into<Exact>) -> String {
    exact_and_places(lang, value, 2)
}

/// The exact value and its decimal with `places` places (`4876543/5000000 ≈
/// 0.975309`); whole numbers print once.
pub fn exact_and_places(lang: Lang, value: impl Into<Exact>, places: u32) -> String {
    let value = value.into();
    if value.is_integer() {
        fraction(value)
    } else {
        // The decimal in the reader's convention (10,75 in Russian); the fraction stays as it is.
        format!("{} ≈ {}", fraction(&value), crate::words::localize_decimal(lang, decimal(value, places)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_print_with_fixed_places() {
        assert_eq!(decimal(Q::new(43, 4), 2), "10.75");
        assert_eq!(decimal(Q::new(151, 6), 2), "25.17");
        assert_eq!(decimal(Q::new(-1, 3), 2), "-0.33");
        assert_eq!(decimal(Q::new(-1, 1000), 2), "0.00");
        assert_eq!(decimal(Q::new(999, 1000), 2), "1.00");
        assert_eq!(exact_and_decimal(Lang::En, Q::new(43, 4)), "43/4 ≈ 10.75");
        assert_eq!(exact_and_decimal(Lang::En, Q::from_integer(10)), "10");
    }
}
