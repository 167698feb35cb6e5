//! The one rasterizer: polygons in scene order, each scan-converted by
//! half-interval scanlines, its covered centres depth-tested and stored,
//! with only the stages the scene asks for.

use crate::geometry::plane::Geometry;
use crate::raster::convert::{Scratch, rasterize};
use crate::raster::depth::{Depth, DepthTest};
use crate::raster::scan::{Crossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::scene::{Polygon, Scene, Winding};
use crate::simulate::buffer::Buffers;
use crate::simulate::events::{Fate, Observer, Outcome, PixelEvent, PolygonEvent, ScanlineEvent, Unobserved};
use crate::simulate::levels::{InOrder, Levels, OnePolygon};
use crate::simulate::stages::{PixelStages, Plain, StageSet, WithEffects};
use crate::simulate::tiles::{Tiles, Tiling, bins};

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
            buffers: Buffers::new(
                scene.width,
                scene.height,
                scene.frame_bits,
                scene.background,
                scene.clear_depth.clone(),
            ),
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
        prefetch_ahead(self.scene, index);
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
        if !(O::OBSERVES_POLYGONS || O::OBSERVES_SCANLINES || O::OBSERVES_PIXELS)
            && let Some(levels) = self.plain_levels()
        {
            // Nobody watches and the plain loop runs: one loop over the polygons.
            self.draw_plain(levels, None);
            return;
        }
        while self.draw_next(observer).is_some() {}
    }

    /// The depth test and the largest level when the plain loop runs on a
    /// quantized z-buffer (no per-pixel effect, no stages forced on).
    fn plain_levels(&self) -> Option<(DepthTest, u32)> {
        let scene = self.scene;
        if scene.has_pixel_effects() || self.stage_set != StageSet::AsAsked || !self.buffers.holds_levels() {
            return None;
        }
        Plain::new(scene).plain_levels()
    }

    /// Draws every remaining polygon with the plain loop, unobserved: in
    /// scene order, or binned into tiles as `tiling` says.
    /// Returns how many threads drew.
    fn draw_plain(&mut self, (test, depth_max): (DepthTest, u32), tiling: Option<Tiling<'_>>) -> usize {
        let scene = self.scene;
        let first = self.next;
        self.next = scene.polygons.len();
        self.stats.polygons += scene.polygons.len() - first;
        match tiling {
            None => {
                let (stats, scratch) = (&mut self.stats, &mut self.scratch);
                let levels = Levels { scene, test, depth_max, stats, scratch };
                self.buffers.with_level_cells(InOrder { levels, first });
                1
            }
            Some(tiling) => {
                let bins = bins(scene, first, tiling.tile);
                let tiles = Tiles { scene, test, depth_max, bins, tiling };
                let (stats, threads) =
                    self.buffers.with_level_cells(tiles).expect("plain levels imply a level z-buffer");
                self.stats.tested += stats.tested;
                self.stats.written += stats.written;
                threads
            }
        }
    }

    /// Draws every remaining polygon tile by tile (`tile`×`tile` pixels), so
    /// that the cells being written stay in the processor's cache: polygons
    /// are binned by the tiles their bounding boxes touch, and each tile draws
    /// its polygons in scene order, so every pixel sees the same sequence of
    /// depth tests as [`Simulation::finish`] and the result is identical
    /// whatever the tile size. Used for unobserved runs of the plain loop; any
    /// other scene is drawn by [`Simulation::finish`]. One thread; see
    /// [`Simulation::finish_parallel`] for more.
    pub fn finish_tiled(&mut self, tile: u32) {
        self.finish_parallel(tile, 1, &|| {});
    }

    /// Like [`Simulation::finish_tiled`], on `threads` threads: each band of
    /// one tile row (`tile` rows of the raster, a contiguous part of both
    /// buffers) is one job of rayon's work-stealing pool, drawn tile by tile
    /// as one thread draws it, so the result is identical for every thread
    /// count and tile size. `band_done` is called after each band (for a
    /// progress bar; there are `height.div_ceil(tile)` of them).
    ///
    /// Returns how many threads drew: `threads` (at least 1) when the plain
    /// loop ran, 1 when the scene needed the general loop ([`Simulation::finish`]).
    pub fn finish_parallel(&mut self, tile: u32, threads: usize, band_done: &(dyn Fn() + Sync)) -> usize {
        match self.plain_levels() {
            Some(levels) if tile > 0 => {
                self.draw_plain(levels, Some(Tiling { tile, threads: threads.max(1), band_done }))
            }
            _ => {
                self.finish(&mut Unobserved);
                1
            }
        }
    }

    fn draw<S: PixelStages, O: Observer>(&mut self, index: usize, stages: &S, observer: &mut O) {
        let scene = self.scene;
        let polygon = &scene.polygons[index];
        let rect = PixelRect::raster(scene.width, scene.height);
        if let Some((test, depth_max)) = stages.plain_levels()
            && self.buffers.holds_levels()
        {
            let (stats, scratch) = (&mut self.stats, &mut self.scratch);
            let levels = Levels { scene, test, depth_max, stats, scratch };
            self.buffers.with_level_cells(OnePolygon { levels, index, observer });
            return;
        }
        let mut sink =
            DrawSink { index, polygon, stages, buffers: &mut self.buffers, stats: &mut self.stats, observer };
        rasterize(polygon.geometry(), scene.rules, rect, &mut self.scratch, &mut sink);
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
    const OBSERVES_SCANLINES: bool = O::OBSERVES_SCANLINES;

    fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]) {
        let (index, polygon) = (self.index, self.polygon);
        self.observer.scanline(&ScanlineEvent { index, polygon, row, crossings, spans });
    }

    #[inline]
    fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
        let stored_before = self.buffers.depth(x, y);
        let frame_before = self.buffers.frame(x, y);
        let decision = self.stages.decide(self.polygon, depth.clone(), stored_before.clone(), frame_before);
        self.stats.tested += 1;
        if decision.outcome == Outcome::Written {
            self.stats.written += 1;
            self.buffers.store(x, y, decision.frame, decision.stored.clone());
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
pub(super) fn pixel_bounds(geometry: &Geometry, width: u32, height: u32) -> Option<PixelRect> {
    let [x0, x1, y0, y1] = geometry.cells();
    // Widen by one cell each way for safety.
    let clamp = |v: i128, max: u32| v.clamp(0, i128::from(max) - 1) as u32;
    let (c0, c1, r0, r1) = (x0 - 1, x1 + 1, y0 - 1, y1 + 1);
    if c1 < 0 || r1 < 0 || c0 >= i128::from(width) || r0 >= i128::from(height) {
        return None;
    }
    Some(PixelRect { columns: (clamp(c0, width), clamp(c1, width)), rows: (clamp(r0, height), clamp(r1, height)) })
}

/// Each polygon's vertices live in their own allocation: asks for those of
/// the polygon a few steps after `index` in scene order, so that they are in
/// cache when it is drawn.
#[inline]
pub(super) fn prefetch_ahead(scene: &Scene, index: usize) {
    if let Some(ahead) = scene.polygons.get(index + 4) {
        prefetch(ahead.geometry().points.as_ptr());
    }
}

/// Asks the processor to bring the memory at `data` into its cache (a hint;
/// nothing on processors without one).
#[inline]
pub(super) fn prefetch<T>(data: *const T) {
    // SAFETY: a prefetch is only a hint: it reads nothing the program sees and
    // cannot fault, whatever the address; SSE is part of every x86-64 processor.
    #[cfg(target_arch = "x86_64")]
    unsafe {
        std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(data.cast());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = data;
}

/// Whether polygon `index` is drawn, and if not, why.
pub fn fate(scene: &Scene, index: usize) -> Fate {
    let polygon = &scene.polygons[index];
    match polygon.clip {
        crate::scene::perspective::Clip::Away => return Fate::ClippedAway,
        crate::scene::perspective::Clip::ViewAway => return Fate::OutsideView,
        _ => {}
    }
    let geometry = polygon.geometry();
    if geometry.is_degenerate() {
        return Fate::Degenerate;
    }
    if geometry.c() == 0 {
        return Fate::EdgeOn;
    }
    // The winding matters only when culling is on (and its sign comes as it comes).
    match scene.effects.cull {
        Some(cull) if Winding::of(geometry.c()) == Some(cull) => Fate::Culled(cull),
        _ => Fate::Drawn,
    }
}
