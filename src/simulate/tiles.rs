//! Tiles and threads for unobserved runs of the plain loop: polygons binned
//! by the tiles their bounding boxes touch, each band of tiles one job of
//! rayon's pool, every pixel seeing the same depth tests in the same order.

use crate::raster::convert::Scratch;
use crate::raster::depth::DepthTest;
use crate::raster::sink::PixelRect;
use crate::scene::Scene;
use crate::simulate::buffer::{FrameCell, LevelCells};
use crate::simulate::events::{Fate, Unobserved};
use crate::simulate::levels::Levels;
use crate::simulate::setup::{CORE_CACHE, Stats, fate, pixel_bounds, prefetch, prefetch_cells};

/// How a tiled run is spread.
#[derive(Clone, Copy)]
pub(super) struct Tiling<'a> {
    /// The side of a tile, in pixels.
    pub(super) tile: u32,
    /// How many threads draw (1: bands one after the other on this thread).
    pub(super) threads: usize,
    /// Called after each band.
    pub(super) band_done: &'a (dyn Fn() + Sync),
}

/// Binned polygons, drawn tile by tile, a band of tile rows a job.
pub(super) struct Tiles<'a> {
    pub(super) scene: &'a Scene,
    pub(super) test: DepthTest,
    pub(super) depth_max: u32,
    pub(super) bins: Vec<Vec<u32>>,
    pub(super) tiling: Tiling<'a>,
}

impl Tiles<'_> {
    /// Draws band `ty` (raster rows `ty·tile …`) on its own cells, which start
    /// at that band's first row; returns its counts.
    pub(super) fn band<F: FrameCell>(&self, ty: u32, frame: &mut [F], depth: &mut [u32]) -> Stats {
        let scene = self.scene;
        let tile = self.tiling.tile;
        let tiles_x = scene.width.div_ceil(tile);
        let (mut stats, mut scratch) = (Stats::default(), Scratch::default());
        let mut levels =
            Levels { scene, test: self.test, depth_max: self.depth_max, stats: &mut stats, scratch: &mut scratch };
        let first_row = ty * tile;
        // A band's cells are worth asking for ahead when its rows outgrow the cache.
        let far = std::mem::size_of_val(depth) > CORE_CACHE;
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
                    prefetch(scene.polygons[ahead as usize].geometry());
                }
                if let Some(&ahead) = bin.get(k + 2) {
                    prefetch(scene.polygons[ahead as usize].geometry().points.as_ptr());
                    if far {
                        prefetch_cells(scene, ahead as usize, (&*frame, &*depth), first_row);
                    }
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

/// The drawn polygons from `first` on, binned by the `tile`×`tile` tiles
/// their bounding boxes touch, each bin in scene order.
pub(super) fn bins(scene: &Scene, polygons: std::ops::Range<usize>, tile: u32) -> Vec<Vec<u32>> {
    let tiles_x = scene.width.div_ceil(tile);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); tiles_x as usize * scene.height.div_ceil(tile) as usize];
    for index in polygons {
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
