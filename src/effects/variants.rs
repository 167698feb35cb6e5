//! Other loop orders and smaller z-buffers (the Russian lecture notes, the Chinese course notes and the Russian text on loop order), all driving
//! the same scan conversion or the same crossing rule:
//!
//! - segmented z-buffers: strips, tiles or one scanline, processing the image
//!   segment by segment with a z-buffer only as large as one segment, each
//!   segment seeing only the polygons whose bounding boxes touch it;
//! - the "for every pixel, for every polygon" order with one depth variable
//!   (the Chinese course notes), with a point-in-polygon test at each centre: ray casting or
//!   the arc-length (quadrant) method.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_traits::Num;

use crate::numbers::Exact;
use crate::raster::convert::{Scratch, rasterize};
use crate::raster::depth::{Depth, depth_at_centre};
use crate::raster::scan::{Crossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::scene::{Polygon, Scene};
use crate::simulate::buffer::Buffers;
use crate::simulate::events::{Fate, Outcome};
use crate::simulate::setup::fate;
use crate::simulate::stages::{Decision, PixelStages, Plain, WithEffects};

/// The per-pixel stages the scene asks for, as a trait object.
fn stages(scene: &Scene) -> Box<dyn PixelStages + '_> {
    if scene.has_pixel_effects() { Box::new(WithEffects::new(scene)) } else { Box::new(Plain::new(scene)) }
}

/// How the image is cut into segments.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Segments {
    /// N horizontal strips of (about) equal height.
    Strips(u32),
    /// N×N tiles of (about) equal size.
    Tiles(u32),
    /// One scanline at a time (the limit the seeds mention).
    Rows,
}

/// Why a text names no segments ([`Segments::parse`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NotSegments {
    /// Not `strips:N`, `tiles:N` or `rows:1`.
    Form {
        /// The text given.
        text: String,
    },
    /// A count that is not a whole number.
    Count {
        /// The count given.
        count: String,
    },
    /// `rows:N` with N other than 1.
    Rows,
}

impl NotSegments {
    /// The refusal in `lang`, one line.
    pub fn message(&self, lang: crate::words::Lang) -> String {
        use crate::words::{printable, token};
        match self {
            NotSegments::Form { text } => {
                words!(lang, "segments-form", text = printable(&token(lang, text)).into_owned())
            }
            NotSegments::Count { count } => {
                words!(lang, "segments-count", count = printable(&token(lang, count)).into_owned())
            }
            NotSegments::Rows => words!(lang, "segments-rows"),
        }
    }
}

impl Segments {
    /// Reads `strips:N`, `tiles:N` or `rows:1`.
    pub fn parse(text: &str) -> Result<Segments, NotSegments> {
        let not_segments = || NotSegments::Form { text: text.to_string() };
        let (kind, count) = text.split_once(':').ok_or_else(not_segments)?;
        let count: u32 = count.parse().map_err(|_| NotSegments::Count { count: count.to_string() })?;
        match (kind, count) {
            ("strips", 1..) => Ok(Segments::Strips(count)),
            ("tiles", 1..) => Ok(Segments::Tiles(count)),
            ("rows", 1) => Ok(Segments::Rows),
            ("rows", _) => Err(NotSegments::Rows),
            _ => Err(not_segments()),
        }
    }

    /// The segments of a `width`×`height` raster, bottom to top, left to right.
    pub fn rects(self, width: u32, height: u32) -> Vec<PixelRect> {
        let cuts = |size: u32, parts: u32| -> Vec<(u32, u32)> {
            let parts = parts.min(size);
            (0..parts).map(|i| (size * i / parts, size * (i + 1) / parts - 1)).collect()
        };
        let (column_cuts, row_cuts) = match self {
            Segments::Strips(n) => (vec![(0, width - 1)], cuts(height, n)),
            Segments::Tiles(n) => (cuts(width, n), cuts(height, n)),
            Segments::Rows => (vec![(0, width - 1)], cuts(height, height)),
        };
        row_cuts.iter().flat_map(|&rows| column_cuts.iter().map(move |&columns| PixelRect { columns, rows })).collect()
    }
}

impl std::fmt::Display for Segments {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Segments::Strips(n) => write!(f, "strips:{n}"),
            Segments::Tiles(n) => write!(f, "tiles:{n}"),
            Segments::Rows => write!(f, "rows:1"),
        }
    }
}

/// What a segmented run measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SegmentStats {
    /// Number of segments.
    pub segments: usize,
    /// Cells of the largest segment: the z-buffer's size.
    pub depth_cells: u64,
    /// (polygon, segment) pairs processed; the plain z-buffer visits each polygon once.
    pub polygon_visits: u64,
}

/// Draws the scene segment by segment. Returns the assembled buffers (the
/// framebuffer is the screen; the z-buffer is assembled from each segment's
/// final contents only so it can be shown and compared) and the statistics.
pub fn run_segmented(scene: &Scene, segments: Segments) -> (Buffers, SegmentStats) {
    let stages = stages(scene);
    let mut screen =
        Buffers::new(scene.width, scene.height, scene.frame_bits, scene.background, scene.clear_depth.clone());
    let rects = segments.rects(scene.width, scene.height);
    let mut stats = SegmentStats { segments: rects.len(), depth_cells: 0, polygon_visits: 0 };
    let mut scratch = Scratch::default();
    for rect in rects {
        let (w, h) = (rect.columns.1 - rect.columns.0 + 1, rect.rows.1 - rect.rows.0 + 1);
        stats.depth_cells = stats.depth_cells.max(u64::from(w) * u64::from(h));
        let mut segment = Buffers::new(w, h, scene.frame_bits, scene.background, scene.clear_depth.clone());
        for index in visited_in(scene, rect) {
            let polygon = &scene.polygons[index];
            stats.polygon_visits += 1;
            let mut sink = SegmentSink {
                polygon,
                stages: stages.as_ref(),
                origin: (rect.columns.0, rect.rows.0),
                buffers: &mut segment,
            };
            rasterize(polygon.geometry(), scene.rules, rect, &mut scratch, &mut sink);
        }
        for y in 0..h {
            for x in 0..w {
                screen.store(rect.columns.0 + x, rect.rows.0 + y, segment.frame(x, y), segment.depth(x, y));
            }
        }
    }
    (screen, stats)
}

/// The polygons (0-based, in order) a segment visits: those drawn whose
/// bounding boxes touch it.
pub fn visited_in(scene: &Scene, rect: PixelRect) -> Vec<usize> {
    (0..scene.polygons.len())
        .filter(|&i| {
            fate(scene, i) == Fate::Drawn && bounding_rect(&scene.polygons[i]).is_some_and(|b| overlaps(b, rect))
        })
        .collect()
}

/// Writes one polygon's pixels into a segment's own buffers.
struct SegmentSink<'a> {
    polygon: &'a Polygon,
    stages: &'a dyn PixelStages,
    origin: (u32, u32),
    buffers: &'a mut Buffers,
}

impl RasterSink for SegmentSink<'_> {
    const OBSERVES_SCANLINES: bool = false;

    fn scanline(&mut self, _row: u32, _crossings: &[Crossing], _spans: &[Span]) {}

    fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
        let (sx, sy) = (x - self.origin.0, y - self.origin.1);
        let decision = self.stages.decide(self.polygon, depth, self.buffers.depth(sx, sy), self.buffers.frame(sx, sy));
        if decision.outcome == Outcome::Written {
            self.buffers.store(sx, sy, decision.frame, decision.stored);
        }
    }
}

/// The pixel rectangle a polygon's vertices span (clipped to nothing when
/// wholly outside the non-negative quadrant); `None` for an empty box.
fn bounding_rect(polygon: &Polygon) -> Option<PixelRect> {
    let floor = |v: &Exact| {
        let floor = v.floor().clamp(BigInt::from(0), BigInt::from(u32::MAX));
        num_traits::ToPrimitive::to_u32(&floor).expect("clamped")
    };
    let vertices = polygon.vertices();
    let xs = vertices.iter().map(|v| &v[0]);
    let ys = vertices.iter().map(|v| &v[1]);
    let (x0, x1) = (xs.clone().min()?, xs.max()?);
    let (y0, y1) = (ys.clone().min()?, ys.max()?);
    // A centre at x + 1/2 inside [x0, x1] needs x ≥ ⌊x0⌋ − 1 … x ≤ ⌊x1⌋; the cell rule takes ⌊x0⌋ … ⌊x1⌋.
    Some(PixelRect {
        columns: (floor(x0).saturating_sub(1), floor(x1)),
        rows: (floor(y0).saturating_sub(1), floor(y1)),
    })
}

fn overlaps(a: PixelRect, b: PixelRect) -> bool {
    a.columns.0 <= b.columns.1 && b.columns.0 <= a.columns.1 && a.rows.0 <= b.rows.1 && b.rows.0 <= a.rows.1
}

/// The point-in-polygon test of the pixel-order loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Inside {
    /// Ray casting to the right, counting edges by the left-open/right-closed
    /// (half-interval) vertex rule; a centre on a crossing counts as inside
    /// ("on the boundary counts").
    Ray,
    /// The arc-length method: the winding number by the quadrant table; a
    /// centre on the boundary counts as inside.
    Arc,
}

/// Why the arc-length test decided differently from the scanline rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArcDifference {
    /// The centre lies exactly on the polygon's boundary where the
    /// half-interval rule leaves it out (a top edge or vertex, or the right
    /// end of a horizontal edge).
    OnBoundary,
    /// The polygon winds around the centre an even, non-zero number of times:
    /// arc counts it inside, the paired crossings (even-odd) outside.
    Winding(i64),
}

/// One cell where `--inside arc` gives a different polygon than the plain z-buffer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct InsideDifference {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// 0-based polygon whose inside test differs there.
    pub polygon: usize,
    /// Why.
    pub why: ArcDifference,
}

/// "For every pixel, for every polygon" with one depth variable per pixel
/// (the Chinese course notes). Returns the buffers and, with [`Inside::Arc`], every
/// (pixel, polygon) whose inside test differs from the scanline rule.
pub fn run_pixel_order(scene: &Scene, inside: Inside) -> (Buffers, Vec<InsideDifference>) {
    let stages = stages(scene);
    let mut buffers =
        Buffers::new(scene.width, scene.height, scene.frame_bits, scene.background, scene.clear_depth.clone());
    let drawn: Vec<usize> = (0..scene.polygons.len()).filter(|&i| fate(scene, i) == Fate::Drawn).collect();
    let mut differences = Vec::new();
    for y in 0..scene.height {
        for x in 0..scene.width {
            // The one depth variable (and frame value) of this pixel.
            let (mut stored, mut frame) = (scene.clear_depth.clone(), scene.background);
            for &index in &drawn {
                let polygon = &scene.polygons[index];
                let by_ray = ray_inside(polygon, x, y);
                let is_inside = match inside {
                    Inside::Ray => by_ray,
                    Inside::Arc => {
                        let (by_arc, why) = arc_inside(polygon, x, y);
                        if by_arc != by_ray {
                            differences.push(InsideDifference { x, y, polygon: index, why });
                        }
                        by_arc
                    }
                };
                if !is_inside {
                    continue;
                }
                let depth = depth_at_centre(polygon.geometry(), x, y);
                let Decision { outcome, stored: after, frame: frame_after, .. } =
                    stages.decide(polygon, depth, stored.clone(), frame);
                if outcome == Outcome::Written {
                    (stored, frame) = (after, frame_after);
                }
            }
            buffers.store(x, y, frame, stored);
        }
    }
    (buffers, differences)
}

/// A polygon's scaled vertices (x, y) relative to the centre of pixel
/// (x, y), in `T`: `i128` for a word-sized polygon, whose products stay
/// below 2^123 ([`crate::geometry::plane::MAX_SCALED`]), `BigInt` for one of the
/// big-integer tier, whose products do not.
fn around<T: From<i128> + Num + Clone>(points: &[[T; 3]], denominator: &T, x: u32, y: u32) -> Vec<[T; 2]> {
    let centre = |i: u32| T::from(2 * i128::from(i) + 1) * denominator.clone();
    let (cx, cy) = (centre(x), centre(y));
    points.iter().map(|p| [p[0].clone() - cx.clone(), p[1].clone() - cy.clone()]).collect()
}

/// Ray casting from the centre to the right with the half-interval vertex
/// rule (an edge counts when `min(y₁, y₂) ≤ y < max(y₁, y₂)`); a crossing
/// exactly at the centre means the centre is on the boundary: inside.
pub fn ray_inside(polygon: &Polygon, x: u32, y: u32) -> bool {
    let geometry = polygon.geometry();
    match geometry.big_scaled() {
        Some((points, denominator)) => ray_inside_from::<BigInt>(&around(points, denominator, x, y)),
        None => ray_inside_from::<i128>(&around(&geometry.points, &geometry.denominator, x, y)),
    }
}

/// [`ray_inside`] on vertices relative to the centre.
fn ray_inside_from<T: Num + Ord + Clone>(points: &[[T; 2]]) -> bool {
    let mut right = 0;
    for (i, p) in points.iter().enumerate() {
        let q = &points[(i + 1) % points.len()];
        let (y1, y2) = (p[1].clone(), q[1].clone());
        if y1 == y2 || T::zero() < y1.clone().min(y2.clone()) || T::zero() >= y1.clone().max(y2.clone()) {
            continue;
        }
        // Crossing x = (x₁(y₂ − y₁) + (x₂ − x₁)(0 − y₁)) / (y₂ − y₁), compared with 0.
        let numerator = p[0].clone() * (y2.clone() - y1.clone()) - (q[0].clone() - p[0].clone()) * y1.clone();
        let numerator = if y2 < y1 { T::zero() - numerator } else { numerator };
        match numerator.cmp(&T::zero()) {
            Ordering::Equal => return true,
            Ordering::Greater => right += 1,
            Ordering::Less => {}
        }
    }
    right % 2 == 1
}

/// The arc-length method with the quadrant table: each vertex's quadrant
/// around the centre (0: x ≥ 0, y ≥ 0; 1: x < 0, y ≥ 0; 2: x < 0, y < 0;
/// 3: x ≥ 0, y < 0); each edge adds +1 or −1 for a neighbouring quadrant and
/// ±2 for the opposite one, by the sign of the cross product; the sum is four
/// times the winding number. A centre on the boundary counts as inside.
/// Returns the decision and, for a difference report, its kind.
pub fn arc_inside(polygon: &Polygon, x: u32, y: u32) -> (bool, ArcDifference) {
    let geometry = polygon.geometry();
    match geometry.big_scaled() {
        Some((points, denominator)) => arc_inside_from::<BigInt>(&around(points, denominator, x, y)),
        None => arc_inside_from::<i128>(&around(&geometry.points, &geometry.denominator, x, y)),
    }
}

/// [`arc_inside`] on vertices relative to the centre.
fn arc_inside_from<T: Num + Ord + Clone>(points: &[[T; 2]]) -> (bool, ArcDifference) {
    let zero = T::zero();
    let quadrant = |p: &[T; 2]| match (p[0] >= zero, p[1] >= zero) {
        (true, true) => 0i64,
        (false, true) => 1,
        (false, false) => 2,
        (true, false) => 3,
    };
    let mut sum = 0i64;
    for (i, p) in points.iter().enumerate() {
        let q = &points[(i + 1) % points.len()];
        let [ax, ay] = p.clone();
        let [bx, by] = q.clone();
        let cross = ax.clone() * by.clone() - ay.clone() * bx.clone();
        // On the segment: collinear with the centre and between the ends.
        let between = |a: &T, b: &T| a.clone().min(b.clone()) <= zero && zero <= a.clone().max(b.clone());
        if cross == zero && between(&ax, &bx) && between(&ay, &by) {
            return (true, ArcDifference::OnBoundary);
        }
        sum += match (quadrant(q) - quadrant(p)).rem_euclid(4) {
            0 => 0,
            1 => 1,
            3 => -1,
            _ => {
                if cross > zero {
                    2
                } else {
                    -2
                }
            }
        };
    }
    let winding = sum / 4;
    (winding != 0, ArcDifference::Winding(winding))
}

/// Keeps every fragment of every pixel, for the back-to-front comparison.
#[derive(Debug, Clone)]
struct Fragment {
    index: usize,
    depth: Depth,
}

/// One cell where drawing order with opacity gave another value than the
/// correct back-to-front blend (the seeds' "local errors").
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LocalError {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The value the z-buffer gave in drawing order.
    pub drawn: u32,
    /// The value of blending every fragment back to front.
    pub correct: u32,
    /// The polygons covering the cell, back to front.
    pub back_to_front: Vec<usize>,
}

/// Compares the z-buffer's result with the correct back-to-front blend of all
/// fragments at each pixel (ties: the earlier polygon counts as nearer, as the
/// z-buffer keeps the first of equal depths).
pub fn local_errors(scene: &Scene, drawn: &Buffers) -> Vec<LocalError> {
    let width = scene.width as usize;
    let mut fragments: Vec<Vec<Fragment>> = vec![Vec::new(); width * scene.height as usize];
    let mut scratch = Scratch::default();
    for (index, polygon) in scene.polygons.iter().enumerate() {
        if fate(scene, index) != Fate::Drawn {
            continue;
        }
        let mut sink = CollectSink { index, width, fragments: &mut fragments, scene };
        rasterize(
            polygon.geometry(),
            scene.rules,
            PixelRect::raster(scene.width, scene.height),
            &mut scratch,
            &mut sink,
        );
    }
    let mut errors = Vec::new();
    for (cell, list) in fragments.iter_mut().enumerate() {
        let (x, y) = ((cell % width) as u32, (cell / width) as u32);
        // Back to front: farthest first by the depth test; among equal depths the later polygon first.
        list.sort_by(|a, b| {
            let nearer = a.depth.cmp_depth(&b.depth);
            let farther_first = if scene.depth_test.larger_is_nearer() { nearer } else { nearer.reverse() };
            farther_first.then(b.index.cmp(&a.index))
        });
        let mut value = scene.background;
        for fragment in list.iter() {
            let polygon = &scene.polygons[fragment.index];
            value = match polygon.opacity {
                Some(alpha) => crate::simulate::stages::blend(polygon.value, value, alpha),
                None => polygon.value,
            };
        }
        if value != drawn.frame(x, y) {
            errors.push(LocalError {
                x,
                y,
                drawn: drawn.frame(x, y),
                correct: value,
                back_to_front: list.iter().map(|f| f.index).collect(),
            });
        }
    }
    errors
}

struct CollectSink<'a> {
    index: usize,
    width: usize,
    fragments: &'a mut Vec<Vec<Fragment>>,
    scene: &'a Scene,
}

impl RasterSink for CollectSink<'_> {
    const OBSERVES_SCANLINES: bool = false;

    fn scanline(&mut self, _row: u32, _crossings: &[Crossing], _spans: &[Span]) {}

    fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
        let scene = self.scene;
        let depth = match scene.effects.perspective {
            Some(p) if p.store_w => p.eye_depth(&depth),
            _ => depth,
        };
        // Fragments the depth range or the cross-section discard never show.
        let outside = scene.depth_range.is_some_and(|range| !depth.within(range));
        if outside || scene.effects.section.is_some_and(|z| !scene.depth_test.keeps_section(&depth, z)) {
            return;
        }
        self.fragments[y as usize * self.width + x as usize].push(Fragment { index: self.index, depth });
    }
}
