//! The branch-free cell of the fast loops (a span, a small triangle's box):
//! the depth test and the store chosen without a branch, and the carry of a
//! depth stepped by whole part and remainder. Their specification is the
//! reference path (`DepthTest::passes`, `Depth::stored`), as the proptests
//! hold them.

use std::hint::select_unpredictable;

use crate::raster::depth::{BranchFreeTest, round_half_up};
use crate::simulate::buffer::FrameCell;

/// One cell of a branch-free loop: the depth `whole + remainder/denominator`
/// (`0 ≤ remainder < denominator`) against the stored level with the test's
/// constants ([`BranchFreeTest`]); both cells are rewritten with their old or
/// their new value, so nothing is guessed. `covered` false leaves them as
/// they are. Returns whether the cell was written.
#[inline(always)]
pub(super) fn test_and_store<F: FrameCell>(
    (depth, frame): (&mut u32, &mut F),
    (whole, remainder, denominator): (i64, i64, i64),
    test: BranchFreeTest,
    (max, value): (i64, F),
    covered: bool,
) -> bool {
    let passes = covered & test.passes(whole, remainder, *depth);
    let rounded = round_half_up(whole, remainder, denominator).clamp(0, max) as u32;
    *depth = select_unpredictable(passes, rounded, *depth);
    *frame = select_unpredictable(passes, value, *frame);
    passes
}

/// `whole + remainder/denominator` plus `step`, as whole part and remainder
/// again (the carry chosen without a branch).
#[inline(always)]
pub(super) fn carry_step(
    (whole, remainder): (i64, i64),
    (step_whole, step_remainder): (i64, i64),
    denominator: i64,
) -> (i64, i64) {
    let remainder = remainder + step_remainder;
    let carry = remainder >= denominator;
    (whole + step_whole + i64::from(carry), remainder - select_unpredictable(carry, denominator, 0))
}
