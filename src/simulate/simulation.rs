//! The one rasterizer: polygons in scene order, each scan-converted by
//! half-interval scanlines, its covered centres depth-tested and stored,
//! with only the stages the scene asks for.

use crate::raster::convert::{Scratch, rasterize};
use crate::raster::depth::{Depth, DepthTest, Stored};
use crate::raster::scan::{Crossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::scene::{Polygon, Scene};
use crate::simulate::buffer::Buffers;
use crate::simulate::events::{Fate, Observer, PolygonEvent, ScanlineEvent, Unobserved};
use crate::simulate::fast::levels::{InOrder, Levels, OnePolygon};
use crate::simulate::fast::tiles::{Cleared, TileStart, Tiles, Tiling, bins, pool};
use crate::simulate::setup::{Stats, fate, prefetch_ahead};
use crate::simulate::stages::{PixelStages, Plain, StageSet, WithEffects, take_pixel};

/// One polygon drawn, with its own counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Drawn {
    /// 0-based polygon index.
    pub index: usize,
    /// Covered pixel centres whose depth it tested.
    pub tested: u64,
    /// Pixels it wrote.
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
    /// The threads that clear large buffers and draw in tiles, started with
    /// the buffers when more than one is asked for ([`Simulation::new_on`]),
    /// as a GPU driver starts its threads with its context: each clear and
    /// draw then finds them waiting.
    pool: Option<std::sync::Arc<rayon::ThreadPool>>,
}

impl<'s> Simulation<'s> {
    /// Cleared buffers: the background value, and the depth test's farthest depth.
    pub fn new(scene: &'s Scene) -> Simulation<'s> {
        Simulation::with_stages(scene, StageSet::AsAsked)
    }

    /// Like [`Simulation::new`], large buffers cleared on `threads` threads
    /// (here and by [`Simulation::restart`]): the same cells; with more than
    /// one, the threads that draw in tiles are started now and kept.
    pub fn new_on(scene: &'s Scene, threads: usize) -> Simulation<'s> {
        Simulation::made(scene, StageSet::AsAsked, threads)
    }

    /// Like [`Simulation::new`], choosing the per-pixel stages.
    pub fn with_stages(scene: &'s Scene, stage_set: StageSet) -> Simulation<'s> {
        Simulation::made(scene, stage_set, 1)
    }

    fn made(scene: &'s Scene, stage_set: StageSet, threads: usize) -> Simulation<'s> {
        let pool = pool(threads).map(std::sync::Arc::new);
        let (width, height, clear_depth) = (scene.width, scene.height, scene.clear_depth.clone());
        let buffers = Buffers::new_on(width, height, scene.frame_bits, scene.background, clear_depth, pool.as_deref());
        Simulation { scene, buffers, next: 0, stats: Stats::default(), scratch: Scratch::default(), stage_set, pool }
    }

    /// The tile side `threads` threads draw the scene in when none is asked
    /// for; 0 draws polygon by polygon on one thread (what one thread does
    /// while the buffers take at most a quarter of a last-level cache).
    /// Tiles of 256, a band of them one job, keep a large raster's rows in
    /// cache while paying a tile's setup rarely (the measurements behind the
    /// choice are in the design notes under `docs/design/`).
    pub fn default_tile(&self, threads: usize) -> u32 {
        const TILE: u32 = 256;
        let large = self.buffers.memory_bytes() > crate::simulate::setup::LAST_LEVEL_CACHE as u64 / 4;
        if threads > 1 || large { TILE } else { 0 }
    }

    /// Back to the start: cleared buffers (in the memory they already hold,
    /// as a GPU clears its framebuffer before drawing a frame again) and no
    /// polygon drawn.
    pub fn restart(&mut self) {
        let scene = self.scene;
        self.buffers.clear(scene.frame_bits, scene.background, &scene.clear_depth, self.pool.as_deref());
        self.next = 0;
        self.stats = Stats::default();
    }

    /// [`Simulation::restart`], then [`Simulation::finish_parallel`]: the
    /// same cells, but with the plain loop in tiles each tile is cleared as
    /// it is drawn, in the core's cache, instead of both buffers being
    /// cleared whole first (as llvmpipe clears its framebuffer tile by tile
    /// when a frame is drawn). Returns how many threads drew.
    pub fn redraw(&mut self, tile: u32, threads: usize, band_done: &(dyn Fn() + Sync)) -> usize {
        let scene = self.scene;
        match (self.plain_levels(), &scene.clear_depth) {
            (Some(levels), Stored::Level(_)) if tile > 0 => {
                self.next = 0;
                self.stats = Stats::default();
                let tiling = Tiling { tile, threads: threads.max(1), band_done };
                self.draw_plain(levels, Some(tiling), scene.polygons.len(), Clearing::Tiles)
            }
            _ => {
                self.restart();
                self.finish_parallel(tile, threads, band_done)
            }
        }
    }

    /// Has the system hand over the buffers' memory now ([`Buffers::take_pages`]):
    /// the cells stay as they are.
    pub fn take_pages(&mut self) {
        self.buffers.take_pages();
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

    /// Draws the next polygon as [`Simulation::draw_next`] does, and says
    /// what it alone tested and wrote.
    pub fn draw_next_counted<O: Observer>(&mut self, observer: &mut O) -> Option<Drawn> {
        let before = self.stats;
        let index = self.draw_next(observer)?;
        Some(Drawn { index, tested: self.stats.tested - before.tested, written: self.stats.written - before.written })
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
            self.draw_plain(levels, None, self.scene.polygons.len(), Clearing::Done);
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

    /// Draws the remaining polygons before `end` with the plain loop,
    /// unobserved: in scene order, or binned into tiles as `tiling` says,
    /// on the buffers as they are or (`Clearing::Tiles`, in tiles only)
    /// clearing each tile first. Returns how many threads drew.
    fn draw_plain(
        &mut self,
        (test, depth_max): (DepthTest, u32),
        tiling: Option<Tiling<'_>>,
        end: usize,
        clearing: Clearing,
    ) -> usize {
        let scene = self.scene;
        let first = self.next;
        let end = end.clamp(first, scene.polygons.len());
        self.next = end;
        self.stats.polygons += end - first;
        match tiling {
            None => {
                let (stats, scratch) = (&mut self.stats, &mut self.scratch);
                let levels = Levels { scene, test, depth_max, stats, scratch, edge_functions: true };
                self.buffers.with_level_cells(InOrder { levels, polygons: first..end });
                1
            }
            Some(tiling) => {
                // The threads started with the buffers, or as many as asked for now.
                let started;
                let pool = match &self.pool {
                    Some(kept) if kept.current_num_threads() == tiling.threads => Some(&**kept),
                    _ => {
                        started = pool(tiling.threads);
                        started.as_ref()
                    }
                };
                let bins = bins(scene, first..end, tiling.tile, pool);
                // Before the first polygon every cell holds the clear values (only drawing,
                // which moves `next` on, writes the buffers).
                let start = match (&scene.clear_depth, clearing) {
                    (&Stored::Level(depth), Clearing::Tiles) => {
                        TileStart::Clearing(Cleared { frame: scene.background, depth })
                    }
                    (&Stored::Level(depth), Clearing::Done) if first == 0 => {
                        TileStart::Cleared(Cleared { frame: scene.background, depth })
                    }
                    _ => TileStart::Buffers,
                };
                let tiles = Tiles { scene, test, depth_max, bins, tiling, pool, start };
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
        self.draw_parallel_before(self.scene.polygons.len(), tile, threads, band_done)
    }

    /// Like [`Simulation::finish_parallel`], for the remaining polygons up
    /// to and including polygon `last` only (the state `--after` and
    /// `--final` print is drawn this way, the last polygon then alone for
    /// its counts); `tile` 0 draws polygon by polygon on this thread with the
    /// plain loop. The result is identical to [`Simulation::draw_through`].
    pub fn draw_parallel_through(
        &mut self,
        last: usize,
        tile: u32,
        threads: usize,
        band_done: &(dyn Fn() + Sync),
    ) -> usize {
        self.draw_parallel_before(last.saturating_add(1), tile, threads, band_done)
    }

    fn draw_parallel_before(&mut self, end: usize, tile: u32, threads: usize, band_done: &(dyn Fn() + Sync)) -> usize {
        match self.plain_levels() {
            Some(levels) if tile > 0 => {
                let tiling = Tiling { tile, threads: threads.max(1), band_done };
                self.draw_plain(levels, Some(tiling), end, Clearing::Done)
            }
            Some(levels) => self.draw_plain(levels, None, end, Clearing::Done),
            None => {
                if end > 0 {
                    self.draw_through(end - 1, &mut Unobserved);
                }
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
            let levels = Levels { scene, test, depth_max, stats, scratch, edge_functions: true };
            self.buffers.with_level_cells(OnePolygon { levels, index, observer });
            return;
        }
        let mut sink =
            DrawSink { index, polygon, stages, buffers: &mut self.buffers, stats: &mut self.stats, observer };
        rasterize(polygon.geometry(), scene.rules, rect, &mut self.scratch, &mut sink);
    }
}

/// Whether the plain loop finds the buffers as the last step left them, or
/// clears each tile before drawing it ([`Simulation::redraw`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Clearing {
    Done,
    Tiles,
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
        let before = (self.buffers.depth(x, y), self.buffers.frame(x, y));
        let (stages, polygon, buffers) = (self.stages, self.polygon, &mut *self.buffers);
        take_pixel(
            (self.index, (x, y)),
            depth,
            before,
            |depth, stored, frame| stages.decide(polygon, depth, stored, frame),
            |decision| buffers.store(x, y, decision.frame, decision.stored.clone()),
            self.stats,
            self.observer,
        );
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;
    use crate::scene::random::RandomScene;

    /// `zsim speed` redraws in tiles without clearing the buffers first:
    /// each tile is cleared as it is drawn, the tiles no polygon touches
    /// too. Over buffers scribbled on everywhere, a redraw gives what a fresh
    /// simulation gives, on one thread and on two, with the book's test
    /// (clear to 0) and with `less` (clear to the farthest level), and
    /// polygon by polygon (tile 0, which clears first).
    #[test]
    fn a_redraw_clears_each_tile_as_it_draws_it() {
        let spec =
            RandomScene { count: 30, seed: 5, width: 300, height: 200, max_size: 40, frame_bits: 8, depth_bits: 16 };
        for test in ["greater", "less"] {
            let json = spec.json().replacen('{', &format!("{{\"depth_test\": \"{test}\", \"background\": 3, "), 1);
            let scene = Scene::from_json(&json, Path::new("redraw.json")).expect("a valid scene");
            let mut fresh = Simulation::new(&scene);
            fresh.finish(&mut Unobserved);
            let mut reused = Simulation::new(&scene);
            for (tile, threads) in [(16, 1), (16, 2), (64, 1), (0, 1)] {
                for (x, y) in (0..scene.width).flat_map(|x| (0..scene.height).map(move |y| (x, y))) {
                    reused.buffers.store(x, y, 1, Stored::Level(7));
                }
                let drew = reused.redraw(tile, threads, &|| {});
                assert_eq!(reused.buffers(), fresh.buffers(), "{test}, tile {tile}, {threads} threads");
                assert_eq!(reused.stats(), fresh.stats(), "{test}, tile {tile}, {threads} threads");
                assert_eq!(drew, if tile == 0 { 1 } else { threads }, "{test}, tile {tile}: threads");
            }
        }
    }
}
