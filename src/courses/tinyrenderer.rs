//! tinyrenderer's z-buffer lesson (Dmitry Sokolov's course, branch `hidden`):
//! its OBJ models drawn as its program draws them, to its two TGA images.
//!
//! The lesson's rules, as its code states them: each vertex projected as
//! ((x+1)·800/2, (y+1)·800/2, (z+1)·255/2) and truncated to integers; pixel
//! (x, y) sampled at the integer point (x, y); a sample inside when its three
//! barycentric coordinates are ≥ 0 (edges included); its depth the
//! interpolation of the integer z's, truncated to 0 … 255 and written when
//! greater than the stored level (cleared to 0); a triangle whose signed
//! area is below 1 skipped. Each face's colour is three `rand() % 255` (glibc,
//! never seeded), drawn whether the face is skipped or not.
//!
//! The areas are integers, so which samples a triangle covers is exact in
//! either arithmetic; the lesson's f64 shows only in the projection and in
//! the interpolated depth, which [`LessonArith::Exact`] computes as fractions.

use crate::numbers::{Exact, Q, parse_exact};
use crate::words::Lang;

/// The lesson's image size (its `width` and `height`).
pub const SIZE: i64 = 800;

/// The smallest and largest image side `--size` allows.
pub const SIDES: std::ops::RangeInclusive<i64> = 4..=4096;

/// A line of an OBJ file that is wrong, and the line.
pub type ObjError = super::CaseError<ObjProblem>;

/// What is wrong on a line of an OBJ file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ObjProblem {
    /// A `v` line with fewer than three coordinates.
    VertexCount {
        /// How many.
        count: usize,
    },
    /// A coordinate that is not a finite number.
    NotANumber {
        /// The word written.
        token: String,
    },
    /// An `f` line of other than three corners.
    FaceCorners {
        /// How many.
        count: usize,
    },
    /// A corner whose vertex index is not a number from 1.
    BadIndex {
        /// The corner written.
        token: String,
    },
    /// More faces than [`MAX_FACES`].
    TooManyFaces,
    /// A face naming a vertex the model does not have.
    NoVertex {
        /// The vertex named (from 1).
        index: usize,
        /// The vertices the model has.
        count: usize,
    },
}

impl crate::error::Refusal for ObjProblem {
    fn message(&self, lang: Lang) -> String {
        use crate::words::token;
        match self {
            ObjProblem::VertexCount { count } => words!(lang, "obj-vertex-count", count = *count),
            ObjProblem::NotANumber { token: word } => words!(lang, "obj-not-a-number", token = token(lang, word)),
            ObjProblem::FaceCorners { count } => words!(lang, "obj-face-corners", count = *count),
            ObjProblem::BadIndex { token: corner } => words!(lang, "obj-bad-index", token = token(lang, corner)),
            ObjProblem::TooManyFaces => words!(lang, "obj-too-many-faces", max = MAX_FACES),
            ObjProblem::NoVertex { index, count } => words!(lang, "obj-no-vertex", index = *index, count = *count),
        }
    }
}

/// A model as the lesson reads it: vertices (as written, and as f64) and
/// triangles of vertex indices.
#[derive(Debug, Clone)]
pub struct Model {
    /// Each `v` line's three coordinates.
    pub vertices: Vec<[Exact; 3]>,
    /// The same, read as f64 as the lesson's `iss >> v[i]` reads them.
    pub vertices_f64: Vec<[f64; 3]>,
    /// Each `f` line's three vertex indices, from 0.
    pub faces: Vec<[usize; 3]>,
}

/// Most faces a model may have (the lesson's models have 2,492 at most).
pub const MAX_FACES: usize = 1_000_000;

impl Model {
    /// Reads `v` and `f` lines (`f a/b/c d/e/f g/h/i`, `f a b c` or `f a//c …`);
    /// every other line is passed over, as the lesson does. A face must have
    /// three corners whose vertices exist.
    pub fn parse(text: &str) -> Result<Model, ObjError> {
        let mut model = Model { vertices: Vec::new(), vertices_f64: Vec::new(), faces: Vec::new() };
        let mut faces = Vec::new();
        for (index, line) in text.lines().enumerate() {
            let number = index + 1;
            let fail = |problem: ObjProblem| ObjError { line: Some(number), problem };
            if let Some(rest) = line.strip_prefix("v ") {
                let words: Vec<&str> = rest.split_whitespace().collect();
                if words.len() < 3 {
                    return Err(fail(ObjProblem::VertexCount { count: words.len() }));
                }
                let mut exact = Vec::with_capacity(3);
                let mut float = [0.0; 3];
                for (k, word) in words.iter().take(3).enumerate() {
                    let bad = || fail(ObjProblem::NotANumber { token: word.to_string() });
                    float[k] = word.parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(bad)?;
                    exact.push(parse_exact(word).map_err(|_| bad())?);
                }
                let [x, y, z]: [Exact; 3] = exact.try_into().expect("three coordinates");
                model.vertices.push([x, y, z]);
                model.vertices_f64.push(float);
            } else if let Some(rest) = line.strip_prefix("f ") {
                let corners: Vec<&str> = rest.split_whitespace().collect();
                if corners.len() != 3 {
                    return Err(fail(ObjProblem::FaceCorners { count: corners.len() }));
                }
                let mut face = [0usize; 3];
                for (k, corner) in corners.iter().enumerate() {
                    let first = corner.split('/').next().unwrap_or("");
                    face[k] = match first.parse::<usize>() {
                        Ok(v) if v >= 1 => v - 1,
                        _ => {
                            return Err(fail(ObjProblem::BadIndex { token: corner.to_string() }));
                        }
                    };
                }
                faces.push((number, face));
                if faces.len() > MAX_FACES {
                    return Err(fail(ObjProblem::TooManyFaces));
                }
            }
        }
        for (line, face) in faces {
            if let Some(&missing) = face.iter().find(|&&v| v >= model.vertices.len()) {
                let problem = ObjProblem::NoVertex { index: missing + 1, count: model.vertices.len() };
                return Err(ObjError { line: Some(line), problem });
            }
            model.faces.push(face);
        }
        Ok(model)
    }
}

/// The arithmetic the lesson's program is run in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LessonArith {
    /// The lesson's: f64, as its C++ computes (same operations, same order).
    F64,
    /// Exact fractions: what the lesson's rules give without rounding errors.
    Exact,
}

/// A vertex on the screen: integer x, y and z (0 … 255), as the lesson
/// truncates them.
pub type Screen = [i64; 3];

/// The lesson's `project` for an image `size` pixels square (the lesson's is
/// [`SIZE`]), truncated to integers as its `std::tuple<int,int,int>` does.
pub fn project(model: &Model, vertex: usize, arith: LessonArith, size: i64) -> Screen {
    match arith {
        LessonArith::F64 => {
            let [x, y, z] = model.vertices_f64[vertex];
            // ((v.x + 1.) * width) / 2, then the conversion to int (toward zero).
            // A value beyond 2^40 lies far off the image: held there, as in exact arithmetic.
            let screen = |v: f64, scale: f64| (((v + 1.0) * scale / 2.0) as i64).clamp(-FAR, FAR);
            [screen(x, size as f64), screen(y, size as f64), screen(z, 255.0)]
        }
        LessonArith::Exact => {
            let [x, y, z] = &model.vertices[vertex];
            let screen = |v: &Exact, scale: i128| {
                let value = v.plus(&Exact::Word(Q::from_integer(1))).times(scale).divided_by(2);
                // Toward zero, as a conversion to int; a value beyond 64 bits lies far off the image.
                value.word().map_or(FAR, |q| q.trunc().to_integer().clamp(-FAR as i128, FAR as i128) as i64)
            };
            [screen(x, i128::from(size)), screen(y, i128::from(size)), screen(z, 255)]
        }
    }
}

/// The lesson's `signed_triangle_area`, times two (an integer: the lesson
/// computes it in `int` and halves it in `double`, which is exact).
// Written by index, not with `array::map`: the release build has no link-time optimization, and
// a nested `map` here stayed two calls a pixel (tinyrenderer's overdrawn models ran 30 times slower).
#[inline(always)]
pub fn twice_area(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> i128 {
    let w = i128::from;
    (w(b[1]) - w(a[1])) * (w(b[0]) + w(a[0]))
        + (w(c[1]) - w(b[1])) * (w(c[0]) + w(b[0]))
        + (w(a[1]) - w(c[1])) * (w(a[0]) + w(c[0]))
}

/// An area beyond 64 bits as a double: out of line, so that the compiler
/// does not convert every area this slow way beside the quick one.
#[cold]
#[inline(never)]
fn wide_to_f64(v: i128) -> f64 {
    v as f64
}

/// How far off the image a projected coordinate is held (2^40 pixels): the
/// areas of triangles with such corners still fit 128 bits.
const FAR: i64 = 1 << 40;

/// glibc's `rand()` (the TYPE_3 additive generator), from a seed.
#[derive(Debug, Clone)]
pub struct GlibcRand {
    state: Vec<i32>,
}

impl GlibcRand {
    /// The generator after `srand(seed)`; a program that never calls `srand` has seed 1.
    pub fn new(seed: u32) -> GlibcRand {
        let mut r = vec![0i32; 34];
        r[0] = seed as i32;
        for i in 1..31 {
            // 16807 · r mod (2^31 − 1), by Schrage's method as glibc computes it.
            let (hi, lo) = (r[i - 1] / 127_773, r[i - 1] % 127_773);
            let word = 16_807 * lo - 2_836 * hi;
            r[i] = if word < 0 { word + 2_147_483_647 } else { word };
        }
        for i in 31..34 {
            r[i] = r[i - 31];
        }
        let mut rand = GlibcRand { state: r };
        for _ in 34..344 {
            rand.step();
        }
        rand
    }

    fn step(&mut self) -> i32 {
        let n = self.state.len();
        let value = self.state[n - 31].wrapping_add(self.state[n - 3]);
        self.state.push(value);
        if self.state.len() > 64 {
            self.state.drain(..self.state.len() - 34);
        }
        value
    }

    /// The next `rand()`: 0 … 2^31 − 1.
    pub fn rand(&mut self) -> i32 {
        ((self.step() as u32) >> 1) as i32
    }
}

/// What the lesson's program wrote: the z-buffer (one level a pixel) and the
/// framebuffer (blue, green, red a pixel, as TGA stores them), rows from the
/// bottom of the image; and which face each pixel shows (`None`: background).
#[derive(Debug, Clone)]
pub struct Render {
    /// 800 × 800 levels.
    pub zbuffer: Vec<u8>,
    /// 800 × 800 pixels, BGR.
    pub framebuffer: Vec<[u8; 3]>,
    /// The face drawn last at each pixel.
    pub face: Vec<Option<u32>>,
    /// How many faces were skipped for an area below 1.
    pub skipped: usize,
}

/// Draws the model as the lesson does, in `arith`, on an image `size`
/// pixels square (the lesson's is [`SIZE`]).
pub fn render(model: &Model, arith: LessonArith, size: i64) -> Render {
    let pixels = (size * size) as usize;
    let mut out =
        Render { zbuffer: vec![0; pixels], framebuffer: vec![[0; 3]; pixels], face: vec![None; pixels], skipped: 0 };
    let mut rand = GlibcRand::new(1);
    for (index, face) in model.faces.iter().enumerate() {
        let [a, b, c] = face.map(|v| project(model, v, arith, size));
        // TGAColor is blue, green, red: rnd[0], rnd[1], rnd[2].
        let colour = [0, 1, 2].map(|_| (rand.rand() % 255) as u8);
        let total = twice_area([a[0], a[1]], [b[0], b[1]], [c[0], c[1]]);
        // `total_area < 1` with total_area = total / 2.
        if total < 2 {
            out.skipped += 1;
            continue;
        }
        // The lesson's bounding box, clipped to the image: the pixels beyond
        // it are never drawn, and a vertex far off the image cannot make the
        // loop run for ever.
        let (minx, maxx) = (a[0].min(b[0]).min(c[0]).max(0), a[0].max(b[0]).max(c[0]).min(size - 1));
        let (miny, maxy) = (a[1].min(b[1]).min(c[1]).max(0), a[1].max(b[1]).max(c[1]).min(size - 1));
        // Row by row (the lesson walks x then y; each pixel of a face is tested once either way,
        // so the images are the same, and rows keep the buffers' cells in order in memory).
        for y in miny..=maxy {
            for x in minx..=maxx {
                let p = [x, y];
                let (wa, wb, wc) = (
                    twice_area(p, [b[0], b[1]], [c[0], c[1]]),
                    twice_area(p, [c[0], c[1]], [a[0], a[1]]),
                    twice_area(p, [a[0], a[1]], [b[0], b[1]]),
                );
                if wa < 0 || wb < 0 || wc < 0 {
                    continue;
                }
                let z = match arith {
                    LessonArith::F64 => {
                        // As the lesson: each area halved in double, divided by the halved total.
                        // An area converted from i64 where it fits (the same double, without
                        // the slow 128-bit conversion).
                        let half = |v: i128| 0.5 * i64::try_from(v).map_or_else(|_| wide_to_f64(v), |v| v as f64);
                        let t = half(total);
                        let (alpha, beta, gamma) = (half(wa) / t, half(wb) / t, half(wc) / t);
                        (alpha * a[2] as f64 + beta * b[2] as f64 + gamma * c[2] as f64) as u8
                    }
                    LessonArith::Exact => {
                        let n = wa * i128::from(a[2]) + wb * i128::from(b[2]) + wc * i128::from(c[2]);
                        (n / total).clamp(0, 255) as u8
                    }
                };
                if !(0..size).contains(&x) || !(0..size).contains(&y) {
                    continue;
                }
                let cell = (y * size + x) as usize;
                if z <= out.zbuffer[cell] {
                    continue;
                }
                out.zbuffer[cell] = z;
                out.framebuffer[cell] = colour;
                out.face[cell] = Some(index as u32);
            }
        }
    }
    out
}

/// The model as a zsim scene under the lesson's rules (`"rules":
/// "tinyrenderer"`): `size`×`size` (the lesson's 800, or smaller to step by hand), a 24-bit framebuffer, an 8-bit z-buffer; each
/// face a triangle at the lesson's integer screen coordinates (projected in
/// `arith`), its value the face's colour as 0xRRGGBB and its name `face N`
/// (from 1, as the OBJ's `f` lines count). Faces the lesson skips are kept:
/// zsim's rules skip them too, and say why.
pub fn scene_json(model: &Model, arith: LessonArith, size: i64) -> String {
    let mut rand = GlibcRand::new(1);
    let mut polygons = Vec::with_capacity(model.faces.len());
    for (index, face) in model.faces.iter().enumerate() {
        let [b, g, r] = [0, 1, 2].map(|_| (rand.rand() % 255) as u32);
        let vertices: Vec<String> =
            face.iter().map(|&v| project(model, v, arith, size)).map(|[x, y, z]| format!("[{x}, {y}, {z}]")).collect();
        polygons.push(format!(
            "    {{\"name\": \"face {}\", \"value\": {}, \"vertices\": [{}]}}",
            index + 1,
            (r << 16) | (g << 8) | b,
            vertices.join(", ")
        ));
    }
    format!(
        "{{\n  \"width\": {size}, \"height\": {size}, \"frame_bits\": 24, \"depth_bits\": 8, \"depth_test\": \"greater\",\n  \"rules\": \"tinyrenderer\",\n  \"polygons\": [\n{}\n  ]\n}}\n",
        polygons.join(",\n")
    )
}

/// A TGA image as the lesson's `TGAImage::write_tga_file` writes it: the
/// 18-byte header (type 3 or 11 for grey, 2 or 10 for colour; origin at the
/// bottom left), the pixels from the bottom row (run-length encoded in the
/// lesson's packets when `rle`), then the empty developer and extension
/// references and the "TRUEVISION-XFILE." footer.
pub fn tga(width: u16, height: u16, bytes_per_pixel: u8, data: &[u8], rle: bool) -> Vec<u8> {
    let mut out = Vec::with_capacity(data.len() + 64);
    let kind = match (bytes_per_pixel, rle) {
        (1, true) => 11,
        (1, false) => 3,
        (_, true) => 10,
        (_, false) => 2,
    };
    out.extend_from_slice(&[0, 0, kind, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
    out.extend_from_slice(&width.to_le_bytes());
    out.extend_from_slice(&height.to_le_bytes());
    out.extend_from_slice(&[bytes_per_pixel * 8, 0]);
    if rle {
        run_length_encode(&mut out, data, usize::from(bytes_per_pixel));
    } else {
        out.extend_from_slice(data);
    }
    out.extend_from_slice(&[0; 8]);
    out.extend_from_slice(b"TRUEVISION-XFILE.\0");
    out
}

/// The lesson's packets: up to 128 pixels, raw while neighbours differ, a
/// run while they repeat.
fn run_length_encode(out: &mut Vec<u8>, data: &[u8], bpp: usize) {
    let pixels = data.len() / bpp;
    let same = |i: usize| data[i * bpp..(i + 1) * bpp] == data[(i + 1) * bpp..(i + 2) * bpp];
    let mut at = 0;
    while at < pixels {
        let mut length = 1;
        let mut raw = true;
        while at + length < pixels && length < 128 {
            let equal = same(at + length - 1);
            if length == 1 {
                raw = !equal;
            }
            if raw && equal {
                length -= 1;
                break;
            }
            if !raw && !equal {
                break;
            }
            length += 1;
        }
        out.push(if raw { (length - 1) as u8 } else { (length + 127) as u8 });
        let start = at * bpp;
        out.extend_from_slice(&data[start..start + if raw { length * bpp } else { bpp }]);
        at += length;
    }
}

/// A TGA image read back: width, height, bytes a pixel and the pixels from
/// the bottom row (types 2, 3, 10 and 11; either origin).
pub fn read_tga(bytes: &[u8]) -> Result<(usize, usize, usize, Vec<u8>), String> {
    let header = bytes.get(..18).ok_or("shorter than a TGA header")?;
    let (id, kind) = (usize::from(header[0]), header[2]);
    let width = usize::from(u16::from_le_bytes([header[12], header[13]]));
    let height = usize::from(u16::from_le_bytes([header[14], header[15]]));
    let bpp = usize::from(header[16] / 8);
    if header[1] != 0 || !matches!(kind, 2 | 3 | 10 | 11) || !(1..=4).contains(&bpp) {
        return Err(format!("TGA type {kind} with {} bits a pixel is not read here", header[16]));
    }
    let size = width * height * bpp;
    let mut data = Vec::with_capacity(size);
    let mut at = 18 + id;
    if kind == 2 || kind == 3 {
        data.extend_from_slice(bytes.get(at..at + size).ok_or("the pixels are cut short")?);
    } else {
        while data.len() < size {
            let packet = *bytes.get(at).ok_or("the pixels are cut short")?;
            at += 1;
            let count = usize::from(packet & 0x7f) + 1;
            if packet & 0x80 == 0 {
                data.extend_from_slice(bytes.get(at..at + count * bpp).ok_or("the pixels are cut short")?);
                at += count * bpp;
            } else {
                let pixel = bytes.get(at..at + bpp).ok_or("the pixels are cut short")?;
                for _ in 0..count {
                    data.extend_from_slice(pixel);
                }
                at += bpp;
            }
        }
        data.truncate(size);
    }
    if header[17] & 0x20 != 0 {
        // Top-left origin: rows turned to run from the bottom.
        let rows: Vec<&[u8]> = data.chunks(width * bpp).rev().collect();
        data = rows.concat();
    }
    Ok((width, height, bpp, data))
}

/// How many pixels `run --arith exact` lists where exact and f64 differ.
pub const DIFFERENCES_LISTED: usize = 10;

/// The pixels where the lesson's f64 gives another z-buffer level than
/// exact arithmetic, counted, the first few listed.
pub fn differences_text(lang: Lang, model: &Model, exact: &Render, size: i64) -> String {
    let float = render(model, LessonArith::F64, size);
    let differing: Vec<usize> = (0..exact.zbuffer.len()).filter(|&i| exact.zbuffer[i] != float.zbuffer[i]).collect();
    let mut text = format!("{}\n", words!(lang, "tinyrenderer-differ", count = differing.len()));
    for &cell in differing.iter().take(DIFFERENCES_LISTED) {
        let (x, y) = (cell % size as usize, cell / size as usize);
        let face = exact.face[cell].map_or(0, |f| f + 1);
        let line = words!(
            lang,
            "tinyrenderer-differ-pixel",
            x = x,
            y = y,
            face = face,
            float = u32::from(float.zbuffer[cell]),
            exact = u32::from(exact.zbuffer[cell])
        );
        text.push_str(&format!("  {line}\n"));
    }
    text
}

/// Reads the model (OBJ) at `path`; errors name the file and the line.
pub fn load(path: &std::path::Path) -> Result<Model, crate::error::Error> {
    let text = crate::door::read_text(path)?;
    Model::parse(&text).map_err(|e| e.in_file(path))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// glibc's documented first values of `rand()` without `srand`.
    #[test]
    fn glibc_rand_starts_as_glibc_does() {
        let mut rand = GlibcRand::new(1);
        let first: Vec<i32> = (0..3).map(|_| rand.rand()).collect();
        assert_eq!(first, [1_804_289_383, 846_930_886, 1_681_692_777]);
    }

    #[test]
    fn run_length_packets_read_back() {
        let data: Vec<u8> = [1u8, 1, 1, 2, 3, 4, 4, 5].iter().copied().cycle().take(1000).collect();
        let image = tga(100, 10, 1, &data, true);
        assert_eq!(read_tga(&image).unwrap(), (100, 10, 1, data.clone()));
        let image = tga(100, 10, 1, &data, false);
        assert_eq!(read_tga(&image).unwrap().3, data);
    }

    #[test]
    fn obj_lines_are_read_as_the_lesson_reads_them_and_a_bad_one_is_named() {
        let model =
            Model::parse("# a comment\nv 0 0 0\nv 1 0 0.5\nv 0 1 -1\nvt 0 0\nf 1/1/1 2/2/2 3/3/3\ns 1\n").unwrap();
        assert_eq!((model.vertices.len(), model.faces.clone()), (3, vec![[0, 1, 2]]));
        let error = Model::parse("v 0 0 0\nv 1 x 0\n").unwrap_err();
        assert_eq!((error.line, error.problem), (Some(2), ObjProblem::NotANumber { token: "x".into() }));
        let error = Model::parse("v 0 0 0\nf 1 2 3\n").unwrap_err();
        assert_eq!((error.line, error.problem), (Some(2), ObjProblem::NoVertex { index: 2, count: 1 }));
    }
}
