//! The one rasterizer: polygons in scene order, each scan-converted by
//! half-interval scanlines, its covered centres depth-tested and stored,
//! with only the stages the scene asks for.

use std::cmp::Ordering;
use std::hint::select_unpredictable;

use crate::geometry::plane::Geometry;
use crate::numbers::Word;
use crate::observe::trace::{Fate, Observer, Outcome, PixelEvent, PolygonEvent, ScanlineEvent, Unobserved};
use crate::raster::depth::{Depth, DepthPlane, DepthStepper, DepthTest, Stored};
use crate::raster::scan::{self, Crossing, RowCrossing, Span};
use crate::rules::Rules;
use crate::scene::{Polygon, Scene, Winding};
use crate::simulate::buffer::{Buffers, FrameCell, LevelCells};
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

/// Reusable space for the edges, crossings and spans of one polygon, so the
/// rasterizer allocates nothing per row.
#[derive(Debug, Clone, Default)]
pub struct Scratch {
    narrow: Walk<i64>,
    wide: Walk<i128>,
    crossings: Vec<Crossing>,
    spans: Vec<Span>,
}

/// The edge table and one row's crossings, in one machine word.
#[derive(Debug, Clone, Default)]
struct Walk<W> {
    edges: scan::EdgeTable<W>,
    row: Vec<RowCrossing<W>>,
}

/// Receives what [`rasterize`] finds.
pub trait RasterSink {
    /// Whether [`RasterSink::scanline`] does anything; when not, the rasterizer
    /// does not build the crossings and spans it would be given.
    const OBSERVES_SCANLINES: bool = true;

    /// A row's crossings (sorted) and spans.
    fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]);
    /// A covered pixel centre and the exact depth of the polygon's plane there.
    fn pixel(&mut self, x: u32, y: u32, depth: Depth);

    /// The covered centres `first ..= last` of `row`, left to right, with the
    /// depth stepped from the first; by default one [`RasterSink::pixel`] each.
    #[inline]
    fn span<W: Word>(&mut self, row: u32, first: u32, last: u32, mut stepper: DepthStepper<W>) {
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
///
/// It runs on 64-bit integers when the polygon's values fit them
/// ([`Geometry::fits_i64`]) and on 128-bit integers otherwise; the same code
/// either way ([`Word`]), with the same results.
pub fn rasterize<S: RasterSink>(
    geometry: &Geometry,
    rules: Rules,
    rect: PixelRect,
    scratch: &mut Scratch,
    sink: &mut S,
) {
    let Scratch { narrow, wide, crossings, spans } = scratch;
    if let Some(polygon) = geometry.big() {
        polygon.rasterize(rules, rect, (crossings, spans), sink);
    } else if geometry.fits_i64() {
        rasterize_in(geometry, rules, rect, narrow, (crossings, spans), sink);
    } else {
        rasterize_in(geometry, rules, rect, wide, (crossings, spans), sink);
    }
}

fn rasterize_in<W: Word, S: RasterSink>(
    geometry: &Geometry,
    rules: Rules,
    rect: PixelRect,
    walk: &mut Walk<W>,
    events: (&mut Vec<Crossing>, &mut Vec<Span>),
    sink: &mut S,
) {
    let Some(rows) = walk.edges.prepare(&geometry.points, geometry.denominator, rect.rows, (rules.rows, rules.columns))
    else {
        return;
    };
    let plane = DepthPlane::<W>::new(geometry);
    let (first_row, last_row) = (*rows.start(), *rows.end());
    let mut row_numerator = plane.row_numerator(W::narrow(scan::scanline_y(first_row, geometry.denominator)));
    let row_step = plane.row_step();
    // Rows in bands over which the same edges cross them.
    let mut row = first_row;
    while row <= last_row {
        let band_last = walk.edges.activate(row).min(last_row);
        match walk.edges.pair() {
            // Two edges and nobody to tell the crossings: walk them here, one span per row.
            Some([one, other]) if !S::OBSERVES_SCANLINES => {
                for row in row..=band_last {
                    let (a, b) = (one.crossing(rules.columns), other.crossing(rules.columns));
                    one.advance();
                    other.advance();
                    // In order unless the two edges cross between vertices.
                    let (left, right) = if a.cmp_position(&b) == Ordering::Greater { (b, a) } else { (a, b) };
                    span(sink, &plane, rect.columns, row, (&left, &right), row_numerator);
                    row_numerator += row_step;
                }
            }
            _ => {
                for row in row..=band_last {
                    walk.edges.crossings(row, rules.columns, &mut walk.row);
                    let found = &walk.row;
                    let pairs = scan::pairs(found.len(), rules.rows);
                    if S::OBSERVES_SCANLINES {
                        let (crossings, spans) = (&mut *events.0, &mut *events.1);
                        crossings.clear();
                        crossings.extend(found.iter().map(|c| c.crossing(geometry.scale())));
                        spans.clear();
                        spans.extend(pairs.clone().map(|(i, j)| Span {
                            left: crossings[i].clone(),
                            right: crossings[j].clone(),
                            columns: scan::clip_columns(found[i].first_column, found[j].last_column, rect.columns),
                        }));
                        sink.scanline(row, crossings, spans);
                    }
                    for (i, j) in pairs {
                        span(sink, &plane, rect.columns, row, (&found[i], &found[j]), row_numerator);
                    }
                    row_numerator += row_step;
                }
            }
        }
        row = band_last + 1;
    }
}

/// A span between two crossings: its columns within `limit`, and the depth
/// at the first of them.
#[inline]
fn span<W: Word, S: RasterSink>(
    sink: &mut S,
    plane: &DepthPlane<W>,
    limit: (u32, u32),
    row: u32,
    (left, right): (&RowCrossing<W>, &RowCrossing<W>),
    row_numerator: W,
) {
    if let Some((first, last)) = scan::clip_columns(left.first_column, right.last_column, limit) {
        sink.span(row, first, last, plane.start_at(row_numerator, first));
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
        rasterize(&polygon.geometry, scene.rules, rect, &mut self.scratch, &mut sink);
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
        rasterize(&polygon.geometry, self.scene.rules, rect, self.scratch, &mut sink);
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
                    prefetch(&scene.polygons[ahead as usize].geometry);
                }
                if let Some(&ahead) = bin.get(k + 2) {
                    prefetch(scene.polygons[ahead as usize].geometry.points.as_ptr());
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
        let Some(rect) = pixel_bounds(&scene.polygons[index].geometry, scene.width, scene.height) else { continue };
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
        prefetch(ahead.geometry.points.as_ptr());
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
    let geometry = &polygon.geometry;
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

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::numbers::Q;
    use crate::rules::{ColumnRule, RowRule};

    /// Everything a sink is told, in order.
    #[derive(Default)]
    struct Collect(Vec<String>);

    impl RasterSink for Collect {
        fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]) {
            // Values: crossings at the same x may come in either order, over different denominators.
            let x = |c: &Crossing| c.x();
            let crossings: Vec<crate::numbers::Exact> = crossings.iter().map(x).collect();
            let spans: Vec<_> = spans.iter().map(|s| (x(&s.left), x(&s.right), s.columns)).collect();
            self.0.push(format!("row {row}: {crossings:?} {spans:?}"));
        }

        fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
            // The value: the tiers may keep a depth over different denominators.
            self.0.push(format!("({x}, {y}) {:?}", depth.value()));
        }
    }

    /// The events of the big-integer tier for the same polygon: with its
    /// crossings and depths in 128 bits, or (`huge`) in big integers.
    fn run_big(geometry: &Geometry, rules: Rules, rect: PixelRect, huge: bool) -> Vec<String> {
        let mut sink = Collect::default();
        let big = if huge { geometry.on_huge_tier() } else { geometry.on_big_tier() };
        rasterize(&big, rules, rect, &mut Scratch::default(), &mut sink);
        sink.0
    }

    fn run<W: Word>(geometry: &Geometry, rules: Rules, rect: PixelRect) -> Vec<String> {
        let (mut walk, mut crossings, mut spans, mut sink) =
            (Walk::<W>::default(), Vec::new(), Vec::new(), Collect::default());
        rasterize_in(geometry, rules, rect, &mut walk, (&mut crossings, &mut spans), &mut sink);
        sink.0
    }

    /// A steep triangle as large as the 64-bit bound allows: it runs on `i64`
    /// without overflow (the test profile checks) and draws as on `i128`;
    /// one pixel larger no longer fits.
    #[test]
    fn the_largest_steep_polygon_that_fits_64_bits_draws_as_on_128() {
        let triangle = |size: i128| {
            let q = |v: i128| Q::from_integer(v);
            let rise = 1 << 30;
            Geometry::new(&[[q(0), q(0), q(7)], [q(size), q(1), q(7 + rise)], [q(2), q(size), q(7 - rise)]]).unwrap()
        };
        // The largest size that fits, by bisection.
        let (mut fits, mut fails) = (16i128, 1i128 << 32);
        assert!(triangle(fits).fits_i64() && !triangle(fails).fits_i64());
        while fails - fits > 1 {
            let middle = (fits + fails) / 2;
            if triangle(middle).fits_i64() { fits = middle } else { fails = middle }
        }
        let rect = PixelRect { columns: (0, 15), rows: (0, 15) };
        for rules in
            [Rules::default(), Rules { rows: RowRule::Closed, columns: ColumnRule::CellHolds, ..Rules::default() }]
        {
            let drawn = run::<i64>(&triangle(fits), rules, rect);
            assert!(drawn.iter().filter(|line| line.starts_with('(')).count() > 20, "{drawn:?}");
            assert_eq!(drawn, run::<i128>(&triangle(fits), rules, rect));
        }
        assert!(!triangle(fits + 1).fits_i64());
    }

    proptest! {
        /// The 64-bit and the 128-bit words, and the big-integer tier with its
        /// reports in 128 bits and in big integers, give the same crossings,
        /// spans, pixels and depths, under every rule and in any clipping
        /// rectangle.
        #[test]
        fn both_words_rasterize_alike(
            vertices in prop::collection::vec((-40i64..80, -40i64..80, 1i64..5), 3..7),
            plane in (-9i64..10, -9i64..10, -60i64..60, 1i64..8),
            row_rule in 0usize..3,
            column_rule in 0usize..3,
            rect in (0u32..20, 0u32..20, 0u32..20, 0u32..20),
        ) {
            // A planar polygon: z = (a·x + b·y + c) / e, vertices over denominators 1 … 4,
            // depths of both signs and with every remainder.
            let (a, b, c, e) = plane;
            let q = |n: i64, d: i64| Q::new(n.into(), d.into());
            let vertices: Vec<[Q; 3]> = vertices
                .iter()
                .map(|&(x, y, d)| {
                    let (x, y) = (q(x, d), q(y, d));
                    [x, y, (x * q(a, 1) + y * q(b, 1) + q(c, 1)) / q(e, 1)]
                })
                .collect();
            let Ok(geometry) = Geometry::new(&vertices) else { return Ok(()) };
            prop_assume!(geometry.c() != 0 && geometry.fits_i64());
            let rules = Rules {
                rows: [RowRule::HalfOpen, RowRule::Closed, RowRule::TopLeft][row_rule],
                columns: [ColumnRule::CentreInside, ColumnRule::CellHolds, ColumnRule::HalfOpen][column_rule],
                ..Rules::default()
            };
            let rect = PixelRect {
                columns: (rect.0.min(rect.1), rect.0.max(rect.1) + 10),
                rows: (rect.2.min(rect.3), rect.2.max(rect.3) + 10),
            };
            let words = run::<i128>(&geometry, rules, rect);
            prop_assert_eq!(&run::<i64>(&geometry, rules, rect), &words);
            prop_assert_eq!(&run_big(&geometry, rules, rect, false), &words);
            prop_assert_eq!(&run_big(&geometry, rules, rect, true), &words);
        }
    }

    /// The pixels a polygon covers under `rules`, as (x, y).
    fn covered(vertices: &[[i64; 2]], rules: Rules, size: u32) -> Vec<(u32, u32)> {
        let q = |v: i64| Q::new(v.into(), 2);
        let points: Vec<[Q; 3]> = vertices.iter().map(|p| [q(p[0]), q(p[1]), Q::from_integer(5)]).collect();
        let geometry = Geometry::new(&points).unwrap();
        let drawn = run::<i128>(&geometry, rules, PixelRect { columns: (0, size - 1), rows: (0, size - 1) });
        let mut cells: Vec<(u32, u32)> = drawn
            .iter()
            .filter_map(|line| {
                let (x, rest) = line.strip_prefix('(')?.split_once(", ")?;
                Some((x.parse().ok()?, rest.split_once(')')?.0.parse().ok()?))
            })
            .collect();
        cells.sort_unstable();
        cells
    }

    /// The Direct3D 11 rule itself, written independently with edge
    /// functions: a centre is covered when strictly inside every edge, or on
    /// an edge that is a top or left edge (and strictly inside the others).
    /// "Top" is as displayed, and zsim displays row 0 at the bottom, so a top
    /// edge is the horizontal edge with the largest y. Vertices in half units.
    fn direct3d(vertices: &[[i64; 2]], size: u32) -> Vec<(u32, u32)> {
        let n = vertices.len();
        let area: i64 =
            (0..n).map(|i| vertices[i][0] * vertices[(i + 1) % n][1] - vertices[(i + 1) % n][0] * vertices[i][1]).sum();
        let mut cells = Vec::new();
        for y in 0..size {
            for x in 0..size {
                let (px, py) = (2 * i64::from(x) + 1, 2 * i64::from(y) + 1);
                let inside = (0..n).all(|i| {
                    let ([ax, ay], [bx, by]) = (vertices[i], vertices[(i + 1) % n]);
                    // Positive inside, for either winding.
                    let e = ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) * area.signum();
                    // Interior on the edge's left when walking counter-clockwise: a left edge
                    // runs downwards (as displayed, y up: by < ay), a top edge runs right to left.
                    let (dx, dy) = ((bx - ax) * area.signum(), (by - ay) * area.signum());
                    let top = dy == 0 && dx < 0;
                    let left = dy < 0;
                    e > 0 || (e == 0 && (top || left))
                });
                if inside {
                    cells.push((x, y));
                }
            }
        }
        cells.sort_unstable();
        cells
    }

    fn gpu() -> Rules {
        Rules::preset(crate::rules::Preset::Gpu)
    }

    /// Each case of the top-left rule, with a centre exactly on the edge or
    /// vertex named (vertices in half units: 2·x, so odd numbers are centres).
    #[test]
    fn top_left_rule_matches_direct3d_on_every_kind_of_edge() {
        let cases: [(&str, &[[i64; 2]]); 8] = [
            ("a centre on a left (slanted) edge is covered", &[[3, 1], [13, 1], [13, 11]]),
            ("a centre on a right (slanted) edge is not", &[[1, 1], [11, 1], [1, 11]]),
            ("a centre on a top (horizontal, largest y) edge is covered", &[[1, 1], [9, 9], [1, 9]]),
            ("a centre on a bottom (horizontal, smallest y) edge is not", &[[1, 1], [9, 1], [1, 9]]),
            ("a centre at a top vertex is not (left and right edges meet)", &[[0, 2], [10, 2], [5, 9]]),
            ("a centre at a bottom vertex is not", &[[5, 1], [10, 8], [0, 8]]),
            ("a centre at a left vertex is covered (two left edges)", &[[1, 5], [10, 0], [10, 10]]),
            ("a centre at a right vertex is not (two right edges)", &[[0, 0], [9, 5], [0, 10]]),
        ];
        for (case, vertices) in cases {
            let expected = direct3d(vertices, 8);
            assert!(!expected.is_empty(), "{case}: the case covers something");
            assert_eq!(covered(vertices, gpu(), 8), expected, "{case}");
            let reversed: Vec<[i64; 2]> = vertices.iter().rev().copied().collect();
            assert_eq!(covered(&reversed, gpu(), 8), expected, "{case}, vertices in the other order");
        }
    }

    /// Two triangles sharing an edge through centres: the book's rule draws
    /// the shared centres twice, the top-left rule once, and together they
    /// cover the square exactly.
    #[test]
    fn shared_edges_are_drawn_once_under_the_top_left_rule() {
        let (lower, upper): (&[[i64; 2]], &[[i64; 2]]) = (&[[1, 1], [13, 1], [13, 13]], &[[1, 1], [13, 13], [1, 13]]);
        let (a, b) = (covered(lower, gpu(), 8), covered(upper, gpu(), 8));
        assert!(a.iter().all(|cell| !b.contains(cell)), "no centre drawn twice");
        let mut both: Vec<(u32, u32)> = a.iter().chain(&b).copied().collect();
        both.sort_unstable();
        assert_eq!(both, direct3d(&[[1, 1], [13, 1], [13, 13], [1, 13]], 8));
        let (a, b) = (covered(lower, Rules::default(), 8), covered(upper, Rules::default(), 8));
        let twice: Vec<&(u32, u32)> = a.iter().filter(|cell| b.contains(cell)).collect();
        assert_eq!(
            twice,
            vec![&(0, 0), &(1, 1), &(2, 2), &(3, 3), &(4, 4), &(5, 5)],
            "the book draws the diagonal twice"
        );
    }
}
