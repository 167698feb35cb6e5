//! The big-integer tier: polygons whose scaled coordinates pass
//! [`crate::geometry::plane::MAX_SCALED`] (2^34), where the word-sized rasterizer's
//! products could overflow `i128`, are drawn here with the same rules.
//!
//! The tier keeps the scaled vertices as arbitrary-precision integers
//! (`num-bigint`), however large the polygon's common denominator, and works
//! from what stays small when the vertices do not: each edge's line and the
//! polygon's plane, reduced once when the polygon is read. A polygon cut by
//! clipping or divided by w has vertices over huge common denominators, but
//! its edges and plane are those of the polygon it came from. When its
//! crossings and depths at pixel centres fit 128-bit fractions (checked
//! once, [`BigPolygon::new`]) they are computed row by row from the lines in
//! `i128` and stepped pixel by pixel; when not (a polygon given with 14 or
//! more significant digits has a plane beyond 128 bits) they are computed
//! in big integers and reported as big rationals ([`crate::numbers::Exact`]),
//! by the same formulas, more slowly. Nothing within
//! [`crate::geometry::plane::MAX_SCALED_BITS`] is refused.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, ToPrimitive, Zero};

use crate::geometry::equation::{GeometryError, PlaneEquation, not_planar};
use crate::geometry::equation::{plane_through, reduced, words};
use crate::geometry::newell::{first_off_plane, newell};
use crate::rules::RowRule;

pub(crate) fn big(v: i128) -> BigInt {
    BigInt::from(v)
}

/// Largest depth numerator the tier hands on as a 128-bit [`Depth`], and
/// largest denominator; largest crossing numerator and denominator.
pub(crate) const DEPTH_NUMERATOR: i128 = 1 << 125;
pub(crate) const DEPTH_DENOMINATOR: i128 = 1 << 124;
pub(crate) const CROSSING: i128 = 1 << 120;

/// Rows and cells are clamped to `ROW_LOW ..= ROW_HIGH`, just outside the
/// range of `u32` every raster lies in: a polygon reaching 2^1000 pixels out
/// is drawn on the raster as one reaching 2^33 would be.
const ROW_LOW: i64 = -2;
const ROW_HIGH: i64 = 1 << 33;

/// An edge that crosses scanlines, as the tier walks it: the rows it
/// crosses under each [`RowRule`] (first and last, in the order of
/// [`rule_index`], clamped to `ROW_LOW ..= ROW_HIGH`; an empty range as
/// `[1, 0]`) and its line `αx + βy + γ = 0` in pixel units, reduced,
/// `α > 0`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Edge {
    pub(crate) rows: [[i128; 2]; 3],
    pub(crate) line: [BigInt; 3],
}

pub(crate) fn rule_index(rule: RowRule) -> usize {
    match rule {
        RowRule::HalfOpen => 0,
        RowRule::Closed => 1,
        RowRule::TopLeft => 2,
    }
}

/// The lines and plane in `i128`, when every crossing and depth the
/// polygon reports fits 128 bits ([`BigPolygon::new`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Words {
    pub(crate) lines: Vec<[i128; 3]>,
    pub(crate) plane: [i128; 4],
}

/// A polygon of the big-integer tier (see the module documentation).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BigPolygon {
    /// `D`, the least common denominator of the polygon's coordinates.
    pub(crate) denominator: BigInt,
    /// Vertices as `[x·2D, y·2D, z·2D]`.
    pub(crate) points: Vec<[BigInt; 3]>,
    pub(crate) edges: Vec<Edge>,
    /// The plane `Ax + By + Cz + D = 0` in pixel units, reduced, `C ≥ 0`.
    pub(crate) plane: PlaneEquation,
    /// `(A, B, C)` pointing as Newell's normal does (its sign gives the
    /// winding); when a coefficient does not fit `i128`, the signs alone.
    pub(crate) normal: [i128; 3],
    /// The lines and plane in 128 bits, when all the polygon reports fits.
    pub(crate) words: Option<Words>,
}

/// `Σ aᵢ·bᵢ` exactly: in `i128` while no step overflows, else in big
/// integers; `None` when the sum itself does not fit `i128`.
pub(crate) fn sum_of_products(terms: &[(i128, i128)]) -> Option<i128> {
    let fast = terms.iter().try_fold(0i128, |sum, &(a, b)| sum.checked_add(a.checked_mul(b)?));
    fast.or_else(|| terms.iter().map(|&(a, b)| big(a) * big(b)).sum::<BigInt>().to_i128())
}

/// Whether `|v| < limit`, for a value that may not have fit `i128` (`None`).
pub(crate) fn below(v: Option<i128>, limit: i128) -> bool {
    v.is_some_and(|v| v.unsigned_abs() < limit.unsigned_abs())
}

/// The line through scaled points `p` and `q` (`p_y ≠ q_y`) in pixel units,
/// reduced, `α > 0`. In scaled units it is
/// `ΔY·X − ΔX·Y + (ΔX·Y₁ − ΔY·X₁) = 0`, and `X = 2D·x`, `Y = 2D·y`.
fn reduced_line(p: &[BigInt; 3], q: &[BigInt; 3], scale: &BigInt) -> [BigInt; 3] {
    let (dx, dy) = (&q[0] - &p[0], &q[1] - &p[1]);
    let gamma = &dx * &p[1] - &dy * &p[0];
    reduced([&dy * scale, -(&dx * scale), gamma], 1)
}

/// `2n + 1`, a row's scanline or a column's centre in half pixels, when it fits.
pub(crate) fn odd(n: i128) -> Option<i128> {
    n.checked_mul(2)?.checked_add(1)
}

/// A row or cell index clamped to `ROW_LOW ..= ROW_HIGH`.
pub(crate) fn clamped(n: BigInt) -> i128 {
    n.clamp(BigInt::from(ROW_LOW), BigInt::from(ROW_HIGH)).to_i128().expect("clamped")
}

/// The rows `first ..= last`, clamped, or `[1, 0]` when empty.
fn row_range(first: BigInt, last: BigInt) -> [i128; 2] {
    if first > last { [1, 0] } else { [clamped(first), clamped(last)] }
}

impl BigPolygon {
    /// The polygon with scaled vertices `points` (over common denominator
    /// `denominator`): its normal and planarity checked, its edges' lines and
    /// plane reduced, and whether what it reports fits 128 bits: a crossing
    /// `−(β(2r + 1) + 2γ) / 2α` at any row `r` the edge reaches, a depth
    /// `−(A(2x + 1) + B(2y + 1) + 2D) / 2C` at the centre of any pixel
    /// `(x, y)` within one of the polygon's bounding box. Both numerators are
    /// linear, so they are largest at the ends of those ranges, where they
    /// are checked.
    pub(crate) fn new(points: Vec<[BigInt; 3]>, denominator: BigInt) -> Result<BigPolygon, GeometryError> {
        let scale = &denominator * 2;
        if let Some(off) = first_off_plane(&points) {
            return Err(not_planar(off, &points, &scale));
        }
        let newell = newell(&points);
        let plane = plane_through(&newell, &points[0], &scale);
        // (A, B, C) with Newell's orientation: the plane's is the last non-zero made positive.
        let flip = newell.iter().rev().find(|v| !v.is_zero()).is_some_and(Signed::is_negative);
        let oriented = |v: &BigInt| if flip { -v } else { v.clone() };
        let normal = [oriented(&plane.a), oriented(&plane.b), oriented(&plane.c)];
        let normal = words(&normal).unwrap_or_else(|| normal.each_ref().map(|v| v.signum().to_i128().expect("a sign")));
        let d = &denominator;
        let mut edges = Vec::with_capacity(points.len());
        for (i, p) in points.iter().enumerate() {
            let q = &points[(i + 1) % points.len()];
            if p[1] == q[1] {
                continue;
            }
            let line = reduced_line(p, q, &scale);
            let (low, high) = if p[1] < q[1] { (&p[1], &q[1]) } else { (&q[1], &p[1]) };
            // Rows whose scanlines (2r + 1)·D lie in [low, high), [low, high], (low, high].
            let (from, to) = (low - d, high - d);
            let (first, after) = (from.div_ceil(&scale), from.div_floor(&scale) + 1);
            let (last_open, last) = (to.div_ceil(&scale) - 1, to.div_floor(&scale));
            let rows = [row_range(first.clone(), last_open), row_range(first, last.clone()), row_range(after, last)];
            edges.push(Edge { rows, line });
        }
        let mut polygon = BigPolygon { denominator, points, edges, plane, normal, words: None };
        polygon.words = polygon.words();
        Ok(polygon)
    }

    /// The lines and plane in `i128`, when every crossing and depth fits
    /// (see [`BigPolygon::new`]).
    fn words(&self) -> Option<Words> {
        let mut lines = Vec::with_capacity(self.edges.len());
        for edge in &self.edges {
            let [alpha, beta, gamma] = words(&edge.line)?;
            // The widest range is the closed one; it may be empty.
            let [first, last] = edge.rows[1];
            let numerator = |r: i128| sum_of_products(&[(beta, odd(r)?), (gamma, 2)]);
            let fits = first > last || (below(numerator(first), CROSSING) && below(numerator(last), CROSSING));
            if !fits || !below(alpha.checked_mul(2), CROSSING) {
                return None;
            }
            lines.push([alpha, beta, gamma]);
        }
        let PlaneEquation { a, b, c, d } = &self.plane;
        let [a, b, c, d] = words(&[a.clone(), b.clone(), c.clone(), d.clone()])?;
        let [x0, x1, y0, y1] = self.cells();
        // Corners one pixel out.
        let depth = |x: i128, y: i128| sum_of_products(&[(a, odd(x)?), (b, odd(y)?), (d, 2)]);
        let (columns, rows) = ([x0 - 1, x1 + 1], [y0 - 1, y1 + 1]);
        let corners = columns.iter().all(|&x| rows.iter().all(|&y| below(depth(x, y), DEPTH_NUMERATOR)));
        (corners && below(c.checked_mul(2), DEPTH_DENOMINATOR)).then_some(Words { lines, plane: [a, b, c, d] })
    }

    /// The same polygon with its crossings and depths in big integers
    /// whatever their size (for the tests that compare the tiers).
    #[cfg(test)]
    pub(crate) fn without_words(mut self) -> BigPolygon {
        self.words = None;
        self
    }

    /// The plane, reduced (as [`crate::geometry::plane::Geometry::plane`]).
    pub(crate) fn plane(&self) -> &PlaneEquation {
        &self.plane
    }

    /// `(A, B, C)` oriented as Newell's normal (the signs alone when a
    /// coefficient does not fit `i128`).
    pub(crate) fn normal(&self) -> [i128; 3] {
        self.normal
    }

    /// The scaled vertices and `D`.
    pub(crate) fn scaled(&self) -> (&[[BigInt; 3]], &BigInt) {
        (&self.points, &self.denominator)
    }

    /// The cells `⌊x⌋`, `⌊y⌋` holding the polygon's bounding box: lowest
    /// and highest column, lowest and highest row, each clamped to
    /// `ROW_LOW ..= ROW_HIGH`.
    pub(crate) fn cells(&self) -> [i128; 4] {
        let scale = &self.denominator * 2;
        let cell = |axis: usize, high: bool| {
            let values = self.points.iter().map(|p| &p[axis]);
            let value = if high { values.max() } else { values.min() };
            clamped(value.expect("a polygon has vertices").div_floor(&scale))
        };
        [cell(0, false), cell(0, true), cell(1, false), cell(1, true)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The crossings and depths of the tier are sums of products that may
    /// overflow `i128` on the way though the sum fits: taken exactly.
    #[test]
    fn sums_of_products_are_exact_past_an_overflowing_term() {
        assert_eq!(sum_of_products(&[(i128::MAX, 2), (-i128::MAX, 2), (3, 5)]), Some(15));
        assert_eq!(sum_of_products(&[(i128::MAX, 2)]), None);
        assert_eq!(sum_of_products(&[(1 << 62, 1 << 62), (-(1 << 62), 1 << 62)]), Some(0));
        assert_eq!(sum_of_products(&[(-7, 6), (4, 10)]), Some(-2));
        assert!(below(Some(-(1 << 119)), CROSSING) && !below(Some(1 << 120), CROSSING) && !below(None, CROSSING));
    }
}
