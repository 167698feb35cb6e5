//! The one rasterizer: polygons in scene order, each scan-converted by
//! half-interval scanlines, its covered centres depth-tested and stored,
//! with only the stages the scene asks for.

use std::hint::select_unpredictable;

use crate::geometry::plane::Geometry;
use crate::numbers::Word;
use crate::raster::convert::{Scratch, rasterize};
use crate::raster::depth::{Depth, DepthStepper, DepthTest, Stored};
use crate::raster::scan::{Crossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::scene::{Polygon, Scene, Winding};
use crate::simulate::buffer::{Buffers, FrameCell, LevelCells};
use crate::simulate::events::{Fate, Observer, Outcome, PixelEvent, PolygonEvent, ScanlineEvent, Unobserved};
use crate::simulate::stages::{PixelStages, Plain, StageSet, WithEffects};

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

/// What the plain loop on a quantized z-buffer needs besides the cells.
struct Levels<'a, 's> {
    scene: &'s Scene,
    test: DepthTest,
    depth_max: u32,
    stats: &'a mut Stats,
    scratch: &'a mut Scratch,
}

impl<'s> Levels<'_, 's> {
    /// Draws polygon `index` within `rect` on the cells.
    #[inline]
    fn draw<F: FrameCell, O: Observer>(
        &mut self,
        (frame, depth): (&mut [F], &mut [u32]),
        first_row: u32,
        index: usize,
        rect: PixelRect,
        observer: &mut O,
    ) {
        let polygon = &self.scene.polygons[index];
        let mut sink = LevelSink {
            index,
            polygon,
            value: F::from_value(polygon.value),
            test: self.test,
            depth_max: self.depth_max,
            width: self.scene.width as usize,
            first_row,
            frame,
            depth,
            stats: &mut *self.stats,
            observer,
        };
        rasterize(polygon.geometry(), self.scene.rules, rect, self.scratch, &mut sink);
    }
}

/// One polygon on the whole raster.
struct OnePolygon<'a, 's, O> {
    levels: Levels<'a, 's>,
    index: usize,
    observer: &'a mut O,
}

impl<O: Observer> LevelCells for OnePolygon<'_, '_, O> {
    type Output = ();

    fn run<F: FrameCell>(mut self, frame: &mut [F], depth: &mut [u32]) {
        let rect = PixelRect::raster(self.levels.scene.width, self.levels.scene.height);
        self.levels.draw((frame, depth), 0, self.index, rect, self.observer);
    }
}

/// How a tiled run is spread.
#[derive(Clone, Copy)]
struct Tiling<'a> {
    /// The side of a tile, in pixels.
    tile: u32,
    /// How many threads draw (1: bands one after the other on this thread).
    threads: usize,
    /// Called after each band.
    band_done: &'a (dyn Fn() + Sync),
}

/// Binned polygons, drawn tile by tile, a band of tile rows a job.
struct Tiles<'a> {
    scene: &'a Scene,
    test: DepthTest,
    depth_max: u32,
    bins: Vec<Vec<u32>>,
    tiling: Tiling<'a>,
}

impl Tiles<'_> {
    /// Draws band `ty` (raster rows `ty·tile …`) on its own cells, which start
    /// at that band's first row; returns its counts.
    fn band<F: FrameCell>(&self, ty: u32, frame: &mut [F], depth: &mut [u32]) -> Stats {
        let scene = self.scene;
        let tile = self.tiling.tile;
        let tiles_x = scene.width.div_ceil(tile);
        let (mut stats, mut scratch) = (Stats::default(), Scratch::default());
        let mut levels =
            Levels { scene, test: self.test, depth_max: self.depth_max, stats: &mut stats, scratch: &mut scratch };
        let first_row = ty * tile;
        for tx in 0..tiles_x {
            let rect = PixelRect {
                columns: (tx * tile, ((tx + 1) * tile).min(scene.width) - 1),
                rows: (first_row, ((ty + 1) * tile).min(scene.height) - 1),
            };
            let bin = &self.bins[(ty * tiles_x + tx) as usize];
            for (k, &index) in bin.iter().enumerate() {
                // The polygons of a tile lie far apart in memory: ask for the
                // ones a few steps ahead while this one is drawn.
                if let Some(&ahead) = bin.get(k + 4) {
                    prefetch(&scene.polygons[ahead as usize].geometry());
                }
                if let Some(&ahead) = bin.get(k + 2) {
                    prefetch(scene.polygons[ahead as usize].geometry().points.as_ptr());
                }
                levels.draw((&mut *frame, &mut *depth), first_row, index as usize, rect, &mut Unobserved);
            }
        }
        (self.tiling.band_done)();
        stats
    }
}

impl LevelCells for Tiles<'_> {
    /// The counts, and how many threads drew.
    type Output = (Stats, usize);

    fn run<F: FrameCell>(self, frame: &mut [F], depth: &mut [u32]) -> (Stats, usize) {
        let band_cells = self.tiling.tile as usize * self.scene.width as usize;
        let bands = frame.chunks_mut(band_cells).zip(depth.chunks_mut(band_cells)).enumerate();
        let add =
            |a: Stats, b: Stats| Stats { polygons: 0, tested: a.tested + b.tested, written: a.written + b.written };
        let one_thread = |bands: std::iter::Enumerate<_>| {
            (bands.map(|(ty, (frame, depth))| self.band(ty as u32, frame, depth)).fold(Stats::default(), add), 1)
        };
        if self.tiling.threads == 1 {
            return one_thread(bands);
        }
        use rayon::prelude::*;
        let Ok(pool) = rayon::ThreadPoolBuilder::new().num_threads(self.tiling.threads).build() else {
            // The system would not start the threads: one thread draws the same cells.
            return one_thread(bands);
        };
        let bands: Vec<_> = bands.collect();
        let stats = pool.install(|| {
            bands
                .into_par_iter()
                .map(|(ty, (frame, depth))| self.band(ty as u32, frame, depth))
                .reduce(Stats::default, add)
        });
        (stats, self.tiling.threads)
    }
}

/// Every polygon from `first` on, in scene order, on the whole raster.
struct InOrder<'a, 's> {
    levels: Levels<'a, 's>,
    first: usize,
}

impl LevelCells for InOrder<'_, '_> {
    type Output = ();

    fn run<F: FrameCell>(mut self, frame: &mut [F], depth: &mut [u32]) {
        let scene = self.levels.scene;
        let rect = PixelRect::raster(scene.width, scene.height);
        for index in self.first..scene.polygons.len() {
            prefetch_ahead(scene, index);
            if fate(scene, index) == Fate::Drawn {
                self.levels.draw((&mut *frame, &mut *depth), 0, index, rect, &mut Unobserved);
            }
        }
    }
}

/// The drawn polygons from `first` on, binned by the `tile`×`tile` tiles
/// their bounding boxes touch, each bin in scene order.
fn bins(scene: &Scene, first: usize, tile: u32) -> Vec<Vec<u32>> {
    let tiles_x = scene.width.div_ceil(tile);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); tiles_x as usize * scene.height.div_ceil(tile) as usize];
    for index in first..scene.polygons.len() {
        if fate(scene, index) != Fate::Drawn {
            continue;
        }
        let Some(rect) = pixel_bounds(scene.polygons[index].geometry(), scene.width, scene.height) else { continue };
        for ty in rect.rows.0 / tile..=rect.rows.1 / tile {
            for tx in rect.columns.0 / tile..=rect.columns.1 / tile {
                bins[(ty * tiles_x + tx) as usize].push(index as u32);
            }
        }
    }
    bins
}

/// The plain stages on a quantized z-buffer, working on the cells directly:
/// the same decisions as [`Plain::decide`], without a match per access.
struct LevelSink<'a, O, F> {
    index: usize,
    polygon: &'a Polygon,
    /// The polygon's value in a framebuffer cell.
    value: F,
    test: DepthTest,
    depth_max: u32,
    width: usize,
    /// The raster row of the cells' first row (a band's cells start there).
    first_row: u32,
    frame: &'a mut [F],
    depth: &'a mut [u32],
    stats: &'a mut Stats,
    observer: &'a mut O,
}

impl<O: Observer, F: FrameCell> LevelSink<'_, O, F> {
    /// The span in 64-bit integers when nobody watches the pixels and every
    /// value of the span fits: the same decisions as [`LevelSink::pixel`].
    /// Returns `false` (having done nothing) when it does not apply.
    #[inline]
    fn span_fast<W: Word>(&mut self, row: u32, first: u32, last: u32, stepper: &DepthStepper<W>) -> bool {
        const LIMIT: i128 = 1 << 61;
        if O::OBSERVES_PIXELS {
            return false;
        }
        let (whole, remainder, denominator, step_whole, step_remainder) = stepper.parts();
        let (Some(mut whole), Some(mut remainder), Some(denominator), Some(step_whole), Some(step_remainder)) =
            (whole.to_i64(), remainder.to_i64(), denominator.to_i64(), step_whole.to_i64(), step_remainder.to_i64())
        else {
            return false;
        };
        // The whole parts along the span and twice a remainder must fit too:
        // proven for a polygon that runs on 64 bits (Geometry::fits_i64), checked otherwise.
        let length = i128::from(last - first) + 1;
        let reach = || i128::from(whole).abs() + length * (i128::from(step_whole).abs() + 1);
        if !W::NARROW && (i128::from(denominator) >= LIMIT || reach() >= LIMIT) {
            return false;
        }
        // z = whole + remainder/denominator with 0 ≤ remainder < denominator and an
        // integer stored s: z > s ⇔ ⌈z⌉ > s, z ≥ s ⇔ ⌊z⌋ ≥ s, z < s ⇔ ⌊z⌋ < s,
        // z ≤ s ⇔ ⌈z⌉ ≤ s. So each test is sign·(v − s) > threshold, with v the
        // floor or the ceiling, sign ±1 and threshold 0 (strict) or −1 (or equal).
        let use_ceiling = matches!(self.test, DepthTest::Greater | DepthTest::LessEqual);
        let sign: i64 = if self.test.larger_is_nearer() { 1 } else { -1 };
        let threshold = match self.test {
            // sign·(v − s) lies well inside ±2^62 (the checks above), so these decide alone.
            DepthTest::Always => i64::MIN,
            DepthTest::Never => i64::MAX,
            _ => -i64::from(self.test.equal_passes()),
        };
        let (max, value) = (i64::from(self.depth_max), self.value);
        let start = (row - self.first_row) as usize * self.width;
        let cells = start + first as usize..=start + last as usize;
        let (tested, mut written) = (u64::from(last - first) + 1, 0u64);
        // Branch-free: every cell is rewritten with its old or its new value.
        for (depth, frame) in self.depth[cells.clone()].iter_mut().zip(&mut self.frame[cells]) {
            let stored = i64::from(*depth);
            let v = whole + i64::from(use_ceiling & (remainder != 0));
            let passes = sign * (v - stored) > threshold;
            let rounded = (whole + i64::from(2 * remainder >= denominator)).clamp(0, max) as u32;
            *depth = select_unpredictable(passes, rounded, *depth);
            *frame = select_unpredictable(passes, value, *frame);
            written += u64::from(passes);
            whole += step_whole;
            remainder += step_remainder;
            let carry = remainder >= denominator;
            remainder -= select_unpredictable(carry, denominator, 0);
            whole += i64::from(carry);
        }
        self.stats.tested += tested;
        self.stats.written += written;
        true
    }
}

impl<O: Observer, F: FrameCell> RasterSink for LevelSink<'_, O, F> {
    const OBSERVES_SCANLINES: bool = O::OBSERVES_SCANLINES;

    #[inline]
    fn span<W: Word>(&mut self, row: u32, first: u32, last: u32, mut stepper: DepthStepper<W>) {
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
        let cell = (y - self.first_row) as usize * self.width + x as usize;
        let (stored_before, frame_before) = (self.depth[cell], self.frame[cell].value());
        self.stats.tested += 1;
        let written = self.test.passes(&depth, &Stored::Level(stored_before));
        let (stored_after, frame_after) = if written {
            self.stats.written += 1;
            let level = depth.quantized(self.depth_max);
            self.depth[cell] = level;
            self.frame[cell] = self.value;
            (level, self.polygon.value)
        } else {
            (stored_before, frame_before)
        };
        self.observer.pixel(&PixelEvent {
            index: self.index,
            x,
            y,
            compared: depth.clone(),
            depth,
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
fn pixel_bounds(geometry: &Geometry, width: u32, height: u32) -> Option<PixelRect> {
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
fn prefetch_ahead(scene: &Scene, index: usize) {
    if let Some(ahead) = scene.polygons.get(index + 4) {
        prefetch(ahead.geometry().points.as_ptr());
    }
}

/// Asks the processor to bring the memory at `data` into its cache (a hint;
/// nothing on processors without one).
#[inline]
fn prefetch<T>(data: *const T) {
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
