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

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::geometry::equation::{GeometryError, MAX_VERTICES, PlaneEquation, not_planar, reduced_plane};
use crate::geometry::newell::{OffPlaneVertex, first_off_plane, newell};
use crate::numbers::{Exact, Q};

/// Largest allowed magnitude of a scaled coordinate `|x·2D|`.
///
/// With `R = 2^34` and at most [`MAX_VERTICES`] vertices every intermediate
/// value fits in `i128`: Newell's coefficients are at most `4nR² ≤ 2^86`, the
/// depth numerator at a pixel centre at most `20nR³ < 2^123`, a crossing's
/// numerator at most `6R² < 2^71` (see `depth` and `scan`).
pub const MAX_SCALED: i128 = 1 << 34;

/// Largest size, in bits, of a scaled coordinate `|x·2D|` in the
/// big-integer tier ([`Geometry::is_big`]): polygons beyond [`MAX_SCALED`]
/// are drawn by a rasterizer that keeps the scaled vertices in
/// arbitrary-precision integers (`crate::raster::big`), and reports crossings,
/// depths and the plane in big integers where they outgrow 128 bits. The
/// bound only keeps absurd input
/// (hundreds of coprime denominators) from running for ever: 2^4096 is about
/// 10^1233.
pub const MAX_SCALED_BITS: u64 = 4096;

/// Scaled vertices: a triangle's in place, with no allocation of their own
/// (reading a large scene was mostly allocation and moving; room for four
/// made every polygon larger to move, and reading slower).
pub type Points = smallvec::SmallVec<[[i128; 3]; 3]>;

/// A polygon ready for the rasterizer: scaled integer vertices and Newell's
/// normal in scaled units.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Geometry {
    /// `D`, the least common denominator of the polygon's coordinates; the
    /// scale of the scaled coordinates is `2D`. 0 on the big-integer tier.
    pub denominator: i128,
    /// Vertices as `[x·2D, y·2D, z·2D]`, within [`MAX_SCALED`]; empty on the
    /// big-integer tier, which keeps them in big integers
    /// ([`Geometry::big_scaled`]).
    pub points: Points,
    /// Newell's normal `(a, b, c)` computed on the scaled vertices (on the
    /// big-integer tier: the reduced plane's, pointing the same way).
    pub normal: [i128; 3],
    /// Whether the rasterizer's integers fit 64 bits ([`Geometry::fits_i64`]).
    narrow: bool,
    /// For a polygon beyond [`MAX_SCALED`], which runs on the big-integer
    /// tier ([`Geometry::is_big`]): its scaled vertices in big integers, its
    /// edges' lines and plane, reduced.
    big: Option<Box<crate::geometry::big::BigPolygon>>,
}

impl Geometry {
    /// Scales the vertices to integers, computes Newell's normal and checks
    /// that every vertex lies on the plane through vertex 1.
    ///
    /// Guarantees: 3 ≤ vertices ≤ [`MAX_VERTICES`], every scaled coordinate
    /// within ±[`MAX_SCALED`], and the polygon planar (trivially so when the
    /// normal is zero, i.e. the vertices are collinear).
    pub fn new(vertices: &[[Q; 3]]) -> Result<Geometry, GeometryError> {
        Geometry::of(vertices)
    }

    /// [`Geometry::new`] for vertices of any size (a clipped clip-space
    /// polygon's may outgrow 128-bit fractions): on the words when they fit
    /// them, else on the big-integer tier.
    pub fn from_exact(vertices: &[[Exact; 3]]) -> Result<Geometry, GeometryError> {
        Geometry::of(vertices)
    }

    fn of<C: Coordinate>(vertices: &[[C; 3]]) -> Result<Geometry, GeometryError> {
        if vertices.len() < 3 {
            return Err(GeometryError::TooFewVertices(vertices.len()));
        }
        if vertices.len() > MAX_VERTICES {
            return Err(GeometryError::TooManyVertices(vertices.len()));
        }
        // The words: D and every scaled coordinate within MAX_SCALED.
        let words = || {
            let mut denominator: i128 = 1;
            // Integers (most coordinates) skip the gcd and the division: 128-bit
            // ones, which were most of the time a large scene took to read.
            for value in vertices.iter().flatten() {
                let value = value.word()?;
                if *value.denom() != 1 {
                    denominator = denominator.checked_mul(value.denom() / denominator.gcd(value.denom()))?;
                }
                if denominator > MAX_SCALED {
                    return None;
                }
            }
            let scale = 2 * denominator;
            let scaled = |v: &C| {
                let v = v.word()?;
                let factor = if *v.denom() == 1 { scale } else { scale / v.denom() };
                Some(v.numer().checked_mul(factor)?).filter(|s| s.abs() <= MAX_SCALED)
            };
            // A loop, not a collect through `Option`: that took a third of a
            // large scene's geometry (callgrind, 930 instructions a triangle).
            let mut points = Points::new();
            for v in vertices {
                points.push([scaled(&v[0])?, scaled(&v[1])?, scaled(&v[2])?]);
            }
            Some((denominator, points))
        };
        let Some((denominator, points)) = words() else {
            return Geometry::new_big(&vertices.iter().map(|v| v.each_ref().map(C::big)).collect::<Vec<_>>());
        };
        let normal = newell(&points);
        let mut geometry = Geometry { denominator, points, normal, narrow: false, big: None };
        geometry.check_planar()?;
        geometry.narrow = geometry.bounds_fit_i64();
        Ok(geometry)
    }

    /// A polygon beyond the words, on the big-integer tier.
    fn new_big(vertices: &[[BigRational; 3]]) -> Result<Geometry, GeometryError> {
        let mut denominator = BigInt::from(1);
        // Far past the bound once D has this many bits more than a value's
        // denominator (|value| × 2D > 2D / denominator): stop before the lcm of
        // absurd input grows for ever.
        let largest = vertices.iter().flatten().map(|v| v.denom().bits()).max().unwrap_or(0).max(128);
        for (index, vertex) in vertices.iter().enumerate() {
            for value in vertex {
                denominator = denominator.lcm(value.denom());
                if denominator.bits() > MAX_SCALED_BITS + largest {
                    let value = Exact::from(value.clone());
                    return Err(GeometryError::OutOfRange { vertex: index + 1, value, denominator });
                }
            }
        }
        let scale: BigInt = &denominator * 2u32;
        let points: Vec<[BigInt; 3]> =
            vertices.iter().map(|v| v.each_ref().map(|c| c.numer() * scale.div_floor(c.denom()))).collect();
        let limit = BigInt::from(1) << MAX_SCALED_BITS;
        let beyond = points
            .iter()
            .enumerate()
            .find_map(|(i, p)| p.iter().position(|v| v.magnitude() > limit.magnitude()).map(|axis| (i, axis)));
        if let Some((index, axis)) = beyond {
            let value = Exact::from(vertices[index][axis].clone());
            return Err(GeometryError::OutOfRange { vertex: index + 1, value, denominator });
        }
        Ok(Geometry::on_big(crate::geometry::big::BigPolygon::new(points, denominator)?))
    }

    /// The geometry of a polygon of the big-integer tier: no word-sized
    /// scaled vertices (`points` empty, `denominator` 0), the normal
    /// `(A, B, C)` of its reduced plane pointing as Newell's does.
    fn on_big(polygon: crate::geometry::big::BigPolygon) -> Geometry {
        Geometry {
            denominator: 0,
            points: Points::new(),
            normal: polygon.normal(),
            narrow: false,
            big: Some(Box::new(polygon)),
        }
    }

    /// The same polygon on the big-integer tier, whatever its size (for the
    /// tests that compare the tiers).
    #[cfg(test)]
    pub(crate) fn on_big_tier(&self) -> Geometry {
        let points = self.points.iter().map(|p| p.map(BigInt::from)).collect();
        Geometry::on_big(crate::geometry::big::BigPolygon::new(points, self.denominator.into()).expect("planar"))
    }

    /// The same polygon on the big-integer tier with its crossings and
    /// depths computed in big integers, as for a plane beyond 128 bits (for
    /// the tests that compare the tiers).
    #[cfg(test)]
    pub(crate) fn on_huge_tier(&self) -> Geometry {
        let points = self.points.iter().map(|p| p.map(BigInt::from)).collect();
        let polygon = crate::geometry::big::BigPolygon::new(points, self.denominator.into()).expect("planar");
        Geometry::on_big(polygon.without_words())
    }

    /// Whether the polygon lies beyond [`MAX_SCALED`], where the word-sized
    /// rasterizer could overflow: it is then drawn by the big-integer tier
    /// (`crate::raster::big`), exactly, more slowly, with the same rules and results.
    /// Its normal is Newell's reduced by the components' common divisor.
    pub fn is_big(&self) -> bool {
        self.big.is_some()
    }

    /// The big-integer tier's polygon, when this is one.
    pub(crate) fn big(&self) -> Option<&crate::geometry::big::BigPolygon> {
        self.big.as_deref()
    }

    /// The scaled vertices and `D` of a polygon on the big-integer tier, in
    /// big integers.
    pub fn big_scaled(&self) -> Option<(&[[BigInt; 3]], &BigInt)> {
        self.big.as_deref().map(crate::geometry::big::BigPolygon::scaled)
    }

    /// The cells `⌊x⌋`, `⌊y⌋` holding the polygon's bounding box, on any
    /// tier: lowest and highest column, lowest and highest row.
    pub fn cells(&self) -> [i128; 4] {
        if let Some(polygon) = &self.big {
            return polygon.cells();
        }
        let (mut x0, mut x1, mut y0, mut y1) = (i128::MAX, i128::MIN, i128::MAX, i128::MIN);
        for p in &self.points {
            (x0, x1, y0, y1) = (x0.min(p[0]), x1.max(p[0]), y0.min(p[1]), y1.max(p[1]));
        }
        // ⌊v / 2D⌋: a shift when 2D is a power of two (integer and binary-fraction
        // vertices, nearly every scene), as a 128-bit division is slow and this runs
        // twice a polygon per draw.
        let scale = self.scale();
        let shift = scale.trailing_zeros();
        let cell = |v: i128| if scale == 1 << shift { v >> shift } else { crate::numbers::floor_div(v, scale).0 };
        [cell(x0), cell(x1), cell(y0), cell(y1)]
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
    /// 64 bits, so that it can run on `i64` ([`crate::numbers::Word`]) with the
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
        if let Some(polygon) = &self.big {
            return polygon.plane().clone();
        }
        reduced_plane(self.normal, self.points[0], self.scale())
    }

    /// How much z changes from one pixel centre to the next on a scanline,
    /// `−a/c` (the Russian coursework: `z₁ = z − a/c`); `None` for a polygon seen edge-on.
    pub fn slope(&self) -> Option<Exact> {
        let PlaneEquation { a, c, .. } = self.plane();
        (!c.is_zero()).then(|| Exact::from_big(-a, c))
    }

    /// Checks every vertex against the plane through vertex 1 and the first two
    /// vertices that are not collinear with it ([`first_off_plane`]).
    fn check_planar(&self) -> Result<(), GeometryError> {
        // In i128: bounded by 3·8R²·2R < 2^108 (see MAX_SCALED).
        let Some(off) = first_off_plane(&self.points) else { return Ok(()) };
        let big = |p: &[i128; 3]| p.map(BigInt::from);
        let points: Vec<[BigInt; 3]> = self.points.iter().map(big).collect();
        let off = OffPlaneVertex {
            vertex: off.vertex,
            through: off.through,
            normal: big(&off.normal),
            residual: off.residual.into(),
        };
        Err(not_planar(off, &points, &BigInt::from(self.scale())))
    }
}

/// A vertex coordinate as [`Geometry`] reads it: a 128-bit fraction when it
/// is one, and as a big rational.
trait Coordinate {
    fn word(&self) -> Option<Q>;
    fn big(&self) -> BigRational;
}

impl Coordinate for Q {
    fn word(&self) -> Option<Q> {
        Some(*self)
    }

    fn big(&self) -> BigRational {
        BigRational::new_raw(BigInt::from(*self.numer()), BigInt::from(*self.denom()))
    }
}

impl Coordinate for Exact {
    fn word(&self) -> Option<Q> {
        Exact::word(self)
    }

    fn big(&self) -> BigRational {
        self.to_big()
    }
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
        assert_eq!(triangle.plane(), PlaneEquation::of(3, 1, 4, -120));
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
                assert_eq!(off.off_by, Exact::Word(Q::from_integer(1)));
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
        // Any common denominator: 3^60 (about 2^95) times 2^100 coordinates, on the plane z = 1/3^60.
        let z = Q::new(1, 3i128.pow(60));
        let far = [[Q::from_integer(1 << 100), Q::from_integer(0), z], [Q::from_integer(4), Q::from_integer(4), z]];
        let geometry = Geometry::new(&[[Q::from_integer(0), Q::from_integer(0), z], far[0], far[1]]).unwrap();
        assert!(geometry.is_big() && geometry.big_scaled().unwrap().1 == &BigInt::from(3i128.pow(60)));
        // What it reports may outgrow 128 bits: a crossing 2^126 pixels out is drawn too.
        assert!(Geometry::new(&q(&[[0, 0, 0], [1 << 126, 0, 0], [0, 1, 0]])).unwrap().is_big());
        // Past MAX_SCALED_BITS: denominators 2 … 3001 have an lcm near e^3000 ≈ 2^4328.
        let vertices: Vec<[Q; 3]> =
            (1..=1500).map(|j| [Q::new(1, 2 * j), Q::new(1, 2 * j + 1), Q::from_integer(0)]).collect();
        let err = Geometry::new(&vertices).unwrap_err();
        assert!(matches!(err, GeometryError::OutOfRange { vertex: 1454, .. }), "{err:?}");
        // 60,000 coprime-ish denominators: refused as soon as the lcm passes the bound (it once
        // ran on, the lcm growing to hundreds of thousands of digits).
        let vertices: Vec<[Q; 3]> = (0..20_000)
            .map(|j| [Q::new(1, 2 * j + 1_000_003), Q::new(1, 2 * j + 1_000_004), Q::from_integer(0)])
            .collect();
        let err = Geometry::new(&vertices).unwrap_err();
        assert!(matches!(err, GeometryError::OutOfRange { vertex: 151, .. }), "{err:?}");
    }
}
