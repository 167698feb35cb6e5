//! The float modes' scanline loop: crossings evaluated or stepped down each
//! edge (the Russian lecture notes' Δx), depth evaluated or stepped by −a/c, in `f32` or `f64`.

use std::hint::select_unpredictable;

use num_traits::{AsPrimitive, Float};

use super::*;
use crate::geometry::newell::newell;
use crate::numbers::Ring;

/// A polygon in floating point: vertices and Newell's plane.
pub struct FloatPolygon<F> {
    pub(super) points: Vec<[F; 3]>,
    /// Plane coefficients `a, b, c, d` computed in `F`.
    pub(super) plane: [F; 4],
    pub(super) value: u32,
}

pub(super) fn prepare<F: Float + Ring>(vertices: &[[Exact; 3]], value: u32) -> FloatPolygon<F> {
    let convert = |v: &Exact| F::from(to_f64(v)).unwrap_or_else(F::nan);
    let points: Vec<[F; 3]> = vertices.iter().map(|v| v.each_ref().map(convert)).collect();
    let [a, b, c] = newell(&points);
    let d = -(a * points[0][0] + b * points[0][1] + c * points[0][2]);
    FloatPolygon { points, plane: [a, b, c, d], value }
}

/// One polygon's rows in `F`: crossings per scanline (evaluated, or stepped
/// down each edge), paired into spans, and the depth at each covered centre
/// (evaluated, or stepped by −a/c). Both the raster and `step --arith` use it.
pub(super) struct FloatWalker<'p, F> {
    polygon: &'p FloatPolygon<F>,
    edges: Vec<SteppedEdge<F>>,
    incremental: bool,
    half: F,
    pub(super) crossings: Vec<F>,
}

impl<'p, F: Float> FloatWalker<'p, F> {
    pub(super) fn new(polygon: &'p FloatPolygon<F>, incremental: bool) -> FloatWalker<'p, F> {
        let half = F::from(0.5).unwrap_or_else(F::nan);
        let mut edges = Vec::new();
        if incremental {
            SteppedEdge::fill(&mut edges, &polygon.points, half);
        }
        FloatWalker { polygon, edges, incremental, half, crossings: Vec::new() }
    }

    /// The walker for another polygon, in the same space: no allocation per polygon.
    pub(super) fn next<'q>(self, polygon: &'q FloatPolygon<F>) -> FloatWalker<'q, F> {
        let FloatWalker { mut edges, incremental, half, crossings, .. } = self;
        edges.clear();
        if incremental {
            SteppedEdge::fill(&mut edges, &polygon.points, half);
        }
        FloatWalker { polygon, edges, incremental, half, crossings }
    }

    /// The rows with `y_min ≤ row + 1/2 < y_max`, clipped to the raster.
    fn rows(&self, height: u32) -> Option<(i64, i64)> {
        let points = &self.polygon.points;
        let y_min = points.iter().map(|v| v[1]).fold(F::infinity(), F::min);
        let y_max = points.iter().map(|v| v[1]).fold(F::neg_infinity(), F::max);
        let first = (y_min - self.half).ceil().max(F::zero()).to_i64()?;
        let last = ((y_max - self.half).ceil() - F::one()).min(F::from(height - 1)?).to_i64()?;
        Some((first, last))
    }

    /// Row `row` (rows in increasing order): sets `self.crossings` and calls
    /// `pixel(x, z)` for each covered centre left to right.
    fn row(&mut self, row: i64, width: u32, mut pixel: impl FnMut(i64, F)) {
        let half = self.half;
        let p = self.polygon;
        let y = F::from(row).unwrap_or_else(F::nan) + half;
        self.crossings.clear();
        if self.incremental {
            self.crossings.extend(self.edges.iter_mut().filter_map(|edge| edge.at(row)));
        } else {
            for (i, v) in p.points.iter().enumerate() {
                let w = p.points[(i + 1) % p.points.len()];
                if v[1] != w[1] && y >= v[1].min(w[1]) && y < v[1].max(w[1]) {
                    self.crossings.push(v[0] + (w[0] - v[0]) * (y - v[1]) / (w[1] - v[1]));
                }
            }
        }
        self.crossings.sort_by(|l, r| l.partial_cmp(r).unwrap_or(std::cmp::Ordering::Equal));
        let [a, b, c, d] = p.plane;
        for pair in self.crossings.chunks_exact(2) {
            let first = (pair[0] - half).ceil().max(F::zero());
            let last = (pair[1] - half).floor().min(F::from(width - 1).unwrap_or_else(F::nan));
            let (Some(first), Some(last)) = (first.to_i64(), last.to_i64()) else { continue };
            // z = −(a·x + b·y + d)/c at the first centre; then z − a/c per pixel, or evaluated again.
            let step = -a / c;
            let mut xc = F::from(first).unwrap_or_else(F::nan) + half;
            let mut z = -(a * xc + b * y + d) / c;
            for x in first..=last {
                if !self.incremental {
                    z = -(a * xc + b * y + d) / c;
                    xc = xc + F::one();
                }
                pixel(x, z);
                if self.incremental {
                    z = z + step;
                }
            }
        }
    }
}

/// The plain z-buffer in `F`, per-pixel (`incremental = false`) or with the
/// seeds' incremental steps.
pub(super) fn raster_float<F: Float + AsPrimitive<u32>>(
    scene: &Scene,
    polygons: &[Option<FloatPolygon<F>>],
    incremental: bool,
) -> (Buffers, Stats) {
    let mut buffers =
        Buffers::new(scene.width, scene.height, scene.frame_bits, scene.background, scene.clear_depth.clone());
    let stats = buffers
        .with_level_cells(FloatRaster { scene, polygons, incremental })
        .expect("inexact modes run quantized z-buffers");
    (buffers, stats)
}

/// The float loop, on the cells whatever the framebuffer's cell width.
pub(super) struct FloatRaster<'a, F> {
    scene: &'a Scene,
    polygons: &'a [Option<FloatPolygon<F>>],
    incremental: bool,
}

impl<F: Float + AsPrimitive<u32>> LevelCells for FloatRaster<'_, F> {
    type Output = Stats;

    fn run<C: FrameCell>(self, frame: &mut [C], depth: &mut [u32]) -> Stats {
        let scene = self.scene;
        let mut stats = Stats::default();
        let max = F::from(scene.depth_max()).unwrap_or_else(F::max_value);
        let nearer = nearer_sign(scene);
        let mut space: Option<FloatWalker<'_, F>> = None;
        for polygon in self.polygons {
            stats.polygons += 1;
            let Some(p) = polygon else { continue };
            let mut walker = match space.take() {
                Some(walker) => walker.next(p),
                None => FloatWalker::new(p, self.incremental),
            };
            draw_walked(&mut walker, scene, (&mut *frame, &mut *depth), (nearer, max), &mut stats);
            space = Some(walker);
        }
        stats
    }
}

/// `1` when larger depths are nearer (`greater`), `−1` when smaller are (`less`).
pub(super) fn nearer_sign<F: Float>(scene: &Scene) -> F {
    if scene.depth_test.larger_is_nearer() { F::one() } else { -F::one() }
}

/// The depth test and the store of one covered-or-not cell, as the exact
/// loop does them: the cell rewritten with its old or its new value, without
/// a branch. A cell counts as tested when `covered`; a NaN depth never passes.
#[inline(always)]
pub(super) fn test_and_store<F: Float + AsPrimitive<u32>, C: FrameCell>(
    stats: &mut Stats,
    (frame, depth): (&mut [C], &mut [u32]),
    cell: usize,
    value: C,
    covered: bool,
    z: F,
    (nearer, max): (F, F),
) {
    let stored = F::from(depth[cell]).unwrap_or_else(F::nan);
    // `nearer·(z − stored) > 0`: z > stored for `greater`, z < stored for `less`,
    // without a branch; exact, since a float difference is 0 only for equal operands.
    let passes = covered & (nearer * (z - stored) > F::zero());
    let half = F::from(0.5).unwrap_or_else(F::nan);
    // Rounded half up and saturated: clamped first, a cast then truncates a
    // value ≥ 0, which is its floor (no call to `floor`, no branch; NaN gives 0).
    let level: u32 = (z + half).max(F::zero()).min(max).as_();
    stats.tested += u64::from(covered);
    stats.written += u64::from(passes);
    frame[cell] = select_unpredictable(passes, value, frame[cell]);
    depth[cell] = select_unpredictable(passes, level, depth[cell]);
}

/// One polygon's rows through the scanline walker, each covered centre tested and stored.
pub(super) fn draw_walked<F: Float + AsPrimitive<u32>, C: FrameCell>(
    walker: &mut FloatWalker<'_, F>,
    scene: &Scene,
    (frame, depth): (&mut [C], &mut [u32]),
    limits: (F, F),
    stats: &mut Stats,
) {
    let value = C::from_value(walker.polygon.value);
    let width = scene.width as usize;
    if let Some((first_row, last_row)) = walker.rows(scene.height) {
        for row in first_row..=last_row {
            let row_start = row as usize * width;
            walker.row(row, scene.width, |x, z| {
                test_and_store(stats, (&mut *frame, &mut *depth), row_start + x as usize, value, true, z, limits);
            });
        }
    }
}

pub(super) fn scanline_in<F: Float + Ring>(scene: &Scene, index: usize, row: u32, incremental: bool) -> FloatScanline {
    let polygon = &scene.polygons[index];
    let p = prepare::<F>(&polygon.vertices(), polygon.value);
    let mut walker = FloatWalker::new(&p, incremental);
    let mut pixels = Vec::new();
    walker.row(i64::from(row), scene.width, |x, z| pixels.push((x as u32, z.to_f64().unwrap_or(f64::NAN))));
    FloatScanline {
        crossings: walker.crossings.iter().map(|v| v.to_f64().unwrap_or(f64::NAN)).collect(),
        pixels,
        bounding_columns: None,
    }
}

/// An edge for the incremental modes: x stepped by Δx per scanline (the Russian lecture notes).
pub(super) struct SteppedEdge<F> {
    first_row: i64,
    last_row: i64,
    row: i64,
    x: F,
    dx: F,
}

impl<F: Float> SteppedEdge<F> {
    /// The non-horizontal edges with their rows (half-open rule), x at the
    /// first row on the raster (row ≥ 0, evaluated directly, as a rasterizer
    /// sets an edge up where it enters the screen), and Δx.
    fn fill(edges: &mut Vec<SteppedEdge<F>>, points: &[[F; 3]], half: F) {
        for (i, v) in points.iter().enumerate() {
            let w = points[(i + 1) % points.len()];
            if v[1] == w[1] {
                continue;
            }
            let (low, high) = if v[1] < w[1] { (*v, w) } else { (w, *v) };
            let first = (low[1] - half).ceil().max(F::zero());
            let last = (high[1] - half).ceil() - F::one();
            let (Some(first_row), Some(last_row)) = (first.to_i64(), last.to_i64()) else { continue };
            let dx = (high[0] - low[0]) / (high[1] - low[1]);
            let x = low[0] + dx * (first + half - low[1]);
            edges.push(SteppedEdge { first_row, last_row, row: first_row, x, dx });
        }
    }

    /// The edge's x on `row`, stepping from the previous row; `None` off the edge.
    fn at(&mut self, row: i64) -> Option<F> {
        if row < self.first_row || row > self.last_row {
            return None;
        }
        while self.row < row {
            self.x = self.x + self.dx;
            self.row += 1;
        }
        Some(self.x)
    }
}
