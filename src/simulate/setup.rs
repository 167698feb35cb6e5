//! What the driver and the plain loop both need before drawing a polygon:
//! whether it is drawn at all, the pixels its bounding box can cover, its data
//! asked into the cache ahead of time; and the counts of a run.

use crate::numbers::{Exact, Q};
use crate::raster::sink::PixelRect;
use crate::scene::{Polygon, Scene};
use crate::simulate::events::Fate;

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

/// The pixels a polygon's bounding box can cover (centres or cells), clipped
/// to the raster; `None` when it lies outside.
pub(super) fn pixel_bounds(polygon: &Polygon, width: u32, height: u32) -> Option<PixelRect> {
    let [x0, x1, y0, y1] = polygon.cells();
    // Widen by one cell each way for safety.
    let clamp = |v: i64, max: u32| v.clamp(0, i64::from(max) - 1) as u32;
    let (c0, c1, r0, r1) = (x0.saturating_sub(1), x1.saturating_add(1), y0.saturating_sub(1), y1.saturating_add(1));
    if c1 < 0 || r1 < 0 || c0 >= i64::from(width) || r0 >= i64::from(height) {
        return None;
    }
    Some(PixelRect { columns: (clamp(c0, width), clamp(c1, width)), rows: (clamp(r0, height), clamp(r1, height)) })
}

/// Asks for the polygons a few steps after `index` in scene order, so that
/// they are in cache when they are drawn: the whole record of the one eight
/// steps on (its bounds are read two steps before it is drawn, to ask for
/// its cells), and the vertices of the one four steps on (in their own
/// allocation when they are more than a triangle's).
#[inline]
pub(super) fn prefetch_ahead(scene: &Scene, index: usize) {
    if let Some(ahead) = scene.polygons.get(index + 8) {
        prefetch_polygon(ahead);
    }
    if let Some(ahead) = scene.polygons.get(index + 4) {
        prefetch(ahead.geometry().points.as_ptr());
    }
}

/// Asks for the cache lines of `polygon`'s own record that drawing reads
/// (its value, clipping and geometry take several; the rest of the record
/// is for reports: [`Polygon::DRAWN_BYTES`]).
#[inline]
pub(super) fn prefetch_polygon(polygon: &Polygon) {
    const LINE: usize = 64;
    let start: *const u8 = std::ptr::from_ref(polygon).cast();
    for offset in (0..Polygon::DRAWN_BYTES).step_by(LINE) {
        prefetch(start.wrapping_add(offset));
    }
    // The line of the last byte, when the record does not start a line.
    prefetch(start.wrapping_add(Polygon::DRAWN_BYTES - 1));
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

/// A z-buffer larger than this many bytes outgrows a core's cache (256 KiB,
/// 256×256 cells): asking for its cells ahead ([`prefetch_cells`]) pays only
/// then, and drawing small triangles by edge functions, which rewrite every
/// cell of their box, pays only below (and not on a tile's copy:
/// `Levels::edge_functions`).
pub(super) const CORE_CACHE: usize = 256 << 10;

/// A processor's last-level cache (32 MiB of L3, a common size), shared
/// with every other program the machine runs:
/// buffers larger than a quarter of it, drawn polygon by polygon, send each
/// triangle's rows to memory and back as soon as other work fills the rest,
/// so one thread draws them in tiles too
/// ([`crate::simulate::simulation::Simulation::default_tile`]).
pub(super) const LAST_LEVEL_CACHE: usize = 32 << 20;

/// Asks for the cells of polygon `index`'s bounding box, row by row, in
/// both buffers (the whole raster's, drawn in scene order), so that they
/// are in cache when it is drawn a couple of polygons later: a large raster's
/// rows lie a page apart, and waiting for each in turn is most of the time a
/// small triangle takes. Only for boxes of at most 64 rows of 256 cells
/// (larger polygons spend long enough on their pixels).
#[inline]
pub(super) fn prefetch_cells<F>(scene: &Scene, index: usize, (frame, depth): (&[F], &[u32])) {
    const ROWS: u32 = 64;
    const CELLS: u32 = 256;
    let Some(polygon) = scene.polygons.get(index) else { return };
    let Some(rect) = pixel_bounds(polygon, scene.width, scene.height) else { return };
    let (rows, columns) = (rect.rows, rect.columns);
    if rows.1 - rows.0 >= ROWS || columns.1 - columns.0 >= CELLS {
        return;
    }
    let width = scene.width as usize;
    let line = |bytes: usize| (64 / bytes.max(1)).max(1);
    for row in rows.0..=rows.1 {
        let start = row as usize * width;
        let (first, last) = (start + columns.0 as usize, start + columns.1 as usize);
        if last >= depth.len().min(frame.len()) {
            return;
        }
        for cell in (first..=last).step_by(line(4)) {
            prefetch(&depth[cell]);
        }
        prefetch(&depth[last]);
        for cell in (first..=last).step_by(line(std::mem::size_of::<F>())) {
            prefetch(&frame[cell]);
        }
        prefetch(&frame[last]);
    }
}

/// A polygon's signed area in the xy plane, counter-clockwise positive (the
/// shoelace formula; tinyrenderer's `signed_triangle_area`).
fn signed_area(vertices: &[[Exact; 3]]) -> Exact {
    let mut twice = Exact::Word(Q::from_integer(0));
    for (i, a) in vertices.iter().enumerate() {
        let b = &vertices[(i + 1) % vertices.len()];
        twice = twice.plus(&a[0].times_exact(&b[1]).minus(&b[0].times_exact(&a[1])));
    }
    twice.divided_by(2)
}

/// Whether polygon `index` is drawn, and if not, why.
pub fn fate(scene: &Scene, index: usize) -> Fate {
    let polygon = &scene.polygons[index];
    match polygon.clip {
        crate::scene::perspective::Clip::Away => return Fate::ClippedAway,
        crate::scene::perspective::Clip::ViewAway => return Fate::OutsideView,
        _ => {}
    }
    // Read from the polygon's first cache line (binning asks every polygon).
    if polygon.is_degenerate() {
        return Fate::Degenerate;
    }
    if let Some(bound) = scene.rules.min_area
        && signed_area(&polygon.vertices()) < Exact::Word(bound)
    {
        return Fate::SmallArea;
    }
    let Some(winding) = polygon.winding() else { return Fate::EdgeOn };
    // The winding matters only when culling is on (and its sign comes as it comes).
    match scene.effects.cull {
        Some(cull) if winding == cull => Fate::Culled(cull),
        _ => Fate::Drawn,
    }
}
