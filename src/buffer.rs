//! The framebuffer and the z-buffer.
//!
//! Both are stored row by row with pixel (0, 0) at the bottom left, as the
//! book numbers pixels; [`Buffers::frame_rows`] and [`Buffers::depth_rows`]
//! give them top row first, as the book prints them.

use crate::depth::Stored;
use crate::exact::Q;

/// A framebuffer and a z-buffer of the same size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Buffers {
    width: u32,
    height: u32,
    frame: Vec<u32>,
    depth: DepthCells,
}

/// The z-buffer's cells: integer levels (4 bytes each) or exact values.
#[derive(Debug, Clone, PartialEq, Eq)]
enum DepthCells {
    Levels(Vec<u32>),
    Exact(Vec<Q>),
}

impl Buffers {
    /// Buffers filled with the background value and the clear depth, whose
    /// kind (level or exact) fixes the kind of every cell.
    /// The size must already be validated (see `scene::MAX_CELLS`).
    pub fn new(width: u32, height: u32, background: u32, clear_depth: Stored) -> Buffers {
        let cells = width as usize * height as usize;
        let depth = match clear_depth {
            Stored::Level(level) => DepthCells::Levels(vec![level; cells]),
            Stored::Exact(q) => DepthCells::Exact(vec![q; cells]),
        };
        Buffers { width, height, frame: vec![background; cells], depth }
    }

    /// The bytes both buffers' cells take in memory, as zsim stores them
    /// (4 bytes a level, a whole rational an exact value); `zsim memory`
    /// gives the book's packed figures instead.
    pub fn memory_bytes(&self) -> u64 {
        let depth = match &self.depth {
            DepthCells::Levels(cells) => std::mem::size_of_val(cells.as_slice()),
            DepthCells::Exact(cells) => std::mem::size_of_val(cells.as_slice()),
        };
        (std::mem::size_of_val(self.frame.as_slice()) + depth) as u64
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
        self.frame[self.index(x, y)]
    }

    /// The z-buffer value at pixel (x, y).
    pub fn depth(&self, x: u32, y: u32) -> Stored {
        let index = self.index(x, y);
        match &self.depth {
            DepthCells::Levels(cells) => Stored::Level(cells[index]),
            DepthCells::Exact(cells) => Stored::Exact(cells[index]),
        }
    }

    /// Writes both buffers at pixel (x, y); the depth is of the buffer's kind.
    pub fn store(&mut self, x: u32, y: u32, frame: u32, depth: Stored) {
        let index = self.index(x, y);
        self.frame[index] = frame;
        match (&mut self.depth, depth) {
            (DepthCells::Levels(cells), Stored::Level(level)) => cells[index] = level,
            (DepthCells::Exact(cells), Stored::Exact(q)) => cells[index] = q,
            _ => debug_assert!(false, "depth of the wrong kind stored: please report this bug"),
        }
    }

    /// How many framebuffer cells and how many z-buffer cells differ from
    /// `other`'s (buffers of the same size and kind).
    pub fn differences(&self, other: &Buffers) -> (u64, u64) {
        let frame = self.frame.iter().zip(&other.frame).filter(|(a, b)| a != b).count() as u64;
        let depth = match (&self.depth, &other.depth) {
            (DepthCells::Levels(a), DepthCells::Levels(b)) => a.iter().zip(b).filter(|(x, y)| x != y).count(),
            (DepthCells::Exact(a), DepthCells::Exact(b)) => a.iter().zip(b).filter(|(x, y)| x != y).count(),
            _ => self.depth.len(),
        } as u64;
        (frame, depth)
    }

    /// The framebuffer as rows, top row (y = height − 1) first.
    pub fn frame_rows(&self) -> Vec<Vec<u32>> {
        rows_top_first(&self.frame, self.width)
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

    /// Both buffers' cells (rows bottom first) when the z-buffer holds
    /// levels, for loops that write many cells.
    pub fn level_cells_mut(&mut self) -> Option<(&mut [u32], &mut [u32])> {
        match &mut self.depth {
            DepthCells::Levels(depth) => Some((&mut self.frame, depth)),
            DepthCells::Exact(_) => None,
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

fn rows_top_first<T: Clone>(cells: &[T], width: u32) -> Vec<Vec<T>> {
    cells.chunks_exact(width as usize).rev().map(<[T]>::to_vec).collect()
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

    #[test]
    fn pixel_origin_is_bottom_left_and_printed_last() {
        let mut buffers = Buffers::new(3, 2, 0, Stored::Level(0));
        buffers.store(0, 0, 7, Stored::Level(9));
        assert_eq!(buffers.frame_rows(), vec![vec![0, 0, 0], vec![7, 0, 0]]);
        assert_eq!(buffers.depth_rows()[1][0], Stored::Level(9));
        assert_eq!(buffers.differences(&Buffers::new(3, 2, 0, Stored::Level(0))), (1, 1));
        assert_eq!(buffers.memory_bytes(), 6 * 4 + 6 * 4);
    }
}
