//! The exact number types: `Q`, a 128-bit fraction, and [`Exact`], a `Q`
//! where the value fits and a big rational where not; and the nearest `f64`.

use std::cmp::Ordering;
use std::fmt;

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{CheckedSub, ToPrimitive, Zero};

use super::*;

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

    /// `self × other`, exactly.
    pub fn times_exact(&self, other: &Exact) -> Exact {
        let word = |a: &Q, b: &Q| Some(Exact::Word(num_traits::CheckedMul::checked_mul(a, b)?));
        match (self, other) {
            (Exact::Word(a), Exact::Word(b)) => word(a, b),
            _ => None,
        }
        .unwrap_or_else(|| Exact::from(self.to_big() * other.to_big()))
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

/// The `f64` nearest to a rational (ties to even), computed exactly from the
/// integers: 55 significant bits by long division, then a sticky bit.
///
/// ```
/// use zsim::{to_f64, Q};
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
    // Both exact in f64: IEEE division rounds their quotient once, to the nearest (ties to even).
    if numer <= 1 << f64::MANTISSA_DIGITS && denom <= 1 << f64::MANTISSA_DIGITS {
        let magnitude = numer as f64 / denom as f64;
        return if negative { -magnitude } else { magnitude };
    }
    nearest_f64(negative, numer, denom)
}

/// The nearest `f64` to `±numer/denom`, rounded half to even, bit by bit.
fn nearest_f64(negative: bool, numer: u128, denom: u128) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;

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

    proptest::proptest! {
        /// Numerator and denominator both exact in f64 take one IEEE
        /// division; it rounds as the bit-by-bit path does.
        #[test]
        fn one_division_rounds_as_the_bit_by_bit_path(
            numer in 1u128..=1 << 53,
            denom in 1u128..=1 << 53,
            negative: bool,
        ) {
            let q = Q::new(if negative { -(numer as i128) } else { numer as i128 }, denom as i128);
            let (n, d) = (q.numer().unsigned_abs(), q.denom().unsigned_abs());
            proptest::prop_assert_eq!(to_f64(q).to_bits(), nearest_f64(negative, n, d).to_bits());
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
}
