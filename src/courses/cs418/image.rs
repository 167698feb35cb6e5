//! Images: the RGBA image the course's pipeline writes, PNG in and out,
//! comparing two images, and the sRGB transfer functions colours and
//! textures pass through.

use super::Texture;

/// An RGBA image, rows from the top, 8 bits a channel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height × 4` bytes, row by row from the top.
    pub rgba: Vec<u8>,
}

impl Image {
    /// The four channels of pixel (x, y), y counted from the top.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        let at = ((y * self.width + x) * 4) as usize;
        [self.rgba[at], self.rgba[at + 1], self.rgba[at + 2], self.rgba[at + 3]]
    }
}

impl Image {
    /// The image as PNG bytes (8-bit RGBA).
    pub fn to_png(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        {
            let mut encoder = png::Encoder::new(&mut bytes, self.width, self.height);
            encoder.set_color(png::ColorType::Rgba);
            encoder.set_depth(png::BitDepth::Eight);
            // Writing into a Vec cannot fail.
            let mut writer = encoder.write_header().expect("PNG header into memory");
            writer.write_image_data(&self.rgba).expect("PNG data into memory");
        }
        bytes
    }

    /// Reads a PNG (any colour type and depth png expands to 8-bit RGB or
    /// RGBA, grey included) that declares at most
    /// [`crate::door::MAX_IMAGE_PIXELS`]; `Err` says why not.
    pub fn from_png(bytes: &[u8]) -> Result<Image, crate::door::PngProblem> {
        use crate::door::PngProblem;
        let mut reader = crate::door::png_reader(bytes)?;
        let size = reader.output_buffer_size().ok_or(PngProblem::TooLarge)?;
        let mut buffer = vec![0; size];
        let frame = reader.next_frame(&mut buffer).map_err(|e| PngProblem::Broken { reason: e.to_string() })?;
        buffer.truncate(frame.buffer_size());
        let rgba = match frame.color_type {
            png::ColorType::Rgba => buffer,
            png::ColorType::GrayscaleAlpha => buffer.chunks(2).flat_map(|c| [c[0], c[0], c[0], c[1]]).collect(),
            other => return Err(PngProblem::ColourType { kind: format!("{other:?}") }),
        };
        Ok(Image { width: frame.width, height: frame.height, rgba })
    }
}

/// How two images differ: pixels over a tolerance, and the largest difference.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImageDifference {
    /// Pixels with some channel differing by more than the tolerance.
    pub pixels: Vec<(u32, u32, [u8; 4], [u8; 4])>,
    /// The largest difference of any channel.
    pub largest: u8,
}

/// Compares two images channel by channel; `None` when their sizes differ.
pub fn compare_images(ours: &Image, theirs: &Image, tolerance: u8) -> Option<ImageDifference> {
    if (ours.width, ours.height) != (theirs.width, theirs.height) {
        return None;
    }
    let mut pixels = Vec::new();
    let mut largest = 0;
    for y in 0..ours.height {
        for x in 0..ours.width {
            let (a, b) = (ours.pixel(x, y), theirs.pixel(x, y));
            let worst = a.iter().zip(&b).map(|(p, q)| p.abs_diff(*q)).max().unwrap_or(0);
            largest = largest.max(worst);
            if worst > tolerance {
                pixels.push((x, y, a, b));
            }
        }
    }
    Some(ImageDifference { pixels, largest })
}

/// A texture's texels in linear light (the file's bytes are sRGB; alpha is
/// linear already).
pub(super) fn linear_texels(texture: &Texture) -> Vec<[f64; 4]> {
    texture
        .image
        .rgba
        .chunks_exact(4)
        .map(|c| {
            let [r, g, b, a] = [c[0], c[1], c[2], c[3]].map(|v| f64::from(v) / 255.0);
            [from_srgb(r), from_srgb(g), from_srgb(b), a]
        })
        .collect()
}

/// The inverse of [`to_srgb`]: sRGB-encoded to linear light.
pub(super) fn from_srgb(encoded: f64) -> f64 {
    if encoded <= 0.04045 { encoded / 12.92 } else { ((encoded + 0.055) / 1.055).powf(2.4) }
}

/// The sRGB transfer function (IEC 61966-2-1) from linear light.
pub(super) fn to_srgb(linear: f64) -> f64 {
    if linear <= 0.0031308 { 12.92 * linear } else { 1.055 * linear.powf(1.0 / 2.4) - 0.055 }
}

/// A channel in 0 … 1 as a byte, rounded to nearest.
pub(super) fn byte(value: f64) -> u8 {
    (value.clamp(0.0, 1.0) * 255.0).round() as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_transfer_matches_the_standard() {
        assert_eq!(byte(to_srgb(0.5)), 188);
        assert_eq!(byte(to_srgb(0.0)), 0);
        assert_eq!(byte(to_srgb(1.0)), 255);
        assert_eq!(byte(to_srgb(0.002)), 7);
        for encoded in 0..=255u8 {
            let value = f64::from(encoded) / 255.0;
            assert_eq!(byte(to_srgb(from_srgb(value))), encoded);
        }
    }
}
