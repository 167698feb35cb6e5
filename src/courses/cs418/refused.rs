//! What a CS 418 case, its textures or a reference image are refused for:
//! facts with their values, worded where they are shown.

use crate::door::PngProblem;
use crate::error::Error;
use crate::numbers::NumberError;
use crate::words::{Lang, token};

use crate::error::Refusal;

/// What is wrong in a CS 418 case (a line of its file, or what a command
/// asks of the vertices given before it), or in a reference image.
#[derive(Debug)]
pub enum Cs418Problem {
    /// A second `png` line.
    SecondPng,
    /// A command before the `png` line.
    BeforePng {
        /// The command.
        keyword: String,
    },
    /// A flag (`depth`, `sRGB`, …) followed by words.
    FlagNumbers {
        /// The flag.
        keyword: String,
        /// How many words follow it.
        found: usize,
    },
    /// An `fsaa` level outside 1 … 8.
    Fsaa {
        /// The level.
        level: usize,
    },
    /// A vertex size the command does not take.
    Size {
        /// The command.
        keyword: String,
        /// The size written.
        size: usize,
        /// The sizes it takes.
        allowed: &'static [usize],
    },
    /// An `elements` word that is not an index.
    NotAnIndex {
        /// The word.
        word: String,
    },
    /// A `uniformMatrix` of other than 16 numbers.
    Matrix {
        /// How many.
        found: usize,
    },
    /// A triangle draw whose count is not a multiple of three.
    Count {
        /// The command.
        keyword: String,
        /// The count.
        count: usize,
    },
    /// `texture` without a name.
    TextureName,
    /// A texture that cannot be used.
    Texture {
        /// The name the case gives.
        name: String,
        /// Why not.
        why: TextureProblem,
    },
    /// A command the course does not have.
    UnknownCommand {
        /// The word written.
        command: String,
    },
    /// No `png` line.
    NoPng,
    /// An image whose samples at its `fsaa` level pass the largest count.
    TooManySamples {
        /// The level.
        level: u32,
        /// The samples it would take.
        samples: u64,
    },
    /// A `png` line of other than three words.
    PngWords {
        /// How many.
        found: usize,
    },
    /// A `png` side that is not a whole number from 1 to the largest side.
    PngSide {
        /// The height, not the width.
        height: bool,
        /// The word written.
        word: String,
    },
    /// A `png` file name with folders in it.
    PngFile {
        /// The name.
        file: String,
    },
    /// A number zsim cannot hold exactly.
    KeywordProblem {
        /// The command.
        keyword: String,
        /// Why.
        problem: NumberError,
    },
    /// A word that is not a finite number.
    NotANumber {
        /// The command.
        keyword: String,
        /// The word.
        word: String,
    },
    /// A command with the wrong count of whole numbers.
    Integers {
        /// The command.
        keyword: String,
        /// How many it takes.
        count: usize,
        /// How many are written.
        found: usize,
    },
    /// A word that is not a whole number.
    NotAWholeNumber {
        /// The command.
        keyword: String,
        /// The word.
        word: String,
    },
    /// A sized command without its size.
    Sized {
        /// The command.
        keyword: String,
    },
    /// A size that is not a whole number.
    SizeWord {
        /// The command.
        keyword: String,
        /// The size written.
        size: String,
    },
    /// A size of 0.
    SizeZero {
        /// The command.
        keyword: String,
    },
    /// Numbers that are not a whole number of vertices.
    Vertices {
        /// The command.
        keyword: String,
        /// The vertex size.
        size: usize,
        /// How many numbers.
        numbers: usize,
    },
    /// A vertex index past the positions given.
    VertexIndex {
        /// The index.
        index: usize,
        /// The positions given.
        count: usize,
    },
    /// `drawElementsTriangles` reading past the elements given.
    ElementsRange {
        /// Its count.
        count: usize,
        /// Its offset.
        offset: usize,
        /// The elements given.
        has: usize,
    },
    /// A point drawn past the point sizes given.
    PointSizeRange {
        /// The index.
        index: usize,
        /// The sizes given.
        has: usize,
    },
    /// A vertex read past the colours given.
    ColourRange {
        /// The index.
        index: usize,
        /// The colours given.
        has: usize,
    },
    /// A textured vertex read past the texture coordinates given.
    TexcoordRange {
        /// The index.
        index: usize,
        /// The coordinates given.
        has: usize,
    },
    /// A vertex too far outside the image to rasterize.
    TooFar {
        /// Where it lands.
        x: f64,
        /// Where it lands.
        y: f64,
    },
    /// More primitives than a framebuffer cell can number.
    TooManyPrimitives {
        /// How many.
        count: u64,
    },
    /// A reference image that cannot be read.
    Reference(PngProblem),
    /// A reference image of another size than the case's.
    ImageSize {
        /// The reference's size.
        size: (u32, u32),
        /// The case's.
        case: (u32, u32),
    },
}

/// Why a texture a case names cannot be used.
#[derive(Debug)]
pub enum TextureProblem {
    /// No such file beside the case.
    Missing,
    /// The file could not be read.
    Unread(Box<Error>),
    /// Not an image zsim decodes.
    Image(PngProblem),
    /// The case's textures together would hold more pixels than allowed.
    TooLarge {
        /// The pixels they would hold.
        pixels: u64,
    },
}

impl TextureProblem {
    fn message(&self, lang: Lang) -> String {
        match self {
            TextureProblem::Missing => words!(lang, "cs418-texture-missing"),
            TextureProblem::Unread(error) => error.message(lang),
            TextureProblem::Image(problem) => problem.message(lang),
            TextureProblem::TooLarge { pixels } => words!(
                lang,
                "cs418-textures-too-large",
                pixels = pixels.to_string(),
                max = super::MAX_CASE_TEXTURE_PIXELS.to_string()
            ),
        }
    }
}

fn list(lang: Lang, values: &[usize]) -> String {
    let words: Vec<String> = values.iter().map(ToString::to_string).collect();
    match words.split_last() {
        Some((last, rest)) if !rest.is_empty() => words!(lang, "list-or", rest = rest.join(", "), last = last.as_str()),
        _ => words.join(""),
    }
}

impl Refusal for Cs418Problem {
    fn message(&self, lang: Lang) -> String {
        let t = |text: &str| token(lang, text);
        match self {
            Cs418Problem::SecondPng => words!(lang, "cs418-second-png"),
            Cs418Problem::BeforePng { keyword } => words!(lang, "cs418-before-png", keyword = t(keyword)),
            Cs418Problem::FlagNumbers { keyword, found } => {
                words!(lang, "cs418-flag-numbers", keyword = t(keyword), found = found.to_string())
            }
            Cs418Problem::Fsaa { level } => words!(lang, "cs418-fsaa", level = level.to_string()),
            Cs418Problem::Size { keyword, size, allowed } => {
                words!(lang, "cs418-size", keyword = t(keyword), size = size.to_string(), allowed = list(lang, allowed))
            }
            Cs418Problem::NotAnIndex { word } => words!(lang, "cs418-not-an-index", word = t(word)),
            Cs418Problem::Matrix { found } => words!(lang, "cs418-matrix", found = found.to_string()),
            Cs418Problem::Count { keyword, count } => {
                words!(lang, "cs418-count", keyword = t(keyword), count = count.to_string())
            }
            Cs418Problem::TextureName => words!(lang, "cs418-texture-name"),
            Cs418Problem::Texture { name, why } => {
                words!(lang, "cs418-texture", name = name.as_str(), why = why.message(lang))
            }
            Cs418Problem::UnknownCommand { command } => words!(lang, "case-unknown-command", command = t(command)),
            Cs418Problem::NoPng => words!(lang, "cs418-no-png"),
            Cs418Problem::TooManySamples { level, samples } => words!(
                lang,
                "cs418-too-many-samples",
                level = level.to_string(),
                samples = samples.to_string(),
                max = super::MAX_SAMPLES.to_string()
            ),
            Cs418Problem::PngWords { found } => words!(lang, "cs418-png-words", found = found.to_string()),
            Cs418Problem::PngSide { height, word } => words!(
                lang,
                "cs418-png-side",
                what = if *height { words!(lang, "cs418-height") } else { words!(lang, "cs418-width") },
                word = t(word),
                max = super::MAX_SIDE.to_string()
            ),
            Cs418Problem::PngFile { file } => words!(lang, "cs418-png-file", file = t(file)),
            Cs418Problem::KeywordProblem { keyword, problem } => {
                words!(lang, "case-keyword-problem", keyword = t(keyword), problem = problem.message(lang))
            }
            Cs418Problem::NotANumber { keyword, word } => {
                words!(lang, "cs418-not-a-number", keyword = t(keyword), word = t(word))
            }
            Cs418Problem::Integers { keyword, count, found } => {
                words!(lang, "cs418-integers", keyword = t(keyword), count = *count, found = found.to_string())
            }
            Cs418Problem::NotAWholeNumber { keyword, word } => {
                words!(lang, "cs418-not-a-whole-number", keyword = t(keyword), word = t(word))
            }
            Cs418Problem::Sized { keyword } => words!(lang, "cs418-sized", keyword = t(keyword)),
            Cs418Problem::SizeWord { keyword, size } => {
                words!(lang, "cs418-size-word", keyword = t(keyword), size = t(size))
            }
            Cs418Problem::SizeZero { keyword } => words!(lang, "cs418-size-zero", keyword = t(keyword)),
            Cs418Problem::Vertices { keyword, size, numbers } => words!(
                lang,
                "cs418-vertices",
                keyword = t(keyword),
                size = size.to_string(),
                numbers = numbers.to_string(),
                whole = (numbers / size).to_string(),
                left = (numbers % size).to_string()
            ),
            Cs418Problem::VertexIndex { index, count } => {
                words!(lang, "cs418-vertex-index", index = index.to_string(), count = count.to_string())
            }
            Cs418Problem::ElementsRange { count, offset, has } => words!(
                lang,
                "cs418-elements-range",
                count = count.to_string(),
                offset = offset.to_string(),
                last = offset.saturating_add(*count).saturating_sub(1).to_string(),
                has = has.to_string()
            ),
            Cs418Problem::PointSizeRange { index, has } => {
                words!(lang, "cs418-point-size-range", index = index.to_string(), has = has.to_string())
            }
            Cs418Problem::ColourRange { index, has } => {
                words!(lang, "cs418-colour-range", index = index.to_string(), has = has.to_string())
            }
            Cs418Problem::TexcoordRange { index, has } => {
                words!(lang, "cs418-texcoord-range", index = index.to_string(), has = has.to_string())
            }
            Cs418Problem::TooFar { x, y } => words!(
                lang,
                "cs418-too-far",
                x = x.to_string(),
                y = y.to_string(),
                reach = super::raster::REACH.to_string()
            ),
            Cs418Problem::TooManyPrimitives { count } => {
                words!(lang, "cs418-too-many-primitives", count = count.to_string())
            }
            Cs418Problem::Reference(problem) => problem.message(lang),
            Cs418Problem::ImageSize { size, case } => words!(
                lang,
                "cs418-image-size",
                width = size.0.to_string(),
                height = size.1.to_string(),
                case_width = case.0.to_string(),
                case_height = case.1.to_string()
            ),
        }
    }
}
