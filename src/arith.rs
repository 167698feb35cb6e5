//! Arithmetic modes: what the book's rules give when computed with less than
//! exact arithmetic, so `zsim accuracy` can show what accuracy costs.
//!
//! | mode | what it computes | where it can go wrong |
//! |---|---|---|
//! | `exact` | the core: integers and rationals, depth stepped by exact whole part and remainder | nowhere (it is the reference) |
//! | `f64` | crossings and the plane's depth evaluated per pixel in `f64` | ties: a centre on an edge or a depth of exactly k + 1/2 may round either way |
//! | `f64-incremental` | x stepped by Δx per scanline along each edge (seed 000), z by −a/c per pixel (seed 002), in `f64` | errors accumulate along long edges and spans |
//! | `f32-incremental` | the same in `f32` | as above, 2^29 times larger; depths above 2^24 lose whole levels |
//! | `f32` | per-pixel evaluation in `f32` | rounding of every product; depths above 2^24 lose whole levels |
//! | `fixed:K` | vertices snapped to K fractional bits (Direct3D snaps to 8), then the exact core | the snapped polygon differs from the given one by up to 2^−K−1 per coordinate |
//!
//! Inexact modes run the plain algorithm with the book's rules (half-open
//! rows, centres inside spans, quantized depth); whether a polygon is drawn
//! at all (culled, edge-on, degenerate) is decided exactly, so the modes
//! differ only in the arithmetic of the raster.

use std::fmt;
use std::hint::select_unpredictable;

use num_traits::Float;

use crate::buffer::{Buffers, FrameCell, LevelCells};
use crate::error::{Error, PolygonProblem};
use crate::exact::{Q, to_f64};
use crate::pipeline::{Simulation, Stats, fate};
use crate::plane::Geometry;
use crate::rules::{Preset, Rules};
use crate::scene::Scene;
use crate::trace::{Fate, Unobserved};

/// An arithmetic mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arith {
    /// Integers and rationals: the reference.
    Exact,
    /// Per-pixel evaluation in `f64`.
    F64,
    /// The seeds' incremental formulas in `f64`.
    F64Incremental,
    /// The seeds' incremental formulas in `f32`.
    F32Incremental,
    /// Per-pixel evaluation in `f32`.
    F32,
    /// Vertices snapped to K fractional bits, then exact.
    Fixed(u32),
}

impl Arith {
    /// Every mode `zsim accuracy` compares, in table order.
    pub const ALL: [Arith; 6] =
        [Arith::Exact, Arith::F64, Arith::F64Incremental, Arith::F32Incremental, Arith::F32, Arith::Fixed(8)];

    /// Reads `exact`, `f64`, `f64-incremental`, `f32-incremental`, `f32` or `fixed:K` (0 ≤ K ≤ 24).
    pub fn parse(text: &str) -> Result<Arith, String> {
        match text {
            "exact" => Ok(Arith::Exact),
            "f64" => Ok(Arith::F64),
            "f64-incremental" => Ok(Arith::F64Incremental),
            "f32-incremental" => Ok(Arith::F32Incremental),
            "f32" => Ok(Arith::F32),
            _ => match text.strip_prefix("fixed:").map(str::parse::<u32>) {
                Some(Ok(bits @ 0..=24)) => Ok(Arith::Fixed(bits)),
                _ => Err(format!(
                    "\"{text}\" is not an arithmetic mode: exact, f64, f64-incremental, f32-incremental, f32 or fixed:K (K from 0 to 24)"
                )),
            },
        }
    }
}

impl fmt::Display for Arith {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Arith::Exact => f.write_str("exact"),
            Arith::F64 => f.write_str("f64"),
            Arith::F64Incremental => f.write_str("f64-incremental"),
            Arith::F32Incremental => f.write_str("f32-incremental"),
            Arith::F32 => f.write_str("f32"),
            Arith::Fixed(bits) => write!(f, "fixed:{bits}"),
        }
    }
}

/// Refuses scenes an inexact mode cannot simulate: other rules than the
/// book's, or per-pixel effects and antialiasing.
pub fn check_supported(scene: &Scene, arith: Arith) -> Result<(), Error> {
    if arith == Arith::Exact {
        return Ok(());
    }
    if scene.rules != Rules::preset(Preset::Rogers) || scene.has_pixel_effects() || scene.effects.antialias.is_some() {
        return Err(Error::Usage(format!(
            "--arith {arith} simulates the plain algorithm with the book's rules; this scene asks for other rules or per-pixel effects (use --arith exact)"
        )));
    }
    Ok(())
}

/// Runs the whole scene in `arith`; returns the final buffers and the counts.
/// The scene must pass [`check_supported`].
pub fn run(scene: &Scene, arith: Arith) -> Result<(Buffers, Stats), Error> {
    match arith {
        Arith::Exact => Ok(exact_raster(scene)),
        Arith::Fixed(bits) => Ok(exact_raster(&snap(scene, bits)?)),
        Arith::F64 => Ok(raster_float(scene, &prepare_scene::<f64>(scene), false)),
        Arith::F64Incremental => Ok(raster_float(scene, &prepare_scene::<f64>(scene), true)),
        Arith::F32 => Ok(raster_float(scene, &prepare_scene::<f32>(scene), false)),
        Arith::F32Incremental => Ok(raster_float(scene, &prepare_scene::<f32>(scene), true)),
    }
}

/// A scene's input converted for one mode (vertices snapped, or converted
/// to floating point with their planes), so that timing covers the raster only.
pub enum Prepared<'s> {
    /// The exact core on the scene.
    Exact(&'s Scene),
    /// The exact core on the scene snapped to fixed point.
    Snapped(Box<Scene>),
    /// Floating-point polygons in `f64`.
    F64(&'s Scene, Vec<Option<FloatPolygon<f64>>>, bool),
    /// Floating-point polygons in `f32`.
    F32(&'s Scene, Vec<Option<FloatPolygon<f32>>>, bool),
}

impl<'s> Prepared<'s> {
    /// Converts a scene's input for `arith`.
    pub fn new(scene: &'s Scene, arith: Arith) -> Result<Prepared<'s>, Error> {
        Ok(match arith {
            Arith::Exact => Prepared::Exact(scene),
            Arith::Fixed(bits) => Prepared::Snapped(Box::new(snap(scene, bits)?)),
            Arith::F64 => Prepared::F64(scene, prepare_scene(scene), false),
            Arith::F64Incremental => Prepared::F64(scene, prepare_scene(scene), true),
            Arith::F32 => Prepared::F32(scene, prepare_scene(scene), false),
            Arith::F32Incremental => Prepared::F32(scene, prepare_scene(scene), true),
        })
    }

    /// Rasterizes: the final buffers and the counts.
    pub fn raster(&self) -> (Buffers, Stats) {
        match self {
            Prepared::Exact(scene) => exact_raster(scene),
            Prepared::Snapped(scene) => exact_raster(scene),
            Prepared::F64(scene, polygons, incremental) => raster_float(scene, polygons, *incremental),
            Prepared::F32(scene, polygons, incremental) => raster_float(scene, polygons, *incremental),
        }
    }
}

fn exact_raster(scene: &Scene) -> (Buffers, Stats) {
    let mut simulation = Simulation::new(scene);
    simulation.finish(&mut Unobserved);
    let stats = simulation.stats();
    (simulation.into_buffers(), stats)
}

/// Every polygon drawn (by the exact fate) converted to `F`; `None` for the others.
fn prepare_scene<F: Float>(scene: &Scene) -> Vec<Option<FloatPolygon<F>>> {
    (0..scene.polygons.len())
        .map(|i| (fate(scene, i) == Fate::Drawn).then(|| prepare(&scene.polygons[i].vertices, scene.polygons[i].value)))
        .collect()
}

/// The scene with every x and y rounded to the nearest multiple of 2^−bits
/// (halves up), as fixed-point hardware snaps vertices; z is kept.
pub fn snap(scene: &Scene, bits: u32) -> Result<Scene, Error> {
    let unit = Q::from_integer(1 << bits);
    let round = |v: Q| ((v * unit) + Q::new(1, 2)).floor() / unit;
    let mut snapped = scene.clone();
    for (index, polygon) in snapped.polygons.iter_mut().enumerate() {
        polygon.vertices = polygon.vertices.iter().map(|v| [round(v[0]), round(v[1]), v[2]]).collect();
        polygon.geometry = Geometry::new(&polygon.vertices).map_err(|e| Error::Polygon {
            path: format!("(snapped to fixed:{bits})").into(),
            index,
            name: polygon.name.clone(),
            problem: Box::new(PolygonProblem::Geometry(e)),
        })?;
    }
    Ok(snapped)
}

/// A polygon in floating point: vertices and Newell's plane.
pub struct FloatPolygon<F> {
    points: Vec<[F; 3]>,
    /// Plane coefficients `a, b, c, d` computed in `F`.
    plane: [F; 4],
    value: u32,
}

fn prepare<F: Float>(vertices: &[[Q; 3]], value: u32) -> FloatPolygon<F> {
    let convert = |q: Q| F::from(to_f64(q)).unwrap_or_else(F::nan);
    let points: Vec<[F; 3]> = vertices.iter().map(|v| v.map(convert)).collect();
    let (mut a, mut b, mut c) = (F::zero(), F::zero(), F::zero());
    for (i, p) in points.iter().enumerate() {
        let q = points[(i + 1) % points.len()];
        a = a + (p[1] - q[1]) * (p[2] + q[2]);
        b = b + (p[2] - q[2]) * (p[0] + q[0]);
        c = c + (p[0] - q[0]) * (p[1] + q[1]);
    }
    let d = -(a * points[0][0] + b * points[0][1] + c * points[0][2]);
    FloatPolygon { points, plane: [a, b, c, d], value }
}

/// One polygon's rows in `F`: crossings per scanline (evaluated, or stepped
/// down each edge), paired into spans, and the depth at each covered centre
/// (evaluated, or stepped by −a/c). Both the raster and `step --arith` use it.
struct FloatWalker<'p, F> {
    polygon: &'p FloatPolygon<F>,
    edges: Vec<Edge<F>>,
    incremental: bool,
    half: F,
    crossings: Vec<F>,
}

impl<'p, F: Float> FloatWalker<'p, F> {
    fn new(polygon: &'p FloatPolygon<F>, incremental: bool) -> FloatWalker<'p, F> {
        let half = F::from(0.5).unwrap_or_else(F::nan);
        let mut edges = Vec::new();
        if incremental {
            Edge::fill(&mut edges, &polygon.points, half);
        }
        FloatWalker { polygon, edges, incremental, half, crossings: Vec::new() }
    }

    /// The walker for another polygon, in the same space: no allocation per polygon.
    fn next<'q>(self, polygon: &'q FloatPolygon<F>) -> FloatWalker<'q, F> {
        let FloatWalker { mut edges, incremental, half, crossings, .. } = self;
        edges.clear();
        if incremental {
            Edge::fill(&mut edges, &polygon.points, half);
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
fn raster_float<F: Float>(scene: &Scene, polygons: &[Option<FloatPolygon<F>>], incremental: bool) -> (Buffers, Stats) {
    let mut buffers = Buffers::new(scene.width, scene.height, scene.frame_bits, scene.background, scene.clear_depth);
    let stats = buffers
        .with_level_cells(FloatRaster { scene, polygons, incremental })
        .expect("inexact modes run quantized z-buffers");
    (buffers, stats)
}

/// The float loop, on the cells whatever the framebuffer's cell width.
struct FloatRaster<'a, F> {
    scene: &'a Scene,
    polygons: &'a [Option<FloatPolygon<F>>],
    incremental: bool,
}

impl<F: Float> LevelCells for FloatRaster<'_, F> {
    type Output = Stats;

    fn run<C: FrameCell>(self, frame: &mut [C], depth: &mut [u32]) -> Stats {
        let scene = self.scene;
        let mut stats = Stats::default();
        let half = F::from(0.5).unwrap_or_else(F::nan);
        let max = F::from(scene.depth_max()).unwrap_or_else(F::max_value);
        let greater = scene.depth_test == crate::depth::DepthTest::Greater;
        let width = scene.width as usize;
        let mut space: Option<FloatWalker<'_, F>> = None;
        for polygon in self.polygons {
            stats.polygons += 1;
            let Some(p) = polygon else { continue };
            let value = C::from_value(p.value);
            let mut walker = match space.take() {
                Some(walker) => walker.next(p),
                None => FloatWalker::new(p, self.incremental),
            };
            if let Some((first_row, last_row)) = walker.rows(scene.height) {
                for row in first_row..=last_row {
                    let row_start = row as usize * width;
                    walker.row(row, scene.width, |x, z| {
                        let cell = row_start + x as usize;
                        stats.tested += 1;
                        let stored = F::from(depth[cell]).unwrap_or_else(F::nan);
                        // As the exact loop: every cell rewritten with its old or new
                        // value, without a branch (a NaN depth never passes).
                        let passes = if greater { z > stored } else { z < stored };
                        let level = (z + half).floor().max(F::zero()).min(max).to_u32().unwrap_or(0);
                        stats.written += u64::from(passes);
                        frame[cell] = select_unpredictable(passes, value, frame[cell]);
                        depth[cell] = select_unpredictable(passes, level, depth[cell]);
                    });
                }
            }
            space = Some(walker);
        }
        stats
    }
}

/// What an inexact mode computes on one scanline of one polygon (for
/// `zsim step --arith`): its crossings, its spans' columns, and its depth at
/// each of those columns, stepped or evaluated as the mode does.
#[derive(Debug, Clone, PartialEq)]
pub struct FloatScanline {
    /// The crossings, sorted, as `f64` (an `f32` mode's values widened).
    pub crossings: Vec<f64>,
    /// The covered columns and the depth the mode computes at each.
    pub pixels: Vec<(u32, f64)>,
}

/// The scanline `row` of polygon `index` in an inexact mode (`None` for
/// `exact` and `fixed:K`, which run the exact core).
pub fn float_scanline(scene: &Scene, index: usize, row: u32, mode: Arith) -> Option<FloatScanline> {
    match mode {
        Arith::F64 => Some(scanline_in::<f64>(scene, index, row, false)),
        Arith::F64Incremental => Some(scanline_in::<f64>(scene, index, row, true)),
        Arith::F32 => Some(scanline_in::<f32>(scene, index, row, false)),
        Arith::F32Incremental => Some(scanline_in::<f32>(scene, index, row, true)),
        Arith::Exact | Arith::Fixed(_) => None,
    }
}

fn scanline_in<F: Float>(scene: &Scene, index: usize, row: u32, incremental: bool) -> FloatScanline {
    let polygon = &scene.polygons[index];
    let p = prepare::<F>(&polygon.vertices, polygon.value);
    let mut walker = FloatWalker::new(&p, incremental);
    let mut pixels = Vec::new();
    walker.row(i64::from(row), scene.width, |x, z| pixels.push((x as u32, z.to_f64().unwrap_or(f64::NAN))));
    FloatScanline { crossings: walker.crossings.iter().map(|v| v.to_f64().unwrap_or(f64::NAN)).collect(), pixels }
}

/// An edge for the incremental modes: x stepped by Δx per scanline (seed 000).
struct Edge<F> {
    first_row: i64,
    last_row: i64,
    row: i64,
    x: F,
    dx: F,
}

impl<F: Float> Edge<F> {
    /// The non-horizontal edges with their rows (half-open rule), x at the
    /// first row on the raster (row ≥ 0, evaluated directly, as a rasterizer
    /// sets an edge up where it enters the screen), and Δx.
    fn fill(edges: &mut Vec<Edge<F>>, points: &[[F; 3]], half: F) {
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
            edges.push(Edge { first_row, last_row, row: first_row, x, dx });
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modes_parse_and_print_alike() {
        for mode in Arith::ALL {
            assert_eq!(Arith::parse(&mode.to_string()), Ok(mode));
        }
        assert_eq!(Arith::parse("fixed:4"), Ok(Arith::Fixed(4)));
        assert!(Arith::parse("fixed:25").is_err());
        assert!(Arith::parse("f16").is_err());
    }

    /// Cells (x, y) where two runs' framebuffers differ.
    fn differing(a: &Buffers, b: &Buffers) -> Vec<(u32, u32)> {
        let mut cells = Vec::new();
        for y in 0..a.height() {
            for x in 0..a.width() {
                if a.frame(x, y) != b.frame(x, y) || a.depth(x, y) != b.depth(x, y) {
                    cells.push((x, y));
                }
            }
        }
        cells
    }

    #[test]
    fn modes_on_the_books_example() {
        let scene =
            Scene::load(std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/rogers.json"))).unwrap();
        let (exact, _) = run(&scene, Arith::Exact).unwrap();
        for mode in [Arith::F64, Arith::F64Incremental, Arith::F32, Arith::Fixed(8)] {
            let (buffers, _) = run(&scene, mode).unwrap();
            assert_eq!(differing(&buffers, &exact), vec![], "{mode}");
        }
        // In f32, stepping the right edge's x by −1/3 per scanline lands just below the
        // centres it should reach exactly (x = 28.5 on row 14, …): those pixels are lost.
        let (f32_incremental, _) = run(&scene, Arith::F32Incremental).unwrap();
        let lost = differing(&f32_incremental, &exact);
        // Each is a centre exactly on the edge x = 25 + (25 − y)/3 (y = 14.5: x = 28.5, …).
        assert_eq!(lost, vec![(28, 14), (27, 17), (26, 20), (25, 23)]);
        assert!(lost.iter().all(|&(x, y)| f32_incremental.frame(x, y) == 0 && exact.frame(x, y) == 2), "{lost:?}");
    }
}
