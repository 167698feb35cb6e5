//! A polygon's geometry in exact integers, and its plane by Newell's method.
//!
//! Every coordinate of one polygon is written over the polygon's least common
//! denominator `D` and then doubled: a vertex's *scaled* coordinates are the
//! integers `x·2D`, `y·2D`, `z·2D`. In those units the centre of pixel column
//! `x` is `(2x + 1)·D` and scanline `row` lies at `(2row + 1)·D`, so pixel
//! centres and half-interval scanlines are integers too, and the whole
//! rasterizer runs on integers with no rounding anywhere: `i128` always fits
//! (see [`MAX_SCALED`]), and `i64` does for most polygons
//! ([`Geometry::fits_i64`]).

use std::fmt;

use num_bigint::BigInt;
use num_integer::Integer;

use crate::exact::Q;

/// Largest allowed magnitude of a scaled coordinate `|x·2D|`.
///
/// With `R = 2^34` and at most [`MAX_VERTICES`] vertices every intermediate
/// value fits in `i128`: Newell's coefficients are at most `4nR² ≤ 2^86`, the
/// depth numerator at a pixel centre at most `20nR³ < 2^123`, a crossing's
/// numerator at most `6R² < 2^71` (see `depth` and `scan`).
pub const MAX_SCALED: i128 = 1 << 34;

/// Largest magnitude of a scaled coordinate in the big-integer tier
/// ([`Geometry::is_big`]): polygons beyond [`MAX_SCALED`] are drawn by a
/// rasterizer that multiplies in arbitrary-precision integers
/// (`crate::big`), as long as what it reports (crossings, depths, the
/// plane, all reduced) still fits the 128-bit numbers the rest of zsim
/// speaks. Sums and differences of two scaled coordinates (and scanline
/// heights, which lie within the polygon) then fit `i128`; every product
/// of them is taken in big integers.
pub const MAX_SCALED_BIG: i128 = 1 << 120;

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
        value: Q,
        /// The polygon's least common denominator `D` (so far), which may
        /// itself have outgrown 128 bits.
        denominator: BigInt,
    },
    /// A vertex that does not lie on the plane through the others.
    NotPlanar(Box<OffPlane>),
    /// As [`GeometryError::NotPlanar`], for a polygon whose plane's
    /// coefficients or the vertex's distance do not fit 128 bits.
    NotPlanarBeyondRange {
        /// 1-based vertex number.
        vertex: usize,
        /// The three vertices (1-based) that fix the plane.
        through: [usize; 3],
        /// The plane, when its coefficients fit (then the distance does not).
        plane: Option<PlaneEquation>,
    },
    /// Within [`MAX_SCALED_BIG`], but the polygon's plane, an edge's
    /// crossings or its depths, reduced, would outgrow the 128-bit numbers
    /// zsim reports (`crate::big::fits`).
    TooLargeForDepth {
        /// 1-based vertex with the largest coordinate.
        vertex: usize,
        /// That coordinate.
        value: Q,
    },
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
    pub off_by: Q,
    /// Whether `off_by` is measured along z.
    pub along_z: bool,
}

impl fmt::Display for GeometryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GeometryError::TooFewVertices(n) => f.write_str(&words!("geometry-too-few", count = n.to_string())),
            GeometryError::TooManyVertices(n) => {
                f.write_str(&words!("geometry-too-many", count = n.to_string(), max = MAX_VERTICES.to_string()))
            }
            GeometryError::OutOfRange { vertex, value, denominator } => f.write_str(&words!(
                "geometry-out-of-range",
                vertex = vertex.to_string(),
                value = crate::exact::fraction(*value),
                denominator = denominator.to_string()
            )),
            GeometryError::TooLargeForDepth { vertex, value } => f.write_str(&words!(
                "geometry-too-large-for-depth",
                vertex = vertex.to_string(),
                value = crate::exact::fraction(*value)
            )),
            GeometryError::NotPlanarBeyondRange { vertex, through: [i, j, k], plane } => f.write_str(&match plane {
                None => words!(
                    "geometry-off-plane-large",
                    vertex = vertex.to_string(),
                    i = i.to_string(),
                    j = j.to_string(),
                    k = k.to_string()
                ),
                Some(plane) => words!(
                    "geometry-off-plane-far",
                    vertex = vertex.to_string(),
                    plane = plane.to_string(),
                    i = i.to_string(),
                    j = j.to_string(),
                    k = k.to_string()
                ),
            }),
            GeometryError::NotPlanar(off) => {
                let OffPlane { vertex, through: [i, j, k], plane, off_by, along_z } = off.as_ref();
                let (key, off) = if *along_z {
                    ("geometry-off-plane-z", crate::exact::exact_and_decimal(*off_by))
                } else {
                    ("geometry-off-plane", crate::exact::fraction(*off_by))
                };
                f.write_str(&words!(
                    key,
                    vertex = vertex.to_string(),
                    plane = plane.to_string(),
                    i = i.to_string(),
                    j = j.to_string(),
                    k = k.to_string(),
                    off = off
                ))
            }
        }
    }
}

/// A plane `a·x + b·y + c·z + d = 0` with integer coefficients reduced by
/// their greatest common divisor, in the polygon's own coordinates (not
/// scaled), signed as the book prints it: `c > 0` (when `c = 0`, `b > 0`;
/// when both are 0, `a > 0`). The winding is reported apart,
/// from the sign of Newell's `c` ([`Geometry::c`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlaneEquation {
    /// Coefficient of x.
    pub a: i128,
    /// Coefficient of y.
    pub b: i128,
    /// Coefficient of z.
    pub c: i128,
    /// Constant term.
    pub d: i128,
}

impl fmt::Display for PlaneEquation {
    /// Prints like the book: `3x + y + 4z - 120 = 0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut out = String::new();
        for (coef, var) in [(self.a, "x"), (self.b, "y"), (self.c, "z"), (self.d, "")] {
            if coef == 0 {
                continue;
            }
            let magnitude = coef.unsigned_abs();
            let number = if magnitude == 1 && !var.is_empty() { String::new() } else { magnitude.to_string() };
            if out.is_empty() {
                out = format!("{}{number}{var}", if coef < 0 { "-" } else { "" });
            } else {
                out = format!("{out} {} {number}{var}", if coef < 0 { "-" } else { "+" });
            }
        }
        if out.is_empty() {
            out.push('0');
        }
        write!(f, "{out} = 0")
    }
}

/// A polygon ready for the rasterizer: scaled integer vertices and Newell's
/// normal in scaled units.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Geometry {
    /// `D`, the least common denominator of the polygon's coordinates; the
    /// scale of the scaled coordinates is `2D`.
    pub denominator: i128,
    /// Vertices as `[x·2D, y·2D, z·2D]`.
    pub points: Vec<[i128; 3]>,
    /// Newell's normal `(a, b, c)` computed on the scaled vertices.
    pub normal: [i128; 3],
    /// Whether the rasterizer's integers fit 64 bits ([`Geometry::fits_i64`]).
    narrow: bool,
    /// For a polygon beyond [`MAX_SCALED`], which runs on the big-integer
    /// tier ([`Geometry::is_big`]): its edges' lines and plane, reduced.
    big: Option<Box<crate::big::Lines>>,
}

impl Geometry {
    /// Scales the vertices to integers, computes Newell's normal and checks
    /// that every vertex lies on the plane through vertex 1.
    ///
    /// Guarantees: 3 ≤ vertices ≤ [`MAX_VERTICES`], every scaled coordinate
    /// within ±[`MAX_SCALED`], and the polygon planar (trivially so when the
    /// normal is zero, i.e. the vertices are collinear).
    pub fn new(vertices: &[[Q; 3]]) -> Result<Geometry, GeometryError> {
        if vertices.len() < 3 {
            return Err(GeometryError::TooFewVertices(vertices.len()));
        }
        if vertices.len() > MAX_VERTICES {
            return Err(GeometryError::TooManyVertices(vertices.len()));
        }
        let mut denominator: i128 = 1;
        for (index, vertex) in vertices.iter().enumerate() {
            for value in vertex {
                // The lcm can outgrow i128 itself before it passes the limit.
                let factor = denominator / denominator.gcd(value.denom());
                match factor.checked_mul(*value.denom()) {
                    Some(lcm) if lcm <= MAX_SCALED_BIG => denominator = lcm,
                    _ => {
                        let denominator = BigInt::from(factor) * BigInt::from(*value.denom());
                        return Err(GeometryError::OutOfRange { vertex: index + 1, value: *value, denominator });
                    }
                }
            }
        }
        let scale = 2 * denominator;
        let mut points = Vec::with_capacity(vertices.len());
        for (index, vertex) in vertices.iter().enumerate() {
            let mut point = [0i128; 3];
            for (axis, value) in vertex.iter().enumerate() {
                let scaled = value.numer().checked_mul(scale / value.denom()).filter(|s| s.abs() <= MAX_SCALED_BIG);
                point[axis] = scaled.ok_or_else(|| GeometryError::OutOfRange {
                    vertex: index + 1,
                    value: *value,
                    denominator: denominator.into(),
                })?;
            }
            points.push(point);
        }
        let big = denominator > MAX_SCALED || points.iter().flatten().any(|v| v.abs() > MAX_SCALED);
        if big {
            let out_of_range = || {
                let (index, value) = vertices
                    .iter()
                    .enumerate()
                    .flat_map(|(i, v)| v.iter().map(move |q| (i, *q)))
                    .max_by_key(|(_, q)| q.numer().unsigned_abs() / q.denom().unsigned_abs())
                    .unwrap_or((0, vertices[0][0]));
                GeometryError::OutOfRange { vertex: index + 1, value, denominator: denominator.into() }
            };
            // A normal beyond 128 bits gives depths beyond them too.
            let too_large = || {
                let GeometryError::OutOfRange { vertex, value, .. } = out_of_range() else { unreachable!() };
                GeometryError::TooLargeForDepth { vertex, value }
            };
            let normal = crate::big::newell(&points).ok_or_else(too_large)?;
            let mut geometry = Geometry { denominator, points, normal, narrow: false, big: None };
            crate::big::check_planar(&geometry)?;
            let lines = crate::big::Lines::new(&geometry).ok_or_else(too_large)?;
            geometry.big = Some(Box::new(lines));
            return Ok(geometry);
        }
        let normal = newell(&points);
        let mut geometry = Geometry { denominator, points, normal, narrow: false, big: None };
        geometry.check_planar()?;
        geometry.narrow = geometry.bounds_fit_i64();
        Ok(geometry)
    }

    /// The same polygon on the big-integer tier, whatever its size (for the
    /// tests that compare the tiers).
    #[cfg(test)]
    pub(crate) fn on_big_tier(&self) -> Geometry {
        let normal = crate::big::newell(&self.points).expect("a small polygon's normal fits");
        let geometry = Geometry { normal, big: None, narrow: false, ..self.clone() };
        let lines = crate::big::Lines::new(&geometry).expect("a small polygon's lines fit");
        Geometry { big: Some(Box::new(lines)), ..geometry }
    }

    /// Whether the polygon lies beyond [`MAX_SCALED`], where the word-sized
    /// rasterizer could overflow: it is then drawn by the big-integer tier
    /// (`crate::big`), exactly, more slowly, with the same rules and results.
    /// Its normal is Newell's reduced by the components' common divisor.
    pub fn is_big(&self) -> bool {
        self.big.is_some()
    }

    /// The edges' lines and the plane of a polygon on the big-integer tier.
    pub(crate) fn lines(&self) -> Option<&crate::big::Lines> {
        self.big.as_deref()
    }

    /// The scale factor `2D` between polygon units and scaled units.
    pub fn scale(&self) -> i128 {
        2 * self.denominator
    }

    /// Newell's `c` in scaled units; zero for a polygon seen edge-on (or with
    /// collinear vertices).
    pub fn c(&self) -> i128 {
        self.normal[2]
    }

    /// Whether Newell's normal vanishes: the vertices are collinear (or the
    /// loops of a self-intersecting polygon cancel), so there is no plane.
    pub fn is_degenerate(&self) -> bool {
        self.normal.iter().all(|&v| v == 0)
    }

    /// Whether every integer the rasterizer computes for this polygon fits
    /// 64 bits, so that it can run on `i64` ([`crate::exact::Word`]) with the
    /// same results. Every covered centre and scanline lies within one pixel
    /// (`2D`) of the polygon's bounding box. With `R` the largest `|x|`, `|y|`
    /// of a scaled vertex plus `2D`, and `Δx`, `Δy` the largest distances of a
    /// vertex from vertex 1 plus `4D`:
    /// - an edge's crossing numerator (also one row past its end) is at most
    ///   `8R² + 4RD`, and sorting multiplies it by a denominator `≤ 2R`;
    /// - the depth numerator at a centre, `c·Z₁ − a(X − X₁) − b(Y − Y₁)`, is at
    ///   most `|c·Z₁| + |a|·Δx + |b|·Δy` plus a row's and a column's step
    ///   `(|a| + |b|)·2D`, and its denominator is `|c|·2D`.
    ///
    /// Each of these must stay below `2^61`, which leaves room for the sums of two.
    /// Decided once, when the geometry is made.
    #[inline]
    pub fn fits_i64(&self) -> bool {
        self.narrow
    }

    fn bounds_fit_i64(&self) -> bool {
        const LIMIT: i128 = 1 << 61;
        let d = self.denominator;
        let r = self.points.iter().map(|p| p[0].abs().max(p[1].abs())).max().unwrap_or(0) + 2 * d;
        let [x1, y1, z1] = self.points[0];
        let reach =
            |axis: usize, first: i128| self.points.iter().map(|p| (p[axis] - first).abs()).max().unwrap_or(0) + 4 * d;
        // All below 2^123 by MAX_SCALED, so none of these overflows i128.
        let crossing = 8 * r * r + 4 * r * d;
        let [a, b, c] = self.normal.map(i128::abs);
        let depth = c * z1.abs() + a * reach(0, x1) + b * reach(1, y1) + (a + b) * 2 * d;
        crossing < LIMIT && crossing * 2 * r < LIMIT && depth < LIMIT && c * 2 * d < LIMIT
    }

    /// The plane through vertex 1 with Newell's normal, in the polygon's own
    /// units, reduced.
    pub fn plane(&self) -> PlaneEquation {
        if let Some(lines) = &self.big {
            return lines.plane();
        }
        reduced_plane(self.normal, self.points[0], self.scale())
    }

    /// Checks every vertex against the plane through vertex 1 and the first two
    /// vertices that are not collinear with it, so that the vertex named is the
    /// first one off that plane (Newell's averaged normal would blame others).
    fn check_planar(&self) -> Result<(), GeometryError> {
        let p1 = self.points[0];
        let sub = |p: [i128; 3]| [p[0] - p1[0], p[1] - p1[1], p[2] - p1[2]];
        let Some(i) = self.points.iter().position(|p| *p != p1) else { return Ok(()) };
        let u = sub(self.points[i]);
        let found = self.points.iter().enumerate().skip(i + 1).find_map(|(k, p)| {
            let v = sub(*p);
            let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
            (n != [0, 0, 0]).then_some((k, n))
        });
        let Some((k, normal)) = found else { return Ok(()) };
        for (index, point) in self.points.iter().enumerate() {
            let w = sub(*point);
            // Bounded by 3·8R²·2R < 2^108 (see MAX_SCALED).
            let residual = normal[0] * w[0] + normal[1] * w[1] + normal[2] * w[2];
            if residual == 0 {
                continue;
            }
            let plane = reduced_plane(normal, p1, self.scale());
            let (off_by, along_z) = if normal[2] != 0 {
                // residual = n_z·ΔZ in scaled units, and Δz = ΔZ / 2D.
                (Q::new(residual, normal[2] * self.scale()), true)
            } else {
                // Without a z term, report the reduced equation's value at the vertex.
                let [x, y, z] = point.map(|v| Q::new(v, self.scale()));
                let value = Q::from_integer(plane.a) * x
                    + Q::from_integer(plane.b) * y
                    + Q::from_integer(plane.c) * z
                    + Q::from_integer(plane.d);
                (value, false)
            };
            return Err(GeometryError::NotPlanar(Box::new(OffPlane {
                vertex: index + 1,
                through: [1, i + 1, k + 1],
                plane,
                off_by,
                along_z,
            })));
        }
        Ok(())
    }
}

/// The plane with `normal` (scaled units) through `point` (scaled units), in
/// polygon units, reduced and signed as the book prints it.
///
/// In scaled units the plane is `a·X + b·Y + c·Z + d' = 0` with
/// `d' = −(a·X₁ + b·Y₁ + c·Z₁)`; with `X = 2D·x` that is
/// `2D·a·x + 2D·b·y + 2D·c·z + d' = 0`, then divided by the gcd.
pub(crate) fn reduced_plane(normal: [i128; 3], point: [i128; 3], scale: i128) -> PlaneEquation {
    // Worked in big integers: for a polygon on the big-integer tier the
    // products outgrow i128 though the reduced plane fits (checked when the
    // geometry is made, [`crate::big::fits`]).
    crate::big::reduced_plane(normal, point, scale)
        .expect("the reduced plane fits i128: checked when the geometry was made")
}

/// Newell's method (seed 002): `a = Σ(yᵢ − yᵢ₊₁)(zᵢ + zᵢ₊₁)`,
/// `b = Σ(zᵢ − zᵢ₊₁)(xᵢ + xᵢ₊₁)`, `c = Σ(xᵢ − xᵢ₊₁)(yᵢ + yᵢ₊₁)`, indices
/// taken around the polygon.
pub fn newell(points: &[[i128; 3]]) -> [i128; 3] {
    let mut normal = [0i128; 3];
    for (i, p) in points.iter().enumerate() {
        let q = points[(i + 1) % points.len()];
        normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
        normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
        normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    normal
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(values: &[[i128; 3]]) -> Vec<[Q; 3]> {
        values.iter().map(|v| v.map(Q::from_integer)).collect()
    }

    #[test]
    fn book_triangle_plane_is_3x_y_4z_minus_120() {
        let triangle = Geometry::new(&q(&[[15, 15, 15], [25, 25, 5], [30, 10, 5]])).unwrap();
        assert!(triangle.c() < 0, "P5, P6, P7 run clockwise; the book prints the plane with c > 0");
        assert_eq!(triangle.plane(), PlaneEquation { a: 3, b: 1, c: 4, d: -120 });
        assert_eq!(triangle.plane().to_string(), "3x + y + 4z - 120 = 0");
    }

    #[test]
    fn book_rectangle_runs_clockwise() {
        let rectangle = Geometry::new(&q(&[[10, 5, 10], [10, 25, 10], [25, 25, 10], [25, 5, 10]])).unwrap();
        assert_eq!(rectangle.plane().to_string(), "z - 10 = 0");
        assert!(rectangle.c() < 0, "Newell's c < 0 means clockwise seen from +z");
    }

    #[test]
    fn fractional_vertices_scale_to_integers() {
        let vertices = vec![
            [Q::new(1, 2), Q::new(1, 3), Q::from_integer(0)],
            [Q::from_integer(4), Q::new(1, 3), Q::from_integer(0)],
            [Q::from_integer(4), Q::from_integer(5), Q::from_integer(0)],
        ];
        let geometry = Geometry::new(&vertices).unwrap();
        assert_eq!(geometry.denominator, 6);
        assert_eq!(geometry.points[0], [6, 4, 0]);
        assert_eq!(geometry.plane().to_string(), "z = 0");
    }

    #[test]
    fn off_plane_vertex_is_named_with_its_distance() {
        let err = Geometry::new(&q(&[[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 1]])).unwrap_err();
        match err {
            GeometryError::NotPlanar(off) => {
                assert_eq!(off.vertex, 4);
                assert_eq!(off.off_by, Q::from_integer(1));
                assert!(off.along_z);
            }
            other => panic!("expected NotPlanar, got {other:?}"),
        }
    }

    #[test]
    fn collinear_vertices_are_degenerate_not_an_error() {
        let geometry = Geometry::new(&q(&[[0, 0, 0], [1, 1, 1], [2, 2, 2]])).unwrap();
        assert!(geometry.is_degenerate());
    }

    #[test]
    fn coordinates_beyond_the_word_range_run_on_the_big_tier_and_beyond_its_range_are_refused() {
        // At the word limit: 2^33 scaled by 2 is exactly 2^34, still on the words.
        assert!(!Geometry::new(&q(&[[0, 0, 0], [1 << 33, 0, 0], [0, 1, 0]])).unwrap().is_big());
        assert!(!Geometry::new(&q(&[[0, 0, 0], [-(1 << 33), 0, 0], [0, 1, 0]])).unwrap().is_big());
        // One more: the big-integer tier draws it.
        assert!(Geometry::new(&q(&[[0, 0, 0], [(1 << 33) + 1, 0, 0], [0, 1, 0]])).unwrap().is_big());
        // Past MAX_SCALED_BIG (2^119 scaled by 2): refused, naming the vertex.
        assert!(Geometry::new(&q(&[[0, 0, 0], [1 << 119, 0, 0], [0, 1, 0]])).unwrap().is_big());
        let err = Geometry::new(&q(&[[0, 0, 0], [(1 << 119) + 1, 0, 0], [0, 1, 0]])).unwrap_err();
        assert!(matches!(err, GeometryError::OutOfRange { vertex: 2, .. }), "{err:?}");
    }
}
