//! The big-integer tier: polygons whose scaled coordinates pass
//! [`crate::plane::MAX_SCALED`] (2^34), where the word-sized rasterizer's
//! products could overflow `i128`, are drawn here with the same rules by the
//! formulas themselves, every product in arbitrary-precision integers
//! (`num-bigint`).
//!
//! What the tier reports is what every tier reports: crossings as fractions
//! in pixel units, depths as exact fractions, the plane reduced, all 128-bit
//! numbers. The tier computes them from the edges' lines and the plane
//! reduced in big integers, not from the scaled vertices: a polygon cut by
//! clipping or divided by w has vertices over huge common denominators, but
//! its edges and plane are those of the polygon it came from, and small. So
//! the tier takes scaled coordinates up to [`crate::plane::MAX_SCALED_BIG`]
//! (2^120), and refuses only a polygon whose plane, crossings or depths at
//! pixel centres would need more than 128 bits even reduced (`fits`).

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, ToPrimitive, Zero};

use crate::depth::Depth;
use crate::exact::{ceil_div, floor_div};
use crate::pipeline::{PixelRect, RasterSink};
use crate::plane::{Geometry, GeometryError, OffPlane, PlaneEquation};
use crate::rules::{RowRule, Rules};
use crate::scan::{self, Crossing, Span};

fn big(v: i128) -> BigInt {
    BigInt::from(v)
}

/// Newell's normal of scaled points, divided by its components' greatest
/// common divisor (the plane is the same); `None` when it does not fit i128.
pub(crate) fn newell(points: &[[i128; 3]]) -> Option<[i128; 3]> {
    let mut normal = [BigInt::zero(), BigInt::zero(), BigInt::zero()];
    for (i, p) in points.iter().enumerate() {
        let q = points[(i + 1) % points.len()];
        normal[0] += big(p[1] - q[1]) * big(p[2] + q[2]);
        normal[1] += big(p[2] - q[2]) * big(p[0] + q[0]);
        normal[2] += big(p[0] - q[0]) * big(p[1] + q[1]);
    }
    let divisor = normal.iter().fold(BigInt::zero(), |g, v| g.gcd(v));
    if !divisor.is_zero() {
        for v in &mut normal {
            *v /= &divisor;
        }
    }
    Some([normal[0].to_i128()?, normal[1].to_i128()?, normal[2].to_i128()?])
}

/// The plane with `normal` through `point` (scaled units) in polygon units,
/// reduced and signed as the book prints it (see [`Geometry::plane`]); `None`
/// when a coefficient does not fit i128.
pub(crate) fn reduced_plane(normal: [i128; 3], point: [i128; 3], scale: i128) -> Option<PlaneEquation> {
    let [a, b, c] = normal.map(big);
    let d = -(&a * big(point[0]) + &b * big(point[1]) + &c * big(point[2]));
    let scale = big(scale);
    let coefficients = [&a * &scale, &b * &scale, &c * &scale, d];
    let divisor = coefficients.iter().fold(BigInt::zero(), |g, v| g.gcd(v));
    if divisor.is_zero() {
        return Some(PlaneEquation { a: 0, b: 0, c: 0, d: 0 });
    }
    let leading_negative = coefficients[..3].iter().rev().find(|v| !v.is_zero()).is_some_and(Signed::is_negative);
    let divisor = if leading_negative { -divisor } else { divisor };
    let [a, b, c, d] = coefficients.map(|v| (v / &divisor).to_i128());
    Some(PlaneEquation { a: a?, b: b?, c: c?, d: d? })
}

/// [`Geometry`]'s planarity check in big integers: every vertex on the plane
/// through vertex 1 and the first two vertices not collinear with it.
pub(crate) fn check_planar(geometry: &Geometry) -> Result<(), GeometryError> {
    let points = &geometry.points;
    let p1 = points[0];
    let sub = |p: [i128; 3]| [big(p[0] - p1[0]), big(p[1] - p1[1]), big(p[2] - p1[2])];
    let Some(i) = points.iter().position(|p| *p != p1) else { return Ok(()) };
    let u = sub(points[i]);
    let found = points.iter().enumerate().skip(i + 1).find_map(|(k, p)| {
        let v = sub(*p);
        let n = [&u[1] * &v[2] - &u[2] * &v[1], &u[2] * &v[0] - &u[0] * &v[2], &u[0] * &v[1] - &u[1] * &v[0]];
        (!n.iter().all(Zero::is_zero)).then_some((k, n))
    });
    let Some((k, normal)) = found else { return Ok(()) };
    for (index, point) in points.iter().enumerate() {
        let w = sub(*point);
        let residual = &normal[0] * &w[0] + &normal[1] * &w[1] + &normal[2] * &w[2];
        if residual.is_zero() {
            continue;
        }
        // Reported with the plane reduced to 128-bit coefficients.
        let divisor = normal.iter().fold(BigInt::zero(), |g, v| g.gcd(v));
        let reduced = normal.clone().map(|v| (v / &divisor).to_i128());
        // The plane or the distance does not fit the 128-bit numbers a
        // report prints: say which vertex is off which plane, and what fits.
        let beyond = |plane: Option<PlaneEquation>| GeometryError::NotPlanarBeyondRange {
            vertex: index + 1,
            through: [1, i + 1, k + 1],
            plane,
        };
        let [Some(a), Some(b), Some(c)] = reduced else { return Err(beyond(None)) };
        let plane = reduced_plane([a, b, c], p1, geometry.scale()).ok_or_else(|| beyond(None))?;
        let distance_too_large = || beyond(Some(plane));
        let residual = residual / divisor;
        let (off_by, along_z) = if c != 0 {
            let (n, d) = (residual, big(c) * big(geometry.scale()));
            let g = n.gcd(&d);
            match ((n / &g).to_i128(), (d / &g).to_i128()) {
                (Some(n), Some(d)) => (crate::exact::Q::new(n, d), true),
                _ => return Err(distance_too_large()),
            }
        } else {
            let scale = big(geometry.scale());
            let value = (big(plane.a) * big(point[0])
                + big(plane.b) * big(point[1])
                + big(plane.c) * big(point[2])
                + big(plane.d) * &scale)
                / &scale;
            match value.to_i128() {
                Some(v) => (crate::exact::Q::from_integer(v), false),
                None => return Err(distance_too_large()),
            }
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

/// Largest depth numerator the tier hands on as a 128-bit [`Depth`], and
/// largest denominator; largest crossing numerator and denominator.
const DEPTH_NUMERATOR: i128 = 1 << 125;
const DEPTH_DENOMINATOR: i128 = 1 << 124;
const CROSSING: i128 = 1 << 120;

/// An edge that crosses scanlines, as the tier walks it: its ends' scaled
/// heights and its line `αx + βy + γ = 0` in pixel units, reduced, `α > 0`.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Edge {
    ends: [i128; 2],
    line: [i128; 3],
}

/// What the tier works from: the edges' lines and the plane `Ax + By + Cz +
/// D = 0`, both in pixel units and reduced, whatever the polygon's common
/// denominator. A clipped or divided polygon's vertices carry large
/// denominators, but its edges and plane are those of the polygon it was cut
/// from and stay small, and so do the crossings and depths computed from them.
/// Made once, with the geometry ([`Geometry::is_big`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Lines {
    edges: Vec<Edge>,
    plane: PlaneEquation,
}

/// `Σ aᵢ·bᵢ` exactly: in `i128` while no step overflows, else in big
/// integers; `None` when the sum itself does not fit `i128`.
fn sum_of_products(terms: &[(i128, i128)]) -> Option<i128> {
    let fast = terms.iter().try_fold(0i128, |sum, &(a, b)| sum.checked_add(a.checked_mul(b)?));
    fast.or_else(|| terms.iter().map(|&(a, b)| big(a) * big(b)).sum::<BigInt>().to_i128())
}

/// Whether `|v| < limit`, for a value that may not have fit `i128` (`None`).
fn below(v: Option<i128>, limit: i128) -> bool {
    v.is_some_and(|v| v.unsigned_abs() < limit.unsigned_abs())
}

/// The line through scaled points `p` and `q` (`p_y ≠ q_y`) in pixel units,
/// reduced, `α > 0`; `None` when it does not fit `i128`. In scaled units it
/// is `ΔY·X − ΔX·Y + (ΔX·Y₁ − ΔY·X₁) = 0`, and `X = 2D·x`, `Y = 2D·y`.
fn reduced_line(p: [i128; 3], q: [i128; 3], scale: i128) -> Option<[i128; 3]> {
    let words = || {
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let line = [
            dy.checked_mul(scale)?,
            dx.checked_mul(scale)?.checked_neg()?,
            sum_of_products(&[(dx, p[1]), (-dy, p[0])])?,
        ];
        line.iter().all(|v| *v != i128::MIN).then_some(line)
    };
    if let Some(mut line) = words() {
        let divisor = line.iter().fold(0i128, |g, v| g.gcd(v)) * line[0].signum();
        for v in &mut line {
            *v /= divisor;
        }
        return Some(line);
    }
    let (dx, dy) = (big(q[0]) - big(p[0]), big(q[1]) - big(p[1]));
    let gamma = &dx * big(p[1]) - &dy * big(p[0]);
    let mut line = [&dy * big(scale), -(&dx * big(scale)), gamma];
    let divisor = line.iter().fold(BigInt::zero(), |g, v| g.gcd(v));
    let divisor = if line[0].is_negative() { -divisor } else { divisor };
    let [alpha, beta, gamma] = line.each_mut().map(|v| (&*v / &divisor).to_i128());
    Some([alpha?, beta?, gamma?])
}

impl Lines {
    /// The plane, reduced (as [`Geometry::plane`]).
    pub(crate) fn plane(&self) -> PlaneEquation {
        self.plane
    }

    /// The lines, or `None` when a crossing or a depth at a centre within a
    /// pixel of the polygon could need more than 128 bits: a crossing
    /// `−(β(2r + 1) + 2γ) / 2α` at any row `r` the edge reaches, a depth
    /// `−(A(2x + 1) + B(2y + 1) + 2D) / 2C` at the centre of any pixel
    /// `(x, y)` within one pixel of the polygon's bounding box. Both
    /// numerators are linear, so they are largest at the ends of those
    /// ranges, where they are checked.
    pub(crate) fn new(geometry: &Geometry) -> Option<Lines> {
        let plane = reduced_plane(geometry.normal, geometry.points[0], geometry.scale())?;
        let (scale, d) = (geometry.scale(), geometry.denominator);
        let points = &geometry.points;
        let mut edges = Vec::with_capacity(points.len());
        for (i, p) in points.iter().enumerate() {
            let q = points[(i + 1) % points.len()];
            if p[1] == q[1] {
                continue;
            }
            let [alpha, beta, gamma] = reduced_line(*p, q, scale)?;
            // The rows whose scanlines (2r + 1)·D lie within the edge's heights, under any rule.
            let (low, high) = (p[1].min(q[1]), p[1].max(q[1]));
            let rows = [ceil_div(low - d, scale), floor_div(high - d, scale).0];
            let numerator = |r: i128| sum_of_products(&[(beta, 2 * r + 1), (gamma, 2)]);
            if !rows.iter().all(|&r| below(numerator(r), CROSSING)) || !below(alpha.checked_mul(2), CROSSING) {
                return None;
            }
            edges.push(Edge { ends: [low, high], line: [alpha, beta, gamma] });
        }
        // The pixels within one of the polygon's bounding box, along x and along y.
        let reach = |axis: usize| {
            let values = points.iter().map(|p| p[axis]);
            let (low, high) = (values.clone().min().unwrap_or(0), values.max().unwrap_or(0));
            [floor_div(low, scale).0 - 1, floor_div(high, scale).0 + 1]
        };
        let PlaneEquation { a, b, c, d } = plane;
        let depth = |x: i128, y: i128| sum_of_products(&[(a, 2 * x + 1), (b, 2 * y + 1), (d, 2)]);
        let fits = reach(0).iter().all(|&x| reach(1).iter().all(|&y| below(depth(x, y), DEPTH_NUMERATOR)));
        (fits && below(c.checked_mul(2), DEPTH_DENOMINATOR)).then_some(Lines { edges, plane })
    }

    /// The exact depth at the centre of pixel `(column, row)`, within a pixel
    /// of the polygon: `−(A(2x + 1) + B(2y + 1) + 2D) / 2C`, below 2^125 over
    /// below 2^124 by [`Lines::new`].
    pub(crate) fn depth_at_centre(&self, column: u32, row: u32) -> Depth {
        let PlaneEquation { a, b, c, d } = self.plane;
        let terms = [(a, 2 * i128::from(column) + 1), (b, 2 * i128::from(row) + 1), (d, 2)];
        Depth::from_fraction(-sum_of_products(&terms).expect("checked by Lines::new"), 2 * c)
    }

    /// The crossings with the scanline at scaled height `scan_y`, row `row`,
    /// sorted left to right (as [`scan::crossings`] computes them from the
    /// vertices).
    fn crossings(&self, row: u32, scan_y: i128, rule: RowRule, out: &mut Vec<Crossing>) {
        out.clear();
        for edge in &self.edges {
            let [low, high] = edge.ends;
            let crosses = match rule {
                RowRule::HalfOpen => low <= scan_y && scan_y < high,
                RowRule::Closed => low <= scan_y && scan_y <= high,
                RowRule::TopLeft => low < scan_y && scan_y <= high,
            };
            if crosses {
                // αx = −(βy + γ) at y = (2r + 1)/2; below 2^120 by `Lines::new`.
                let [alpha, beta, gamma] = edge.line;
                let numerator = sum_of_products(&[(beta, 2 * i128::from(row) + 1), (gamma, 2)]);
                out.push(Crossing { numerator: -numerator.expect("checked by Lines::new"), denominator: 2 * alpha });
            }
        }
        out.sort_unstable_by(Crossing::cmp_position);
    }
}

/// Draws a polygon of the big-integer tier: the same events, in the same
/// order, as the word-sized rasterizer ([`crate::pipeline::rasterize`]).
pub(crate) fn rasterize<S: RasterSink>(
    geometry: &Geometry,
    rules: Rules,
    rect: PixelRect,
    (found, spans): (&mut Vec<Crossing>, &mut Vec<Span>),
    sink: &mut S,
) {
    let Some(rows) = scan::rows(&geometry.points, geometry.denominator, rect.rows, rules.rows) else { return };
    let lines = geometry.lines().expect("a polygon of the big-integer tier has its lines");
    // z₁ = z − A/C per column: the numerator over |2C| falls by 2A·sign(C),
    // below 2^125 as the depths at two columns of `Lines::new`'s range are.
    let step = 2 * lines.plane.a * lines.plane.c.signum();
    for row in rows {
        let scan_y = scan::scanline_y(row, geometry.denominator);
        lines.crossings(row, scan_y, rules.rows, found);
        spans.clear();
        spans.extend(scan::pairs(found.len(), rules.rows).map(|(i, j)| Span {
            left: found[i],
            right: found[j],
            columns: scan::columns(found[i], found[j], rect.columns, rules.columns),
        }));
        if S::OBSERVES_SCANLINES {
            sink.scanline(row, found, spans);
        }
        for span in spans.iter() {
            if let Some((first, last)) = span.columns {
                // The first centre's depth, then z₁ = z − A/C per column (every
                // numerator below 2^125 by `Lines::new`).
                let (mut numerator, denominator) = lines.depth_at_centre(first, row).fraction();
                for x in first..=last {
                    sink.pixel(x, row, Depth::from_fraction(numerator, denominator));
                    numerator -= step;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Q;
    use crate::pipeline::{Scratch, rasterize as draw};

    /// Every event as values: scanlines' crossings and spans, pixels' depths.
    #[derive(Default)]
    struct Values(Vec<String>);

    impl RasterSink for Values {
        fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]) {
            let xs: Vec<Q> = crossings.iter().map(|c| c.x()).collect();
            let columns: Vec<_> = spans.iter().map(|s| s.columns).collect();
            self.0.push(format!("row {row}: {xs:?} {columns:?}"));
        }

        fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
            self.0.push(format!("({x}, {y}) {:?}", depth.value()));
        }
    }

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

    /// BUET CSE 410's 2018 assignment maps a window 0.7 wide onto 500 pixels
    /// from 7-decimal input: the common denominator reaches 10^7 and the
    /// scaled coordinates pass 2^34. Such a triangle is drawn (on this tier),
    /// and every covered centre lies inside it, by an independent test in
    /// big rationals, with the plane's depth there.
    #[test]
    fn seven_decimal_input_beyond_the_word_range_is_drawn_exactly() {
        let d = |text: &str| crate::exact::parse_number(text).unwrap();
        // Pixel units of a 500-px raster over a 0.7-wide window: 7 decimals times 500/0.7.
        let window = |v: &str| (d(v) + Q::new(35, 100)) * Q::new(5000, 7);
        let vertices: Vec<[Q; 3]> = [
            ["-0.2480390", "-0.1234567", "1.2345678"],
            ["0.3012345", "-0.2999999", "2.7654321"],
            ["0.0123457", "0.3301234", "1.9876543"],
        ]
        .iter()
        .map(|[x, y, z]| [window(x), window(y), d(z)])
        .collect();
        let geometry = Geometry::new(&vertices).expect("drawn, not refused");
        assert!(geometry.is_big(), "the scaled coordinates pass 2^34");
        let rect = PixelRect { columns: (0, 499), rows: (0, 499) };
        let mut sink = Values::default();
        draw(&geometry, Rules::default(), rect, &mut Scratch::default(), &mut sink);
        let pixels: Vec<&String> = sink.0.iter().filter(|e| e.starts_with('(')).collect();
        assert!(pixels.len() > 10_000, "{}", pixels.len());
        // Independent check on a sample of pixels: the centre is inside (edge functions in big
        // rationals, all of one sign) and the depth is the plane's.
        use num_rational::BigRational;
        let r = |q: Q| BigRational::new(BigInt::from(*q.numer()), BigInt::from(*q.denom()));
        let v: Vec<[BigRational; 3]> = vertices.iter().map(|p| p.map(r)).collect();
        for event in pixels.iter().step_by(997) {
            let (x, rest) = event[1..].split_once(", ").unwrap();
            let y: u32 = rest.split_once(')').unwrap().0.parse().unwrap();
            let x: u32 = x.parse().unwrap();
            let (cx, cy) = (r(Q::new(2 * i128::from(x) + 1, 2)), r(Q::new(2 * i128::from(y) + 1, 2)));
            let side = |i: usize| {
                let (a, b) = (&v[i], &v[(i + 1) % 3]);
                (&b[0] - &a[0]) * (&cy - &a[1]) - (&b[1] - &a[1]) * (&cx - &a[0])
            };
            let signs: Vec<bool> = (0..3).map(|i| side(i).is_positive()).collect();
            assert!(signs.iter().all(|s| *s == signs[0]), "({x}, {y}) lies inside");
            // z by the plane through the three vertices (Cramer on the barycentric weights).
            let det = (&v[1][0] - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (&v[1][1] - &v[0][1]);
            let w1 = ((&cx - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (&cy - &v[0][1])) / &det;
            let w2 = ((&v[1][0] - &v[0][0]) * (&cy - &v[0][1]) - (&cx - &v[0][0]) * (&v[1][1] - &v[0][1])) / &det;
            let z = &v[0][2] + w1 * (&v[1][2] - &v[0][2]) + w2 * (&v[2][2] - &v[0][2]);
            let expected = Q::new(z.numer().to_i128().unwrap(), z.denom().to_i128().unwrap());
            assert!(event.ends_with(&format!("{expected:?}")), "{event}: expected {expected:?}");
        }
    }
}
