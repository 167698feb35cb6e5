//! The plain loop on a quantized z-buffer: the depth test and the store of
//! the book's algorithm on the cells themselves, with nothing between them,
//! polygon by polygon in scene order.

use crate::numbers::Word;
use crate::raster::convert::{Scratch, rasterize};
use crate::raster::depth::{BranchFreeTest, Depth, DepthStepper, DepthTest, Stored};
use crate::raster::scan::{Crossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::scene::{Polygon, Scene};
use crate::simulate::buffer::{FrameCell, LevelCells};
use crate::simulate::events::{Fate, Observer, ScanlineEvent, Unobserved};
use crate::simulate::fast::branch_free::{CellWrite, Stepped};
use crate::simulate::fast::lanes;
use crate::simulate::setup::{CORE_CACHE, Stats, fate, prefetch_ahead, prefetch_cells};
use crate::simulate::stages::{PixelStages, Plain, take_pixel};

/// How many polygons ahead the plain loop asks for the cells of.
const AHEAD: usize = 2;

/// What the plain loop on a quantized z-buffer needs besides the cells.
pub(in crate::simulate) struct Levels<'a, 's> {
    pub(in crate::simulate) scene: &'s Scene,
    pub(in crate::simulate) test: DepthTest,
    pub(in crate::simulate) depth_max: u32,
    pub(in crate::simulate) stats: &'a mut Stats,
    pub(in crate::simulate) scratch: &'a mut Scratch,
    /// Whether small triangles may be drawn by edge functions
    /// ([`LevelSink::small_triangle`]), which rewrite every cell of their
    /// box: only on cells that fit the core's cache, and not on a tile's
    /// copy, where the scan converter, visiting only covered centres, is the
    /// faster (the design note on tiles drawn in cache).
    pub(in crate::simulate) edge_functions: bool,
}

impl<'s> Levels<'_, 's> {
    /// Draws polygon `index` within `rect` on the cells, which hold the
    /// pixels from `origin` on.
    #[inline]
    pub(in crate::simulate) fn draw<F: FrameCell, O: Observer>(
        &mut self,
        (frame, depth): (&mut [F], &mut [u32]),
        origin: Origin,
        index: usize,
        rect: PixelRect,
        observer: &mut O,
    ) {
        let polygon = &self.scene.polygons[index];
        let edge_functions = self.edge_functions && std::mem::size_of_val(depth) <= CORE_CACHE;
        let mut sink = LevelSink {
            index,
            polygon,
            value: F::from_value(polygon.value),
            test: self.test,
            depth_max: self.depth_max,
            origin,
            frame,
            depth,
            stats: &mut *self.stats,
            observer,
            eight: None,
        };
        if !(edge_functions && sink.small_triangle(polygon.geometry(), self.scene.rules, rect)) {
            rasterize(polygon.geometry(), self.scene.rules, rect, self.scratch, &mut sink);
        }
    }
}

/// Where a slice of cells lies in the raster: the pixel its first cell
/// holds, and how many cells a row of it takes. The whole raster's cells
/// start at (0, 0) with a row of the raster's width; a band's at its first
/// row; a tile's copy at its first pixel, with a row of the tile's width.
#[derive(Debug, Clone, Copy)]
pub(in crate::simulate) struct Origin {
    pub(in crate::simulate) column: u32,
    pub(in crate::simulate) row: u32,
    pub(in crate::simulate) stride: usize,
}

impl Origin {
    /// The whole raster's cells.
    pub(in crate::simulate) fn raster(scene: &Scene) -> Origin {
        Origin { column: 0, row: 0, stride: scene.width as usize }
    }

    /// The index of pixel (`x`, `y`)'s cell.
    #[inline(always)]
    pub(in crate::simulate) fn cell(self, x: u32, y: u32) -> usize {
        (y - self.row) as usize * self.stride + (x - self.column) as usize
    }
}

/// One polygon on the whole raster.
pub(in crate::simulate) struct OnePolygon<'a, 's, O> {
    pub(in crate::simulate) levels: Levels<'a, 's>,
    pub(in crate::simulate) index: usize,
    pub(in crate::simulate) observer: &'a mut O,
}

impl<O: Observer> LevelCells for OnePolygon<'_, '_, O> {
    type Output = ();

    fn run<F: FrameCell>(mut self, frame: &mut [F], depth: &mut [u32]) {
        let rect = PixelRect::raster(self.levels.scene.width, self.levels.scene.height);
        let origin = Origin::raster(self.levels.scene);
        self.levels.draw((frame, depth), origin, self.index, rect, self.observer);
    }
}

/// The polygons of a range, in scene order, on the whole raster.
pub(in crate::simulate) struct InOrder<'a, 's> {
    pub(in crate::simulate) levels: Levels<'a, 's>,
    pub(in crate::simulate) polygons: std::ops::Range<usize>,
}

impl LevelCells for InOrder<'_, '_> {
    type Output = ();

    fn run<F: FrameCell>(mut self, frame: &mut [F], depth: &mut [u32]) {
        let scene = self.levels.scene;
        let (rect, origin) = (PixelRect::raster(scene.width, scene.height), Origin::raster(scene));
        // Cells worth asking for ahead only when the buffers outgrow the cache.
        let far = std::mem::size_of_val(depth) > CORE_CACHE;
        for index in self.polygons.clone() {
            prefetch_ahead(scene, index);
            if far && index + AHEAD < self.polygons.end {
                prefetch_cells(scene, index + AHEAD, (&*frame, &*depth));
            }
            if fate(scene, index) == Fate::Drawn {
                self.levels.draw((&mut *frame, &mut *depth), origin, index, rect, &mut Unobserved);
            }
        }
    }
}

/// The plain stages on a quantized z-buffer, working on the cells directly:
/// a covered centre decided by the reference ([`Plain::decide`]), a span by
/// the branch-free cell or the lanes where nobody watches its pixels.
pub(super) struct LevelSink<'a, O, F> {
    pub(super) index: usize,
    pub(super) polygon: &'a Polygon,
    /// The polygon's value in a framebuffer cell.
    pub(super) value: F,
    pub(super) test: DepthTest,
    pub(super) depth_max: u32,
    /// Where the cells lie in the raster.
    pub(super) origin: Origin,
    pub(super) frame: &'a mut [F],
    pub(super) depth: &'a mut [u32],
    pub(super) stats: &'a mut Stats,
    pub(super) observer: &'a mut O,
    /// The polygon's step in 32-bit lanes for its short spans, made at its
    /// first span ([`lanes::EightLanes`]; the inner `None`: its values do not fit them).
    pub(super) eight: Option<Option<lanes::EightLanes>>,
}

impl<O: Observer, F: FrameCell> LevelSink<'_, O, F> {
    /// The span in 64-bit integers when nobody watches the pixels and every
    /// value of the span fits: the same decisions as [`LevelSink::pixel`].
    /// Returns `false` (having done nothing) when it does not apply.
    #[inline]
    pub(super) fn span_fast<W: Word>(&mut self, row: u32, first: u32, last: u32, stepper: &DepthStepper<W>) -> bool {
        const LIMIT: i128 = 1 << 61;
        if O::OBSERVES_PIXELS {
            return false;
        }
        let state = stepper.state();
        let (whole, remainder, denominator, step_whole, step_remainder) =
            (state.whole, state.remainder, state.denominator, state.step_whole, state.step_remainder);
        let (Some(whole), Some(remainder), Some(denominator), Some(step_whole), Some(step_remainder)) =
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
        let cell = self.origin.cell(first, row);
        let length = (last - first) as usize + 1;
        let (start, step) = (Stepped { whole, remainder }, Stepped { whole: step_whole, remainder: step_remainder });
        // The book's test compiled with its constants, as a small triangle's.
        let written = if self.test == DepthTest::Greater {
            self.span_cells::<true>((cell, length), start, denominator, step)
        } else {
            self.span_cells::<false>((cell, length), start, denominator, step)
        };
        self.stats.tested += u64::from(last - first) + 1;
        self.stats.written += written;
        true
    }

    /// A span's `length` cells from cell `cell`, each rewritten with its old
    /// or its new value, from the depth at the first as whole part and
    /// remainder with its denominator and step; `GREATER` as
    /// `LevelSink::box_rows` takes it. The lanes may rewrite cells after the
    /// span with their own values ([`lanes::span`]). Returns how many were
    /// written.
    #[inline(always)]
    fn span_cells<const GREATER: bool>(
        &mut self,
        (cell, length): (usize, usize),
        depth: Stepped,
        denominator: i64,
        step: Stepped,
    ) -> u64 {
        let write = self.cell_write::<GREATER>();
        // Only AVX2 reads the eight lanes' data: elsewhere it is not made.
        let eight = match cfg!(target_arch = "x86_64") {
            true => self.eight.get_or_insert_with(|| lanes::EightLanes::new(step, denominator, write)).as_ref(),
            false => None,
        };
        let cells = (&mut self.depth[cell..], &mut self.frame[cell..]);
        lanes::span::<F, GREATER>(cells, length, (depth, step, denominator), eight, write)
    }

    /// What the branch-free loops write: `GREATER`, the book's test with its
    /// constants known to the compiler; else the scene's test read as the loop runs.
    #[inline(always)]
    pub(super) fn cell_write<const GREATER: bool>(&self) -> CellWrite<F> {
        CellWrite { test: BranchFreeTest::of(self.test), max: i64::from(self.depth_max), value: self.value }
            .compiled::<GREATER>()
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
        let cell = self.origin.cell(x, y);
        let before = (Stored::Level(self.depth[cell]), self.frame[cell].value());
        let (plain, polygon, value) = (Plain::quantized(self.test, self.depth_max), self.polygon, self.value);
        let (depth_cells, frame_cells) = (&mut *self.depth, &mut *self.frame);
        take_pixel(
            (self.index, (x, y)),
            depth,
            before,
            |depth, stored, frame| plain.decide(polygon, depth, stored, frame),
            |decision| {
                debug_assert!(matches!(decision.stored, Stored::Level(_)), "a quantized store keeps levels");
                if let Stored::Level(level) = decision.stored {
                    depth_cells[cell] = level;
                }
                frame_cells[cell] = value;
            },
            self.stats,
            self.observer,
        );
    }
}
