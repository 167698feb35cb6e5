//! What the scan converter hands on: the sink trait its callers implement,
//! and the rectangle of pixels it is asked to cover. It sits below the scan
//! converter and the big-integer tier that call it, and below the driver and
//! the observers that implement it.

use crate::numbers::Word;
use crate::raster::depth::{Depth, DepthStepper};
use crate::raster::scan::{Crossing, Span};

/// Receives what the scan converter (`rasterize`) finds.
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

/// The pixel centres a polygon covers, `(x, y)` in the order the scan
/// converter hands them on (row by row, left to right): for the observers
/// that ask only which centres one rasterizer covers.
#[derive(Debug, Default)]
pub struct CoveredCentres(pub Vec<(u32, u32)>);

impl RasterSink for CoveredCentres {
    const OBSERVES_SCANLINES: bool = false;

    fn scanline(&mut self, _: u32, _: &[Crossing], _: &[Span]) {}

    fn pixel(&mut self, x: u32, y: u32, _: Depth) {
        self.0.push((x, y));
    }

    /// The span's centres, without stepping a depth nobody reads.
    fn span<W: Word>(&mut self, row: u32, first: u32, last: u32, _: DepthStepper<W>) {
        self.0.extend((first..=last).map(|x| (x, row)));
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
