//! Random scenes (the Russian coursework's program adds random triangles one by one) and
//! the memory figures of the buffers (the Russian coursework: "almost 1.5 MB").

use std::fmt::Write as _;

/// SplitMix64 (Steele, Lea, Flood 2014): a tiny, well-known generator whose
/// sequence is fixed by its seed, so `zsim random --seed S` prints the same
/// scene on every machine and every version.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator started at `seed`.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform integer in `low ..= high` (rejection sampling, no modulo bias).
    pub fn range(&mut self, low: i64, high: i64) -> i64 {
        debug_assert!(low <= high);
        let span = (high - low) as u64 + 1;
        let zone = u64::MAX - (u64::MAX % span + 1) % span;
        loop {
            let value = self.next_u64();
            if value <= zone {
                return low + (value % span) as i64;
            }
        }
    }
}

/// What `zsim random` makes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RandomScene {
    /// Number of triangles.
    pub count: usize,
    /// Seed of the generator.
    pub seed: u64,
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// Largest extent of a triangle in x and in y, in pixels.
    pub max_size: u32,
    /// Framebuffer bits; values are drawn from 1 … 2^bits − 1.
    pub frame_bits: u32,
    /// z-buffer bits; depths are drawn from 0 … 2^bits − 1 (at most 2^24).
    pub depth_bits: u32,
}

impl RandomScene {
    /// The scene as zsim scene JSON: triangles with integer vertices inside
    /// the raster, each within a `max_size` square, depths and values random.
    pub fn json(&self) -> String {
        let mut rng = SplitMix64::new(self.seed);
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let size = i64::from(self.max_size.max(1));
        let depth_high = (1i64 << self.depth_bits.min(24)) - 1;
        let value_high = (1i64 << self.frame_bits.min(32)) - 1;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{{\"width\": {}, \"height\": {}, \"frame_bits\": {}, \"depth_bits\": {}, \"polygons\": [",
            self.width, self.height, self.frame_bits, self.depth_bits
        );
        for i in 0..self.count {
            // A corner of the triangle's box, then three vertices inside the box.
            let (box_w, box_h) = (size.min(w), size.min(h));
            let x0 = rng.range(0, w - box_w);
            let y0 = rng.range(0, h - box_h);
            let mut vertices = Vec::with_capacity(3);
            for _ in 0..3 {
                let x = x0 + rng.range(0, box_w);
                let y = y0 + rng.range(0, box_h);
                let z = rng.range(0, depth_high);
                vertices.push(format!("[{x}, {y}, {z}]"));
            }
            let value = rng.range(1, value_high.max(1));
            let comma = if i + 1 < self.count { "," } else { "" };
            let _ = writeln!(
                out,
                "  {{\"name\": \"t{}\", \"value\": {value}, \"vertices\": [{}]}}{comma}",
                i + 1,
                vertices.join(", ")
            );
        }
        out.push_str("]}\n");
        out
    }
}

/// One buffer's memory.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BufferMemory {
    /// Cells (pixels or sub-pixels).
    pub cells: u64,
    /// Bits per cell.
    pub bits_per_cell: u32,
}

impl BufferMemory {
    /// Bits in all.
    pub fn bits(&self) -> u64 {
        self.cells * u64::from(self.bits_per_cell)
    }

    /// Bytes in all, bits packed (rounded up to a whole byte).
    pub fn bytes(&self) -> u64 {
        self.bits().div_ceil(8)
    }
}

/// The framebuffer's and z-buffer's memory for a raster, supersampled
/// `k`×`k` (the Russian coursework: with `depth_at_samples` both buffers are at the higher
/// resolution, the second approach; otherwise only the framebuffer, the first).
pub fn memory(
    width: u64,
    height: u64,
    frame_bits: u32,
    depth_bits: u32,
    k: u64,
    depth_at_samples: bool,
) -> [BufferMemory; 2] {
    let samples = width * height * k * k;
    let depth_cells = if depth_at_samples { samples } else { width * height };
    [
        BufferMemory { cells: samples, bits_per_cell: frame_bits },
        BufferMemory { cells: depth_cells, bits_per_cell: depth_bits },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_books_memory_figures_come_out() {
        let [frame, depth] = memory(512, 512, 24, 20, 1, true);
        assert_eq!(frame.bytes() + depth.bytes(), 1_441_792, "almost 1.5 MB");
        let [frame, depth] = memory(512, 512, 24, 20, 2, true);
        assert_eq!(frame.bytes() + depth.bytes(), 5_767_168, "almost 6 MB");
    }

    #[test]
    fn splitmix_is_fixed_by_its_seed() {
        // Reference values of SplitMix64 from seed 0.
        let mut rng = SplitMix64::new(0);
        assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(rng.next_u64(), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn random_scenes_repeat_for_a_seed() {
        let spec = RandomScene { count: 5, seed: 7, width: 32, height: 32, max_size: 8, frame_bits: 2, depth_bits: 4 };
        assert_eq!(spec.json(), spec.json());
        assert_ne!(spec.json(), RandomScene { seed: 8, ..spec }.json());
    }
}
