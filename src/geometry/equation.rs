//! A polygon's plane and what can be wrong with its vertices: the plane
//! equation reduced as the book prints it, worked in big integers on every
//! tier, and the errors a polygon's geometry reports.

use crate::words::Lang;
use std::fmt;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::geometry::newell::OffPlaneVertex;
use crate::numbers::Exact;

/// Most vertices one polygon may have.
pub const MAX_VERTICES: usize = 1 << 16;

/// Why a polygon's vertices cannot be turned into exact geometry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GeometryError {
    /// Fewer than three vertices.
    TooFewVertices(usize),
    /// More than [`MAX_VERTICES`] vertices.
    TooManyVertices(usize),
    /// A coordinate beyond the range where the exact arithmetic cannot overflow.
    OutOfRange {
        /// 1-based vertex number.
        vertex: usize,
        /// The offending coordinate.
        value: Exact,
        /// The polygon's least common denominator `D` (so far), which may
        /// itself have outgrown 128 bits.
        denominator: BigInt,
    },
    /// A vertex that does not lie on the plane through the others.
    NotPlanar(Box<OffPlane>),
}

/// The first vertex found off a polygon's plane.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OffPlane {
    /// 1-based vertex number.
    pub vertex: usize,
    /// The three vertices (1-based) that fix the plane.
    pub through: [usize; 3],
    /// The plane through them.
    pub plane: PlaneEquation,
    /// How far the vertex is off, along z when the plane has a z term,
    /// otherwise the value of the reduced equation at the vertex.
    pub off_by: Exact,
    /// Whether `off_by` is measured along z.
    pub along_z: bool,
}

impl GeometryError {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            GeometryError::TooFewVertices(n) => words!(lang, "geometry-too-few", count = n.to_string()),
            GeometryError::TooManyVertices(n) => {
                words!(lang, "geometry-too-many", count = n.to_string(), max = MAX_VERTICES.to_string())
            }
            GeometryError::OutOfRange { vertex, value, denominator } => words!(
                lang,
                "geometry-out-of-range",
                vertex = vertex.to_string(),
                value = crate::numbers::fraction(value),
                denominator = crate::numbers::big_integer(lang, denominator)
            ),
            GeometryError::NotPlanar(off) => {
                let OffPlane { vertex, through: [i, j, k], plane, off_by, along_z } = off.as_ref();
                let (key, off) = if *along_z {
                    ("geometry-off-plane-z", crate::numbers::exact_and_decimal(lang, off_by))
                } else {
                    ("geometry-off-plane", crate::numbers::fraction(off_by))
                };
                words!(
                    lang,
                    key,
                    vertex = vertex.to_string(),
                    plane = plane.to_string(),
                    i = i.to_string(),
                    j = j.to_string(),
                    k = k.to_string(),
                    off = off
                )
            }
        }
    }
}

/// A plane `a·x + b·y + c·z + d = 0` with integer coefficients reduced by
/// their greatest common divisor, in the polygon's own coordinates (not
/// scaled), signed as the book prints it: `c > 0` (when `c = 0`, `b > 0`;
/// when both are 0, `a > 0`). The winding is reported apart,
/// from the sign of Newell's `c` ([`Geometry::c`]). The coefficients are
/// big integers: a polygon given with many significant digits has a plane
/// beyond 128 bits (`crate::raster::big`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PlaneEquation {
    /// Coefficient of x.
    pub a: BigInt,
    /// Coefficient of y.
    pub b: BigInt,
    /// Coefficient of z.
    pub c: BigInt,
    /// Constant term.
    pub d: BigInt,
}

impl PlaneEquation {
    /// The plane with small coefficients (for tests and examples).
    pub fn of(a: i128, b: i128, c: i128, d: i128) -> PlaneEquation {
        PlaneEquation { a: a.into(), b: b.into(), c: c.into(), d: d.into() }
    }
}

impl fmt::Display for PlaneEquation {
    /// Prints like the book: `3x + y + 4z - 120 = 0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut out = String::new();
        for (coef, var) in [(&self.a, "x"), (&self.b, "y"), (&self.c, "z"), (&self.d, "")] {
            if coef.is_zero() {
                continue;
            }
            let magnitude = coef.magnitude();
            let number = if magnitude.is_one() && !var.is_empty() { String::new() } else { magnitude.to_string() };
            let negative = coef.is_negative();
            if out.is_empty() {
                out = format!("{}{number}{var}", if negative { "-" } else { "" });
            } else {
                out = format!("{out} {} {number}{var}", if negative { "-" } else { "+" });
            }
        }
        if out.is_empty() {
            out.push('0');
        }
        write!(f, "{out} = 0")
    }
}

/// The error for a polygon with a vertex off its plane, in big integers on
/// every tier (the word tiers' values are widened on this path only): the
/// plane through vertex 1 and the two that fix it, and how far off the vertex
/// lies, along z where the plane has a z term, else the reduced equation's
/// value there.
pub(crate) fn not_planar(off: OffPlaneVertex<BigInt>, points: &[[BigInt; 3]], scale: &BigInt) -> GeometryError {
    let OffPlaneVertex { vertex, through: [i, k], normal, residual } = off;
    let plane = crate::geometry::equation::plane_through(&normal, &points[0], scale);
    let (off_by, along_z) = if normal[2].is_zero() {
        let PlaneEquation { a, b, c, d } = &plane;
        let point = &points[vertex];
        let value = a * &point[0] + b * &point[1] + c * &point[2] + d * scale;
        (Exact::from_big(value, scale.clone()), false)
    } else {
        // residual = n_z·ΔZ in scaled units, and Δz = ΔZ / 2D.
        (Exact::from_big(residual, &normal[2] * scale), true)
    };
    GeometryError::NotPlanar(Box::new(OffPlane {
        vertex: vertex + 1,
        through: [1, i + 1, k + 1],
        plane,
        off_by,
        along_z,
    }))
}

/// The plane with `normal` (scaled units) through `point` (scaled units), in
/// polygon units, reduced and signed as the book prints it.
///
/// In scaled units the plane is `a·X + b·Y + c·Z + d' = 0` with
/// `d' = −(a·X₁ + b·Y₁ + c·Z₁)`; with `X = 2D·x` that is
/// `2D·a·x + 2D·b·y + 2D·c·z + d' = 0`, then divided by the gcd.
pub(crate) fn reduced_plane(normal: [i128; 3], point: [i128; 3], scale: i128) -> PlaneEquation {
    // Worked in big integers: the products can outgrow i128.
    crate::geometry::equation::plane_through(&normal.map(BigInt::from), &point.map(BigInt::from), &BigInt::from(scale))
}

/// The plane with `normal` through `point` (both in scaled units, scale
/// `2D`) in pixel units, reduced and signed as the book prints it (see
/// [`crate::geometry::plane::Geometry::plane`]). In scaled units the plane is
/// `a·X + b·Y + c·Z + d' = 0` with `d' = −(a·X₁ + b·Y₁ + c·Z₁)`, and
/// `X = 2D·x`.
pub(crate) fn plane_through(normal: &[BigInt; 3], point: &[BigInt; 3], scale: &BigInt) -> PlaneEquation {
    let [a, b, c] = normal;
    let d = -(a * &point[0] + b * &point[1] + c * &point[2]);
    let [a, b, c, d] = reduced([a * scale, b * scale, c * scale, d], 3);
    PlaneEquation { a, b, c, d }
}

/// The values divided by their greatest common divisor, the last non-zero
/// of the first `lead` made positive.
pub(crate) fn reduced<const N: usize>(values: [BigInt; N], lead: usize) -> [BigInt; N] {
    // Most often the values themselves fit 128 bits: reduced there, faster.
    if let Some(words) = words(&values) {
        let divisor = words.iter().fold(0i128, |g, v| g.gcd(v));
        if divisor == 0 {
            return values;
        }
        let negative = words[..lead].iter().rev().find(|v| **v != 0).is_some_and(|v| *v < 0);
        let divisor = if negative { -divisor } else { divisor };
        return words.map(|v| BigInt::from(v / divisor));
    }
    let divisor = values.iter().fold(BigInt::zero(), |g, v| g.gcd(v));
    if divisor.is_zero() {
        return values;
    }
    let negative = values[..lead].iter().rev().find(|v| !v.is_zero()).is_some_and(Signed::is_negative);
    let divisor = if negative { -divisor } else { divisor };
    values.map(|v| v / &divisor)
}

/// The values as `i128`, when they all fit.
pub(crate) fn words<const N: usize>(values: &[BigInt; N]) -> Option<[i128; N]> {
    let values = values.each_ref().map(|v| v.to_i128().filter(|w| *w != i128::MIN));
    values.iter().all(Option::is_some).then(|| values.map(|v| v.expect("checked")))
}
