//! Tiles and threads for unobserved runs of the plain loop: polygons binned
//! by the tiles their bounding boxes touch, each band of tiles one job of
//! rayon's pool, every pixel seeing the same depth tests in the same order.

use crate::raster::convert::Scratch;
use crate::raster::depth::DepthTest;
use crate::raster::sink::PixelRect;
use crate::scene::Scene;
use crate::simulate::buffer::{FrameCell, LevelCells};
use crate::simulate::events::{Fate, Unobserved};
use crate::simulate::fast::levels::{Levels, Origin};
use crate::simulate::fast::wide::{stream_copy, streamed};
use crate::simulate::setup::{Stats, fate, pixel_bounds, prefetch, prefetch_polygon};

/// How a tiled run is spread.
#[derive(Clone, Copy)]
pub(in crate::simulate) struct Tiling<'a> {
    /// The side of a tile, in pixels.
    pub(in crate::simulate) tile: u32,
    /// How many threads draw (1: bands one after the other on this thread).
    pub(in crate::simulate) threads: usize,
    /// Called after each band.
    pub(in crate::simulate) band_done: &'a (dyn Fn() + Sync),
}

/// Binned polygons, drawn tile by tile, a band of tile rows a job.
pub(in crate::simulate) struct Tiles<'a> {
    pub(in crate::simulate) scene: &'a Scene,
    pub(in crate::simulate) test: DepthTest,
    pub(in crate::simulate) depth_max: u32,
    pub(in crate::simulate) bins: Vec<Vec<u32>>,
    pub(in crate::simulate) tiling: Tiling<'a>,
    /// The threads that draw the bands, when more than one does.
    pub(in crate::simulate) pool: Option<&'a rayon::ThreadPool>,
    /// What each tile's copy starts from.
    pub(in crate::simulate) start: TileStart,
}

/// What a tile's copy starts from, and whether the tiles without polygons
/// are written.
#[derive(Debug, Clone, Copy)]
pub(in crate::simulate) enum TileStart {
    /// The buffers' cells, copied in (polygons were drawn before); tiles
    /// without polygons are left as they are.
    Buffers,
    /// The clear values, which every cell holds before the first polygon;
    /// tiles without polygons are left as they are, so that fresh buffers'
    /// memory is first touched when a tile is copied back
    /// ([`crate::simulate::buffer::Buffers::new`] leaves zeros unwritten).
    Cleared(Cleared),
    /// The clear values, whatever the buffers hold; tiles without polygons
    /// are set to them too ([`crate::simulate::simulation::Simulation::redraw`]:
    /// the buffers are then not cleared beforehand).
    Clearing(Cleared),
}

/// The values of a cleared framebuffer cell and z-buffer cell.
#[derive(Debug, Clone, Copy)]
pub(in crate::simulate) struct Cleared {
    pub(in crate::simulate) frame: u32,
    pub(in crate::simulate) depth: u32,
}

impl Tiles<'_> {
    /// Draws band `ty` (raster rows `ty·tile …`) on its own cells, which start
    /// at that band's first row; returns its counts. Each tile with polygons
    /// is drawn on a copy of its cells, row after row in one piece of memory
    /// that stays in the core's cache, then copied back: in the raster's
    /// own layout a tile's rows lie a raster row apart, and a triangle's
    /// first touch of each of them waits for memory.
    pub(in crate::simulate) fn band<F: FrameCell>(
        &self,
        ty: u32,
        (frame, depth): (&mut [F], &mut [u32]),
        copy_cells: &mut TileCopy<F>,
    ) -> Stats {
        let scene = self.scene;
        let tile = self.tiling.tile;
        let tiles_x = scene.width.div_ceil(tile);
        let (mut stats, mut scratch) = (Stats::default(), Scratch::default());
        let (test, depth_max) = (self.test, self.depth_max);
        let mut levels =
            Levels { scene, test, depth_max, stats: &mut stats, scratch: &mut scratch, edge_functions: false };
        let band = Origin { column: 0, row: ty * tile, stride: scene.width as usize };
        let (tile_frame, tile_depth) = copy_cells.cells(tile);
        for tx in 0..tiles_x {
            let bin = &self.bins[(ty * tiles_x + tx) as usize];
            let rect = PixelRect {
                columns: (tx * tile, ((tx + 1) * tile).min(scene.width) - 1),
                rows: (band.row, ((ty + 1) * tile).min(scene.height) - 1),
            };
            let width = (rect.columns.1 - rect.columns.0 + 1) as usize;
            if bin.is_empty() {
                if let TileStart::Clearing(cleared) = self.start {
                    for row in rect.rows.0..=rect.rows.1 {
                        let from = band.cell(rect.columns.0, row);
                        frame[from..from + width].fill(F::from_value(cleared.frame));
                        depth[from..from + width].fill(cleared.depth);
                    }
                }
                continue;
            }
            let origin = Origin { column: rect.columns.0, row: rect.rows.0, stride: width };
            let copy = |row: u32| (band.cell(rect.columns.0, row), origin.cell(rect.columns.0, row));
            let cells = width * (rect.rows.1 - rect.rows.0 + 1) as usize;
            if let TileStart::Cleared(cleared) | TileStart::Clearing(cleared) = self.start {
                tile_frame[..cells].fill(F::from_value(cleared.frame));
                tile_depth[..cells].fill(cleared.depth);
            } else {
                for row in rect.rows.0..=rect.rows.1 {
                    let (from, to) = copy(row);
                    tile_frame[to..to + width].copy_from_slice(&frame[from..from + width]);
                    tile_depth[to..to + width].copy_from_slice(&depth[from..from + width]);
                }
            }
            for (k, &index) in bin.iter().enumerate() {
                // The polygons of a tile lie far apart in memory: ask for the
                // ones a few steps ahead while this one is drawn.
                if let Some(&ahead) = bin.get(k + 4) {
                    prefetch_polygon(&scene.polygons[ahead as usize]);
                }
                if let Some(&ahead) = bin.get(k + 2) {
                    prefetch(scene.polygons[ahead as usize].geometry().points.as_ptr());
                }
                let cells = (&mut tile_frame[..], &mut tile_depth[..]);
                levels.draw(cells, origin, index as usize, rect, &mut Unobserved);
            }
            for row in rect.rows.0..=rect.rows.1 {
                let (from, to) = copy(row);
                stream_copy(&mut frame[from..from + width], &tile_frame[to..to + width]);
                stream_copy(&mut depth[from..from + width], &tile_depth[to..to + width]);
            }
            streamed();
        }
        (self.tiling.band_done)();
        stats
    }
}

/// The cells a tile is drawn on, kept from tile to tile and band to band
/// on one thread.
pub(in crate::simulate) struct TileCopy<F> {
    frame: Vec<F>,
    depth: Vec<u32>,
}

impl<F: FrameCell> Default for TileCopy<F> {
    fn default() -> Self {
        TileCopy { frame: Vec::new(), depth: Vec::new() }
    }
}

impl<F: FrameCell> TileCopy<F> {
    /// Room for a `tile`×`tile` tile in both buffers.
    fn cells(&mut self, tile: u32) -> (&mut [F], &mut [u32]) {
        let cells = tile as usize * tile as usize;
        self.frame.resize(cells, F::default());
        self.depth.resize(cells, 0);
        (&mut self.frame, &mut self.depth)
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
        let Some(pool) = self.pool else {
            let mut copy_cells = TileCopy::default();
            return (
                bands.map(|(ty, cells)| self.band(ty as u32, cells, &mut copy_cells)).fold(Stats::default(), add),
                1,
            );
        };
        use rayon::prelude::*;
        let bands: Vec<_> = bands.collect();
        // One tile copy a thread, the thread's own and never waited for (one
        // a job, as rayon's `map_init` makes them, paid a fault a fresh page).
        let copies: Vec<std::sync::Mutex<TileCopy<F>>> =
            (0..pool.current_num_threads()).map(|_| std::sync::Mutex::new(TileCopy::default())).collect();
        let stats = pool.install(|| {
            bands
                .into_par_iter()
                .map(|(ty, cells)| {
                    let thread = rayon::current_thread_index().unwrap_or(0) % copies.len();
                    let mut copy = copies[thread].lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                    self.band(ty as u32, cells, &mut copy)
                })
                .reduce(Stats::default, add)
        });
        (stats, pool.current_num_threads())
    }
}

/// The threads that draw in tiles when `threads` asks for more than one;
/// `None` for one, or when the system would not start them (then one thread
/// bins and draws the same cells).
/// WebAssembly has no threads to start: there one thread draws, and the
/// parallel paths are not in the module.
pub(in crate::simulate) fn pool(threads: usize) -> Option<rayon::ThreadPool> {
    let threads = if cfg!(target_arch = "wasm32") { 1 } else { threads };
    (threads > 1).then(|| rayon::ThreadPoolBuilder::new().num_threads(threads).build().ok()).flatten()
}

/// The drawn polygons of a range, binned by the `tile`×`tile` tiles their
/// bounding boxes touch, each bin in scene order; with a pool, a part of the
/// range on each of its threads, the parts' bins then joined in order.
pub(in crate::simulate) fn bins(
    scene: &Scene,
    polygons: std::ops::Range<usize>,
    tile: u32,
    pool: Option<&rayon::ThreadPool>,
) -> Vec<Vec<u32>> {
    let Some(pool) = pool else { return bins_in_order(scene, polygons, tile) };
    use rayon::prelude::*;
    let part = polygons.len().div_ceil(pool.current_num_threads()).max(1);
    let parts: Vec<std::ops::Range<usize>> =
        polygons.clone().step_by(part).map(|start| start..(start + part).min(polygons.end)).collect();
    pool.install(|| {
        let binned: Vec<Vec<Vec<u32>>> = parts.into_par_iter().map(|part| bins_in_order(scene, part, tile)).collect();
        let tiles = scene.width.div_ceil(tile) as usize * scene.height.div_ceil(tile) as usize;
        (0..tiles).into_par_iter().map(|t| binned.iter().flat_map(|bins| bins[t].iter().copied()).collect()).collect()
    })
}

fn bins_in_order(scene: &Scene, polygons: std::ops::Range<usize>, tile: u32) -> Vec<Vec<u32>> {
    // How many polygons ahead to ask for: far enough for memory to answer
    // while the ones between are binned (the design note on the 2048² runs).
    const AHEAD: usize = 32;
    let tiles_x = scene.width.div_ceil(tile);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); tiles_x as usize * scene.height.div_ceil(tile) as usize];
    for index in polygons {
        // Binning reads a polygon's first 64 bytes, which may straddle two lines.
        if let Some(ahead) = scene.polygons.get(index + AHEAD) {
            let start = std::ptr::from_ref(ahead).cast::<u8>();
            prefetch(start);
            prefetch(start.wrapping_add(63));
        }
        if fate(scene, index) != Fate::Drawn {
            continue;
        }
        let Some(rect) = pixel_bounds(&scene.polygons[index], scene.width, scene.height) else { continue };
        for ty in rect.rows.0 / tile..=rect.rows.1 / tile {
            for tx in rect.columns.0 / tile..=rect.columns.1 / tile {
                bins[(ty * tiles_x + tx) as usize].push(index as u32);
            }
        }
    }
    bins
}
