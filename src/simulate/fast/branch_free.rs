//! The branch-free cell of the fast loops (a span, a small triangle's box):
//! the depth test and the store chosen without a branch, and the carry of a
//! depth stepped by whole part and remainder. Their specification is the
//! reference path (`DepthTest::passes`, `Depth::stored`), as the proptests
//! hold them.

use std::hint::select_unpredictable;

use crate::raster::depth::{BranchFreeTest, round_half_up};
use crate::simulate::buffer::FrameCell;

/// A depth `whole + remainder/denominator` (`0 ≤ remainder < denominator`)
/// over the denominator its loop keeps; also a step of that form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Stepped {
    /// The whole part.
    pub(super) whole: i64,
    /// The remainder.
    pub(super) remainder: i64,
}

impl Stepped {
    /// This plus `step`, as whole part and remainder again (the carry chosen
    /// without a branch).
    #[inline(always)]
    pub(super) fn plus(self, step: Stepped, denominator: i64) -> Stepped {
        let remainder = self.remainder + step.remainder;
        let carry = remainder >= denominator;
        Stepped {
            whole: self.whole + step.whole + i64::from(carry),
            remainder: remainder - select_unpredictable(carry, denominator, 0),
        }
    }
}

/// What a loop writes where the test passes: the test's constants, the
/// largest level the z-buffer holds, and the polygon's framebuffer value.
#[derive(Debug, Clone, Copy)]
pub(super) struct CellWrite<F> {
    pub(super) test: BranchFreeTest,
    pub(super) max: i64,
    pub(super) value: F,
}

impl<F: FrameCell> CellWrite<F> {
    /// This write for a loop compiled with `GREATER`: its test then the
    /// book's `z > stored` as constants the compiler folds in (callers pass
    /// only that test then), any test otherwise. Each loop that is its own
    /// function (the lanes' is, for AVX2) sets it again, since constants do
    /// not cross a call.
    #[inline(always)]
    pub(super) fn compiled<const GREATER: bool>(self) -> CellWrite<F> {
        if GREATER { CellWrite { test: BranchFreeTest::GREATER, ..self } } else { self }
    }
}

/// One cell of a branch-free loop: `depth` over `denominator` against the
/// stored level with the test's constants ([`BranchFreeTest`]); both cells
/// are rewritten with their old or their new value, so nothing is guessed.
/// `covered` false leaves them as they are. Returns whether the cell was
/// written.
#[inline(always)]
pub(super) fn test_and_store<F: FrameCell>(
    (depth_cell, frame_cell): (&mut u32, &mut F),
    depth: Stepped,
    denominator: i64,
    write: CellWrite<F>,
    covered: bool,
) -> bool {
    let passes = covered & write.test.passes(depth.whole, depth.remainder, *depth_cell);
    let rounded = round_half_up(depth.whole, depth.remainder, denominator).clamp(0, write.max) as u32;
    *depth_cell = select_unpredictable(passes, rounded, *depth_cell);
    *frame_cell = select_unpredictable(passes, write.value, *frame_cell);
    passes
}

/// A span's cells one after the other: the specification of the lanes.
#[inline(always)]
pub(super) fn cell_by_cell<F: FrameCell>(
    (depth, frame): (&mut [u32], &mut [F]),
    mut at: Stepped,
    step: Stepped,
    denominator: i64,
    write: CellWrite<F>,
) -> u64 {
    let mut written = 0;
    let cells = depth.len().min(frame.len());
    let (depth, frame) = (&mut depth[..cells], &mut frame[..cells]);
    // By index, not by zipping the two: no call per span where the compiler's inlining stops.
    for k in 0..depth.len() {
        let cell = (&mut depth[k], &mut frame[k]);
        written += u64::from(test_and_store(cell, at, denominator, write, true));
        at = at.plus(step, denominator);
    }
    written
}
