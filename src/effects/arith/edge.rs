//! `f32-edge`: a GPU's loop, edge functions over the bounding box stepped per
//! column in `f32`, depth from the plane stepped by ∂z/∂x.

use num_traits::{Num, Signed};

use super::*;

/// The plain z-buffer with `f32-edge`.
pub(super) fn raster_edges(scene: &Scene, shapes: &[Option<EdgeShape>]) -> (Buffers, Stats) {
    let mut buffers =
        Buffers::new(scene.width, scene.height, scene.frame_bits, scene.background, scene.clear_depth.clone());
    let stats = buffers.with_level_cells(EdgeRaster { scene, shapes }).expect("inexact modes run quantized z-buffers");
    (buffers, stats)
}

/// The edge-function loop, on the cells whatever the framebuffer's cell width.
pub(super) struct EdgeRaster<'a> {
    scene: &'a Scene,
    shapes: &'a [Option<EdgeShape>],
}

impl LevelCells for EdgeRaster<'_> {
    type Output = Stats;

    fn run<C: FrameCell>(self, frame: &mut [C], depth: &mut [u32]) -> Stats {
        let scene = self.scene;
        let mut stats = Stats::default();
        let limits = (nearer_sign(scene), scene.depth_max() as f32);
        let size = (scene.width, scene.height);
        let mut space: Option<FloatWalker<'_, f32>> = None;
        for shape in self.shapes {
            stats.polygons += 1;
            match shape {
                None => {}
                Some(EdgeShape::Triangle(p, c)) => {
                    draw_edges::<3, C>((p, *c), (frame, depth), size, limits, &mut stats)
                }
                Some(EdgeShape::Quad(p, c)) => draw_edges::<4, C>((p, *c), (frame, depth), size, limits, &mut stats),
                Some(EdgeShape::Other(p)) => {
                    let mut walker = match space.take() {
                        Some(walker) => walker.next(p),
                        None => FloatWalker::new(p, false),
                    };
                    draw_walked(&mut walker, scene, (&mut *frame, &mut *depth), limits, &mut stats);
                    space = Some(walker);
                }
            }
        }
        stats
    }
}

/// One convex polygon of `N` vertices (its vertices and plane in `f32`, and
/// Newell's exact `c`), set up as it is drawn, as the exact loop sets up its
/// own; then its bounding box, row by row.
#[inline(always)]
fn draw_edges<const N: usize, C: FrameCell>(
    (polygon, newell_c): (&FloatPolygon<f32>, i128),
    (frame, depth): (&mut [C], &mut [u32]),
    (width, height): (u32, u32),
    limits: (f32, f32),
    stats: &mut Stats,
) {
    let polygon = EdgePolygon::<N>::new(polygon, newell_c, width, height);
    let width = width as usize;
    let value = C::from_value(polygon.value);
    for row in polygon.rows.0..=polygon.rows.1 {
        let row_start = row as usize * width;
        polygon.row(row, |x, covered, z| {
            test_and_store(stats, (&mut *frame, &mut *depth), row_start + x as usize, value, covered, z, limits);
        });
    }
}

pub(super) fn edge_scanline<const N: usize>(polygon: &EdgePolygon<N>, row: u32) -> FloatScanline {
    let mut pixels = Vec::new();
    let row = i64::from(row);
    if (polygon.rows.0..=polygon.rows.1).contains(&row) {
        polygon.row(row, |x, covered, z| {
            if covered {
                pixels.push((x as u32, f64::from(z)));
            }
        });
    }
    let (first, last) = polygon.columns;
    let bounding_columns = (first <= last).then_some((first as u32, last as u32));
    FloatScanline { crossings: Vec::new(), pixels, bounding_columns }
}

/// A convex polygon of three or four vertices as a GPU sets it up: one edge
/// function per edge, `E(x, y) = A·(x − xᵢ) + B·(y − yᵢ)` through its first
/// vertex, positive inside, and depth interpolated from vertex 1,
/// `z = z₁ + (x − x₁)·∂z/∂x + (y − y₁)·∂z/∂y` with `∂z/∂x = −a/c`,
/// `∂z/∂y = −b/c` from Newell's plane, all in `f32`.
#[derive(Debug, Clone)]
pub struct EdgePolygon<const N: usize> {
    /// `[A, B, x₀, y₀, 1/A]` per edge, signed so that the inside is `E ≥ 0`
    /// (`1/A` is 0 for a horizontal edge).
    edges: [[f32; 5]; N],
    /// `[∂z/∂x, ∂z/∂y, x₁, y₁, z₁]`.
    depth: [f32; 5],
    /// The rows whose centre lies in `[y_min, y_max)` and the columns whose
    /// centre lies in `[x_min, x_max]`, clipped to the raster.
    rows: (i64, i64),
    columns: (i64, i64),
    value: u32,
}

/// What `f32-edge` draws a polygon with: its vertices and plane in `f32`
/// (as the exact loop has its scaled vertices and Newell's normal from the
/// scene), and which loop draws it; the edge functions are set up as it is
/// drawn ([`EdgePolygon::new`]), with Newell's exact `c` for their sign.
pub enum EdgeShape {
    /// A triangle: three edge functions.
    Triangle(FloatPolygon<f32>, i128),
    /// A convex quadrilateral: four.
    Quad(FloatPolygon<f32>, i128),
    /// Anything else (concave, self-intersecting, five or more vertices), which
    /// a GPU would first cut into triangles: drawn by the `f32` scanline walker.
    Other(FloatPolygon<f32>),
}

impl EdgeShape {
    /// Sets a drawn polygon up: edge functions when it is a convex triangle
    /// or quadrilateral (decided exactly, on its scaled integer vertices).
    pub(super) fn new(polygon: &crate::scene::Polygon) -> EdgeShape {
        let float = prepare::<f32>(&polygon.vertices(), polygon.value);
        let points = &polygon.geometry().points;
        let (convex, count) = match polygon.geometry().big_scaled() {
            Some((points, _)) => (is_convex(points), points.len()),
            None => (is_convex(points), points.len()),
        };
        match (count, convex) {
            (3, true) => EdgeShape::Triangle(float, polygon.geometry().c()),
            (4, true) => EdgeShape::Quad(float, polygon.geometry().c()),
            _ => EdgeShape::Other(float),
        }
    }
}

/// Whether a polygon (scaled integer vertices, seen from +z) is convex and
/// winds once: every turn the same way (or straight), and its edges go up,
/// then down, at most once each.
pub(super) fn is_convex<T: Num + Ord + Clone + Signed>(points: &[[T; 3]]) -> bool {
    let n = points.len();
    let (mut left, mut right, mut direction_changes) = (false, false, 0);
    let mut last_dy = 0;
    let dy_sign = |p: &[T; 3], q: &[T; 3]| (q[1].clone() - p[1].clone()).cmp(&T::zero()) as i32;
    for i in 0..n {
        let [p, q, r] = [&points[i], &points[(i + 1) % n], &points[(i + 2) % n]];
        // In i128 bounded by 2·(2^35)² < 2^71 (plane::MAX_SCALED); the big tier's in BigInt.
        let turn = (q[0].clone() - p[0].clone()) * (r[1].clone() - q[1].clone())
            - (q[1].clone() - p[1].clone()) * (r[0].clone() - q[0].clone());
        left |= turn.is_positive();
        right |= turn.is_negative();
        let dy = dy_sign(p, q);
        if dy != 0 {
            direction_changes += i32::from(last_dy != 0 && dy != last_dy);
            last_dy = dy;
        }
    }
    // Close the loop: the first edge that goes up or down against the last.
    let first_dy = (0..n).map(|i| dy_sign(&points[i], &points[(i + 1) % n])).find(|d| *d != 0).unwrap_or(0);
    direction_changes += i32::from(first_dy != 0 && first_dy != last_dy);
    !(left && right) && direction_changes <= 2
}

impl<const N: usize> EdgePolygon<N> {
    pub(super) fn new(polygon: &FloatPolygon<f32>, newell_c: i128, width: u32, height: u32) -> EdgePolygon<N> {
        let points = &polygon.points;
        // Newell's c > 0: counter-clockwise seen from the viewer, the inside on each edge's left.
        let sign = if newell_c > 0 { 1.0 } else { -1.0 };
        let edges = std::array::from_fn(|i| {
            let (p, q) = (points[i], points[(i + 1) % N]);
            let a = -(q[1] - p[1]) * sign;
            [a, (q[0] - p[0]) * sign, p[0], p[1], if a == 0.0 { 0.0 } else { 1.0 / a }]
        });
        let [a, b, c, _] = polygon.plane;
        let (x_min, x_max) =
            points.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(l, h), p| (l.min(p[0]), h.max(p[0])));
        let (y_min, y_max) =
            points.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(l, h), p| (l.min(p[1]), h.max(p[1])));
        let clip = |first: f32, last: f32, size: u32| (first.max(0.0) as i64, last.min(size as f32 - 1.0) as i64);
        EdgePolygon {
            edges,
            depth: [-a / c, -b / c, points[0][0], points[0][1], points[0][2]],
            rows: clip((y_min - 0.5).ceil(), (y_max - 0.5).ceil() - 1.0, height),
            columns: clip((x_min - 0.5).ceil(), (x_max - 0.5).floor(), width),
            value: polygon.value,
        }
    }

    /// Row `row`: calls `pixel(x, covered, z)` for the columns of the
    /// bounding box that the row can cover, left to right. Those columns are
    /// found from the edge functions' zeros on the row (widened by one column
    /// each way, so rounding there decides nothing); the edge functions and
    /// the depth are then evaluated at the first of them and stepped by `A`
    /// and `∂z/∂x` per column. A centre on an edge (`E = 0`) is covered, and
    /// rows are half-open in y (`rows`): the book's rule, so that this mode
    /// differs from exact only in its arithmetic.
    #[inline(always)]
    fn row(&self, row: i64, mut pixel: impl FnMut(i64, bool, f32)) {
        let (mut first, mut last) = self.columns;
        let y = row as f32 + 0.5;
        let at = |i: usize, x: f32| {
            let [a, b, x0, y0, _] = self.edges[i];
            a * (x - x0) + b * (y - y0)
        };
        // Offsets in columns from the bounding box's first column.
        let (start, left) = (first, first as f32 + 0.5);
        for i in 0..N {
            let (a, reciprocal, e) = (self.edges[i][0], self.edges[i][4], at(i, left));
            // The zero lies −E/A columns on.
            let zero = -e * reciprocal;
            if a > 0.0 {
                first = first.max(start + ceil(zero) - 1);
            } else if a < 0.0 {
                last = last.min(start + floor(zero) + 1);
            } else if e < 0.0 {
                return; // a horizontal edge with the row outside it
            }
        }
        if first > last {
            return;
        }
        let x = first as f32 + 0.5;
        // Filled and stepped by index: no call per row or column where the compiler's
        // inlining stops (a release build optimizes each code generation unit alone).
        let (mut e, mut step) = ([0.0f32; N], [0.0f32; N]);
        for i in 0..N {
            (e[i], step[i]) = (at(i, x), self.edges[i][0]);
        }
        let [dzdx, dzdy, x1, y1, z1] = self.depth;
        let mut z = z1 + dzdx * (x - x1) + dzdy * (y - y1);
        for column in first..=last {
            let covered = e.iter().fold(true, |inside, v| inside & (*v >= 0.0));
            pixel(column, covered, z);
            for i in 0..N {
                e[i] += step[i];
            }
            z += dzdx;
        }
    }
}

/// `⌈v⌉` and `⌊v⌋` by a cast and a comparison: without SSE4.1 (the x86-64
/// baseline) `f32::ceil` is a library call. A cast saturates, so a far-away
/// or NaN `v` gives a bound that clipping to the bounding box then ignores.
#[inline(always)]
pub(super) fn ceil(v: f32) -> i64 {
    let t = v as i64;
    t + i64::from((t as f32) < v)
}

#[inline(always)]
pub(super) fn floor(v: f32) -> i64 {
    let t = v as i64;
    t - i64::from((t as f32) > v)
}
