//! Lanes: small fixed-width integer vectors the span loops
//! ([`super::lanes`]) are written over, as tiny-skia's `wide` does: eight
//! 32-bit lanes ([`Lanes32`]) and four 64-bit ones ([`Lanes64`]), each with
//! a plain version of arrays compiled on every target ([`Plain8`],
//! [`Plain4`]) and, on x86-64, an AVX2 one ([`Avx8`], [`Avx4`]). The loops
//! are generic over them: a processor with AVX2 runs them in its registers,
//! every other target (wasm32 included) over the plain arrays, and the
//! property tests run both.
//!
//! The streaming stores that put a drawn tile back ([`stream_copy`],
//! [`streamed`]) live here too: the crate's raw intrinsics are in this file
//! alone.
//!
//! Arithmetic wraps, as the processor's does; a comparison gives a mask,
//! every bit of a lane set where it holds and none where not; a selection
//! takes the lanes of `yes` where the mask is set.

/// Eight 32-bit lanes.
pub(super) trait Lanes32: Copy {
    /// Every lane `value`.
    fn splat(value: i32) -> Self;
    /// The lanes of an array.
    fn from_array(values: [i32; 8]) -> Self;
    /// Eight cells (each below 2^31).
    fn load(cells: &[u32]) -> Self;
    /// Into eight cells.
    fn store(self, cells: &mut [u32]);
    /// Lane by lane `self + other`.
    fn add(self, other: Self) -> Self;
    /// Lane by lane `self − other`.
    fn sub(self, other: Self) -> Self;
    /// Lane by lane `self & other`.
    fn and(self, other: Self) -> Self;
    /// The mask of `self > other`.
    fn gt(self, other: Self) -> Self;
    /// Lane by lane the smaller.
    fn min(self, other: Self) -> Self;
    /// Lane by lane the larger.
    fn max(self, other: Self) -> Self;
    /// `yes` where `mask` is set, `self` elsewhere.
    fn select(self, yes: Self, mask: Self) -> Self;
    /// Bit `k` set where lane `k`'s mask is.
    fn mask_bits(self) -> u32;
    /// Byte cell `k` of eight set to `value` where lane `k` of `self`, a
    /// mask, is set; the others left as they are.
    fn select_bytes(self, cells: &mut [u8], value: u8);
}

/// Four 64-bit lanes.
pub(super) trait Lanes64: Copy {
    /// Every lane `value`.
    fn splat(value: i64) -> Self;
    /// The lanes of an array.
    fn from_array(values: [i64; 4]) -> Self;
    /// Four cells, widened.
    fn widen(cells: &[u32]) -> Self;
    /// Lane `k` into cell `k` where `mask` is set (its low 32 bits), the
    /// other cells left as they are.
    fn store_where(self, mask: Self, cells: &mut [u32]);
    /// Lane by lane `self + other`.
    fn add(self, other: Self) -> Self;
    /// Lane by lane `self − other`.
    fn sub(self, other: Self) -> Self;
    /// Lane by lane `self & other`.
    fn and(self, other: Self) -> Self;
    /// The mask of `self > other`.
    fn gt(self, other: Self) -> Self;
    /// `yes` where `mask` is set, `self` elsewhere.
    fn select(self, yes: Self, mask: Self) -> Self;
    /// Bit `k` set where lane `k`'s mask is.
    fn mask_bits(self) -> u32;
    /// The first lane.
    fn first(self) -> i64;
}

/// Eight 32-bit lanes as an array: every target.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Plain8([i32; 8]);

impl Plain8 {
    #[inline(always)]
    fn zip(self, other: Plain8, f: impl Fn(i32, i32) -> i32) -> Plain8 {
        let mut lanes = self.0;
        for (lane, other) in lanes.iter_mut().zip(other.0) {
            *lane = f(*lane, other);
        }
        Plain8(lanes)
    }
}

impl Lanes32 for Plain8 {
    #[inline(always)]
    fn splat(value: i32) -> Self {
        Plain8([value; 8])
    }
    #[inline(always)]
    fn from_array(values: [i32; 8]) -> Self {
        Plain8(values)
    }
    #[inline(always)]
    fn load(cells: &[u32]) -> Self {
        let mut lanes = [0; 8];
        for (lane, cell) in lanes.iter_mut().zip(&cells[..8]) {
            *lane = *cell as i32;
        }
        Plain8(lanes)
    }
    #[inline(always)]
    fn store(self, cells: &mut [u32]) {
        for (cell, lane) in cells[..8].iter_mut().zip(self.0) {
            *cell = lane as u32;
        }
    }
    #[inline(always)]
    fn add(self, other: Self) -> Self {
        self.zip(other, i32::wrapping_add)
    }
    #[inline(always)]
    fn sub(self, other: Self) -> Self {
        self.zip(other, i32::wrapping_sub)
    }
    #[inline(always)]
    fn and(self, other: Self) -> Self {
        self.zip(other, |a, b| a & b)
    }
    #[inline(always)]
    fn gt(self, other: Self) -> Self {
        self.zip(other, |a, b| -i32::from(a > b))
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        self.zip(other, i32::min)
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        self.zip(other, i32::max)
    }
    #[inline(always)]
    fn select(self, yes: Self, mask: Self) -> Self {
        self.zip(mask, |no, mask| no & !mask).zip(yes.and(mask), |no, yes| no | yes)
    }
    #[inline(always)]
    fn mask_bits(self) -> u32 {
        (0..8).fold(0, |bits, k| bits | (u32::from(self.0[k] < 0) << k))
    }
    #[inline(always)]
    fn select_bytes(self, cells: &mut [u8], value: u8) {
        for (cell, mask) in cells[..8].iter_mut().zip(self.0) {
            *cell = std::hint::select_unpredictable(mask != 0, value, *cell);
        }
    }
}

/// Four 64-bit lanes as an array: every target.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Plain4([i64; 4]);

impl Plain4 {
    #[inline(always)]
    fn zip(self, other: Plain4, f: impl Fn(i64, i64) -> i64) -> Plain4 {
        let mut lanes = self.0;
        for (lane, other) in lanes.iter_mut().zip(other.0) {
            *lane = f(*lane, other);
        }
        Plain4(lanes)
    }
}

impl Lanes64 for Plain4 {
    #[inline(always)]
    fn splat(value: i64) -> Self {
        Plain4([value; 4])
    }
    #[inline(always)]
    fn from_array(values: [i64; 4]) -> Self {
        Plain4(values)
    }
    #[inline(always)]
    fn widen(cells: &[u32]) -> Self {
        let mut lanes = [0; 4];
        for (lane, cell) in lanes.iter_mut().zip(&cells[..4]) {
            *lane = i64::from(*cell);
        }
        Plain4(lanes)
    }
    #[inline(always)]
    fn store_where(self, mask: Self, cells: &mut [u32]) {
        for ((cell, value), mask) in cells[..4].iter_mut().zip(self.0).zip(mask.0) {
            *cell = std::hint::select_unpredictable(mask != 0, value as u32, *cell);
        }
    }
    #[inline(always)]
    fn add(self, other: Self) -> Self {
        self.zip(other, i64::wrapping_add)
    }
    #[inline(always)]
    fn sub(self, other: Self) -> Self {
        self.zip(other, i64::wrapping_sub)
    }
    #[inline(always)]
    fn and(self, other: Self) -> Self {
        self.zip(other, |a, b| a & b)
    }
    #[inline(always)]
    fn gt(self, other: Self) -> Self {
        self.zip(other, |a, b| -i64::from(a > b))
    }
    #[inline(always)]
    fn select(self, yes: Self, mask: Self) -> Self {
        self.zip(mask, |no, mask| no & !mask).zip(yes.and(mask), |no, yes| no | yes)
    }
    #[inline(always)]
    fn mask_bits(self) -> u32 {
        (0..4).fold(0, |bits, k| bits | (u32::from(self.0[k] < 0) << k))
    }
    #[inline(always)]
    fn first(self) -> i64 {
        self.0[0]
    }
}

/// Copies `from` into `to`, of the same length, past the cache where the
/// processor can: a tile's drawn cells go back to the buffers without the
/// buffers' old cells first being read into the cache (which an ordinary
/// store does, doubling the memory traffic). [`streamed`] orders them
/// before what follows.
pub(super) fn stream_copy<T: Copy>(to: &mut [T], from: &[T]) {
    assert_eq!(to.len(), from.len(), "a tile's row and the buffers' are as long");
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128i, _mm_loadu_si128, _mm_stream_si128};
        let bytes = std::mem::size_of_val(from);
        let (target, source) = (to.as_mut_ptr().cast::<u8>(), from.as_ptr().cast::<u8>());
        let head = target.align_offset(16).min(bytes);
        // SAFETY: both ranges are `bytes` long and lie in distinct slices;
        // each 16-byte store starts at a multiple of 16 (after `head`) and
        // ends within `to`; SSE2, which streaming stores need, is part of
        // every x86_64 processor.
        unsafe {
            std::ptr::copy_nonoverlapping(source, target, head);
            let mut offset = head;
            while offset + 16 <= bytes {
                let chunk = _mm_loadu_si128(source.add(offset).cast::<__m128i>());
                _mm_stream_si128(target.add(offset).cast::<__m128i>(), chunk);
                offset += 16;
            }
            std::ptr::copy_nonoverlapping(source.add(offset), target.add(offset), bytes - offset);
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    to.copy_from_slice(from);
}

/// Orders the streamed stores of [`stream_copy`] before every later store,
/// so that the band's cells are whole when another thread reads them.
pub(super) fn streamed() {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE is part of every x86_64 processor.
    unsafe {
        std::arch::x86_64::_mm_sfence()
    };
}

#[cfg(target_arch = "x86_64")]
pub(super) use avx2::{Avx4, Avx8};

/// The lanes in AVX2's 256-bit registers. A value of these types is made
/// only inside a function compiled with AVX2 (`#[target_feature(enable =
/// "avx2")]`, [`super::lanes`]) that runs after the processor was found to
/// have it; their methods, inlined there, are its instructions.
#[cfg(target_arch = "x86_64")]
mod avx2 {
    use std::arch::x86_64::{
        __m256i, _mm_blendv_epi8, _mm_loadl_epi64, _mm_loadu_si128, _mm_packs_epi16, _mm_packs_epi32, _mm_set1_epi8,
        _mm_storel_epi64, _mm_storeu_si128, _mm256_add_epi32, _mm256_add_epi64, _mm256_and_si256, _mm256_blendv_epi8,
        _mm256_castsi256_pd, _mm256_castsi256_ps, _mm256_castsi256_si128, _mm256_cmpgt_epi32, _mm256_cmpgt_epi64,
        _mm256_cvtepu32_epi64, _mm256_extracti128_si256, _mm256_loadu_si256, _mm256_max_epi32, _mm256_min_epi32,
        _mm256_movemask_pd, _mm256_movemask_ps, _mm256_permutevar8x32_epi32, _mm256_set1_epi32, _mm256_set1_epi64x,
        _mm256_setr_epi32, _mm256_storeu_si256, _mm256_sub_epi32, _mm256_sub_epi64,
    };

    use super::{Lanes32, Lanes64};

    /// Eight 32-bit lanes in an AVX2 register.
    #[derive(Debug, Clone, Copy)]
    pub(in crate::simulate::fast) struct Avx8(__m256i);

    /// Four 64-bit lanes in an AVX2 register.
    #[derive(Debug, Clone, Copy)]
    pub(in crate::simulate::fast) struct Avx4(__m256i);

    // SAFETY (every `unsafe` block below): the processor has AVX2, as a value of these
    // types exists only then (the module's documentation); loads and stores are unaligned
    // and within the slices, whose lengths are checked by indexing first.
    impl Lanes32 for Avx8 {
        #[inline(always)]
        fn splat(value: i32) -> Self {
            Avx8(unsafe { _mm256_set1_epi32(value) })
        }
        #[inline(always)]
        fn from_array(values: [i32; 8]) -> Self {
            Avx8(unsafe { _mm256_loadu_si256(values.as_ptr().cast()) })
        }
        #[inline(always)]
        fn load(cells: &[u32]) -> Self {
            let cells = &cells[..8];
            Avx8(unsafe { _mm256_loadu_si256(cells.as_ptr().cast()) })
        }
        #[inline(always)]
        fn store(self, cells: &mut [u32]) {
            let cells = &mut cells[..8];
            unsafe { _mm256_storeu_si256(cells.as_mut_ptr().cast(), self.0) }
        }
        #[inline(always)]
        fn add(self, other: Self) -> Self {
            Avx8(unsafe { _mm256_add_epi32(self.0, other.0) })
        }
        #[inline(always)]
        fn sub(self, other: Self) -> Self {
            Avx8(unsafe { _mm256_sub_epi32(self.0, other.0) })
        }
        #[inline(always)]
        fn and(self, other: Self) -> Self {
            Avx8(unsafe { _mm256_and_si256(self.0, other.0) })
        }
        #[inline(always)]
        fn gt(self, other: Self) -> Self {
            Avx8(unsafe { _mm256_cmpgt_epi32(self.0, other.0) })
        }
        #[inline(always)]
        fn min(self, other: Self) -> Self {
            Avx8(unsafe { _mm256_min_epi32(self.0, other.0) })
        }
        #[inline(always)]
        fn max(self, other: Self) -> Self {
            Avx8(unsafe { _mm256_max_epi32(self.0, other.0) })
        }
        #[inline(always)]
        fn select(self, yes: Self, mask: Self) -> Self {
            Avx8(unsafe { _mm256_blendv_epi8(self.0, yes.0, mask.0) })
        }
        #[inline(always)]
        fn mask_bits(self) -> u32 {
            (unsafe { _mm256_movemask_ps(_mm256_castsi256_ps(self.0)) }) as u32
        }
        #[inline(always)]
        fn select_bytes(self, cells: &mut [u8], value: u8) {
            let cells = &mut cells[..8];
            unsafe {
                // Each lane's mask narrowed to a byte, in lane order: 32 → 16 → 8 bits, saturated.
                let words = _mm_packs_epi32(_mm256_castsi256_si128(self.0), _mm256_extracti128_si256::<1>(self.0));
                let bytes = _mm_packs_epi16(words, words);
                let before = _mm_loadl_epi64(cells.as_ptr().cast());
                let after = _mm_blendv_epi8(before, _mm_set1_epi8(value as i8), bytes);
                _mm_storel_epi64(cells.as_mut_ptr().cast(), after);
            }
        }
    }

    impl Lanes64 for Avx4 {
        #[inline(always)]
        fn splat(value: i64) -> Self {
            Avx4(unsafe { _mm256_set1_epi64x(value) })
        }
        #[inline(always)]
        fn from_array(values: [i64; 4]) -> Self {
            Avx4(unsafe { _mm256_loadu_si256(values.as_ptr().cast()) })
        }
        #[inline(always)]
        fn widen(cells: &[u32]) -> Self {
            let cells = &cells[..4];
            Avx4(unsafe { _mm256_cvtepu32_epi64(_mm_loadu_si128(cells.as_ptr().cast())) })
        }
        #[inline(always)]
        fn store_where(self, mask: Self, cells: &mut [u32]) {
            let cells = &mut cells[..4];
            unsafe {
                // The low 32 bits of each 64-bit lane, gathered into the low 128 bits.
                let low_halves = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
                let values = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(self.0, low_halves));
                let mask = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(mask.0, low_halves));
                let before = _mm_loadu_si128(cells.as_ptr().cast());
                _mm_storeu_si128(cells.as_mut_ptr().cast(), _mm_blendv_epi8(before, values, mask));
            }
        }
        #[inline(always)]
        fn add(self, other: Self) -> Self {
            Avx4(unsafe { _mm256_add_epi64(self.0, other.0) })
        }
        #[inline(always)]
        fn sub(self, other: Self) -> Self {
            Avx4(unsafe { _mm256_sub_epi64(self.0, other.0) })
        }
        #[inline(always)]
        fn and(self, other: Self) -> Self {
            Avx4(unsafe { _mm256_and_si256(self.0, other.0) })
        }
        #[inline(always)]
        fn gt(self, other: Self) -> Self {
            Avx4(unsafe { _mm256_cmpgt_epi64(self.0, other.0) })
        }
        #[inline(always)]
        fn select(self, yes: Self, mask: Self) -> Self {
            Avx4(unsafe { _mm256_blendv_epi8(self.0, yes.0, mask.0) })
        }
        #[inline(always)]
        fn mask_bits(self) -> u32 {
            (unsafe { _mm256_movemask_pd(_mm256_castsi256_pd(self.0)) }) as u32
        }
        #[inline(always)]
        fn first(self) -> i64 {
            unsafe { std::arch::x86_64::_mm_cvtsi128_si64(_mm256_castsi256_si128(self.0)) }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Streamed copies hold what `copy_from_slice` gives, whatever the
    /// target's alignment and length (the head before a 16-byte boundary
    /// and the tail after the last whole chunk are copied as usual).
    #[cfg_attr(not(target_family = "wasm"), test)]
    #[cfg_attr(target_family = "wasm", wasm_bindgen_test::wasm_bindgen_test)]
    fn a_streamed_copy_is_a_copy() {
        fn check<T: Copy + PartialEq + std::fmt::Debug + From<u8>>() {
            let source: Vec<T> = (0..200u8).map(T::from).collect();
            for offset in 0..9 {
                for length in 0..source.len() - offset {
                    let mut target = vec![T::from(255); source.len()];
                    let mut copied = target.clone();
                    stream_copy(&mut target[offset..offset + length], &source[..length]);
                    streamed();
                    copied[offset..offset + length].copy_from_slice(&source[..length]);
                    assert_eq!(target, copied, "offset {offset}, length {length}");
                }
            }
        }
        check::<u8>();
        check::<u16>();
        check::<u32>();
    }
}
