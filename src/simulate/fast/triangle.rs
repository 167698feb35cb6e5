//! Small triangles of the plain loop, nobody watching, on buffers that fit
//! the cache: the book's rules decided by edge functions over the bounding
//! box, in 64-bit integers, without a division per row. A triangle is most of a small triangle's cost
//! in the scan converter's setup (its edges, its rows, a division per span);
//! here the setup is three edge functions and one depth stepper.
//!
//! Why it is the same: with the book's rules (rows half-open, columns
//! `CentreInside`), a triangle's scanline at `y_min ≤ y < y_max` meets
//! exactly two of its edges (each holds `y_low ≤ y < y_high`; a horizontal one
//! none), and the span between their crossings, ends included, is the closed
//! triangle's section at `y`. So a centre is covered exactly when every edge
//! function (signed so that the inside is positive) is at least 0 and the
//! centre lies below `y_max`. The depth is the same stepper as the span's,
//! stepped down the rows by whole part and remainder. The proptest
//! `every_path_draws_alike` and `small_triangles_draw_as_the_scan_converter_draws_them`
//! hold it to the scan converter.

use crate::geometry::plane::Geometry;
use crate::numbers::Word;
use crate::raster::depth::{DepthPlane, DepthTest};
use crate::raster::sink::PixelRect;
use crate::rules::{ColumnRule, RowRule, Rules};
use crate::simulate::buffer::FrameCell;
use crate::simulate::events::Observer;
use crate::simulate::fast::branch_free::{Stepped, test_and_store};
use crate::simulate::fast::levels::LevelSink;

/// The largest bounding box (in pixel centres) drawn this way: above it the
/// scan converter, which visits only covered centres, is faster.
const MAX_BOX: i64 = 24 * 24;

/// Coordinates (scaled) below this keep every edge function in 62 bits.
const MAX_COORDINATE: i64 = 1 << 29;

impl<O: Observer, F: FrameCell> LevelSink<'_, O, F> {
    /// Draws a small triangle within `rect` by edge functions, with the same
    /// cells and counts as the scan converter; `false` (having done nothing)
    /// when the triangle, the rules or an observer need the scan converter.
    /// [`Levels::draw`](crate::simulate::fast::levels::Levels) decides whether the cells suit it.
    pub(super) fn small_triangle(&mut self, geometry: &Geometry, rules: Rules, rect: PixelRect) -> bool {
        if O::OBSERVES_PIXELS
            || O::OBSERVES_SCANLINES
            || rules.rows != RowRule::HalfOpen
            || rules.columns != ColumnRule::CentreInside
            || geometry.big().is_some()
            || !geometry.fits_i64()
        {
            return false;
        }
        let points: &[[i128; 3]] = &geometry.points;
        let [p, q, r] = match *points {
            [p, q, r] => [[p[0], p[1]], [q[0], q[1]], [r[0], r[1]]],
            _ => return false,
        };
        let d = geometry.denominator;
        let small = |v: i128| v.unsigned_abs() < MAX_COORDINATE as u128;
        let fits = small(p[0]) && small(p[1]) && small(q[0]) && small(q[1]) && small(r[0]) && small(r[1]);
        if !fits || !small(d * (2 * i128::from(u16::MAX) + 2)) {
            return false;
        }
        let ([px, py], [qx, qy], [rx, ry]) =
            ([p[0] as i64, p[1] as i64], [q[0] as i64, q[1] as i64], [r[0] as i64, r[1] as i64]);
        let d = d as i64;
        let two_d = 2 * d;
        // Rows with y_min ≤ (2row + 1)·D < y_max; columns whose centres lie within x_min … x_max.
        let (y_min, y_max) = (py.min(qy).min(ry), py.max(qy).max(ry));
        let (x_min, x_max) = (px.min(qx).min(rx), px.max(qx).max(rx));
        // ⌊v / 2D⌋, a shift when 2D is a power of two (integer and binary-fraction vertices).
        let shift = two_d.trailing_zeros();
        let floor = |v: i64| if two_d == 1 << shift { v >> shift } else { v.floor_div(two_d).0 };
        let ceil = |v: i64| -floor(-v);
        let first_row = ceil(y_min - d).max(i64::from(rect.rows.0));
        let last_row = (ceil(y_max - d) - 1).min(i64::from(rect.rows.1));
        let first_column = ceil(x_min - d).max(i64::from(rect.columns.0));
        let last_column = floor(x_max - d).min(i64::from(rect.columns.1));
        if first_row > last_row || first_column > last_column {
            return true;
        }
        if (last_row - first_row + 1) * (last_column - first_column + 1) > MAX_BOX {
            return false;
        }
        // Edge functions, inside positive: e(X, Y) = (bx − ax)(Y − ay) − (by − ay)(X − ax),
        // times the winding's sign (Newell's c).
        let sign: i64 = if geometry.c() > 0 { 1 } else { -1 };
        let (centre_x, centre_y) = ((2 * first_column + 1) * d, (2 * first_row + 1) * d);
        let edge = |[ax, ay]: [i64; 2], [bx, by]: [i64; 2]| {
            let (dx, dy) = (sign * (bx - ax), sign * (by - ay));
            // At the first centre; per column −dy·2D, per row +dx·2D.
            EdgeFunction {
                at_first: dx * (centre_y - ay) - dy * (centre_x - ax),
                per_column: -dy * two_d,
                per_row: dx * two_d,
            }
        };
        let edges = [edge([px, py], [qx, qy]), edge([qx, qy], [rx, ry]), edge([rx, ry], [px, py])];
        let plane = DepthPlane::<i64>::new(geometry);
        let stepper = plane.start_at(plane.row_numerator(centre_y), first_column as u32);
        let state = stepper.state();
        let (down_whole, down_remainder) = plane.row_step().floor_div(state.denominator);
        let start = Stepped { whole: state.whole, remainder: state.remainder };
        let steps = Steps {
            denominator: state.denominator,
            per_column: Stepped { whole: state.step_whole, remainder: state.step_remainder },
            per_row: Stepped { whole: down_whole, remainder: down_remainder },
        };
        let box_ =
            CentreBox { first_row, last_row, first_column: first_column as usize, last_column: last_column as usize };
        // The book's test with its constants known to the compiler (about 5% of exact's time
        // in `zsim accuracy`); any other with them read as the loop runs.
        let (tested, written) = if self.test == DepthTest::Greater {
            self.box_rows::<true>(box_, edges, start, steps)
        } else {
            self.box_rows::<false>(box_, edges, start, steps)
        };
        self.stats.tested += tested;
        self.stats.written += written;
        true
    }

    /// The rows of a triangle's box (rows, then columns), each cell rewritten
    /// with its old or its new value, branch-free as the span's loop: the
    /// edge functions at the box's first centre with their steps per column
    /// and per row, the depth there as whole part and remainder, and its
    /// denominator and steps per column and per row. `GREATER`: the test is
    /// `z > stored`, compiled with its constants. Returns the centres tested
    /// and written.
    #[inline(always)]
    fn box_rows<const GREATER: bool>(
        &mut self,
        centres: CentreBox,
        edges: [EdgeFunction; 3],
        mut row_start: Stepped,
        steps: Steps,
    ) -> (u64, u64) {
        let write = self.cell_write::<GREATER>();
        let denominator = steps.denominator;
        let (mut tested, mut written) = (0u64, 0u64);
        let mut row_edges = [edges[0].at_first, edges[1].at_first, edges[2].at_first];
        for row in centres.first_row..=centres.last_row {
            let start = self.origin.cell(centres.first_column as u32, row as u32);
            let cells = start..=start + (centres.last_column - centres.first_column);
            let [mut e0, mut e1, mut e2] = row_edges;
            let mut depth = row_start;
            let (depth_cells, frame_cells) = (&mut self.depth[cells.clone()], &mut self.frame[cells]);
            let frame_cells = &mut frame_cells[..depth_cells.len()];
            // By index, not by zipping the two: the same loop, with no call per row where the
            // compiler's inlining stops (a release build optimizes each code generation unit alone).
            for k in 0..depth_cells.len() {
                let cell = (&mut depth_cells[k], &mut frame_cells[k]);
                let covered = (e0 | e1 | e2) >= 0;
                let passes = test_and_store(cell, depth, denominator, write, covered);
                tested += u64::from(covered);
                written += u64::from(passes);
                (e0, e1, e2) = (e0 + edges[0].per_column, e1 + edges[1].per_column, e2 + edges[2].per_column);
                depth = depth.plus(steps.per_column, denominator);
            }
            row_edges =
                [row_edges[0] + edges[0].per_row, row_edges[1] + edges[1].per_row, row_edges[2] + edges[2].per_row];
            row_start = row_start.plus(steps.per_row, denominator);
        }
        (tested, written)
    }
}

/// A small triangle's box of pixel centres: rows and columns, inclusive.
#[derive(Debug, Clone, Copy)]
struct CentreBox {
    first_row: i64,
    last_row: i64,
    first_column: usize,
    last_column: usize,
}

/// An edge function at the box's first centre, with its steps per column
/// and per row (a centre is inside where all three are ≥ 0).
#[derive(Debug, Clone, Copy)]
struct EdgeFunction {
    at_first: i64,
    per_column: i64,
    per_row: i64,
}

/// The depth's denominator and its steps per column and per row.
#[derive(Debug, Clone, Copy)]
struct Steps {
    denominator: i64,
    per_column: Stepped,
    per_row: Stepped,
}
