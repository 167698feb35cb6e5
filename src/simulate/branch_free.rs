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

/// The fewest cells a span drawn in lanes has.
#[cfg(target_arch = "x86_64")]
const LONG_SPAN: usize = 16;

/// A span's cells, each rewritten with its old or its new value as
/// [`test_and_store`] decides, from the depth at the first (`start`) with
/// `step` per cell; returns how many were written. `GREATER`: the test is
/// the book's `z > stored`, its constants known to the compiler. Where the
/// processor has AVX2 and the span [`LONG_SPAN`] cells or more, four cells
/// at a time in its 256-bit registers ([`super::lanes`]); the decisions are the same (the proptest
/// `lanes_decide_as_the_cell_does`).
#[inline(always)]
pub(super) fn span<F: FrameCell, const GREATER: bool>(
    cells: (&mut [u32], &mut [F]),
    start: Stepped,
    step: Stepped,
    denominator: i64,
    write: CellWrite<F>,
) -> u64 {
    let write = if GREATER { CellWrite { test: BranchFreeTest::GREATER, ..write } } else { write };
    // Lanes pay for their setup (four depths and a stride) only on longer spans.
    #[cfg(target_arch = "x86_64")]
    if cells.0.len() >= LONG_SPAN && std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2, checked just above.
        return unsafe { super::lanes::span_avx2::<F, GREATER>(cells, start, step, denominator, write) };
    }
    cell_by_cell(cells, start, step, denominator, write)
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
    for cell in depth.iter_mut().zip(frame) {
        written += u64::from(test_and_store(cell, at, denominator, write, true));
        at = at.plus(step, denominator);
    }
    written
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::raster::depth::DepthTest;

    /// A depth or a step over `denominator`: a whole part near the stored
    /// levels (so that tests go both ways) and a remainder below it.
    fn stepped(denominator: i64, whole: std::ops::Range<i64>) -> impl Strategy<Value = Stepped> {
        (whole, 0..denominator).prop_map(|(whole, remainder)| Stepped { whole, remainder })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        /// Spans of 0 to 40 cells over every test, with denominators from 1
        /// to near 2^61, on stored levels of 0 … 15: the lanes (in AVX2 where
        /// the processor has it) leave the cells and the count the loop one
        /// cell at a time leaves.
        #[test]
        fn lanes_decide_as_the_cell_does(
            (denominator, start, step) in prop_oneof![1i64..40, Just((1i64 << 61) - 1)]
                .prop_flat_map(|d| (Just(d), stepped(d, -3..18), stepped(d, -2..3))),
            stored in prop::collection::vec(0u32..16, 0..40),
            test in prop::sample::select(vec![
                DepthTest::Greater,
                DepthTest::Less,
                DepthTest::GreaterEqual,
                DepthTest::LessEqual,
                DepthTest::Always,
                DepthTest::Never,
            ]),
            greater in any::<bool>(),
        ) {
            let test = if greater { DepthTest::Greater } else { test };
            let write = CellWrite { test: BranchFreeTest::of(test), max: 15, value: 9u8 };
            let frame: Vec<u8> = (0..stored.len() as u8).collect();
            let (mut depth_lanes, mut frame_lanes) = (stored.clone(), frame.clone());
            let written = if greater {
                span::<u8, true>((&mut depth_lanes, &mut frame_lanes), start, step, denominator, write)
            } else {
                span::<u8, false>((&mut depth_lanes, &mut frame_lanes), start, step, denominator, write)
            };
            let (mut depth_cells, mut frame_cells) = (stored, frame);
            let expected = cell_by_cell((&mut depth_cells, &mut frame_cells), start, step, denominator, write);
            prop_assert_eq!(depth_lanes, depth_cells);
            prop_assert_eq!(frame_lanes, frame_cells);
            prop_assert_eq!(written, expected);
        }
    }
}
