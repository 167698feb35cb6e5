//! UIUC CS 418's rasterizer assignment (fall 2023), end to end: the course's
//! input files (`rast-*.txt`), its pipeline (clip space, division by w, the
//! viewport, the DDA scanline algorithm, depth, sRGB, hyperbolic
//! interpolation, alpha, multisampling, culling, frustum clipping, points),
//! and its output (an RGBA image).
//!
//! The course defines its answers by a float algorithm, so this module runs
//! that algorithm in one of two arithmetics ([`Arithmetic`]): the course's own
//! `f64` DDA, which its reference images were made with, or exact rationals,
//! which show where the course's floats land on the other side of a pixel
//! sample. Colour lives here only: the book's 2-bit framebuffer path is
//! untouched.
//!
//! # The course's conventions
//!
//! - **Viewport.** A vertex (x, y, z, w) goes to `x' = (x/w + 1)·W/2`,
//!   `y' = (y/w + 1)·H/2`, depth `z/w`; row `y'` is the image's row `y'`
//!   counted from the top (no flip).
//! - **Samples.** Pixel (x, y) is sampled at the integer point (x, y), not at
//!   x + 1/2.
//! - **DDA.** Between points a and b along coordinate d: the first point is
//!   where `d = ⌈a_d⌉`, then steps of `(b − a)/(b_d − a_d)` while `p_d < b_d`.
//!   Every attribute rides along. So rows run `⌈y_top⌉ ≤ y < y_bottom` and
//!   columns `⌈x_left⌉ ≤ x < x_right`: the top-left rule of a y-down raster.
//! - **Depth** (`depth`): cleared to 1, a fragment is kept when `z/w` is less.
//! - **Colour**: linear RGBA in 0 … 1, blended with "over"; `sRGB` converts
//!   at output; `hyp` interpolates attributes divided by w (perspective
//!   correct); `fsaa n` renders n×n samples per pixel and averages them,
//!   colours weighted by alpha.
//! - **Textures** (`texture FILE`, `texcoord 2 …`): the texture's bytes are
//!   sRGB, converted to linear when read. A fragment's (s, t), interpolated
//!   like the colour, is wrapped into 0 … 1 *after* interpolation (repeat)
//!   and looks up the texel whose centre is nearest: column
//!   `⌊frac(s)·W + ½⌋ mod W`, row likewise counted from the file's top row.
//!   A negative coordinate's texel lies 5 texels further on (column
//!   `⌊frac(s)·W + ½⌋ + 5 mod W`): the course's `textures` image shows it on
//!   its −z face, where s and t run below 0 (690 pixels differ without the
//!   shift, none with it; only its 186-texel textures show it). The texel replaces the vertex colour, or with
//!   `decals` goes over it: `rgb = tex.rgb·tex.a + colour.rgb·(1 − tex.a)`,
//!   `a = tex.a + colour.a − tex.a·colour.a`. A point drawn while a texture
//!   is bound is a sprite: (s, t) runs from (0, 0) at its top-left corner to
//!   (1, 1) at its bottom-right.

mod clip;
mod compare;
mod image;
pub mod import;
mod raster;
mod refused;
pub mod report;
mod scalar;

pub use compare::{CellDifference, Comparison, Primitive, Reason, SampleGrid, differences};
pub use image::{Image, ImageDifference, compare_images};
pub use raster::{Arithmetic, render};

pub use refused::{Cs418Problem, TextureProblem};

/// A problem in a CS 418 case, with its line.
pub type Cs418Error = super::CaseError<Cs418Problem>;

fn error(line: usize, problem: Cs418Problem) -> Cs418Error {
    Cs418Error { line: Some(line), problem }
}

/// A number as the file writes it: the `f64` the course reads from it, and
/// its exact value.
#[derive(Debug, Clone, PartialEq)]
pub struct RastNumber {
    /// The nearest `f64`, as the course's programs parse it.
    pub value: f64,
    /// The decimal as written, exactly.
    pub exact: crate::numbers::Q,
}

/// One command of the file.
#[derive(Debug, Clone, PartialEq)]
pub enum FileCommand {
    /// `position SIZE n…`: vertex positions, SIZE (2–4) numbers each; z
    /// defaults to 0 and w to 1.
    Position {
        /// Numbers per vertex.
        size: usize,
        /// All the numbers.
        numbers: Vec<RastNumber>,
    },
    /// `color SIZE n…`: vertex colours, 3 (alpha 1) or 4 numbers each.
    Color {
        /// Numbers per vertex.
        size: usize,
        /// All the numbers.
        numbers: Vec<RastNumber>,
    },
    /// `elements i…`: indices for `drawElementsTriangles`.
    Elements(Vec<usize>),
    /// `pointsize 1 n…`: a size in pixels per vertex, for points.
    PointSize(Vec<RastNumber>),
    /// `uniformMatrix` and 16 numbers in column-major order: every position
    /// is multiplied by it from then on.
    Matrix(Vec<RastNumber>),
    /// `texture FILE`: binds `RastFile::textures[i]` for the draws that follow.
    Texture(usize),
    /// `texcoord 2 s t …`: texture coordinates per vertex.
    TexCoord(Vec<RastNumber>),
    /// `drawArraysTriangles FIRST COUNT`.
    DrawArrays {
        /// The first vertex.
        first: usize,
        /// How many vertices (three per triangle).
        count: usize,
    },
    /// `drawElementsTriangles COUNT OFFSET`.
    DrawElements {
        /// How many elements (three per triangle).
        count: usize,
        /// The first element.
        offset: usize,
    },
    /// `drawArraysPoints FIRST COUNT`.
    DrawPoints {
        /// The first vertex.
        first: usize,
        /// How many points.
        count: usize,
    },
}

/// The switches a file turns on (each a line of its own).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Features {
    /// `depth`: the depth buffer.
    pub depth: bool,
    /// `sRGB`: colours are linear, converted to sRGB at output.
    pub srgb: bool,
    /// `hyp`: hyperbolic (perspective-correct) interpolation.
    pub hyp: bool,
    /// `cull`: only triangles whose vertices run clockwise on the image
    /// (y down) are drawn.
    pub cull: bool,
    /// `frustum`: clip to the view volume (−w ≤ x, y, z ≤ w) before dividing.
    pub frustum: bool,
    /// `fsaa n`: n×n samples per pixel (1 = off).
    pub fsaa: u32,
    /// `decals`: a texture goes over the vertex colour instead of replacing it.
    pub decals: bool,
}

/// A texture a case names, read from its PNG.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Texture {
    /// The file name as the case writes it.
    pub name: String,
    /// Its pixels (sRGB bytes, as stored): one decoded image for every name
    /// that leads to the same file (`x.png`, `./x.png`), shared.
    pub image: std::sync::Arc<Image>,
}

/// A whole CS 418 input file.
#[derive(Debug, Clone, PartialEq)]
pub struct RastFile {
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// The file name the first line asks for.
    pub output: String,
    /// The switches.
    pub features: Features,
    /// The commands in order, each with its line.
    pub commands: Vec<(usize, FileCommand)>,
    /// The textures the case names, in the order first named.
    pub textures: Vec<Texture>,
}

/// Largest image side accepted: 16384 × 16384 RGBA in f64 is 8 GiB already.
pub const MAX_SIDE: u32 = 8192;

/// The most samples a case may ask for, width × height × fsaa², 2^23
/// (8,388,608: 2896 × 2896 at fsaa 1, 1024 × 1024 at fsaa 2): exact
/// arithmetic keeps a rational depth and the course's floats beside each
/// sample. A larger image or `fsaa` is refused at its line, before any
/// sample buffer is allocated (the guide's Safety chapter has the memory
/// this takes).
pub const MAX_SAMPLES: u64 = 1 << 23;

/// The most pixels a case's textures hold together: as many as the largest
/// one image may declare ([`crate::door::MAX_IMAGE_PIXELS`]), so that a case
/// naming several large textures peaks where one does. Each texture's share
/// is known from its header, before it is decoded.
pub const MAX_CASE_TEXTURE_PIXELS: u64 = crate::door::MAX_IMAGE_PIXELS;

impl RastFile {
    /// Reads a CS 418 file. `load_texture` reads a texture the case names
    /// (the caller knows where the case's folder is; the same image for every
    /// name of one file), or says why it cannot.
    pub fn parse(
        text: &str,
        load_texture: &dyn Fn(&str) -> Result<std::sync::Arc<Image>, TextureProblem>,
    ) -> Result<RastFile, Cs418Error> {
        let mut case: Option<RastFile> = None;
        for (index, raw) in text.lines().enumerate() {
            let line = index + 1;
            let words: Vec<&str> = raw.split_whitespace().collect();
            let Some((&keyword, args)) = words.split_first() else { continue };
            if keyword.starts_with('#') {
                continue;
            }
            if keyword == "png" {
                if case.is_some() {
                    return Err(error(line, Cs418Problem::SecondPng));
                }
                case = Some(png_line(line, args)?);
                continue;
            }
            let Some(case) = case.as_mut() else {
                return Err(error(line, Cs418Problem::BeforePng { keyword: keyword.to_string() }));
            };
            let flag = |on: &mut bool| {
                if args.is_empty() {
                    *on = true;
                    Ok(())
                } else {
                    Err(error(line, Cs418Problem::FlagNumbers { keyword: keyword.to_string(), found: args.len() }))
                }
            };
            match keyword {
                "depth" => flag(&mut case.features.depth)?,
                "sRGB" => flag(&mut case.features.srgb)?,
                "hyp" => flag(&mut case.features.hyp)?,
                "cull" => flag(&mut case.features.cull)?,
                "frustum" => flag(&mut case.features.frustum)?,
                "decals" => flag(&mut case.features.decals)?,
                "fsaa" => {
                    let [level] = integers::<1>(line, keyword, args)?;
                    if !(1..=8).contains(&level) {
                        return Err(error(line, Cs418Problem::Fsaa { level }));
                    }
                    samples_within_limit(line, case.width, case.height, level as u32)?;
                    case.features.fsaa = level as u32;
                }
                "position" | "color" | "pointsize" | "texcoord" => {
                    let (size, numbers) = sized(line, keyword, args)?;
                    let allowed: &[usize] = match keyword {
                        "position" => &[1, 2, 3, 4],
                        "color" => &[3, 4],
                        "texcoord" => &[2],
                        _ => &[1],
                    };
                    if !allowed.contains(&size) {
                        return Err(error(line, Cs418Problem::Size { keyword: keyword.to_string(), size, allowed }));
                    }
                    case.commands.push((
                        line,
                        match keyword {
                            "position" => FileCommand::Position { size, numbers },
                            "color" => FileCommand::Color { size, numbers },
                            "texcoord" => FileCommand::TexCoord(numbers),
                            _ => FileCommand::PointSize(numbers),
                        },
                    ));
                }
                "elements" => {
                    let indices = args
                        .iter()
                        .map(|w| {
                            w.parse::<usize>()
                                .map_err(|_| error(line, Cs418Problem::NotAnIndex { word: w.to_string() }))
                        })
                        .collect::<Result<Vec<_>, _>>()?;
                    case.commands.push((line, FileCommand::Elements(indices)));
                }
                "uniformMatrix" => {
                    if args.len() != 16 {
                        return Err(error(line, Cs418Problem::Matrix { found: args.len() }));
                    }
                    let numbers = args.iter().map(|w| number(line, keyword, w)).collect::<Result<Vec<_>, _>>()?;
                    case.commands.push((line, FileCommand::Matrix(numbers)));
                }
                "drawArraysTriangles" | "drawElementsTriangles" | "drawArraysPoints" => {
                    let [a, b] = integers::<2>(line, keyword, args)?;
                    let command = match keyword {
                        "drawArraysTriangles" => FileCommand::DrawArrays { first: a, count: b },
                        "drawElementsTriangles" => FileCommand::DrawElements { count: a, offset: b },
                        _ => FileCommand::DrawPoints { first: a, count: b },
                    };
                    if let FileCommand::DrawArrays { count, .. } | FileCommand::DrawElements { count, .. } = command
                        && count % 3 != 0
                    {
                        return Err(error(line, Cs418Problem::Count { keyword: keyword.to_string(), count }));
                    }
                    case.commands.push((line, command));
                }
                "texture" => {
                    let name = args.join(" ");
                    if name.is_empty() {
                        return Err(error(line, Cs418Problem::TextureName));
                    }
                    let index = match case.textures.iter().position(|t| t.name == name) {
                        Some(index) => index,
                        None => {
                            let image = load_texture(&name)
                                .map_err(|why| error(line, Cs418Problem::Texture { name: name.clone(), why }))?;
                            case.textures.push(Texture { name, image });
                            case.textures.len() - 1
                        }
                    };
                    case.commands.push((line, FileCommand::Texture(index)));
                }
                _ => {
                    return Err(error(line, Cs418Problem::UnknownCommand { command: keyword.to_string() }));
                }
            }
        }
        case.ok_or(Cs418Error { line: None, problem: Cs418Problem::NoPng })
    }
}

/// Refuses, at its line, an image of `width` × `height` at `fsaa level` whose
/// samples pass [`MAX_SAMPLES`].
fn samples_within_limit(line: usize, width: u32, height: u32, level: u32) -> Result<(), Cs418Error> {
    let samples = u64::from(width) * u64::from(height) * u64::from(level * level);
    if samples <= MAX_SAMPLES {
        return Ok(());
    }
    Err(error(line, Cs418Problem::TooManySamples { level, samples }))
}

fn png_line(line: usize, args: &[&str]) -> Result<RastFile, Cs418Error> {
    let [width, height, file] = args else {
        return Err(error(line, Cs418Problem::PngWords { found: args.len() }));
    };
    let side = |word: &str, height: bool| {
        word.parse::<u32>()
            .ok()
            .filter(|v| (1..=MAX_SIDE).contains(v))
            .ok_or_else(|| error(line, Cs418Problem::PngSide { height, word: word.to_string() }))
    };
    let (width, height) = (side(width, false)?, side(height, true)?);
    samples_within_limit(line, width, height, 1)?;
    if file.contains(['/', '\\']) || *file == ".." || *file == "." {
        return Err(error(line, Cs418Problem::PngFile { file: (*file).to_string() }));
    }
    Ok(RastFile {
        width,
        height,
        output: (*file).to_string(),
        features: Features { fsaa: 1, ..Features::default() },
        commands: Vec::new(),
        textures: Vec::new(),
    })
}

fn number(line: usize, keyword: &str, word: &str) -> Result<RastNumber, Cs418Error> {
    let finite = word.bytes().all(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.' | b'e' | b'E'));
    match (word.parse::<f64>(), crate::numbers::parse_number(word)) {
        (Ok(value), Ok(exact)) if finite && value.is_finite() => Ok(RastNumber { value, exact }),
        (Ok(value), Err(problem)) if finite && value.is_finite() => {
            Err(error(line, Cs418Problem::KeywordProblem { keyword: keyword.to_string(), problem }))
        }
        _ => Err(error(line, Cs418Problem::NotANumber { keyword: keyword.to_string(), word: word.to_string() })),
    }
}

fn integers<const N: usize>(line: usize, keyword: &str, args: &[&str]) -> Result<[usize; N], Cs418Error> {
    if args.len() != N {
        return Err(error(line, Cs418Problem::Integers { keyword: keyword.to_string(), count: N, found: args.len() }));
    }
    let mut out = [0; N];
    for (slot, word) in out.iter_mut().zip(args) {
        *slot = word.parse::<usize>().map_err(|_| {
            error(line, Cs418Problem::NotAWholeNumber { keyword: keyword.to_string(), word: word.to_string() })
        })?;
    }
    Ok(out)
}

fn sized(line: usize, keyword: &str, args: &[&str]) -> Result<(usize, Vec<RastNumber>), Cs418Error> {
    let Some((size, rest)) = args.split_first() else {
        return Err(error(line, Cs418Problem::Sized { keyword: keyword.to_string() }));
    };
    let size: usize = size
        .parse()
        .map_err(|_| error(line, Cs418Problem::SizeWord { keyword: keyword.to_string(), size: (*size).to_string() }))?;
    if size == 0 {
        return Err(error(line, Cs418Problem::SizeZero { keyword: keyword.to_string() }));
    }
    let numbers = rest.iter().map(|w| number(line, keyword, w)).collect::<Result<Vec<_>, _>>()?;
    if numbers.len() % size != 0 {
        let numbers = numbers.len();
        return Err(error(line, Cs418Problem::Vertices { keyword: keyword.to_string(), size, numbers }));
    }
    Ok((size, numbers))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::words::Lang;

    fn parse(text: &str) -> Result<RastFile, Cs418Error> {
        RastFile::parse(text, &|_| Err(TextureProblem::Missing))
    }

    #[test]
    fn reads_commands_with_their_lines() {
        let case = parse("png 20 30 gray.png\n# note\ndepth\nposition 2  1 2  3 4\ndrawArraysTriangles 0 3\n").unwrap();
        assert_eq!((case.width, case.height, case.output.as_str()), (20, 30, "gray.png"));
        assert!(case.features.depth && !case.features.srgb);
        assert_eq!(case.commands.len(), 2);
        assert_eq!(case.commands[1], (5, FileCommand::DrawArrays { first: 0, count: 3 }));
    }

    #[test]
    fn bad_lines_name_the_line_and_the_problem() {
        let message = |text: &str| parse(text).unwrap_err().message(Lang::En);
        assert_eq!(message("png 2 2 a.png\nfrobnicate 3"), "line 2: unknown command \"frobnicate\"");
        assert_eq!(
            message("png 2 2 a.png\nposition 3 1 2 3 4"),
            "line 2: position 3: 4 numbers is not a whole number of vertices (1 and 1 left over)"
        );
        assert_eq!(message("png 2 2 a.png\ncolor 3 1 x 0"), "line 2: color: \"x\" is not a number");
        assert_eq!(message("png 2 2 a.png\ncolor 3 1 nan 0"), "line 2: color: \"nan\" is not a number");
        assert_eq!(
            message("depth"),
            "line 1: \"depth\" before the \"png WIDTH HEIGHT FILE\" line that must come first"
        );
        assert_eq!(
            message("png 2 2 a.png\ntexture block.png"),
            "line 2: texture \"block.png\": no such file beside the case"
        );
        assert_eq!(message("png 2 2 a.png\ntexcoord 3 0 0 1"), "line 2: texcoord 3: the size must be 2");
        assert_eq!(message("png 2 2 ../a.png"), "line 1: png: \"../a.png\" must be a plain file name, without folders");
        assert_eq!(message("png 0 2 a.png"), "line 1: png: width \"0\" must be a whole number from 1 to 8192");
        assert_eq!(
            message("png 2 2 a.png\ndrawArraysTriangles 0 4"),
            "line 2: drawArraysTriangles: count 4 is not a multiple of 3"
        );
        assert_eq!(message("png 2 2 a.png\nfsaa 9"), "line 2: fsaa 9: the level must be 1 to 8");
        assert_eq!(message(""), "no \"png WIDTH HEIGHT FILE\" line: is this a CS 418 file?");
    }
}
