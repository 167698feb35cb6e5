//! Integer arithmetic on fractions without overflow, and the machine-word
//! trait the scan converter runs on (`i64` or `i128`).

use std::cmp::Ordering;
use std::fmt;

use num_integer::Integer;

use super::*;

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
    /// What [`Word::floor_div_by`] multiplies by to divide by `d > 0`: on
    /// 64 bits `⌊(2^64 − 1)/d⌋`, on 128 bits nothing (0).
    fn reciprocal(d: Self) -> u64;
    /// [`Word::floor_div`] by `d`, given its [`Word::reciprocal`]: on 64
    /// bits a multiplication and one correction instead of a division (the
    /// quotient of `|self|` by the reciprocal is the true one or one less),
    /// on 128 bits the division.
    fn floor_div_by(self, d: Self, reciprocal: u64) -> (Self, Self);
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

    #[inline(always)]
    fn floor_div(self, d: i64) -> (i64, i64) {
        debug_assert!(d > 0);
        // Truncated division, then one step down for a negative remainder,
        // chosen without a branch (signs come as they come).
        let (quotient, remainder) = (self / d, self % d);
        let negative = remainder < 0;
        (quotient - i64::from(negative), remainder + std::hint::select_unpredictable(negative, d, 0))
    }

    #[inline(always)]
    fn reciprocal(d: i64) -> u64 {
        debug_assert!(d > 0);
        u64::MAX / d as u64
    }

    #[inline(always)]
    fn floor_div_by(self, d: i64, reciprocal: u64) -> (i64, i64) {
        debug_assert!(d > 0 && reciprocal == u64::MAX / d as u64);
        // A negative n is −u − 1 with u = !n ≥ 0: ⌊n/d⌋ = −⌊u/d⌋ − 1, remainder d − 1 − (u mod d).
        let negative = self < 0;
        let u = (self ^ (self >> 63)) as u64;
        let d_unsigned = d as u64;
        // reciprocal ≥ (2^64 − d)/d, so u·reciprocal/2^64 > u/d − 1: the estimate is ⌊u/d⌋ or one less.
        let estimate = ((u128::from(u) * u128::from(reciprocal)) >> 64) as u64;
        let remainder = u - estimate * d_unsigned;
        let short = remainder >= d_unsigned;
        let (quotient, remainder) =
            ((estimate + u64::from(short)) as i64, (remainder - if short { d_unsigned } else { 0 }) as i64);
        (
            std::hint::select_unpredictable(negative, -quotient - 1, quotient),
            std::hint::select_unpredictable(negative, d - 1 - remainder, remainder),
        )
    }

    #[inline(always)]
    fn floor_div_pow2(self, shift: u32) -> (i64, i64) {
        (self >> shift, self & ((1 << shift) - 1))
    }

    #[inline(always)]
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
    fn reciprocal(_d: i128) -> u64 {
        0
    }

    #[inline]
    fn floor_div_by(self, d: i128, _reciprocal: u64) -> (i128, i128) {
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

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

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

    proptest! {
        /// The division by a reciprocal gives the division's quotient and
        /// remainder for every 64-bit numerator and positive divisor, small
        /// ones and those near a power of two weighted.
        #[test]
        fn dividing_by_a_reciprocal_is_dividing(
            n in prop_oneof![-1000i64..1000, any::<i64>()],
            d in prop_oneof![
                1i64..100,
                1i64..=i64::MAX,
                (1u32..63).prop_flat_map(|k| (-3i64..4).prop_map(move |e| ((1i64 << k) + e).max(1))),
            ],
        ) {
            prop_assert_eq!(n.floor_div_by(d, i64::reciprocal(d)), n.floor_div(d), "{} / {}", n, d);
            prop_assert_eq!(i128::from(n).floor_div_by(i128::from(d), 0), i128::from(n).floor_div(i128::from(d)));
        }
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
}
