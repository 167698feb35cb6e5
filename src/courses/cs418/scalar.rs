//! The number type the course's pipeline is written over: `f64` (the
//! course's arithmetic) or exact big rationals.

use std::fmt;

use super::RastNumber;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

/// A number type the pipeline runs on.
pub(super) trait Scalar: Clone + PartialOrd + fmt::Debug {
    fn number(n: &RastNumber) -> Self;
    fn int(v: i64) -> Self;
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn div(&self, o: &Self) -> Self;
    fn ceil(&self) -> Self;
    fn floor(&self) -> Self {
        Self::int(0).sub(&Self::int(0).sub(self).ceil())
    }
    fn to_f64(&self) -> f64;
    fn is_zero(&self) -> bool;
    /// Whether adding is exact, so that k steps of a DDA land where one
    /// step of k times the size does.
    const EXACT: bool;
    /// The value as a person reads it: the shortest decimal that reads back
    /// as this `f64`, or an exact fraction.
    fn text(&self) -> String;
}

impl Scalar for f64 {
    const EXACT: bool = false;
    fn number(n: &RastNumber) -> f64 {
        n.value
    }
    fn int(v: i64) -> f64 {
        v as f64
    }
    fn add(&self, o: &f64) -> f64 {
        self + o
    }
    fn sub(&self, o: &f64) -> f64 {
        self - o
    }
    fn mul(&self, o: &f64) -> f64 {
        self * o
    }
    fn div(&self, o: &f64) -> f64 {
        self / o
    }
    fn ceil(&self) -> f64 {
        f64::ceil(*self)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn text(&self) -> String {
        format!("{self}")
    }
}

impl Scalar for BigRational {
    const EXACT: bool = true;
    fn number(n: &RastNumber) -> BigRational {
        BigRational::new(BigInt::from(*n.exact.numer()), BigInt::from(*n.exact.denom()))
    }
    fn int(v: i64) -> BigRational {
        BigRational::from_integer(BigInt::from(v))
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn div(&self, o: &Self) -> Self {
        self / o
    }
    fn ceil(&self) -> Self {
        BigRational::ceil(self)
    }
    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn text(&self) -> String {
        if self.is_integer() { self.numer().to_string() } else { format!("{}/{}", self.numer(), self.denom()) }
    }
}

/// A vertex as the pipeline carries it: position and attributes, one number each.
pub(super) type Vertex<S> = Vec<S>;
