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
//! | `f32-edge` | a GPU's loop: edge functions over the bounding box, stepped per column in `f32`, depth from the plane stepped by ∂z/∂x | rounding of the edge functions at centres on an edge; depths above 2^24 lose whole levels |
//! | `fixed:K` | vertices snapped to K fractional bits (Direct3D snaps to 8), then the exact core | the snapped polygon differs from the given one by up to 2^−K−1 per coordinate |
//!
//! Inexact modes run the plain algorithm with the book's rules (half-open
//! rows, centres inside spans, quantized depth); whether a polygon is drawn
//! at all (culled, edge-on, degenerate) is decided exactly, so the modes
//! differ only in the arithmetic of the raster.

use std::fmt;
use std::hint::select_unpredictable;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{AsPrimitive, Float, Num, Signed};

use crate::error::{Error, PolygonProblem};
use crate::geometry::plane::Geometry;
use crate::numbers::{Exact, to_f64};
use crate::raster::depth::depth_at;
use crate::rules::{Preset, Rules};
use crate::scene::Scene;
use crate::simulate::buffer::{Buffers, FrameCell, LevelCells};
use crate::simulate::events::{Fate, Unobserved};
use crate::simulate::pipeline::{Simulation, Stats, fate};

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
    /// Edge functions over the bounding box in `f32`, as a GPU rasterizes.
    F32Edge,
    /// Vertices snapped to K fractional bits, then exact.
    Fixed(u32),
}

impl Arith {
    /// Every mode `zsim accuracy` compares, in table order.
    pub const ALL: [Arith; 7] = [
        Arith::Exact,
        Arith::F64,
        Arith::F64Incremental,
        Arith::F32Incremental,
        Arith::F32,
        Arith::F32Edge,
        Arith::Fixed(8),
    ];

    /// Reads `exact`, `f64`, `f64-incremental`, `f32-incremental`, `f32`, `f32-edge` or `fixed:K` (0 ≤ K ≤ 24).
    pub fn parse(text: &str) -> Result<Arith, String> {
        match text {
            "exact" => Ok(Arith::Exact),
            "f64" => Ok(Arith::F64),
            "f64-incremental" => Ok(Arith::F64Incremental),
            "f32-incremental" => Ok(Arith::F32Incremental),
            "f32" => Ok(Arith::F32),
            "f32-edge" => Ok(Arith::F32Edge),
            _ => match text.strip_prefix("fixed:").map(str::parse::<u32>) {
                Some(Ok(bits @ 0..=24)) => Ok(Arith::Fixed(bits)),
                _ => Err(format!(
                    "\"{text}\" is not an arithmetic mode: exact, f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K (K from 0 to 24)"
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
            Arith::F32Edge => f.write_str("f32-edge"),
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
    if scene.depth_test.equal_passes() || !scene.depth_test.compares() {
        return Err(Error::Usage(format!(
            "--arith {arith} simulates the depth tests greater and less; this scene asks for {} (use --arith exact)",
            scene.depth_test.name()
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
        Arith::F32Edge => Ok(raster_edges(scene, &prepare_edges(scene))),
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
    /// Edge functions in `f32`.
    F32Edge(&'s Scene, Vec<Option<EdgeShape>>),
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
            Arith::F32Edge => Prepared::F32Edge(scene, prepare_edges(scene)),
        })
    }

    /// Rasterizes: the final buffers and the counts.
    pub fn raster(&self) -> (Buffers, Stats) {
        match self {
            Prepared::Exact(scene) => exact_raster(scene),
            Prepared::Snapped(scene) => exact_raster(scene),
            Prepared::F64(scene, polygons, incremental) => raster_float(scene, polygons, *incremental),
            Prepared::F32(scene, polygons, incremental) => raster_float(scene, polygons, *incremental),
            Prepared::F32Edge(scene, shapes) => raster_edges(scene, shapes),
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

/// Every polygon drawn (by the exact fate) set up for `f32-edge`; `None` for the others.
fn prepare_edges(scene: &Scene) -> Vec<Option<EdgeShape>> {
    (0..scene.polygons.len())
        .map(|i| (fate(scene, i) == Fate::Drawn).then(|| EdgeShape::new(&scene.polygons[i], scene.width, scene.height)))
        .collect()
}

/// The scene with every x and y rounded to the nearest multiple of 2^−bits
/// (halves up), as fixed-point hardware snaps vertices. A triangle keeps
/// each vertex's z, as hardware does; a polygon of more vertices (which
/// hardware would split into triangles, and which snapping would bend out
/// of its plane) takes at each snapped vertex the depth of its own plane
/// there, so it stays one plane.
pub fn snap(scene: &Scene, bits: u32) -> Result<Scene, Error> {
    // ⌊v·2^bits + 1/2⌋ / 2^bits, in big rationals (a clipped vertex may not fit 128 bits).
    let unit = BigRational::from_integer(BigInt::from(1) << bits);
    let half = BigRational::new(BigInt::from(1), BigInt::from(2));
    let round = |v: &Exact| Exact::from((v.to_big() * &unit + &half).floor() / &unit);
    let mut snapped = scene.clone();
    for (index, polygon) in snapped.polygons.iter_mut().enumerate() {
        if polygon.vertices.is_empty() {
            // Clipped away in clip space: nothing on the raster to snap.
            continue;
        }
        let on_plane = |x: Exact, y: Exact, z: &Exact| {
            let kept = if polygon.vertices.len() > 3 { depth_at(&polygon.geometry, &x, &y) } else { None };
            [x, y, kept.unwrap_or_else(|| z.clone())]
        };
        polygon.vertices = polygon.vertices.iter().map(|v| on_plane(round(&v[0]), round(&v[1]), &v[2])).collect();
        polygon.geometry = Geometry::from_exact(&polygon.vertices).map_err(|e| Error::Polygon {
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

fn prepare<F: Float>(vertices: &[[Exact; 3]], value: u32) -> FloatPolygon<F> {
    let convert = |v: &Exact| F::from(to_f64(v)).unwrap_or_else(F::nan);
    let points: Vec<[F; 3]> = vertices.iter().map(|v| v.each_ref().map(convert)).collect();
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
fn raster_float<F: Float + AsPrimitive<u32>>(
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
struct FloatRaster<'a, F> {
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
fn nearer_sign<F: Float>(scene: &Scene) -> F {
    if scene.depth_test.larger_is_nearer() { F::one() } else { -F::one() }
}

/// The depth test and the store of one covered-or-not cell, as the exact
/// loop does them: the cell rewritten with its old or its new value, without
/// a branch. A cell counts as tested when `covered`; a NaN depth never passes.
#[inline(always)]
fn test_and_store<F: Float + AsPrimitive<u32>, C: FrameCell>(
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

/// The plain z-buffer with `f32-edge`.
fn raster_edges(scene: &Scene, shapes: &[Option<EdgeShape>]) -> (Buffers, Stats) {
    let mut buffers =
        Buffers::new(scene.width, scene.height, scene.frame_bits, scene.background, scene.clear_depth.clone());
    let stats = buffers.with_level_cells(EdgeRaster { scene, shapes }).expect("inexact modes run quantized z-buffers");
    (buffers, stats)
}

/// The edge-function loop, on the cells whatever the framebuffer's cell width.
struct EdgeRaster<'a> {
    scene: &'a Scene,
    shapes: &'a [Option<EdgeShape>],
}

impl LevelCells for EdgeRaster<'_> {
    type Output = Stats;

    fn run<C: FrameCell>(self, frame: &mut [C], depth: &mut [u32]) -> Stats {
        let scene = self.scene;
        let mut stats = Stats::default();
        let limits = (nearer_sign(scene), scene.depth_max() as f32);
        let width = scene.width as usize;
        let mut space: Option<FloatWalker<'_, f32>> = None;
        for shape in self.shapes {
            stats.polygons += 1;
            match shape {
                None => {}
                Some(EdgeShape::Triangle(p)) => draw_edges(p, (frame, depth), width, limits, &mut stats),
                Some(EdgeShape::Quad(p)) => draw_edges(p, (frame, depth), width, limits, &mut stats),
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

/// One polygon's rows through the scanline walker, each covered centre tested and stored.
fn draw_walked<F: Float + AsPrimitive<u32>, C: FrameCell>(
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

/// One convex polygon's bounding box, row by row.
#[inline(always)]
fn draw_edges<const N: usize, C: FrameCell>(
    polygon: &EdgePolygon<N>,
    (frame, depth): (&mut [C], &mut [u32]),
    width: usize,
    limits: (f32, f32),
    stats: &mut Stats,
) {
    let value = C::from_value(polygon.value);
    for row in polygon.rows.0..=polygon.rows.1 {
        let row_start = row as usize * width;
        polygon.row(row, |x, covered, z| {
            test_and_store(stats, (&mut *frame, &mut *depth), row_start + x as usize, value, covered, z, limits);
        });
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
    /// For `f32-edge` on a convex triangle or quadrilateral: the columns of
    /// the bounding box whose centres were tested by edge functions (there
    /// are no crossings then).
    pub bounding_columns: Option<(u32, u32)>,
}

/// The scanline `row` of polygon `index` in an inexact mode (`None` for
/// `exact` and `fixed:K`, which run the exact core).
pub fn float_scanline(scene: &Scene, index: usize, row: u32, mode: Arith) -> Option<FloatScanline> {
    match mode {
        Arith::F64 => Some(scanline_in::<f64>(scene, index, row, false)),
        Arith::F64Incremental => Some(scanline_in::<f64>(scene, index, row, true)),
        Arith::F32 => Some(scanline_in::<f32>(scene, index, row, false)),
        Arith::F32Incremental => Some(scanline_in::<f32>(scene, index, row, true)),
        Arith::F32Edge => {
            let polygon = &scene.polygons[index];
            Some(match EdgeShape::new(polygon, scene.width, scene.height) {
                EdgeShape::Triangle(p) => edge_scanline(&p, row),
                EdgeShape::Quad(p) => edge_scanline(&p, row),
                EdgeShape::Other(_) => scanline_in::<f32>(scene, index, row, false),
            })
        }
        Arith::Exact | Arith::Fixed(_) => None,
    }
}

fn scanline_in<F: Float>(scene: &Scene, index: usize, row: u32, incremental: bool) -> FloatScanline {
    let polygon = &scene.polygons[index];
    let p = prepare::<F>(&polygon.vertices, polygon.value);
    let mut walker = FloatWalker::new(&p, incremental);
    let mut pixels = Vec::new();
    walker.row(i64::from(row), scene.width, |x, z| pixels.push((x as u32, z.to_f64().unwrap_or(f64::NAN))));
    FloatScanline {
        crossings: walker.crossings.iter().map(|v| v.to_f64().unwrap_or(f64::NAN)).collect(),
        pixels,
        bounding_columns: None,
    }
}

fn edge_scanline<const N: usize>(polygon: &EdgePolygon<N>, row: u32) -> FloatScanline {
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

/// What `f32-edge` draws a polygon with.
pub enum EdgeShape {
    /// A triangle's three edge functions.
    Triangle(EdgePolygon<3>),
    /// A convex quadrilateral's four.
    Quad(EdgePolygon<4>),
    /// Anything else (concave, self-intersecting, five or more vertices), which
    /// a GPU would first cut into triangles: drawn by the `f32` scanline walker.
    Other(FloatPolygon<f32>),
}

impl EdgeShape {
    /// Sets a drawn polygon up: edge functions when it is a convex triangle
    /// or quadrilateral (decided exactly, on its scaled integer vertices).
    fn new(polygon: &crate::scene::Polygon, width: u32, height: u32) -> EdgeShape {
        let float = prepare::<f32>(&polygon.vertices, polygon.value);
        let points = &polygon.geometry.points;
        let (convex, count) = match polygon.geometry.big_scaled() {
            Some((points, _)) => (is_convex(points), points.len()),
            None => (is_convex(points), points.len()),
        };
        match (count, convex) {
            (3, true) => EdgeShape::Triangle(EdgePolygon::new(&float, polygon.geometry.c(), width, height)),
            (4, true) => EdgeShape::Quad(EdgePolygon::new(&float, polygon.geometry.c(), width, height)),
            _ => EdgeShape::Other(float),
        }
    }
}

/// Whether a polygon (scaled integer vertices, seen from +z) is convex and
/// winds once: every turn the same way (or straight), and its edges go up,
/// then down, at most once each.
fn is_convex<T: Num + Ord + Clone + Signed>(points: &[[T; 3]]) -> bool {
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
    fn new(polygon: &FloatPolygon<f32>, newell_c: i128, width: u32, height: u32) -> EdgePolygon<N> {
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
        let mut e: [f32; N] = std::array::from_fn(|i| at(i, x));
        let step: [f32; N] = std::array::from_fn(|i| self.edges[i][0]);
        let [dzdx, dzdy, x1, y1, z1] = self.depth;
        let mut z = z1 + dzdx * (x - x1) + dzdy * (y - y1);
        for column in first..=last {
            let covered = e.iter().fold(true, |inside, v| inside & (*v >= 0.0));
            pixel(column, covered, z);
            for (v, s) in e.iter_mut().zip(&step) {
                *v += s;
            }
            z += dzdx;
        }
    }
}

/// `⌈v⌉` and `⌊v⌋` by a cast and a comparison: without SSE4.1 (the x86-64
/// baseline) `f32::ceil` is a library call. A cast saturates, so a far-away
/// or NaN `v` gives a bound that clipping to the bounding box then ignores.
#[inline(always)]
fn ceil(v: f32) -> i64 {
    let t = v as i64;
    t + i64::from((t as f32) < v)
}

#[inline(always)]
fn floor(v: f32) -> i64 {
    let t = v as i64;
    t - i64::from((t as f32) > v)
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
        for mode in [Arith::F64, Arith::F64Incremental, Arith::F32, Arith::F32Edge, Arith::Fixed(8)] {
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

    fn scaled(points: &[(i128, i128)]) -> Vec<[i128; 3]> {
        points.iter().map(|&(x, y)| [x, y, 0]).collect()
    }

    #[test]
    fn convex_polygons_are_told_from_concave_and_self_intersecting_ones() {
        assert!(is_convex(&scaled(&[(0, 0), (4, 0), (0, 4)])), "a counter-clockwise triangle");
        assert!(is_convex(&scaled(&[(0, 0), (0, 4), (4, 0)])), "a clockwise triangle");
        assert!(is_convex(&scaled(&[(0, 0), (4, 0), (4, 4), (0, 4)])), "a square");
        assert!(is_convex(&scaled(&[(0, 0), (2, 0), (4, 0), (0, 4)])), "a triangle with a straight vertex");
        assert!(!is_convex(&scaled(&[(0, 0), (4, 0), (1, 1), (0, 4)])), "a dart (concave quadrilateral)");
        assert!(!is_convex(&scaled(&[(0, 0), (4, 4), (4, 0), (0, 4)])), "a bow tie");
        // A pentagram turns the same way at every vertex but winds twice.
        assert!(!is_convex(&scaled(&[(0, 10), (6, -8), (-10, 3), (10, 3), (-6, -8)])), "a pentagram");
    }

    /// The book's example, the `less` test and a concave polygon (drawn by
    /// the fallback walker) come out as in exact arithmetic, counts included.
    #[test]
    fn edge_functions_cover_what_exact_covers_on_convex_and_concave_scenes() {
        for example in ["rogers", "less", "concave"] {
            let path = format!("{}/examples/{example}.json", env!("CARGO_MANIFEST_DIR"));
            let scene = Scene::load(std::path::Path::new(&path)).unwrap();
            let (exact, exact_stats) = run(&scene, Arith::Exact).unwrap();
            let (edge, edge_stats) = run(&scene, Arith::F32Edge).unwrap();
            assert_eq!(differing(&edge, &exact), vec![], "{example}");
            assert_eq!(edge_stats, exact_stats, "{example}: the same centres tested and written");
        }
    }

    #[test]
    fn edge_function_ties_follow_the_books_rule() {
        // The square [1.5, 3.5] × [1.5, 3.5] has pixel centres on all four edges.
        let scene = Scene::from_json(
            r#"{"width": 5, "height": 5, "polygons": [{"value": 1, "vertices": [[1.5, 1.5, 5], [3.5, 1.5, 5], [3.5, 3.5, 5], [1.5, 3.5, 5]]}]}"#,
            std::path::Path::new("square.json"),
        )
        .unwrap();
        let (edge, _) = run(&scene, Arith::F32Edge).unwrap();
        // Left, right and bottom edges covered; the top edge (y = 3.5, the end of the
        // half-open row range) not: rows 1 … 2, columns 1 … 3.
        let covered: Vec<(u32, u32)> =
            (0..5).flat_map(|y| (0..5).map(move |x| (x, y))).filter(|&(x, y)| edge.frame(x, y) == 1).collect();
        assert_eq!(covered, vec![(1, 1), (2, 1), (3, 1), (1, 2), (2, 2), (3, 2)]);
    }
}
