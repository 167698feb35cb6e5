//! The arithmetic that Newell's method and the planarity check need, over
//! every number type zsim computes them in: `i128` (the word tiers), big
//! integers (the big-integer tier), and `f32`/`f64` (the float modes). One
//! formula, one place, any number type.

use num_bigint::BigInt;
use num_traits::Zero;

/// A number with `+`, `−` and `×` (by reference, so big integers are not
/// copied); integer types wrap nothing: an overflow of `i128` is a bug the
/// callers' bounds rule out (and test builds check).
pub trait Ring: Clone + PartialEq + Zero {
    /// `self + other`.
    fn plus(&self, other: &Self) -> Self;
    /// `self − other`.
    fn minus(&self, other: &Self) -> Self;
    /// `self × other`.
    fn times(&self, other: &Self) -> Self;
}

macro_rules! ring_by_value {
    ($($t:ty),*) => {$(
        impl Ring for $t {
            #[inline]
            fn plus(&self, other: &$t) -> $t {
                self + other
            }
            #[inline]
            fn minus(&self, other: &$t) -> $t {
                self - other
            }
            #[inline]
            fn times(&self, other: &$t) -> $t {
                self * other
            }
        }
    )*};
}
ring_by_value!(i128, f32, f64, BigInt);
