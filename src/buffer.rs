//! The framebuffer and the z-buffer.
//!
//! Both are stored row by row with pixel (0, 0) at the bottom left, as the
//! book numbers pixels; [`Buffers::frame_rows`] and [`Buffers::depth_rows`]
//! give them top row first, as the book prints them.

/// A framebuffer and a z-buffer of the same size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Buffers {
    width: u32,
    height: u32,
    frame: Vec<u32>,
    depth: Vec<u32>,
}

impl Buffers {
    /// Buffers filled with the background value and the clear depth.
    /// The size must already be validated (see `scene::MAX_CELLS`).
    pub fn new(width: u32, height: u32, background: u32, clear_depth: u32) -> Buffers {
        let cells = width as usize * height as usize;
        Buffers { width, height, frame: vec![background; cells], depth: vec![clear_depth; cells] }
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
    pub fn depth(&self, x: u32, y: u32) -> u32 {
        self.depth[self.index(x, y)]
    }

    /// Writes both buffers at pixel (x, y).
    pub fn store(&mut self, x: u32, y: u32, frame: u32, depth: u32) {
        let index = self.index(x, y);
        self.frame[index] = frame;
        self.depth[index] = depth;
    }

    /// The framebuffer as rows, top row (y = height − 1) first.
    pub fn frame_rows(&self) -> Vec<Vec<u32>> {
        rows_top_first(&self.frame, self.width)
    }

    /// The z-buffer as rows, top row (y = height − 1) first.
    pub fn depth_rows(&self) -> Vec<Vec<u32>> {
        rows_top_first(&self.depth, self.width)
    }
}

fn rows_top_first(cells: &[u32], width: u32) -> Vec<Vec<u32>> {
    cells.chunks_exact(width as usize).rev().map(<[u32]>::to_vec).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_origin_is_bottom_left_and_printed_last() {
        let mut buffers = Buffers::new(3, 2, 0, 0);
        buffers.store(0, 0, 7, 9);
        assert_eq!(buffers.frame_rows(), vec![vec![0, 0, 0], vec![7, 0, 0]]);
        assert_eq!(buffers.depth_rows()[1][0], 9);
    }
}
