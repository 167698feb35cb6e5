//! A span's cells several at a time ([`span`]): spans of up to 32 cells
//! eight at a time in 32-bit lanes when the polygon's values fit them
//! ([`eight_cells`]), others from 16 cells on four at a time in 64-bit
//! lanes ([`four_cells`]). Lane `k` holds the depth of a chunk's cell `k` as
//! whole part and remainder and steps a chunk at once, the carry a compare
//! and a masked subtraction; the test, the rounding, the saturation and the
//! store are the branch-free cell's ([`super::branch_free::test_and_store`])
//! on every lane. Both loops are written over the lane types of
//! [`super::wide`], and run in AVX2's registers where the processor has them
//! ([`Registers::of_processor`]), in the plain lanes (arrays) everywhere
//! else; which loop a span takes is decided in one place ([`lanes_for`]):
//! the plain lanes take only the four 64-bit ones, and not in WebAssembly
//! ([`Registers::draw_in`]).
//! Their specification is [`super::branch_free::cell_by_cell`], as the
//! proptests `lanes_decide_as_the_cell_does` and
//! `lanes_decide_as_the_cell_does_at_their_bounds` hold both loops in both
//! registers, chosen or not, on every target the tests run on.

use std::hint::select_unpredictable;

use crate::simulate::buffer::FrameCell;
use crate::simulate::fast::branch_free::{CellWrite, Stepped, cell_by_cell};
#[cfg(target_arch = "x86_64")]
use crate::simulate::fast::wide::{Avx4, Avx8};
use crate::simulate::fast::wide::{Lanes32, Lanes64, Plain4, Plain8};

/// How many cells a chunk of 64-bit lanes holds.
const LANES: usize = 4;

/// The fewest cells a span drawn in 64-bit lanes has.
const LONG_SPAN: usize = 16;

/// How many cells a chunk of 32-bit lanes holds.
const EIGHT: usize = 8;

/// A span's cells, each rewritten with its old or its new value as
/// [`super::branch_free::test_and_store`] decides, from the depth at the first (`start`) with
/// `step` per cell; returns how many were written. The span is the first
/// `length` cells of `cells`, which may hold more after it (left as they
/// are). `GREATER`: the test is the book's `z > stored`, its constants known
/// to the compiler. Drawn in this processor's registers
/// ([`Registers::of_processor`]), in the lanes [`lanes_for`] chooses.
#[inline(always)]
pub(super) fn span<F: FrameCell, const GREATER: bool>(
    cells: (&mut [u32], &mut [F]),
    length: usize,
    stepping: (Stepped, Stepped, i64),
    eight: Option<&EightLanes>,
    write: CellWrite<F>,
) -> u64 {
    in_registers::<F, GREATER>(Registers::of_processor(), cells, length, stepping, eight, write)
}

/// The registers a span's lanes are held in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Registers {
    /// AVX2's: made only by [`Registers::of_processor`] on a processor that has them.
    #[cfg(target_arch = "x86_64")]
    Avx2,
    /// The plain lanes, arrays: every target.
    Plain,
}

impl Registers {
    /// AVX2's where this processor has them, the plain lanes elsewhere.
    #[inline(always)]
    fn of_processor() -> Registers {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            return Registers::Avx2;
        }
        Registers::Plain
    }

    /// Whether these registers draw a span in `lanes`. AVX2's draw both.
    /// The plain lanes draw only the four 64-bit ones: eight plain lanes
    /// rewrite up to seven cells past a short span, which costs an array as
    /// much as the span's own cells. And none in WebAssembly, whose module
    /// the plain loops would take past its size budget. (The design notes
    /// have the measurements.)
    #[inline(always)]
    fn draw_in(self, lanes: &Lanes<'_>) -> bool {
        match (self, lanes) {
            #[cfg(target_arch = "x86_64")]
            (Registers::Avx2, _) => true,
            (Registers::Plain, Lanes::Eight(..)) => false,
            (Registers::Plain, Lanes::Four) => !cfg!(target_family = "wasm"),
        }
    }

    /// [`eight_cells`] in these registers.
    #[inline(always)]
    fn eight<F: FrameCell, const GREATER: bool>(
        self,
        cells: (&mut [u32], &mut [F]),
        length: usize,
        start: Stepped,
        eight: &EightLanes,
        write: CellWrite<F>,
    ) -> u64 {
        match self {
            // SAFETY: `Registers::Avx2` is made only where the processor has AVX2.
            #[cfg(target_arch = "x86_64")]
            Registers::Avx2 => unsafe { eight_in_avx2::<F, GREATER>(cells, length, start, eight, write) },
            Registers::Plain => eight_cells::<Plain8, F, GREATER>(cells, length, start, eight, write),
        }
    }

    /// [`four_cells`] in these registers.
    #[inline(always)]
    fn four<F: FrameCell, const GREATER: bool>(
        self,
        cells: (&mut [u32], &mut [F]),
        start: Stepped,
        step: Stepped,
        denominator: i64,
        write: CellWrite<F>,
    ) -> u64 {
        match self {
            // SAFETY: `Registers::Avx2` is made only where the processor has AVX2.
            #[cfg(target_arch = "x86_64")]
            Registers::Avx2 => unsafe { four_in_avx2::<F, GREATER>(cells, start, step, denominator, write) },
            Registers::Plain => four_cells::<Plain4, F, GREATER>(cells, start, step, denominator, write),
        }
    }
}

/// [`eight_cells`] in AVX2's registers (each loop its own function, so that
/// each is compiled as small as it was written).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn eight_in_avx2<F: FrameCell, const GREATER: bool>(
    cells: (&mut [u32], &mut [F]),
    length: usize,
    start: Stepped,
    eight: &EightLanes,
    write: CellWrite<F>,
) -> u64 {
    eight_cells::<Avx8, F, GREATER>(cells, length, start, eight, write)
}

/// [`four_cells`] in AVX2's registers.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn four_in_avx2<F: FrameCell, const GREATER: bool>(
    cells: (&mut [u32], &mut [F]),
    start: Stepped,
    step: Stepped,
    denominator: i64,
    write: CellWrite<F>,
) -> u64 {
    four_cells::<Avx4, F, GREATER>(cells, start, step, denominator, write)
}

/// [`span`] in `registers`: the one place the lanes are chosen. A span of up
/// to [`EightLanes::LONGEST`] cells eight at a time in 32-bit lanes when its
/// polygon's values fit them (`eight`, [`EightLanes::new`]) and the cells
/// hold whole chunks from its start ([`eight_cells`]), a chunk's cells past
/// the span rewritten with their own values; else a span of [`LONG_SPAN`]
/// cells or more four at a time in 64-bit lanes ([`four_cells`]); one cell
/// at a time otherwise.
#[inline(always)]
fn in_registers<F: FrameCell, const GREATER: bool>(
    registers: Registers,
    (depth, frame): (&mut [u32], &mut [F]),
    length: usize,
    stepping: (Stepped, Stepped, i64),
    eight: Option<&EightLanes>,
    write: CellWrite<F>,
) -> u64 {
    let write = write.compiled::<GREATER>();
    let Some(lanes) = lanes_for(registers, length, depth.len().min(frame.len()), stepping.0, eight) else {
        let (start, step, denominator) = stepping;
        return cell_by_cell((&mut depth[..length], &mut frame[..length]), start, step, denominator, write);
    };
    let (start, step, denominator) = stepping;
    match lanes {
        Lanes::Eight(room, eight) => {
            registers.eight::<F, GREATER>((&mut depth[..room], &mut frame[..room]), length, start, eight, write)
        }
        Lanes::Four => {
            registers.four::<F, GREATER>((&mut depth[..length], &mut frame[..length]), start, step, denominator, write)
        }
    }
}

/// Which lanes a span is drawn in.
#[derive(Debug, Clone, Copy)]
enum Lanes<'e> {
    /// Eight 32-bit lanes over the first `room` cells (a multiple of eight).
    Eight(usize, &'e EightLanes),
    /// Four 64-bit lanes.
    Four,
}

/// The lanes in `registers` for a span of `length` cells with `cells` cells
/// from its start (the span's and those after it), from `start` with the
/// polygon's `eight`; `None`: one cell at a time.
#[inline(always)]
fn lanes_for(
    registers: Registers,
    length: usize,
    cells: usize,
    start: Stepped,
    eight: Option<&EightLanes>,
) -> Option<Lanes<'_>> {
    let room = length.next_multiple_of(EIGHT);
    match eight {
        Some(eight)
            if room <= cells
                && start.whole.unsigned_abs() < EightLanes::WHOLE
                && length <= EightLanes::LONGEST
                && registers.draw_in(&Lanes::Eight(room, eight)) =>
        {
            Some(Lanes::Eight(room, eight))
        }
        // Lanes of 64 bits pay for their setup (four depths and a stride) only on longer spans.
        _ if length >= LONG_SPAN && registers.draw_in(&Lanes::Four) => Some(Lanes::Four),
        _ => None,
    }
}

/// A polygon's step, for its short spans drawn eight cells at a time in
/// 32-bit lanes ([`eight_cells`]): each lane's offset from a span's first
/// cell (`k` steps, as whole part and remainder), eight steps as one, the
/// denominator, and the test's constants in 32 bits.
#[derive(Debug, Clone, Copy)]
pub(super) struct EightLanes {
    whole: [i32; EIGHT],
    remainder: [i32; EIGHT],
    stride: [i32; 2],
    denominator: i32,
    max: i32,
    threshold: i32,
}

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
#[inline(always)]
fn eight_cells<L: Lanes32, F: FrameCell, const GREATER: bool>(
    (depth, frame): (&mut [u32], &mut [F]),
    length: usize,
    start: Stepped,
    eight: &EightLanes,
    write: CellWrite<F>,
) -> u64 {
    let write = write.compiled::<GREATER>();
    let test = write.test;
    let zero = L::splat(0);
    let denominator = L::splat(eight.denominator);
    let below_denominator = L::splat(eight.denominator - 1);
    let max = L::splat(eight.max);
    let threshold = L::splat(if GREATER { 0 } else { eight.threshold });
    let index = L::from_array([0, 1, 2, 3, 4, 5, 6, 7]);
    // The first chunk's depths: the start plus each lane's offset, one carry at most.
    let mut whole = L::splat(start.whole as i32).add(L::from_array(eight.whole));
    let mut remainder = L::splat(start.remainder as i32).add(L::from_array(eight.remainder));
    let carry = remainder.gt(below_denominator);
    whole = whole.sub(carry);
    remainder = remainder.sub(carry.and(denominator));
    let (stride_whole, stride_remainder) = (L::splat(eight.stride[0]), L::splat(eight.stride[1]));
    let mut written = 0u64;
    // By index, not by iterators over chunks: no call per chunk (the development guide).
    for chunk in 0..depth.len().min(frame.len()) / EIGHT {
        let cells = chunk * EIGHT..chunk * EIGHT + EIGHT;
        let (depth_cells, frame_cells) = (&mut depth[cells.clone()], &mut frame[cells]);
        let inside = L::splat((length - chunk * EIGHT) as i32).gt(index);
        // Each stored level at most the largest, below 2^28.
        let stored = L::load(depth_cells);
        // v: the ceiling (whole part, plus one where a remainder is left) or the floor.
        let v = if test.use_ceiling { whole.sub(remainder.gt(zero)) } else { whole };
        let difference = if test.sign > 0 { v.sub(stored) } else { stored.sub(v) };
        let passes = difference.gt(threshold).and(inside);
        // Rounded half up (one more where 2·remainder ≥ denominator), saturated to 0 … max.
        let half_up = remainder.add(remainder).gt(below_denominator);
        let rounded = whole.sub(half_up).max(zero).min(max);
        stored.select(rounded, passes).store(depth_cells);
        let mask = passes.mask_bits();
        match F::bytes(frame_cells) {
            Some(bytes) => passes.select_bytes(bytes, write.value.value() as u8),
            None => {
                for (k, cell) in frame_cells.iter_mut().enumerate() {
                    *cell = select_unpredictable(mask & (1 << k) != 0, write.value, *cell);
                }
            }
        }
        written += u64::from(mask.count_ones());
        // Eight cells on: the carry (−1 where the remainder reached the denominator) added to the whole part.
        remainder = remainder.add(stride_remainder);
        let carry = remainder.gt(below_denominator);
        whole = whole.add(stride_whole).sub(carry);
        remainder = remainder.sub(carry.and(denominator));
    }
    written
}

/// The span's cells, four at a time where the span holds four more, from
/// the depth at the first (`start`) with `step` per cell; returns how many
/// were written. `GREATER`: `write.test` is the book's test, its constants
/// folded in by the compiler.
#[inline(always)]
fn four_cells<L: Lanes64, F: FrameCell, const GREATER: bool>(
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
    let mut whole = L::from_array(wholes);
    let mut remainder = L::from_array(remainders);
    let (stride_whole, stride_remainder) = (L::splat(stride.whole), L::splat(stride.remainder));
    let zero = L::splat(0);
    let (denominator_lanes, below_denominator) = (L::splat(denominator), L::splat(denominator - 1));
    let (max, threshold) = (L::splat(write.max), L::splat(write.test.threshold));
    let mut written = 0u64;
    for chunk in 0..chunks {
        let cells = chunk * LANES..chunk * LANES + LANES;
        let depth_cells = &mut depth[cells.clone()];
        let stored = L::widen(depth_cells);
        // v: the ceiling (whole part, plus one where a remainder is left) or the floor.
        let v = if write.test.use_ceiling { whole.sub(remainder.gt(zero)) } else { whole };
        let difference = if write.test.sign > 0 { v.sub(stored) } else { stored.sub(v) };
        let passes = difference.gt(threshold);
        // Rounded half up (one more where 2·remainder ≥ denominator), saturated to 0 … max.
        let half_up = remainder.add(remainder).gt(below_denominator);
        let rounded = whole.sub(half_up);
        let rounded = rounded.select(zero, zero.gt(rounded));
        let rounded = rounded.select(max, rounded.gt(max));
        rounded.store_where(passes, depth_cells);
        let mask = passes.mask_bits();
        for (k, cell) in frame[cells].iter_mut().enumerate() {
            *cell = select_unpredictable(mask & (1 << k) != 0, write.value, *cell);
        }
        written += u64::from(mask.count_ones());
        // Four cells on: the carry (−1 where the remainder reached the denominator) added to the whole part.
        remainder = remainder.add(stride_remainder);
        let carry = remainder.gt(below_denominator);
        whole = whole.add(stride_whole).sub(carry);
        remainder = remainder.sub(carry.and(denominator_lanes));
    }
    let next = Stepped { whole: whole.first(), remainder: remainder.first() };
    let done = chunks * LANES;
    written + cell_by_cell((&mut depth[done..], &mut frame[done..]), next, step, denominator, write)
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::raster::depth::{BranchFreeTest, DepthTest};

    /// A depth or a step over `denominator`: a whole part in `whole` and a
    /// remainder below the denominator.
    fn stepped(denominator: i64, whole: std::ops::Range<i64>) -> impl Strategy<Value = Stepped> {
        (whole, 0..denominator).prop_map(|(whole, remainder)| Stepped { whole, remainder })
    }

    fn any_test() -> impl Strategy<Value = DepthTest> {
        prop::sample::select(vec![
            DepthTest::Greater,
            DepthTest::Less,
            DepthTest::GreaterEqual,
            DepthTest::LessEqual,
            DepthTest::Always,
            DepthTest::Never,
        ])
    }

    /// The span drawn in this processor's registers (AVX2's where it has
    /// them) and in the plain lanes, each on a copy of the cells, against the
    /// cells one at a time: the same cells, the same count, the cells after
    /// the span as they were. `F`: the framebuffer's cells (bytes take the
    /// 32-bit lanes' own byte selection, wider cells a cell at a time).
    fn lanes_agree<F: FrameCell + From<u8>>(
        (denominator, start, step): (i64, Stepped, Stepped),
        (stored, after, max): (&[u32], usize, u32),
        test: DepthTest,
        greater: bool,
    ) -> Result<(), TestCaseError> {
        let test = if greater { DepthTest::Greater } else { test };
        let write = CellWrite { test: BranchFreeTest::of(test), max: i64::from(max), value: F::from(9u8) };
        let length = stored.len();
        let cells: Vec<u32> = (0..length + after).map(|k| stored.get(k).copied().unwrap_or(max / 2)).collect();
        let frames: Vec<F> = (0..length + after).map(|k| F::from(k as u8)).collect();
        let eight = EightLanes::new(step, denominator, write);
        prop_assert_eq!(eight.is_some(), denominator < 1 << 26 && step.whole.unsigned_abs() < 1 << 20 && max < 1 << 28);
        let (mut depth_cells, mut frame_cells) = (cells.clone(), frames.clone());
        let expected =
            cell_by_cell((&mut depth_cells[..length], &mut frame_cells[..length]), start, step, denominator, write);
        let stepping = (start, step, denominator);
        let room = length.next_multiple_of(EIGHT);
        let eight_fits = start.whole.unsigned_abs() < EightLanes::WHOLE && length <= EightLanes::LONGEST;
        for registers in [Registers::of_processor(), Registers::Plain] {
            // The span as the registers' choice draws it, then in each loop whether chosen or not.
            let mut paths = vec![("chosen", usize::MAX)];
            paths.push(("four lanes", length));
            if eight.is_some() && eight_fits && room <= cells.len() {
                paths.push(("eight lanes", room));
            }
            for (path, cells_given) in paths {
                let (mut depth, mut frame) = (cells.clone(), frames.clone());
                let given = cells_given.min(depth.len());
                let drawn = (&mut depth[..given], &mut frame[..given]);
                let written = match (path, greater) {
                    ("chosen", true) => {
                        in_registers::<F, true>(registers, drawn, length, stepping, eight.as_ref(), write)
                    }
                    ("chosen", false) => {
                        in_registers::<F, false>(registers, drawn, length, stepping, eight.as_ref(), write)
                    }
                    ("four lanes", true) => registers.four::<F, true>(drawn, start, step, denominator, write),
                    ("four lanes", false) => registers.four::<F, false>(drawn, start, step, denominator, write),
                    (_, true) => registers.eight::<F, true>(drawn, length, start, eight.as_ref().unwrap(), write),
                    (_, false) => registers.eight::<F, false>(drawn, length, start, eight.as_ref().unwrap(), write),
                };
                prop_assert_eq!(&depth, &depth_cells, "{:?} registers, {}", registers, path);
                prop_assert_eq!(&frame, &frame_cells, "{:?} registers, {}", registers, path);
                prop_assert_eq!(written, expected, "{:?} registers, {}", registers, path);
            }
        }
        Ok(())
    }

    /// On a processor without AVX2 every span is drawn in the plain lanes or
    /// one cell at a time: CI runs the fast paths' tests so, under qemu's
    /// Westmere (`.ci/run`).
    #[test]
    #[ignore = "needs a processor without AVX2 (CI: qemu-x86_64 -cpu Westmere)"]
    fn without_avx2_the_lanes_are_the_plain_ones() {
        assert_eq!(Registers::of_processor(), Registers::Plain);
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        /// Spans of 0 to 40 cells over every test, with denominators from 1
        /// to near 2^61, on stored levels of 0 … 15, with up to 9 more cells
        /// after the span (which the 32-bit lanes may rewrite).
        #[cfg_attr(not(target_family = "wasm"), test)]
        #[cfg_attr(target_family = "wasm", wasm_bindgen_test::wasm_bindgen_test)]
        fn lanes_decide_as_the_cell_does(
            stepping in prop_oneof![1i64..40, Just((1i64 << 61) - 1)]
                .prop_flat_map(|d| (Just(d), stepped(d, -3..18), stepped(d, -2..3))),
            stored in prop::collection::vec(0u32..16, 0..40),
            after in 0usize..10,
            test in any_test(),
            greater in any::<bool>(),
        ) {
            lanes_agree::<u8>(stepping, (&stored, after, 15), test, greater)?;
            lanes_agree::<u16>(stepping, (&stored, after, 15), test, greater)?;
        }

        /// At the lanes' bounds: spans of 1 to 64 cells; stored levels, start
        /// depths and largest levels near the 2^28 the 32-bit lanes allow, on
        /// both sides of it; steps' whole parts near their 2^20; denominators
        /// near 2^26 and 2^61.
        #[cfg_attr(not(target_family = "wasm"), test)]
        #[cfg_attr(target_family = "wasm", wasm_bindgen_test::wasm_bindgen_test)]
        fn lanes_decide_as_the_cell_does_at_their_bounds(
            (max, stepping) in (prop_oneof![Just((1u32 << 28) - 1), Just(1u32 << 28), (1u32 << 27)..(1u32 << 29), 1u32..16],
                prop_oneof![Just((1i64 << 26) - 1), Just(1i64 << 26), 1i64..5, Just((1i64 << 61) - 1)])
                .prop_flat_map(|(max, d)| {
                    let reach = i64::from(max) + 8;
                    let whole = prop_oneof![-reach..reach, (1i64 << 28) - 40..(1i64 << 28) + 40, -(1i64 << 28) - 40..-(1i64 << 28) + 40];
                    let step = prop_oneof![-4i64..4, (1i64 << 20) - 2..(1i64 << 20) + 2, -(1i64 << 20) - 2..-(1i64 << 20) + 2];
                    let at = (whole, 0..d).prop_map(|(whole, remainder)| Stepped { whole, remainder });
                    let step = (step, 0..d).prop_map(|(whole, remainder)| Stepped { whole, remainder });
                    (Just(max), (Just(d), at, step))
                }),
            cells in 1usize..65,
            stored_seed in any::<u64>(),
            after in 0usize..10,
            test in any_test(),
            greater in any::<bool>(),
        ) {
            // Stored levels spread over 0 … max, and its ends.
            let mut state = stored_seed;
            let stored: Vec<u32> = (0..cells)
                .map(|k| {
                    state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    match k % 4 {
                        0 => max,
                        1 => 0,
                        _ => (state >> 33) as u32 % (max + 1),
                    }
                })
                .collect();
            lanes_agree::<u8>(stepping, (&stored, after, max), test, greater)?;
            lanes_agree::<u32>(stepping, (&stored, after, max), test, greater)?;
        }
    }
}
