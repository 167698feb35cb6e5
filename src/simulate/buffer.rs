//! The framebuffer and the z-buffer.
//!
//! Both are stored row by row with pixel (0, 0) at the bottom left, as the
//! book numbers pixels; [`Buffers::frame_rows`] and [`Buffers::depth_rows`]
//! give them top row first, as the book prints them.

use crate::numbers::Exact;
use crate::raster::depth::Stored;
use crate::scene::pages::{HUGE_PAGE, PAGE, advise_huge_pages, with_huge_pages};

/// A framebuffer and a z-buffer of the same size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Buffers {
    width: u32,
    height: u32,
    frame: FrameCells,
    depth: DepthCells,
}

/// A framebuffer cell: the smallest unsigned integer that holds the scene's
/// `frame_bits` (1 byte up to 8 bits, 2 up to 16, 4 beyond), so that large
/// rasters take no more memory than their values need.
pub trait FrameCell: Copy + Eq + Default + Send + std::fmt::Debug {
    /// The cell holding `value`, which fits (values are checked against
    /// `frame_bits` when the scene is read).
    fn from_value(value: u32) -> Self;
    /// The value held.
    fn value(self) -> u32;
    /// The cells as bytes, when a cell is one.
    fn bytes(cells: &mut [Self]) -> Option<&mut [u8]>;
}

macro_rules! frame_cell {
    ($($cell:ty: $bytes:expr),*) => {$(
        impl FrameCell for $cell {
            #[inline]
            fn from_value(value: u32) -> $cell {
                debug_assert!(<$cell>::try_from(value).is_ok(), "value {value} wider than its cell: please report this bug");
                value as $cell
            }

            #[inline]
            fn value(self) -> u32 {
                u32::from(self)
            }

            #[inline(always)]
            fn bytes(cells: &mut [$cell]) -> Option<&mut [u8]> {
                $bytes(cells)
            }
        }
    )*};
}

frame_cell!(u8: Some, u16: |_| None, u32: |_| None);

/// The framebuffer's cells, in the width its bits need.
#[derive(Debug, Clone, PartialEq, Eq)]
enum FrameCells {
    Bytes(Cells<u8>),
    Halves(Cells<u16>),
    Words(Cells<u32>),
}

/// Code that works on the cells of a quantized z-buffer and of the
/// framebuffer, whatever the framebuffer's cell width: see
/// [`Buffers::with_level_cells`].
pub trait LevelCells {
    /// What it returns.
    type Output;
    /// Runs on both buffers' cells, rows bottom first.
    fn run<F: FrameCell>(self, frame: &mut [F], depth: &mut [u32]) -> Self::Output;
}

/// The z-buffer's cells: integer levels (4 bytes each) or exact values.
#[derive(Debug, Clone, PartialEq, Eq)]
enum DepthCells {
    Levels(Cells<u32>),
    Exact(Vec<Exact>),
}

impl Buffers {
    /// Buffers filled with the background value and the clear depth, whose
    /// kind (level or exact) fixes the kind of every cell.
    /// The size must already be validated (see `scene::MAX_CELLS`).
    /// The framebuffer's cells are as wide as `frame_bits` need (see `FrameCell`).
    pub fn new(width: u32, height: u32, frame_bits: u32, background: u32, clear_depth: Stored) -> Buffers {
        Buffers::new_on(width, height, frame_bits, background, clear_depth, None)
    }

    /// [`Buffers::new`], large buffers cleared on `pool`'s threads: the same
    /// cells, the page faults of fresh memory taken on every core.
    pub fn new_on(
        width: u32,
        height: u32,
        frame_bits: u32,
        background: u32,
        clear_depth: Stored,
        pool: Option<&rayon::ThreadPool>,
    ) -> Buffers {
        let cells = width as usize * height as usize;
        // Threads only where cells are written now: zeros are left unwritten (`Cells::new`).
        let written = background != 0 || !matches!(clear_depth, Stored::Level(0));
        let pool = if written { clearing(cells, pool) } else { None };
        let depth = match clear_depth {
            Stored::Level(level) => DepthCells::Levels(Cells::new(cells, level, pool)),
            Stored::Exact(value) => DepthCells::Exact(filled(cells, value, pool)),
        };
        let frame = match frame_bits {
            0..=8 => FrameCells::Bytes(Cells::new(cells, u8::from_value(background), pool)),
            9..=16 => FrameCells::Halves(Cells::new(cells, u16::from_value(background), pool)),
            _ => FrameCells::Words(Cells::new(cells, background, pool)),
        };
        Buffers { width, height, frame, depth }
    }

    /// Sets every cell back to the background value and the clear depth in
    /// the memory the buffers already hold (a GPU's clear): the cells
    /// [`Buffers::new`] would make with the same values.
    /// Large buffers are cleared on `pool`'s threads.
    pub fn clear(&mut self, frame_bits: u32, background: u32, clear_depth: &Stored, pool: Option<&rayon::ThreadPool>) {
        let pool = clearing(self.width as usize * self.height as usize, pool);
        match (&mut self.depth, clear_depth) {
            (DepthCells::Levels(cells), Stored::Level(level)) => fill(cells, *level, pool),
            (DepthCells::Exact(cells), Stored::Exact(value)) => fill(cells, value.clone(), pool),
            // Another kind of depth: new buffers.
            _ => {
                *self = Buffers::new_on(self.width, self.height, frame_bits, background, clear_depth.clone(), pool);
                return;
            }
        }
        match &mut self.frame {
            FrameCells::Bytes(cells) => fill(cells, u8::from_value(background), pool),
            FrameCells::Halves(cells) => fill(cells, u16::from_value(background), pool),
            FrameCells::Words(cells) => fill(cells, background, pool),
        }
    }

    /// Has the system hand over every page of both buffers now, their cells
    /// unchanged. Fresh memory reads as zeros that are not there yet: the
    /// first write to each page waits for the kernel to zero it. A run that
    /// times its clearing and drawing, as a GPU's frame is timed in a
    /// framebuffer made beforehand, takes the pages first.
    pub fn take_pages(&mut self) {
        match &mut self.depth {
            DepthCells::Levels(cells) => cells.take_pages(),
            // Exact depths are written when made.
            DepthCells::Exact(_) => {}
        }
        match &mut self.frame {
            FrameCells::Bytes(cells) => cells.take_pages(),
            FrameCells::Halves(cells) => cells.take_pages(),
            FrameCells::Words(cells) => cells.take_pages(),
        }
    }

    /// Runs `code` on both buffers' cells when the z-buffer holds levels
    /// (`None` when it holds exact values): the loops that write many cells.
    pub fn with_level_cells<C: LevelCells>(&mut self, code: C) -> Option<C::Output> {
        let DepthCells::Levels(depth) = &mut self.depth else { return None };
        Some(match &mut self.frame {
            FrameCells::Bytes(frame) => code.run(frame, depth),
            FrameCells::Halves(frame) => code.run(frame, depth),
            FrameCells::Words(frame) => code.run(frame, depth),
        })
    }

    /// Whether the z-buffer holds levels, so that [`Buffers::with_level_cells`] runs.
    pub fn holds_levels(&self) -> bool {
        matches!(self.depth, DepthCells::Levels(_))
    }

    /// The bytes both buffers' cells take in memory, as zsim stores them (a
    /// framebuffer cell of 1, 2 or 4 bytes, 4 bytes a depth level, a whole
    /// rational an exact depth); `zsim memory` gives the book's packed figures.
    pub fn memory_bytes(&self) -> u64 {
        let depth = match &self.depth {
            DepthCells::Levels(cells) => std::mem::size_of_val(&**cells),
            DepthCells::Exact(cells) => std::mem::size_of_val(cells.as_slice()),
        };
        let frame = match &self.frame {
            FrameCells::Bytes(cells) => cells.len(),
            FrameCells::Halves(cells) => cells.len() * 2,
            FrameCells::Words(cells) => cells.len() * 4,
        };
        (frame + depth) as u64
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    fn index(&self, x: u32, y: u32) -> usize {
        debug_assert!(x < self.width && y < self.height, "pixel ({x}, {y}) outside the raster: please report this bug");
        y as usize * self.width as usize + x as usize
    }

    /// The framebuffer value at pixel (x, y).
    pub fn frame(&self, x: u32, y: u32) -> u32 {
        self.frame.get(self.index(x, y))
    }

    /// The z-buffer value at pixel (x, y).
    pub fn depth(&self, x: u32, y: u32) -> Stored {
        let index = self.index(x, y);
        match &self.depth {
            DepthCells::Levels(cells) => Stored::Level(cells[index]),
            DepthCells::Exact(cells) => Stored::Exact(cells[index].clone()),
        }
    }

    /// Writes both buffers at pixel (x, y); the depth is of the buffer's kind.
    pub fn store(&mut self, x: u32, y: u32, frame: u32, depth: Stored) {
        let index = self.index(x, y);
        self.frame.set(index, frame);
        match (&mut self.depth, depth) {
            (DepthCells::Levels(cells), Stored::Level(level)) => cells[index] = level,
            (DepthCells::Exact(cells), Stored::Exact(value)) => cells[index] = value,
            _ => debug_assert!(false, "depth of the wrong kind stored: please report this bug"),
        }
    }

    /// How many framebuffer cells and how many z-buffer cells differ from
    /// `other`'s (buffers of the same size and kind).
    pub fn differences(&self, other: &Buffers) -> (u64, u64) {
        let frame = (0..self.frame.len()).filter(|&i| self.frame.get(i) != other.frame.get(i)).count() as u64;
        let depth = match (&self.depth, &other.depth) {
            (DepthCells::Levels(a), DepthCells::Levels(b)) => a.iter().zip(b.iter()).filter(|(x, y)| x != y).count(),
            (DepthCells::Exact(a), DepthCells::Exact(b)) => a.iter().zip(b).filter(|(x, y)| x != y).count(),
            _ => self.depth.len(),
        } as u64;
        (frame, depth)
    }

    /// The framebuffer as rows, top row (y = height − 1) first.
    pub fn frame_rows(&self) -> Vec<Vec<u32>> {
        let values: Vec<u32> = (0..self.frame.len()).map(|i| self.frame.get(i)).collect();
        rows_top_first(&values, self.width)
    }

    /// The z-buffer as rows, top row (y = height − 1) first.
    pub fn depth_rows(&self) -> Vec<Vec<Stored>> {
        match &self.depth {
            DepthCells::Levels(cells) => rows_top_first(cells, self.width)
                .into_iter()
                .map(|r| r.into_iter().map(Stored::Level).collect())
                .collect(),
            DepthCells::Exact(cells) => rows_top_first(cells, self.width)
                .into_iter()
                .map(|r| r.into_iter().map(Stored::Exact).collect())
                .collect(),
        }
    }

    /// The z-buffer as integer rows, top row first, when it holds levels.
    pub fn depth_level_rows(&self) -> Option<Vec<Vec<u32>>> {
        match &self.depth {
            DepthCells::Levels(cells) => Some(rows_top_first(cells, self.width)),
            DepthCells::Exact(_) => None,
        }
    }
}

/// The integer cells of one buffer: a vector of zeros from the system, of
/// which the cells used start at `start`. Memory fresh from the system
/// reads as zeros, so zeros are left unwritten: its pages are first touched
/// where the cells are first written, by the thread that draws them, and a
/// tiled run writes them once instead of twice. A large buffer's cells
/// start on a 2 MiB boundary and are offered huge pages: Linux backs with
/// them only whole 2 MiB pages aligned in memory, which a vector's start is
/// not, so that otherwise the first and last megabytes of each buffer take
/// a page fault every 4 KiB.
#[derive(Clone)]
struct Cells<T> {
    memory: Vec<T>,
    start: usize,
}

impl<T: FrameCell + Sync> Cells<T> {
    /// `cells` copies of `value`; any other value than zero written now
    /// (the book's first step: clear both buffers), with a pool each of its
    /// threads writing a part.
    fn new(cells: usize, value: T, pool: Option<&rayon::ThreadPool>) -> Cells<T> {
        let size = std::mem::size_of::<T>();
        let large = cells * size >= 2 * HUGE_PAGE;
        let room = if large { HUGE_PAGE / size } else { 0 };
        // The standard library allocates integer zeros already zeroed (calloc), without writing them.
        let mut memory = vec![T::default(); cells + room];
        let start = if large { memory.as_ptr().align_offset(HUGE_PAGE).min(room) } else { 0 };
        memory.truncate(start + cells);
        if large {
            advise_huge_pages(memory[start..].as_mut_ptr().cast(), cells * size);
        }
        let mut made = Cells { memory, start };
        if value != T::default() {
            fill(&mut made, value, pool);
        }
        made
    }
}

impl<T: Copy> Cells<T> {
    /// Writes each page's first cell with the value it holds, so that the
    /// system hands the page over now (see [`Buffers::take_pages`]).
    fn take_pages(&mut self) {
        let step = (PAGE / std::mem::size_of::<T>()).max(1);
        let cells: &mut [T] = self;
        for cell in cells.iter_mut().step_by(step) {
            // Unknown to the compiler, so the write is made.
            *cell = std::hint::black_box(*cell);
        }
    }
}

impl<T> std::ops::Deref for Cells<T> {
    type Target = [T];

    fn deref(&self) -> &[T] {
        &self.memory[self.start..]
    }
}

impl<T> std::ops::DerefMut for Cells<T> {
    fn deref_mut(&mut self) -> &mut [T] {
        &mut self.memory[self.start..]
    }
}

impl<T: PartialEq> PartialEq for Cells<T> {
    fn eq(&self, other: &Cells<T>) -> bool {
        **self == **other
    }
}

impl<T: Eq> Eq for Cells<T> {}

impl<T: std::fmt::Debug> std::fmt::Debug for Cells<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(&**self, f)
    }
}

/// `cells` copies of `value`, all written now (the book's first step: clear
/// both buffers). A large buffer is first offered transparent huge pages, so
/// that clearing it takes a few dozen page faults instead of tens of
/// thousands.
/// With a pool, each of its threads writes a part.
fn filled<T: Clone + Send + Sync>(cells: usize, value: T, pool: Option<&rayon::ThreadPool>) -> Vec<T> {
    let mut out = with_huge_pages(cells);
    match pool {
        Some(pool) => {
            pool.install(|| rayon::iter::ParallelExtend::par_extend(&mut out, rayon::iter::repeat_n(value, cells)))
        }
        None => out.resize(cells, value),
    }
    out
}

/// Every cell set to `value`; with a pool, a part on each of its threads.
fn fill<T: Clone + Send + Sync>(cells: &mut [T], value: T, pool: Option<&rayon::ThreadPool>) {
    use rayon::prelude::*;
    match pool {
        Some(pool) => {
            let part = cells.len().div_ceil(pool.current_num_threads()).max(1);
            pool.install(|| cells.par_chunks_mut(part).for_each(|part| part.fill(value.clone())));
        }
        None => cells.fill(value),
    }
}

/// Buffers of at least this many cells are cleared on several threads when
/// asked to (a 1024² raster, 8 MiB of 24-bit depth and 8-bit frame): below
/// it a second thread wins nothing.
const PARALLEL_CLEAR: usize = 1 << 20;

/// The threads that clear `cells` cells: `pool`'s when the buffers are
/// large; `None` (one thread clears) otherwise.
fn clearing(cells: usize, pool: Option<&rayon::ThreadPool>) -> Option<&rayon::ThreadPool> {
    pool.filter(|_| cells >= PARALLEL_CLEAR)
}

fn rows_top_first<T: Clone>(cells: &[T], width: u32) -> Vec<Vec<T>> {
    cells.chunks_exact(width as usize).rev().map(<[T]>::to_vec).collect()
}

impl FrameCells {
    fn len(&self) -> usize {
        match self {
            FrameCells::Bytes(cells) => cells.len(),
            FrameCells::Halves(cells) => cells.len(),
            FrameCells::Words(cells) => cells.len(),
        }
    }

    fn get(&self, index: usize) -> u32 {
        match self {
            FrameCells::Bytes(cells) => cells[index].value(),
            FrameCells::Halves(cells) => cells[index].value(),
            FrameCells::Words(cells) => cells[index],
        }
    }

    fn set(&mut self, index: usize, value: u32) {
        match self {
            FrameCells::Bytes(cells) => cells[index] = u8::from_value(value),
            FrameCells::Halves(cells) => cells[index] = u16::from_value(value),
            FrameCells::Words(cells) => cells[index] = value,
        }
    }
}

impl DepthCells {
    fn len(&self) -> usize {
        match self {
            DepthCells::Levels(cells) => cells.len(),
            DepthCells::Exact(cells) => cells.len(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bytes of private memory the system has handed over in the
    /// mapping that holds `cells` (Linux's `/proc/self/smaps`, "Anonymous"):
    /// pages written, not fresh pages only read (those show the system's
    /// one page of zeros). A large buffer offered huge pages is a mapping of
    /// its own.
    #[cfg(target_os = "linux")]
    fn handed_over<T>(cells: &[T]) -> u64 {
        let at = cells.as_ptr() as u64;
        let smaps = crate::door::inward::read_bytes(
            std::path::Path::new("/proc/self/smaps"),
            crate::door::inward::Links::Follow,
        )
        .expect("Linux has /proc/self/smaps");
        let smaps = String::from_utf8_lossy(&smaps);
        let mut inside = false;
        for line in smaps.lines() {
            let range = line.split_whitespace().next().and_then(|range| range.split_once('-'));
            if let Some((start, end)) =
                range.and_then(|(s, e)| Some((u64::from_str_radix(s, 16).ok()?, u64::from_str_radix(e, 16).ok()?)))
            {
                inside = (start..end).contains(&at);
            } else if inside && let Some(kib) = line.strip_prefix("Anonymous:") {
                return kib.trim().trim_end_matches("kB").trim().parse::<u64>().expect("a size in kB") * 1024;
            }
        }
        panic!("no mapping holds the cells")
    }

    /// Fresh buffers' memory is not yet the process's; taking the pages
    /// has the system hand over every page of the z-buffer (written, not
    /// only read) and changes no cell.
    #[cfg(target_os = "linux")]
    #[test]
    fn taking_the_pages_has_the_system_hand_them_over_and_changes_no_cell() {
        // Compared with buffers made alike: a clone would read the cells first.
        let made = || Buffers::new(4096, 2048, 2, 0, Stored::Level(0));
        let mut buffers = made();
        let depth = |buffers: &Buffers| match &buffers.depth {
            DepthCells::Levels(cells) => (handed_over(cells), std::mem::size_of_val(&**cells) as u64),
            DepthCells::Exact(_) => panic!("level cells"),
        };
        let (before, bytes) = depth(&buffers);
        assert!(before < bytes / 100, "a fresh z-buffer is not yet the process's: {before} of {bytes} bytes");
        buffers.take_pages();
        let (after, _) = depth(&buffers);
        assert!(after >= bytes, "{after} of {bytes} bytes handed over");
        assert_eq!(buffers, made());
        let mut cleared = Buffers::new(64, 64, 8, 3, Stored::Level(9));
        let before = cleared.clone();
        cleared.take_pages();
        assert_eq!(cleared, before);
    }

    /// A large buffer's cells start on a 2 MiB boundary (so that every page
    /// of it can be a huge one) and hold the clear value, zero or not; a
    /// small buffer's start where its vector does.
    #[test]
    fn large_buffers_start_on_a_huge_page() {
        let cells = 1 << 20;
        for value in [0, 5] {
            let large = Cells::<u32>::new(cells, value, None);
            assert_eq!(large.as_ptr() as usize % HUGE_PAGE, 0, "value {value}");
            assert_eq!(large.len(), cells);
            assert!(large.iter().all(|&cell| cell == value), "value {value}");
            let small = Cells::<u8>::new(1000, value as u8, None);
            assert_eq!((small.start, small.len()), (0, 1000));
            assert_eq!(large.clone(), large, "value {value}: a copy holds the same cells");
        }
    }

    #[test]
    fn pixel_origin_is_bottom_left_and_printed_last() {
        let mut buffers = Buffers::new(3, 2, 2, 0, Stored::Level(0));
        buffers.store(0, 0, 7, Stored::Level(9));
        assert_eq!(buffers.frame_rows(), vec![vec![0, 0, 0], vec![7, 0, 0]]);
        assert_eq!(buffers.depth_rows()[1][0], Stored::Level(9));
        assert_eq!(buffers.differences(&Buffers::new(3, 2, 2, 0, Stored::Level(0))), (1, 1));
        // 2-bit framebuffer values in bytes, depth levels in 4 bytes.
        assert_eq!(buffers.memory_bytes(), 6 + 6 * 4);
        assert_eq!(Buffers::new(3, 2, 9, 0, Stored::Level(0)).memory_bytes(), 6 * 2 + 6 * 4);
        assert_eq!(Buffers::new(3, 2, 17, 0, Stored::Level(0)).memory_bytes(), 6 * 4 + 6 * 4);
        let mut wide = Buffers::new(3, 2, 32, 0, Stored::Level(0));
        wide.store(2, 1, u32::MAX, Stored::Level(1));
        assert_eq!(wide.frame(2, 1), u32::MAX);
    }
}
