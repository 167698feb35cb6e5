//! What the rasterizer does, as events handed to an [`Observer`]. Events are
//! data only; `step`, `explain` and `check` build their reports from them.
//! A run with [`Unobserved`] pays nothing: every method is an empty default
//! that the compiler removes.

use crate::depth::Depth;
use crate::scan::{Crossing, Span};
use crate::scene::{Polygon, Winding};

/// Receives the rasterizer's events. Every method defaults to doing nothing.
pub trait Observer {
    /// A polygon is about to be drawn (or skipped, see [`Fate`]).
    fn polygon(&mut self, _event: &PolygonEvent<'_>) {}
    /// A scanline of the current polygon has its crossings and spans; sent
    /// only for rows that lie inside the raster and the polygon's y range.
    fn scanline(&mut self, _event: &ScanlineEvent<'_>) {}
    /// A covered pixel centre was tested.
    fn pixel(&mut self, _event: &PixelEvent) {}
}

/// The observer of a run nobody watches.
#[derive(Debug, Clone, Copy, Default)]
pub struct Unobserved;

impl Observer for Unobserved {}

/// What happens to a polygon as a whole.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fate {
    /// It is scan-converted.
    Drawn,
    /// Back-face culling skips it: its vertices run this way.
    Culled(Winding),
    /// Newell's `c = 0` with a non-zero normal: seen edge-on, it covers no pixel.
    EdgeOn,
    /// Newell's normal is zero (collinear vertices, or loops that cancel): no plane, no pixel.
    Degenerate,
}

/// A polygon starts.
#[derive(Debug, Clone, Copy)]
pub struct PolygonEvent<'a> {
    /// 0-based index in the scene.
    pub index: usize,
    /// The polygon.
    pub polygon: &'a Polygon,
    /// Whether it is drawn.
    pub fate: Fate,
}

/// One scanline of a polygon.
#[derive(Debug, Clone, Copy)]
pub struct ScanlineEvent<'a> {
    /// 0-based polygon index.
    pub index: usize,
    /// The polygon.
    pub polygon: &'a Polygon,
    /// The pixel row; the scanline is at `y = row + 1/2`.
    pub row: u32,
    /// The edge crossings, sorted left to right.
    pub crossings: &'a [Crossing],
    /// The crossings paired into spans, with the columns each covers.
    pub spans: &'a [Span],
}

/// The outcome of one covered pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// The depth test passed: both buffers were written.
    Written,
    /// The depth test failed: nothing changed.
    Hidden,
    /// The depth test passed but the depth lies in front of the cross-section.
    BeyondSection,
}

/// One covered pixel centre and what the depth test made of it.
#[derive(Debug, Clone, Copy)]
pub struct PixelEvent {
    /// 0-based polygon index.
    pub index: usize,
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The exact depth at the centre.
    pub depth: Depth,
    /// The z-buffer before.
    pub stored_before: u32,
    /// The framebuffer before.
    pub frame_before: u32,
    /// What happened.
    pub outcome: Outcome,
    /// The z-buffer after.
    pub stored_after: u32,
    /// The framebuffer after.
    pub frame_after: u32,
}
