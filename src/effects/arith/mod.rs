//! Arithmetic modes: what the book's rules give when computed with less than
//! exact arithmetic, so `zsim accuracy` can show what accuracy costs.
//!
//! | mode | what it computes | where it can go wrong |
//! |---|---|---|
//! | `exact` | the core: integers and rationals, depth stepped by exact whole part and remainder | nowhere (it is the reference) |
//! | `f64` | crossings and the plane's depth evaluated per pixel in `f64` | ties: a centre on an edge or a depth of exactly k + 1/2 may round either way |
//! | `f64-incremental` | x stepped by Δx per scanline along each edge (the Russian lecture notes), z by −a/c per pixel (the Russian coursework), in `f64` | errors accumulate along long edges and spans |
//! | `f32-incremental` | the same in `f32` | as above, 2^29 times larger; depths above 2^24 lose whole levels |
//! | `f32` | per-pixel evaluation in `f32` | rounding of every product; depths above 2^24 lose whole levels |
//! | `f32-edge` | a GPU's loop: edge functions over the bounding box, stepped per column in `f32`, depth from the plane stepped by ∂z/∂x | rounding of the edge functions at centres on an edge; depths above 2^24 lose whole levels |
//! | `fixed:K` | vertices snapped to K fractional bits (Direct3D snaps to 8), then the exact core | the snapped polygon differs from the given one by up to 2^−K−1 per coordinate |
//!
//! Inexact modes run the plain algorithm with the book's rules (half-open
//! rows, centres inside spans, quantized depth); whether a polygon is drawn
//! at all (culled, edge-on, degenerate) is decided exactly, so the modes
//! differ only in the arithmetic of the raster.

use crate::words::Lang;
use std::fmt;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Float;

mod edge;
mod float;

use edge::*;
use float::*;

use crate::error::{Error, PolygonOrigin, PolygonProblem, Refusal};

use crate::numbers::{Exact, to_f64};
use crate::raster::depth::depth_at;
use crate::rules::{Preset, Rules};
use crate::scene::Scene;
use crate::simulate::buffer::{Buffers, FrameCell, LevelCells};
use crate::simulate::events::{Fate, Unobserved};
use crate::simulate::setup::{Stats, fate};
use crate::simulate::simulation::Simulation;

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
    pub fn parse(text: &str) -> Result<Arith, NotAnArith> {
        match text {
            "exact" => Ok(Arith::Exact),
            "f64" => Ok(Arith::F64),
            "f64-incremental" => Ok(Arith::F64Incremental),
            "f32-incremental" => Ok(Arith::F32Incremental),
            "f32" => Ok(Arith::F32),
            "f32-edge" => Ok(Arith::F32Edge),
            _ => match text.strip_prefix("fixed:").map(str::parse::<u32>) {
                Some(Ok(bits @ 0..=24)) => Ok(Arith::Fixed(bits)),
                _ => Err(NotAnArith { text: text.to_string() }),
            },
        }
    }
}

/// A name that is no arithmetic mode ([`Arith::parse`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotAnArith {
    /// The name given.
    pub text: String,
}

impl NotAnArith {
    /// The refusal in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        let text = crate::words::printable(&crate::words::token(lang, &self.text)).into_owned();
        words!(lang, "usage-arith", text = text)
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

/// A scene an inexact mode cannot simulate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unsupported {
    /// Other rules than the book's, per-pixel effects or antialiasing.
    OtherRules(Arith),
    /// A depth test other than greater and less.
    OtherTest(Arith, crate::raster::depth::DepthTest),
}

impl Refusal for Unsupported {
    fn message(&self, lang: Lang) -> String {
        match self {
            Unsupported::OtherRules(arith) => words!(lang, "usage-arith-plain-rules", arith = arith.to_string()),
            Unsupported::OtherTest(arith, test) => {
                words!(lang, "usage-arith-greater-or-less", arith = arith.to_string(), test = test.name())
            }
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
        return Err(Unsupported::OtherRules(arith).into());
    }
    if scene.depth_test.equal_passes() || !scene.depth_test.compares() {
        return Err(Unsupported::OtherTest(arith, scene.depth_test).into());
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
fn prepare_scene<F: Float + crate::numbers::Ring>(scene: &Scene) -> Vec<Option<FloatPolygon<F>>> {
    (0..scene.polygons.len())
        .map(|i| {
            (fate(scene, i) == Fate::Drawn).then(|| prepare(&scene.polygons[i].vertices(), scene.polygons[i].value))
        })
        .collect()
}

/// Every polygon drawn (by the exact fate) set up for `f32-edge`; `None` for the others.
fn prepare_edges(scene: &Scene) -> Vec<Option<EdgeShape>> {
    (0..scene.polygons.len())
        .map(|i| (fate(scene, i) == Fate::Drawn).then(|| EdgeShape::new(&scene.polygons[i])))
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
        if polygon.vertices().is_empty() {
            // Clipped away in clip space: nothing on the raster to snap.
            continue;
        }
        let on_plane = |x: Exact, y: Exact, z: &Exact| {
            let kept = if polygon.vertices().len() > 3 { depth_at(polygon.geometry(), &x, &y) } else { None };
            [x, y, kept.unwrap_or_else(|| z.clone())]
        };
        let vertices = polygon.vertices().iter().map(|v| on_plane(round(&v[0]), round(&v[1]), &v[2])).collect();
        *polygon = polygon.with_vertices(vertices).map_err(|e| Error::Polygon {
            origin: PolygonOrigin::Snapped { bits },
            index,
            name: polygon.name.clone(),
            problem: Box::new(PolygonProblem::Geometry(e)),
        })?;
    }
    Ok(snapped)
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
            let (width, height) = (scene.width, scene.height);
            Some(match EdgeShape::new(polygon) {
                EdgeShape::Triangle(p, c) => edge_scanline(&EdgePolygon::<3>::new(&p, c, width, height), row),
                EdgeShape::Quad(p, c) => edge_scanline(&EdgePolygon::<4>::new(&p, c, width, height), row),
                EdgeShape::Other(_) => scanline_in::<f32>(scene, index, row, false),
            })
        }
        Arith::Exact | Arith::Fixed(_) => None,
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
        assert_eq!(Arith::parse("fixed:25"), Err(NotAnArith { text: "fixed:25".into() }));
        assert!(Arith::parse("f16").unwrap_err().message(Lang::En).starts_with("\"f16\" is not an arithmetic mode"));
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
        let scene = Scene::from_json(r#"{"width": 5, "height": 5, "polygons": [{"value": 1, "vertices": [[1.5, 1.5, 5], [3.5, 1.5, 5], [3.5, 3.5, 5], [1.5, 3.5, 5]]}]}"#,
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
