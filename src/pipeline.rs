//! The one rasterizer: polygons in scene order, each scan-converted by
//! half-interval scanlines, its covered centres depth-tested and stored,
//! with only the stages the scene asks for.

use crate::buffer::Buffers;
use crate::depth::{Depth, DepthPlane, DepthStepper, DepthTest, Stored};
use crate::plane::Geometry;
use crate::rules::Rules;
use crate::scan::{self, Crossing, Span};
use crate::scene::{Polygon, Scene, Winding};
use crate::stages::{PixelStages, Plain, StageSet, WithEffects};
use crate::trace::{Fate, Observer, Outcome, PixelEvent, PolygonEvent, ScanlineEvent, Unobserved};

/// Counts of a run so far.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Polygons processed (drawn or skipped).
    pub polygons: usize,
    /// Covered pixel centres whose depth was tested.
    pub tested: u64,
    /// Pixels written.
    pub written: u64,
}

/// Reusable space for the crossings and spans of one scanline, so the
/// rasterizer allocates nothing per row.
#[derive(Debug, Clone, Default)]
pub struct Scratch {
    edges: scan::EdgeTable,
    crossings: Vec<Crossing>,
    spans: Vec<Span>,
}

/// Receives what [`rasterize`] finds.
pub trait RasterSink {
    /// A row's crossings (sorted) and spans.
    fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]);
    /// A covered pixel centre and the exact depth of the polygon's plane there.
    fn pixel(&mut self, x: u32, y: u32, depth: Depth);

    /// The covered centres `first ..= last` of `row`, left to right, with the
    /// depth stepped from the first; by default one [`RasterSink::pixel`] each.
    #[inline]
    fn span(&mut self, row: u32, first: u32, last: u32, mut stepper: DepthStepper) {
        for x in first..=last {
            self.pixel(x, row, stepper.current());
            stepper.advance();
        }
    }
}

/// A rectangle of pixels, inclusive: the raster, or one segment of it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PixelRect {
    /// First and last column.
    pub columns: (u32, u32),
    /// First and last row.
    pub rows: (u32, u32),
}

impl PixelRect {
    /// The whole raster.
    pub fn raster(width: u32, height: u32) -> PixelRect {
        PixelRect { columns: (0, width - 1), rows: (0, height - 1) }
    }
}

/// Scan-converts one polygon with the scene's rules: for each row inside
/// `rect` and the polygon's y range, the sink gets the crossings and spans;
/// for each covered pixel centre, left to right, (x, y) and the exact depth
/// there. This is the one rasterizer; everything else (the depth test,
/// effects, stepping, explaining, supersampling) observes it.
pub fn rasterize(
    geometry: &Geometry,
    rules: Rules,
    rect: PixelRect,
    scratch: &mut Scratch,
    sink: &mut impl RasterSink,
) {
    let Some(rows) = scan::rows(&geometry.points, geometry.denominator, rect.rows, rules.rows) else {
        return;
    };
    scratch.edges.prepare(&geometry.points, geometry.denominator, &rows, rules.rows);
    let plane = DepthPlane::new(geometry);
    for row in rows {
        let scan_y = scan::scanline_y(row, geometry.denominator);
        scratch.edges.crossings(row, &mut scratch.crossings);
        scan::spans(
            &scratch.crossings,
            geometry.denominator,
            rect.columns,
            (rules.rows, rules.columns),
            &mut scratch.spans,
        );
        sink.scanline(row, &scratch.crossings, &scratch.spans);
        for span in &scratch.spans {
            let Some((first, last)) = span.columns else { continue };
            sink.span(row, first, last, plane.start(i128::from(first), scan_y));
        }
    }
}

/// A scene being drawn, one polygon at a time.
#[derive(Debug, Clone)]
pub struct Simulation<'s> {
    scene: &'s Scene,
    buffers: Buffers,
    next: usize,
    stats: Stats,
    scratch: Scratch,
    stage_set: StageSet,
}

impl<'s> Simulation<'s> {
    /// Cleared buffers: the background value, and the depth test's farthest depth.
    pub fn new(scene: &'s Scene) -> Simulation<'s> {
        Simulation::with_stages(scene, StageSet::AsAsked)
    }

    /// Like [`Simulation::new`], choosing the per-pixel stages.
    pub fn with_stages(scene: &'s Scene, stage_set: StageSet) -> Simulation<'s> {
        Simulation {
            scene,
            buffers: Buffers::new(scene.width, scene.height, scene.background, scene.clear_depth),
            next: 0,
            stats: Stats::default(),
            scratch: Scratch::default(),
            stage_set,
        }
    }

    /// The buffers as they are now.
    pub fn buffers(&self) -> &Buffers {
        &self.buffers
    }

    /// The buffers, giving up the simulation.
    pub fn into_buffers(self) -> Buffers {
        self.buffers
    }

    /// The counts so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// Draws the next polygon; returns its index, or `None` when all are done.
    pub fn draw_next<O: Observer>(&mut self, observer: &mut O) -> Option<usize> {
        let index = self.next;
        let polygon = self.scene.polygons.get(index)?;
        self.next += 1;
        self.stats.polygons += 1;
        let fate = fate(self.scene, index);
        observer.polygon(&PolygonEvent { index, polygon, fate });
        if fate == Fate::Drawn {
            let scene = self.scene;
            if self.stage_set == StageSet::AsAsked && !scene.has_pixel_effects() {
                self.draw(index, &Plain::new(scene), observer);
            } else {
                self.draw(index, &WithEffects::new(scene), observer);
            }
        }
        Some(index)
    }

    /// Draws the remaining polygons up to and including polygon `last`.
    pub fn draw_through<O: Observer>(&mut self, last: usize, observer: &mut O) {
        while self.next <= last && self.draw_next(observer).is_some() {}
    }

    /// Draws every remaining polygon.
    pub fn finish<O: Observer>(&mut self, observer: &mut O) {
        while self.draw_next(observer).is_some() {}
    }

    /// Draws every remaining polygon tile by tile (`tile`×`tile` pixels), so
    /// that the cells being written stay in the processor's cache: polygons
    /// are binned by the tiles their bounding boxes touch, and each tile draws
    /// its polygons in scene order, so every pixel sees the same sequence of
    /// depth tests as [`Simulation::finish`] and the result is identical
    /// whatever the tile size. Used for unobserved runs of the plain loop; any
    /// other scene is drawn by [`Simulation::finish`].
    pub fn finish_tiled(&mut self, tile: u32) {
        let scene = self.scene;
        let plain = Plain::new(scene);
        if tile == 0
            || scene.has_pixel_effects()
            || self.stage_set != StageSet::AsAsked
            || plain.plain_levels().is_none()
            || self.buffers.level_cells_mut().is_none()
        {
            self.finish(&mut Unobserved);
            return;
        }
        let (tiles_x, tiles_y) = (scene.width.div_ceil(tile), scene.height.div_ceil(tile));
        let mut bins: Vec<Vec<u32>> = vec![Vec::new(); tiles_x as usize * tiles_y as usize];
        for index in self.next..scene.polygons.len() {
            self.stats.polygons += 1;
            if fate(scene, index) != Fate::Drawn {
                continue;
            }
            let Some(rect) = pixel_bounds(&scene.polygons[index].geometry, scene.width, scene.height) else { continue };
            for ty in rect.rows.0 / tile..=rect.rows.1 / tile {
                for tx in rect.columns.0 / tile..=rect.columns.1 / tile {
                    bins[(ty * tiles_x + tx) as usize].push(index as u32);
                }
            }
        }
        self.next = scene.polygons.len();
        let (test, depth_max) = plain.plain_levels().expect("checked above");
        let width = scene.width as usize;
        let Simulation { buffers, stats, scratch, .. } = self;
        let (frame, depth) = buffers.level_cells_mut().expect("checked above");
        for ty in 0..tiles_y {
            for tx in 0..tiles_x {
                let rect = PixelRect {
                    columns: (tx * tile, ((tx + 1) * tile).min(scene.width) - 1),
                    rows: (ty * tile, ((ty + 1) * tile).min(scene.height) - 1),
                };
                for &index in &bins[(ty * tiles_x + tx) as usize] {
                    let polygon = &scene.polygons[index as usize];
                    let mut sink = LevelSink {
                        index: index as usize,
                        polygon,
                        test,
                        depth_max,
                        width,
                        frame: &mut *frame,
                        depth: &mut *depth,
                        stats: &mut *stats,
                        observer: &mut Unobserved,
                    };
                    rasterize(&polygon.geometry, scene.rules, rect, scratch, &mut sink);
                }
            }
        }
    }

    fn draw<S: PixelStages, O: Observer>(&mut self, index: usize, stages: &S, observer: &mut O) {
        let scene = self.scene;
        let polygon = &scene.polygons[index];
        let rect = PixelRect::raster(scene.width, scene.height);
        if let Some((test, depth_max)) = stages.plain_levels()
            && let Some((frame, depth)) = self.buffers.level_cells_mut()
        {
            let width = scene.width as usize;
            let mut sink =
                LevelSink { index, polygon, test, depth_max, width, frame, depth, stats: &mut self.stats, observer };
            rasterize(&polygon.geometry, scene.rules, rect, &mut self.scratch, &mut sink);
            return;
        }
        let mut sink =
            DrawSink { index, polygon, stages, buffers: &mut self.buffers, stats: &mut self.stats, observer };
        rasterize(&polygon.geometry, scene.rules, rect, &mut self.scratch, &mut sink);
    }
}

/// The plain stages on a quantized z-buffer, working on the cells directly:
/// the same decisions as [`Plain::decide`], without a match per access.
struct LevelSink<'a, O> {
    index: usize,
    polygon: &'a Polygon,
    test: DepthTest,
    depth_max: u32,
    width: usize,
    frame: &'a mut [u32],
    depth: &'a mut [u32],
    stats: &'a mut Stats,
    observer: &'a mut O,
}

impl<O: Observer> LevelSink<'_, O> {
    /// The span in 64-bit integers when nobody watches the pixels and every
    /// value of the span fits: the same decisions as [`LevelSink::pixel`].
    /// Returns `false` (having done nothing) when it does not apply.
    #[inline]
    fn span_fast(&mut self, row: u32, first: u32, last: u32, stepper: &DepthStepper) -> bool {
        const LIMIT: i128 = 1 << 61;
        let (whole, remainder, denominator, step_whole, step_remainder) = stepper.parts();
        let length = i128::from(last - first) + 1;
        if O::OBSERVES_PIXELS || denominator >= LIMIT || whole.abs() + length * (step_whole.abs() + 1) >= LIMIT {
            return false;
        }
        let (mut whole, mut remainder) = (whole as i64, remainder as i64);
        let (denominator, step_whole, step_remainder) = (denominator as i64, step_whole as i64, step_remainder as i64);
        let greater = self.test == DepthTest::Greater;
        let max = i64::from(self.depth_max);
        let start = row as usize * self.width;
        let (mut tested, mut written) = (0u64, 0u64);
        for cell in start + first as usize..=start + last as usize {
            let stored = i64::from(self.depth[cell]);
            // z = whole + remainder/denominator with 0 ≤ remainder < denominator.
            let passes = if greater { whole > stored || (whole == stored && remainder > 0) } else { whole < stored };
            tested += 1;
            if passes {
                written += 1;
                let rounded = whole + i64::from(2 * remainder >= denominator);
                self.depth[cell] = rounded.clamp(0, max) as u32;
                self.frame[cell] = self.polygon.value;
            }
            whole += step_whole;
            remainder += step_remainder;
            if remainder >= denominator {
                remainder -= denominator;
                whole += 1;
            }
        }
        self.stats.tested += tested;
        self.stats.written += written;
        true
    }
}

impl<O: Observer> RasterSink for LevelSink<'_, O> {
    #[inline]
    fn span(&mut self, row: u32, first: u32, last: u32, mut stepper: DepthStepper) {
        if self.span_fast(row, first, last, &stepper) {
            return;
        }
        for x in first..=last {
            self.pixel(x, row, stepper.current());
            stepper.advance();
        }
    }

    fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]) {
        let (index, polygon) = (self.index, self.polygon);
        self.observer.scanline(&ScanlineEvent { index, polygon, row, crossings, spans });
    }

    #[inline]
    fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
        let cell = y as usize * self.width + x as usize;
        let (stored_before, frame_before) = (self.depth[cell], self.frame[cell]);
        self.stats.tested += 1;
        let written = self.test.passes(depth, Stored::Level(stored_before));
        let (stored_after, frame_after) = if written {
            self.stats.written += 1;
            let level = depth.quantized(self.depth_max);
            self.depth[cell] = level;
            self.frame[cell] = self.polygon.value;
            (level, self.polygon.value)
        } else {
            (stored_before, frame_before)
        };
        self.observer.pixel(&PixelEvent {
            index: self.index,
            x,
            y,
            depth,
            compared: depth,
            stored_before: Stored::Level(stored_before),
            frame_before,
            outcome: if written { Outcome::Written } else { Outcome::Hidden },
            stored_after: Stored::Level(stored_after),
            frame_after,
        });
    }
}

/// Tests and stores each covered pixel of one polygon, and tells the observer.
struct DrawSink<'a, S, O> {
    index: usize,
    polygon: &'a Polygon,
    stages: &'a S,
    buffers: &'a mut Buffers,
    stats: &'a mut Stats,
    observer: &'a mut O,
}

impl<S: PixelStages, O: Observer> RasterSink for DrawSink<'_, S, O> {
    fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]) {
        let (index, polygon) = (self.index, self.polygon);
        self.observer.scanline(&ScanlineEvent { index, polygon, row, crossings, spans });
    }

    #[inline]
    fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
        let stored_before = self.buffers.depth(x, y);
        let frame_before = self.buffers.frame(x, y);
        let decision = self.stages.decide(self.polygon, depth, stored_before, frame_before);
        self.stats.tested += 1;
        if decision.outcome == Outcome::Written {
            self.stats.written += 1;
            self.buffers.store(x, y, decision.frame, decision.stored);
        }
        self.observer.pixel(&PixelEvent {
            index: self.index,
            x,
            y,
            depth,
            compared: decision.compared,
            stored_before,
            frame_before,
            outcome: decision.outcome,
            stored_after: decision.stored,
            frame_after: decision.frame,
        });
    }
}

/// The pixels a polygon's bounding box can cover (centres or cells), clipped
/// to the raster; `None` when it lies outside.
fn pixel_bounds(geometry: &Geometry, width: u32, height: u32) -> Option<PixelRect> {
    let scale = geometry.scale();
    let (mut x0, mut x1, mut y0, mut y1) = (i128::MAX, i128::MIN, i128::MAX, i128::MIN);
    for p in &geometry.points {
        (x0, x1, y0, y1) = (x0.min(p[0]), x1.max(p[0]), y0.min(p[1]), y1.max(p[1]));
    }
    // Cell ⌊x⌋ in pixel units is ⌊X / 2D⌋; widen by one cell each way for safety.
    let cell = |v: i128| crate::exact::floor_div(v, scale).0;
    let clamp = |v: i128, max: u32| v.clamp(0, i128::from(max) - 1) as u32;
    let (c0, c1, r0, r1) = (cell(x0) - 1, cell(x1) + 1, cell(y0) - 1, cell(y1) + 1);
    if c1 < 0 || r1 < 0 || c0 >= i128::from(width) || r0 >= i128::from(height) {
        return None;
    }
    Some(PixelRect { columns: (clamp(c0, width), clamp(c1, width)), rows: (clamp(r0, height), clamp(r1, height)) })
}

/// Whether polygon `index` is drawn, and if not, why.
pub fn fate(scene: &Scene, index: usize) -> Fate {
    let polygon = &scene.polygons[index];
    if polygon.clip == crate::perspective::Clip::Away {
        return Fate::ClippedAway;
    }
    let geometry = &polygon.geometry;
    if geometry.is_degenerate() {
        return Fate::Degenerate;
    }
    match Winding::of(geometry.c()) {
        None => Fate::EdgeOn,
        Some(winding) if scene.effects.cull == Some(winding) => Fate::Culled(winding),
        Some(_) => Fate::Drawn,
    }
}
