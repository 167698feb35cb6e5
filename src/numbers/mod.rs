//! Exact numbers: the rational type `Q`, the reported number [`Exact`] (a
//! `Q` where it fits, a big rational where not), reading numbers from scene
//! files, and overflow-free comparison and rounding helpers on `i128`
//! fractions.
//!
//! The rasterizer itself works on integer numerators over a known per-polygon
//! denominator (see [`crate::geometry::plane`]); `Q` and `Exact` are what it reports to
//! people.

use std::cmp::Ordering;
use std::fmt;

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{CheckedSub, Signed, ToPrimitive, Zero};

/// An exact rational number over `i128`, always reduced with a positive
/// denominator (`num_rational::Ratio` keeps that invariant).
pub type Q = num_rational::Ratio<i128>;

/// An exact number as zsim reports it (a depth, a crossing, a stored
/// value): a [`Q`] whenever the reduced fraction fits 128 bits, which is
/// almost always, else a big rational (polygons given with 14 or more
/// significant digits, `crate::raster::big`). The form is canonical: `Big` only
/// holds values that do not fit `Q`, so equal values are equal as data.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Exact {
    /// A value that fits 128 bits.
    Word(Q),
    /// A value beyond 128 bits, reduced, denominator positive.
    Big(Box<BigRational>),
}

impl Exact {
    /// The value `numerator / denominator` (denominator non-zero), reduced,
    /// in the smallest form that holds it.
    pub fn from_big(numerator: BigInt, denominator: BigInt) -> Exact {
        Exact::from(BigRational::new(numerator, denominator))
    }

    /// The value as a [`Q`], when it fits.
    pub fn word(&self) -> Option<Q> {
        match self {
            Exact::Word(q) => Some(*q),
            Exact::Big(_) => None,
        }
    }

    /// The value as a big rational.
    pub fn to_big(&self) -> BigRational {
        match self {
            Exact::Word(q) => BigRational::new_raw(BigInt::from(*q.numer()), BigInt::from(*q.denom())),
            Exact::Big(b) => (**b).clone(),
        }
    }

    /// An integer, exactly.
    pub fn integer(value: BigInt) -> Exact {
        Exact::from(BigRational::from_integer(value))
    }

    /// Whether the value is a whole number.
    pub fn is_integer(&self) -> bool {
        match self {
            Exact::Word(q) => q.is_integer(),
            Exact::Big(b) => b.is_integer(),
        }
    }

    /// `self + other`, exactly.
    pub fn plus(&self, other: &Exact) -> Exact {
        let word = |a: &Q, b: &Q| Some(Exact::Word(num_traits::CheckedAdd::checked_add(a, b)?));
        match (self, other) {
            (Exact::Word(a), Exact::Word(b)) => word(a, b),
            _ => None,
        }
        .unwrap_or_else(|| Exact::from(self.to_big() + other.to_big()))
    }

    /// `self / divisor` (`divisor ≠ 0`), exactly.
    pub fn divided_by(&self, divisor: i128) -> Exact {
        let word = |q: &Q| Some(Exact::Word(Q::new(*q.numer(), q.denom().checked_mul(divisor)?)));
        self.word().as_ref().and_then(word).unwrap_or_else(|| Exact::from(self.to_big() / BigInt::from(divisor)))
    }

    /// `self × factor`, exactly.
    pub fn times(&self, factor: i128) -> Exact {
        let word = |q: &Q| Some(Exact::Word(num_traits::CheckedMul::checked_mul(q, &Q::from_integer(factor))?));
        self.word().as_ref().and_then(word).unwrap_or_else(|| Exact::from(self.to_big() * BigInt::from(factor)))
    }

    /// The greatest integer not above the value.
    pub fn floor(&self) -> BigInt {
        match self {
            Exact::Word(q) => BigInt::from(q.floor().to_integer()),
            Exact::Big(b) => b.floor().to_integer(),
        }
    }

    /// `self − other`, exactly.
    pub fn minus(&self, other: &Exact) -> Exact {
        let word = |a: &Q, b: &Q| Some(Exact::Word(a.checked_sub(b)?));
        match (self, other) {
            (Exact::Word(a), Exact::Word(b)) => word(a, b),
            _ => None,
        }
        .unwrap_or_else(|| Exact::from(self.to_big() - other.to_big()))
    }
}

impl From<Q> for Exact {
    fn from(value: Q) -> Exact {
        Exact::Word(value)
    }
}

impl From<&Exact> for Exact {
    fn from(value: &Exact) -> Exact {
        value.clone()
    }
}

impl From<BigRational> for Exact {
    /// The canonical form of a reduced big rational (as num-rational's
    /// arithmetic and `BigRational::new` give it): a `Q` when it fits.
    fn from(value: BigRational) -> Exact {
        match (value.numer().to_i128(), value.denom().to_i128()) {
            (Some(n), Some(d)) if n != i128::MIN => Exact::Word(Q::new(n, d)),
            _ => Exact::Big(Box::new(value)),
        }
    }
}

impl fmt::Display for Exact {
    /// As [`fraction`] prints it: `43/4`, `10`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&fraction(self))
    }
}

impl PartialEq<Q> for Exact {
    fn eq(&self, other: &Q) -> bool {
        self.word() == Some(*other)
    }
}

impl Ord for Exact {
    fn cmp(&self, other: &Exact) -> Ordering {
        match (self, other) {
            (Exact::Word(a), Exact::Word(b)) => cmp_fractions(*a.numer(), *a.denom(), *b.numer(), *b.denom()),
            _ => self.to_big().cmp(&other.to_big()),
        }
    }
}

impl PartialOrd for Exact {
    fn partial_cmp(&self, other: &Exact) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

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
    /// have ([`MAX_BIG_DIGITS`]).
    TooLong(String),
}

impl fmt::Display for NumberError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NumberError::NotANumber(text) => f.write_str(&words!("number-not-a-number", text = text)),
            NumberError::ZeroDenominator(text) => f.write_str(&words!("number-zero-denominator", text = text)),
            NumberError::TooLarge(text) => f.write_str(&words!("number-too-large", text = text)),
            NumberError::TooLong(text) => {
                f.write_str(&words!("number-too-long", text = text, max = MAX_BIG_DIGITS.to_string()))
            }
        }
    }
}

/// Reads an integer, a decimal (`-2.125`, `1e3`, `2.5E-2`) or a fraction of
/// two integers (`5/2`, `-7/3`) exactly. Decimals never pass through binary
/// floating point: `2.1` is `21/10`.
///
/// ```
/// use zsim::exact::{parse_number, Q};
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
/// [`MAX_BIG_DIGITS`] digits and powers of ten: a 128-bit fraction where it
/// fits, a big one where not (for vertex coordinates).
///
/// ```
/// use zsim::exact::{parse_exact, Exact, Q};
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

/// `a / b` without overflow panics; `None` when the result does not fit.
pub fn checked_div(a: Q, b: Q) -> Option<Q> {
    let numer = a.numer().checked_mul(*b.denom())?;
    let denom = a.denom().checked_mul(*b.numer())?;
    if denom == 0 {
        return None;
    }
    Some(Q::new(numer, denom))
}

/// Compares `n1/d1` with `n2/d2` (both denominators positive) without
/// overflow, by the continued-fraction expansion: whole parts first, then the
/// reciprocals of the remainders.
pub fn cmp_fractions(mut n1: i128, mut d1: i128, mut n2: i128, mut d2: i128) -> Ordering {
    debug_assert!(d1 > 0 && d2 > 0, "cmp_fractions needs positive denominators");
    // Each round swaps the roles and reverses the sense, like Euclid's algorithm.
    let mut reversed = false;
    loop {
        let (q1, r1) = (n1.div_euclid(d1), n1.rem_euclid(d1));
        let (q2, r2) = (n2.div_euclid(d2), n2.rem_euclid(d2));
        let ord = q1.cmp(&q2).then_with(|| match (r1 == 0, r2 == 0) {
            (true, true) => Ordering::Equal,
            (true, false) => Ordering::Less,
            (false, true) => Ordering::Greater,
            (false, false) => Ordering::Equal,
        });
        if ord != Ordering::Equal || r1 == 0 {
            return if reversed { ord.reverse() } else { ord };
        }
        // q1 == q2 and both remainders non-zero: r1/d1 < r2/d2 ⇔ d1/r1 > d2/r2.
        (n1, d1, n2, d2) = (d1, r1, d2, r2);
        reversed = !reversed;
    }
}

/// Floor of `n / d` for `d > 0`, as whole part and remainder `0 ≤ r < d`.
pub fn floor_div(n: i128, d: i128) -> (i128, i128) {
    debug_assert!(d > 0);
    // 128-bit division is a slow library call; most operands fit 64 bits.
    if let (Ok(n64), Ok(d64)) = (i64::try_from(n), i64::try_from(d)) {
        // d > 0, so Euclidean division is floor division.
        return (i128::from(n64.div_euclid(d64)), i128::from(n64.rem_euclid(d64)));
    }
    n.div_mod_floor(&d)
}

/// Ceiling of `n / d` for `d > 0`.
pub fn ceil_div(n: i128, d: i128) -> i128 {
    debug_assert!(d > 0);
    if let (Ok(n64), Ok(d64)) = (i64::try_from(n), i64::try_from(d)) {
        return -i128::from((-n64).div_euclid(d64));
    }
    Integer::div_ceil(&n, &d)
}

/// A machine integer the rasterizer runs on. Every polygon can run on `i128`
/// (the bounds in [`crate::geometry::plane`] guarantee it); a polygon whose values all
/// fit 64 bits ([`crate::geometry::plane::Geometry::fits_i64`], most scenes) runs on
/// `i64`, which is several times faster and gives identical results, since
/// both compute the same integers and neither overflows.
pub trait Word:
    Copy
    + Ord
    + Default
    + fmt::Debug
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
    + std::ops::AddAssign
    + std::ops::SubAssign
{
    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
    /// Whether this is the 64-bit word, used only for polygons that
    /// [`crate::geometry::plane::Geometry::fits_i64`].
    const NARROW: bool;
    /// The value of `value`, which the caller has checked fits.
    fn narrow(value: i128) -> Self;
    /// The value as `i128`.
    fn wide(self) -> i128;
    /// The value as `i64`, when it fits.
    fn to_i64(self) -> Option<i64>;
    /// Floor of `self / d` for `d > 0`, as whole part and remainder `0 ≤ r < d`.
    fn floor_div(self, d: Self) -> (Self, Self);
    /// Ceiling of `self / d` for `d > 0`.
    fn ceil_div(self, d: Self) -> Self;
    /// Floor of `self / 2^shift`, as whole part and remainder: the same as
    /// [`Word::floor_div`] by a power of two, by a shift and a mask.
    fn floor_div_pow2(self, shift: u32) -> (Self, Self);
}

impl Word for i64 {
    const ZERO: i64 = 0;
    const ONE: i64 = 1;
    const NARROW: bool = true;

    #[inline]
    fn narrow(value: i128) -> i64 {
        debug_assert!(i64::try_from(value).is_ok(), "{value} does not fit 64 bits: please report this bug");
        value as i64
    }

    #[inline]
    fn wide(self) -> i128 {
        i128::from(self)
    }

    #[inline]
    fn to_i64(self) -> Option<i64> {
        Some(self)
    }

    #[inline]
    fn floor_div(self, d: i64) -> (i64, i64) {
        debug_assert!(d > 0);
        // Truncated division, then one step down for a negative remainder,
        // chosen without a branch (signs come as they come).
        let (quotient, remainder) = (self / d, self % d);
        let negative = remainder < 0;
        (quotient - i64::from(negative), remainder + std::hint::select_unpredictable(negative, d, 0))
    }

    #[inline]
    fn floor_div_pow2(self, shift: u32) -> (i64, i64) {
        (self >> shift, self & ((1 << shift) - 1))
    }

    #[inline]
    fn ceil_div(self, d: i64) -> i64 {
        debug_assert!(d > 0);
        let (quotient, remainder) = self.floor_div(d);
        quotient + i64::from(remainder != 0)
    }
}

impl Word for i128 {
    const ZERO: i128 = 0;
    const ONE: i128 = 1;
    const NARROW: bool = false;

    #[inline]
    fn narrow(value: i128) -> i128 {
        value
    }

    #[inline]
    fn wide(self) -> i128 {
        self
    }

    #[inline]
    fn to_i64(self) -> Option<i64> {
        i64::try_from(self).ok()
    }

    #[inline]
    fn floor_div(self, d: i128) -> (i128, i128) {
        floor_div(self, d)
    }

    #[inline]
    fn floor_div_pow2(self, shift: u32) -> (i128, i128) {
        (self >> shift, self & ((1 << shift) - 1))
    }

    #[inline]
    fn ceil_div(self, d: i128) -> i128 {
        ceil_div(self, d)
    }
}

/// The `f64` nearest to a rational (ties to even), computed exactly from the
/// integers: 55 significant bits by long division, then a sticky bit.
///
/// ```
/// use zsim::exact::{to_f64, Q};
/// assert_eq!(to_f64(Q::new(1, 10)), 0.1);
/// assert_eq!(to_f64(Q::new(-979798, 1000000)), -0.979798);
/// ```
pub fn to_f64(value: impl Into<Exact>) -> f64 {
    let value = match value.into() {
        Exact::Word(q) => q,
        Exact::Big(big) => return big_to_f64(&big),
    };
    let negative = *value.numer() < 0;
    let (numer, denom) = (value.numer().unsigned_abs(), value.denom().unsigned_abs());
    if numer == 0 {
        return 0.0;
    }
    // mantissa holds the leading significant bits; exponent e: value ≈ mantissa·2^e.
    let whole = numer / denom;
    let mut remainder = numer % denom;
    let (mut mantissa, mut exponent): (u128, i32) = (whole, 0);
    let mut sticky = false;
    let bits = |m: u128| 128 - m.leading_zeros() as i32;
    if bits(mantissa) > 55 {
        let shift = bits(mantissa) - 55;
        sticky = mantissa & ((1u128 << shift) - 1) != 0 || remainder != 0;
        mantissa >>= shift;
        exponent = shift;
    } else {
        // denom < 2^127, so 2·remainder fits in u128.
        while bits(mantissa) < 55 {
            remainder <<= 1;
            mantissa = (mantissa << 1) | u128::from(remainder >= denom);
            if remainder >= denom {
                remainder -= denom;
            }
            exponent -= 1;
        }
        sticky = sticky || remainder != 0;
    }
    // 55 bits: 53 kept, a guard bit and a round bit; round half to even.
    let kept = mantissa >> 2;
    let guard = (mantissa >> 1) & 1 == 1;
    let round_or_sticky = mantissa & 1 == 1 || sticky;
    let kept = if guard && (round_or_sticky || kept & 1 == 1) { kept + 1 } else { kept };
    let magnitude = (kept as f64) * 2f64.powi(exponent + 2);
    if negative { -magnitude } else { magnitude }
}

/// [`to_f64`] of a value beyond 128 bits: the 55 leading bits of the
/// quotient by one big division, then a sticky bit, rounded half to even.
fn big_to_f64(value: &BigRational) -> f64 {
    let (numer, denom) = (value.numer().magnitude(), value.denom().magnitude());
    if numer.is_zero() {
        return 0.0;
    }
    // value ≈ 2^(n − d); shift so that the quotient has 55 or 56 bits.
    let exponent = numer.bits() as i64 - denom.bits() as i64 - 56;
    let (scaled_numer, scaled_denom) = if exponent >= 0 {
        (numer.clone(), denom << exponent as u64)
    } else {
        (numer << (-exponent) as u64, denom.clone())
    };
    let (quotient, remainder) = scaled_numer.div_rem(&scaled_denom);
    let mut mantissa = quotient.to_u64().expect("at most 57 bits");
    let mut exponent = exponent;
    let mut sticky = !remainder.is_zero();
    while mantissa >= 1 << 55 {
        sticky |= mantissa & 1 == 1;
        mantissa >>= 1;
        exponent += 1;
    }
    let kept = mantissa >> 2;
    let guard = (mantissa >> 1) & 1 == 1;
    let round_or_sticky = mantissa & 1 == 1 || sticky;
    let kept = if guard && (round_or_sticky || kept & 1 == 1) { kept + 1 } else { kept };
    // Scaled by 2^exponent in steps that stay within f64's range (`powi` of a
    // large negative power divides by an infinity). Exact but in the
    // subnormal range, where the 53 bits kept are rounded once more.
    let (mut magnitude, mut power) = (kept as f64, exponent + 2);
    while power.abs() > 1000 {
        let step = 1000 * power.signum();
        magnitude *= 2f64.powi(step as i32);
        power -= step;
    }
    let magnitude = magnitude * 2f64.powi(power as i32);
    if value.numer().sign() == Sign::Minus { -magnitude } else { magnitude }
}

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
pub fn big_integer(value: &num_bigint::BigInt) -> String {
    let text = value.to_string();
    let (sign, digits) = text.strip_prefix('-').map_or(("", text.as_str()), |rest| ("-", rest));
    if digits.len() <= 60 {
        return text;
    }
    let count = words!("digits", count = digits.len().to_string());
    format!("{sign}{}…{} ({count})", &digits[..12], &digits[digits.len() - 12..])
}

/// A number as a student writes it: `12`, `12.5`, `5.375`, or a fraction
/// (`41/3`) when no decimal of at most four places is exact; the decimal
/// separator is the language's (`12,5` in Russian).
///
/// ```
/// use zsim::exact::{Q, short};
/// assert_eq!((short(Q::new(13, 2)), short(Q::new(43, 8)), short(Q::new(41, 3))), ("6.5".into(), "5.375".into(), "41/3".into()));
/// ```
pub fn short(value: impl Into<Exact>) -> String {
    crate::words::localize_decimal(short_in_files(value))
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
pub fn exact_and_decimal(value: impl Into<Exact>) -> String {
    exact_and_places(value, 2)
}

/// The exact value and its decimal with `places` places (`4876543/5000000 ≈
/// 0.975309`); whole numbers print once.
pub fn exact_and_places(value: impl Into<Exact>, places: u32) -> String {
    let value = value.into();
    if value.is_integer() {
        fraction(value)
    } else {
        // The decimal in the reader's convention (10,75 in Russian); the fraction stays as it is.
        format!("{} ≈ {}", fraction(&value), crate::words::localize_decimal(decimal(value, places)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_words_divide_alike_by_any_divisor_and_by_shifts() {
        for n in -300i64..300 {
            for d in 1i64..40 {
                let (q, r) = n.floor_div(d);
                assert_eq!((q, r), (n.div_euclid(d), n.rem_euclid(d)), "{n} / {d}");
                assert_eq!(i128::from(n).floor_div(i128::from(d)), (i128::from(q), i128::from(r)));
                assert_eq!(n.ceil_div(d), q + i64::from(r != 0), "⌈{n} / {d}⌉");
                assert_eq!(i128::from(n).ceil_div(i128::from(d)), i128::from(q + i64::from(r != 0)));
            }
            for shift in 0..6 {
                assert_eq!(n.floor_div_pow2(shift), n.floor_div(1 << shift), "{n} >> {shift}");
                assert_eq!(i128::from(n).floor_div_pow2(shift), i128::from(n).floor_div(1 << shift));
            }
        }
    }

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

    #[test]
    fn fraction_comparison_matches_cross_multiplication() {
        let cases = [(1, 3, 1, 2), (7, 2, 7, 2), (-1, 3, -1, 2), (10, 4, 5, 2), (22, 7, 355, 113), (-5, 1, 4, 1)];
        for (n1, d1, n2, d2) in cases {
            assert_eq!(cmp_fractions(n1, d1, n2, d2), (n1 * d2).cmp(&(n2 * d1)), "{n1}/{d1} vs {n2}/{d2}");
        }
        // Values whose cross products would overflow i128.
        let big = 1i128 << 120;
        assert_eq!(cmp_fractions(big + 1, big, big, big - 1), Ordering::Less);
        assert_eq!(cmp_fractions(big, big - 1, big + 1, big), Ordering::Greater);
    }

    #[test]
    fn nearest_f64_matches_the_correctly_rounded_parse() {
        for text in ["0.1", "0.9797980", "-1.8316516", "123456.789", "0.0078125", "1e-7", "2.5e20", "-7"] {
            let value = parse_number(text).unwrap();
            assert_eq!(to_f64(value), text.parse::<f64>().unwrap(), "{text}");
        }
        for (n, d) in [(1, 3), (2, 3), (-22, 7), (355, 113), (1, 1 << 100), ((1 << 100) + 1, 3)] {
            let expected = format!("{}", n as f64 / d as f64);
            assert_eq!(to_f64(Q::new(n, d)).to_string(), expected, "{n}/{d}");
        }
    }

    /// Beyond 128 bits the nearest f64 comes from one big division; Rust's
    /// own parse rounds correctly, so the two agree.
    #[test]
    fn nearest_f64_of_a_big_value_matches_the_correctly_rounded_parse() {
        for text in [
            "0.123456789012345678901234567890123456789012345",
            "-98765432109876543210987654321.0987654321",
            "3.00000000000000000000000000000000000000000000001",
            "1e-300",
            "7e250",
        ] {
            let value = parse_exact(text).unwrap();
            assert!(value.word().is_none(), "{text} is beyond 128 bits");
            assert_eq!(to_f64(value), text.parse::<f64>().unwrap(), "{text}");
        }
    }

    #[test]
    fn decimals_print_with_fixed_places() {
        assert_eq!(decimal(Q::new(43, 4), 2), "10.75");
        assert_eq!(decimal(Q::new(151, 6), 2), "25.17");
        assert_eq!(decimal(Q::new(-1, 3), 2), "-0.33");
        assert_eq!(decimal(Q::new(-1, 1000), 2), "0.00");
        assert_eq!(decimal(Q::new(999, 1000), 2), "1.00");
        assert_eq!(exact_and_decimal(Q::new(43, 4)), "43/4 ≈ 10.75");
        assert_eq!(exact_and_decimal(Q::from_integer(10)), "10");
    }
}
