//! A span's cells several at a time in AVX2's 256-bit registers, where the
//! processor has them ([`span`]): spans of up to 32 cells eight at a time
//! in 32-bit lanes when the polygon's values fit them ([`span_eight`]),
//! others from 16 cells on four at a time in 64-bit lanes ([`span_avx2`]).
//! Lane `k` holds the depth of a chunk's cell `k` as whole part and
//! remainder and steps a chunk at once, the carry a compare and a masked
//! subtraction; the test, the rounding, the saturation and the store are the
//! branch-free cell's ([`super::branch_free::test_and_store`]) on every lane.
//! Its specification is [`super::branch_free::cell_by_cell`], as the
//! proptest `lanes_decide_as_the_cell_does` holds it.

#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::{
    __m256i, _mm_blendv_epi8, _mm_loadu_si128, _mm_storeu_si128, _mm256_add_epi32, _mm256_add_epi64, _mm256_and_si256,
    _mm256_andnot_si256, _mm256_blendv_epi8, _mm256_castsi256_pd, _mm256_castsi256_ps, _mm256_castsi256_si128,
    _mm256_cmpgt_epi32, _mm256_cmpgt_epi64, _mm256_cvtepu32_epi64, _mm256_loadu_si256, _mm256_max_epi32,
    _mm256_min_epi32, _mm256_movemask_pd, _mm256_movemask_ps, _mm256_permutevar8x32_epi32, _mm256_set1_epi32,
    _mm256_set1_epi64x, _mm256_setr_epi32, _mm256_setr_epi64x, _mm256_setzero_si256, _mm256_storeu_si256,
    _mm256_sub_epi32, _mm256_sub_epi64,
};

use crate::simulate::branch_free::{CellWrite, Stepped, cell_by_cell};
use crate::simulate::buffer::FrameCell;

/// How many cells a chunk holds.
#[cfg(target_arch = "x86_64")]
const LANES: usize = 4;

/// The fewest cells a span drawn in 64-bit lanes has.
#[cfg(target_arch = "x86_64")]
const LONG_SPAN: usize = 16;

/// A span's cells, each rewritten with its old or its new value as
/// [`super::branch_free::test_and_store`] decides, from the depth at the first (`start`) with
/// `step` per cell; returns how many were written. The span is the first
/// `length` cells of `cells`, which may hold more after it (left as they
/// are). `GREATER`: the test is the book's `z > stored`, its constants known
/// to the compiler. Where the processor has AVX2: a span of up to
/// [`EightLanes::LONGEST`] cells eight at a time in 32-bit lanes when its
/// polygon's values fit them (`eight`, [`EightLanes::new`]) and the cells
/// hold whole chunks from its start ([`span_eight`]), a chunk's cells past
/// the span rewritten with their own values; else a span of [`LONG_SPAN`]
/// cells or more four at a time in 64-bit lanes ([`span_avx2`]). The
/// decisions are the same (the proptest `lanes_decide_as_the_cell_does`).
#[inline(always)]
pub(super) fn span<F: FrameCell, const GREATER: bool>(
    (depth, frame): (&mut [u32], &mut [F]),
    length: usize,
    (start, step, denominator): (Stepped, Stepped, i64),
    eight: Option<&EightLanes>,
    write: CellWrite<F>,
) -> u64 {
    let write = write.compiled::<GREATER>();
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        let room = length.next_multiple_of(EIGHT);
        if let Some(eight) = eight
            && room <= depth.len().min(frame.len())
            && start.whole.unsigned_abs() < EightLanes::WHOLE
            && length <= EightLanes::LONGEST
        {
            let cells = (&mut depth[..room], &mut frame[..room]);
            // SAFETY: the processor has AVX2, checked above.
            return unsafe { span_eight::<F, GREATER>(cells, length, start, eight, write) };
        }
        // Lanes of 64 bits pay for their setup (four depths and a stride) only on longer spans.
        if length >= LONG_SPAN {
            let cells = (&mut depth[..length], &mut frame[..length]);
            // SAFETY: the processor has AVX2, checked just above.
            return unsafe { span_avx2::<F, GREATER>(cells, start, step, denominator, write) };
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = eight;
    cell_by_cell((&mut depth[..length], &mut frame[..length]), start, step, denominator, write)
}

/// How many cells a chunk of 32-bit lanes holds.
const EIGHT: usize = 8;

/// A polygon's step, for its short spans drawn eight cells at a time in
/// 32-bit lanes ([`span_eight`]): each lane's offset from a span's first
/// cell (`k` steps, as whole part and remainder), eight steps as one, the
/// denominator, and the test's constants in 32 bits.
#[derive(Debug, Clone, Copy)]
// Only x86-64's AVX2 reads them: elsewhere a polygon's lanes are made and left unread.
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
pub(super) struct EightLanes {
    whole: [i32; EIGHT],
    remainder: [i32; EIGHT],
    stride: [i32; 2],
    denominator: i32,
    max: i32,
    threshold: i32,
}

#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
impl EightLanes {
    /// A span's first whole part must lie below this for its lanes to fit 32
    /// bits (with the bounds [`EightLanes::new`] checks, every whole part,
    /// rounded level and difference to a stored level then lies within ±2^30).
    const WHOLE: u64 = 1 << 28;

    /// The longest span drawn in these lanes: 32 steps of a whole part
    /// below 2^20 stay below 2^26.
    const LONGEST: usize = 32;

    /// The lanes of a polygon stepping `step` over `denominator`, when its
    /// values fit 32 bits: a denominator below 2^26 (so that a remainder
    /// plus an offset's, and twice a remainder, stay below 2^27), a step's
    /// whole part below 2^20 (the [`EightLanes::LONGEST`] steps of a span
    /// below 2^26) and a largest level below 2^28; `None` otherwise.
    pub(super) fn new<F: FrameCell>(step: Stepped, denominator: i64, write: CellWrite<F>) -> Option<EightLanes> {
        if denominator >= 1 << 26 || step.whole.unsigned_abs() >= 1 << 20 || write.max >= 1 << 28 {
            return None;
        }
        let (mut whole, mut remainder) = ([0; EIGHT], [0; EIGHT]);
        let mut at = Stepped { whole: 0, remainder: 0 };
        for k in 0..EIGHT {
            (whole[k], remainder[k]) = (at.whole as i32, at.remainder as i32);
            at = at.plus(step, denominator);
        }
        Some(EightLanes {
            whole,
            remainder,
            stride: [at.whole as i32, at.remainder as i32],
            denominator: denominator as i32,
            max: write.max as i32,
            // sign·(v − s) lies within ±2^30: the extremes decide alone, as in 64 bits.
            threshold: write.test.threshold.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32,
        })
    }
}

/// A short span in chunks of eight cells, the first `length` of `cells`
/// (whose length is a multiple of eight), from the depth at the first
/// (`start`, its whole part below [`EightLanes::WHOLE`]); lane `k` holds
/// cell `k`'s depth as whole part and remainder in 32 bits, the carry a
/// compare and a masked subtraction, the cells past the span rewritten with
/// their own values. Returns how many were written.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
pub(super) fn span_eight<F: FrameCell, const GREATER: bool>(
    (depth, frame): (&mut [u32], &mut [F]),
    length: usize,
    start: Stepped,
    eight: &EightLanes,
    write: CellWrite<F>,
) -> u64 {
    let write = write.compiled::<GREATER>();
    let test = write.test;
    let zero = _mm256_setzero_si256();
    let denominator = _mm256_set1_epi32(eight.denominator);
    let below_denominator = _mm256_set1_epi32(eight.denominator - 1);
    let max = _mm256_set1_epi32(eight.max);
    let threshold = _mm256_set1_epi32(if GREATER { 0 } else { eight.threshold });
    let index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    // SAFETY: each array is eight i32s, 32 bytes, read unaligned.
    let (offset_whole, offset_remainder) = unsafe {
        (_mm256_loadu_si256(eight.whole.as_ptr().cast()), _mm256_loadu_si256(eight.remainder.as_ptr().cast()))
    };
    // The first chunk's depths: the start plus each lane's offset, one carry at most.
    let mut whole = _mm256_add_epi32(_mm256_set1_epi32(start.whole as i32), offset_whole);
    let mut remainder = _mm256_add_epi32(_mm256_set1_epi32(start.remainder as i32), offset_remainder);
    let carry = _mm256_cmpgt_epi32(remainder, below_denominator);
    whole = _mm256_sub_epi32(whole, carry);
    remainder = _mm256_sub_epi32(remainder, _mm256_and_si256(carry, denominator));
    let (stride_whole, stride_remainder) = (_mm256_set1_epi32(eight.stride[0]), _mm256_set1_epi32(eight.stride[1]));
    let mut written = 0u64;
    // By index, not by iterators over chunks: no call per chunk (the development guide).
    for chunk in 0..depth.len().min(frame.len()) / EIGHT {
        let cells = chunk * EIGHT..chunk * EIGHT + EIGHT;
        let (depth_cells, frame_cells) = (&mut depth[cells.clone()], &mut frame[cells]);
        let inside = _mm256_cmpgt_epi32(_mm256_set1_epi32((length - chunk * EIGHT) as i32), index);
        // SAFETY: `depth_cells` is eight u32s, 32 bytes, read unaligned; each at most the largest level, below 2^28.
        let stored = unsafe { _mm256_loadu_si256(depth_cells.as_ptr().cast()) };
        // v: the ceiling (whole part, plus one where a remainder is left) or the floor.
        let above_whole = _mm256_cmpgt_epi32(remainder, zero);
        let v = if test.use_ceiling { _mm256_sub_epi32(whole, above_whole) } else { whole };
        let difference = if test.sign > 0 { _mm256_sub_epi32(v, stored) } else { _mm256_sub_epi32(stored, v) };
        let passes = _mm256_and_si256(_mm256_cmpgt_epi32(difference, threshold), inside);
        // Rounded half up (one more where 2·remainder ≥ denominator), saturated to 0 … max.
        let half_up = _mm256_cmpgt_epi32(_mm256_add_epi32(remainder, remainder), below_denominator);
        let rounded = _mm256_min_epi32(_mm256_max_epi32(_mm256_sub_epi32(whole, half_up), zero), max);
        let stored_after = _mm256_blendv_epi8(stored, rounded, passes);
        // SAFETY: `depth_cells` is eight u32s, 32 bytes, written unaligned.
        unsafe { _mm256_storeu_si256(depth_cells.as_mut_ptr().cast(), stored_after) };
        let mask = _mm256_movemask_ps(_mm256_castsi256_ps(passes));
        for (k, cell) in frame_cells.iter_mut().enumerate() {
            *cell = std::hint::select_unpredictable(mask & (1 << k) != 0, write.value, *cell);
        }
        written += u64::from(mask.count_ones());
        // Eight cells on: the carry (−1 where the remainder reached the denominator) added to the whole part.
        remainder = _mm256_add_epi32(remainder, stride_remainder);
        let carry = _mm256_cmpgt_epi32(remainder, below_denominator);
        whole = _mm256_sub_epi32(_mm256_add_epi32(whole, stride_whole), carry);
        remainder = _mm256_sub_epi32(remainder, _mm256_and_si256(carry, denominator));
    }
    written
}

/// The span's cells, four at a time where the span holds four more, from
/// the depth at the first (`start`) with `step` per cell; returns how many
/// were written. `GREATER`: `write.test` is the book's test, its constants
/// folded in by the compiler.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
pub(super) fn span_avx2<F: FrameCell, const GREATER: bool>(
    (depth, frame): (&mut [u32], &mut [F]),
    start: Stepped,
    step: Stepped,
    denominator: i64,
    write: CellWrite<F>,
) -> u64 {
    let write = write.compiled::<GREATER>();
    let chunks = depth.len().min(frame.len()) / LANES;
    if chunks == 0 {
        return cell_by_cell((depth, frame), start, step, denominator, write);
    }
    // The first chunk's four depths, and four steps as one (each sum's remainder below the denominator).
    let (mut wholes, mut remainders) = ([0i64; LANES], [0i64; LANES]);
    let (mut at, mut stride) = (start, Stepped { whole: 0, remainder: 0 });
    for k in 0..LANES {
        (wholes[k], remainders[k]) = (at.whole, at.remainder);
        at = at.plus(step, denominator);
        stride = stride.plus(step, denominator);
    }
    let [w0, w1, w2, w3] = wholes;
    let [r0, r1, r2, r3] = remainders;
    let mut whole = _mm256_setr_epi64x(w0, w1, w2, w3);
    let mut remainder = _mm256_setr_epi64x(r0, r1, r2, r3);
    let (stride_whole, stride_remainder) = (_mm256_set1_epi64x(stride.whole), _mm256_set1_epi64x(stride.remainder));
    let zero = _mm256_setzero_si256();
    let (denominator_lanes, below_denominator) = (_mm256_set1_epi64x(denominator), _mm256_set1_epi64x(denominator - 1));
    let (max, threshold) = (_mm256_set1_epi64x(write.max), _mm256_set1_epi64x(write.test.threshold));
    // The low 32 bits of each 64-bit lane, gathered into the low 128 bits.
    let low_halves = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    let mut written = 0u64;
    for chunk in 0..chunks {
        let cells = chunk * LANES..chunk * LANES + LANES;
        let depth_cells = &mut depth[cells.clone()];
        // SAFETY: `depth_cells` is four u32s, 16 bytes, read unaligned.
        let stored_32 = unsafe { _mm_loadu_si128(depth_cells.as_ptr().cast()) };
        let stored = _mm256_cvtepu32_epi64(stored_32);
        // v: the ceiling (whole part, plus one where a remainder is left) or the floor.
        let above_whole = _mm256_cmpgt_epi64(remainder, zero);
        let v = if write.test.use_ceiling { _mm256_sub_epi64(whole, above_whole) } else { whole };
        let difference = if write.test.sign > 0 { _mm256_sub_epi64(v, stored) } else { _mm256_sub_epi64(stored, v) };
        let passes = _mm256_cmpgt_epi64(difference, threshold);
        // Rounded half up (one more where 2·remainder ≥ denominator), saturated to 0 … max.
        let half_up = _mm256_cmpgt_epi64(_mm256_add_epi64(remainder, remainder), below_denominator);
        let rounded = _mm256_sub_epi64(whole, half_up);
        let rounded = _mm256_andnot_si256(_mm256_cmpgt_epi64(zero, rounded), rounded);
        let rounded = _mm256_blendv_epi8(rounded, max, _mm256_cmpgt_epi64(rounded, max));
        let rounded_32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(rounded, low_halves));
        let passes_32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(passes, low_halves));
        let stored_after = _mm_blendv_epi8(stored_32, rounded_32, passes_32);
        // SAFETY: `depth_cells` is four u32s, 16 bytes, written unaligned.
        unsafe { _mm_storeu_si128(depth_cells.as_mut_ptr().cast(), stored_after) };
        let mask = _mm256_movemask_pd(_mm256_castsi256_pd(passes));
        for (k, cell) in frame[cells].iter_mut().enumerate() {
            *cell = std::hint::select_unpredictable(mask & (1 << k) != 0, write.value, *cell);
        }
        written += u64::from(mask.count_ones());
        // Four cells on: the carry (−1 where the remainder reached the denominator) added to the whole part.
        remainder = _mm256_add_epi64(remainder, stride_remainder);
        let carry = _mm256_cmpgt_epi64(remainder, below_denominator);
        whole = _mm256_sub_epi64(_mm256_add_epi64(whole, stride_whole), carry);
        remainder = _mm256_sub_epi64(remainder, _mm256_and_si256(carry, denominator_lanes));
    }
    let next = Stepped { whole: lane_0(whole), remainder: lane_0(remainder) };
    let done = chunks * LANES;
    written + cell_by_cell((&mut depth[done..], &mut frame[done..]), next, step, denominator, write)
}

/// The first lane's 64 bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn lane_0(lanes: __m256i) -> i64 {
    std::arch::x86_64::_mm_cvtsi128_si64(_mm256_castsi256_si128(lanes))
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::raster::depth::BranchFreeTest;
    use crate::raster::depth::DepthTest;

    /// A depth or a step over `denominator`: a whole part near the stored
    /// levels (so that tests go both ways) and a remainder below it.
    fn stepped(denominator: i64, whole: std::ops::Range<i64>) -> impl Strategy<Value = Stepped> {
        (whole, 0..denominator).prop_map(|(whole, remainder)| Stepped { whole, remainder })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        /// Spans of 0 to 40 cells over every test, with denominators from 1
        /// to near 2^61, on stored levels of 0 … 15, with up to 9 more cells
        /// after the span (which the 32-bit lanes may rewrite): the lanes (in
        /// AVX2 where the processor has it) leave the cells and the count the
        /// loop one cell at a time leaves, and the cells after the span as
        /// they were.
        #[test]
        fn lanes_decide_as_the_cell_does(
            (denominator, start, step) in prop_oneof![1i64..40, Just((1i64 << 61) - 1)]
                .prop_flat_map(|d| (Just(d), stepped(d, -3..18), stepped(d, -2..3))),
            stored in prop::collection::vec(0u32..16, 0..40),
            after in 0usize..10,
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
            let length = stored.len();
            let (mut depth_cells, mut frame_cells): (Vec<u32>, Vec<u8>) =
                ((0..length + after).map(|k| stored.get(k).copied().unwrap_or(7)).collect(), (0..(length + after) as u8).collect());
            let eight = EightLanes::new(step, denominator, write);
            prop_assert_eq!(eight.is_some(), denominator < 1 << 26);
            let (mut depth_lanes, mut frame_lanes) = (depth_cells.clone(), frame_cells.clone());
            let stepping = (start, step, denominator);
            let written = if greater {
                span::<u8, true>((&mut depth_lanes, &mut frame_lanes), length, stepping, eight.as_ref(), write)
            } else {
                span::<u8, false>((&mut depth_lanes, &mut frame_lanes), length, stepping, eight.as_ref(), write)
            };
            let cells = (&mut depth_cells[..length], &mut frame_cells[..length]);
            let expected = cell_by_cell(cells, start, step, denominator, write);
            prop_assert_eq!(depth_lanes, depth_cells);
            prop_assert_eq!(frame_lanes, frame_cells);
            prop_assert_eq!(written, expected);
        }
    }
}
