//! What the rasterizer does, as events handed to an [`Observer`]. Events are
//! data only; the recorders of the observe layer (`step`, `explain`, `check`)
//! build their reports from them. A run with [`Unobserved`] pays nothing:
//! every method is an empty default that the compiler removes.

use crate::raster::depth::{Depth, Stored};
use crate::raster::scan::{Crossing, Span};
use crate::scene::{Polygon, Winding};

/// Receives the rasterizer's events. Every method defaults to doing nothing.
pub trait Observer {
    /// Whether this observer looks at pixel events at all; the rasterizer
    /// skips building them (and may take a faster inner loop) when not.
    const OBSERVES_PIXELS: bool = true;
    /// Whether this observer looks at scanline events; the rasterizer skips
    /// building their crossings and spans when not.
    const OBSERVES_SCANLINES: bool = true;
    /// Whether this observer looks at polygon events; a run that looks at
    /// none of the three draws its polygons in one loop without them.
    const OBSERVES_POLYGONS: bool = true;

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

impl Observer for Unobserved {
    const OBSERVES_PIXELS: bool = false;
    const OBSERVES_SCANLINES: bool = false;
    const OBSERVES_POLYGONS: bool = false;
}

/// What happens to a polygon as a whole.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fate {
    /// It is scan-converted.
    Drawn,
    /// Back-face culling skips it: its vertices run this way.
    Culled(Winding),
    /// Its signed area is below the rules' bound (tinyrenderer skips back
    /// faces and slivers so).
    SmallArea,
    /// Newell's `c = 0` with a non-zero normal: seen edge-on, it covers no pixel.
    EdgeOn,
    /// Newell's normal is zero (collinear vertices, or loops that cancel): no plane, no pixel.
    Degenerate,
    /// With perspective, every vertex lies behind the near plane: nothing is drawn.
    ClippedAway,
    /// Given in clip space, nothing of it lies inside the view volume.
    OutsideView,
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
    /// The depth lies outside the scene's depth range: discarded before the test.
    OutsideDepthRange,
}

/// One covered pixel centre and what the depth test made of it.
#[derive(Debug, Clone)]
pub struct PixelEvent {
    /// 0-based polygon index.
    pub index: usize,
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The exact depth of the polygon's plane at the centre (with perspective, the projected z').
    pub depth: Depth,
    /// The depth that was tested and stored: `depth`, or with a w-buffer the eye-space depth.
    pub compared: Depth,
    /// The z-buffer before.
    pub stored_before: Stored,
    /// The framebuffer before.
    pub frame_before: u32,
    /// What happened.
    pub outcome: Outcome,
    /// The z-buffer after.
    pub stored_after: Stored,
    /// The framebuffer after.
    pub frame_after: u32,
}
