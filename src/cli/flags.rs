//! Errors of the command line's own flags (a tile of zero pixels, a
//! format that does not go with another flag): worded here, in the
//! reader's language, and reported as every other error is (exit status 2).
//! The library's errors are the library's (`zsim::Error`).

use std::path::PathBuf;

/// A request of the command line that its flags do not allow.
#[derive(Debug)]
pub enum Flag {
    /// An inexact `--arith` with `--segments` or `--order`.
    ArithPlainLoopOnly,
    /// A figure file that is neither SVG nor PNG.
    FigureFormat {
        /// The file asked for.
        path: PathBuf,
    },
    /// `check` with neither `--frame` nor `--depth`.
    CheckNeedsAnswer,
    /// `check SCENE FILE`: an answer named without `--frame` or `--depth`.
    AnswerWithoutBuffer {
        /// The answer named.
        path: PathBuf,
    },
    /// `grade --identity`: a column the chosen platform does not import by.
    IdentityColumn {
        /// The column's header.
        column: &'static str,
    },
    /// `grade --points 0`.
    NoPoints,
    /// `step --html --quiz` with an inexact `--arith`: the page's quiz asks in exact arithmetic.
    HtmlQuiz,
    /// The playground's site asked of a zsim built without it.
    NoPlayground,
    /// A line of `step`'s line mode longer than it reads.
    LineTooLong {
        /// The longest line, in bytes.
        max: usize,
    },
    /// `grade` without SCENE and CLASS, or `grade --variants` without exactly CLASS.
    GradeFolders {
        /// Whether --variants was given.
        variants: bool,
    },
    /// `accuracy --scenes` out of range.
    ScenesOutOfRange,
    /// `memory --frame-bits`/`--depth-bits` out of range.
    MemoryBits {
        /// The option.
        option: &'static str,
        /// The bits given.
        bits: u32,
    },
    /// `memory` with a zero size.
    MemoryZeroSize,
    /// `memory` on a raster of more than 2^50 cells.
    MemoryTooLarge,
    /// `random --count` too large.
    RandomCount {
        /// The count given.
        count: usize,
        /// The largest allowed.
        max: usize,
    },
    /// `random --frame-bits`/`--depth-bits` out of range.
    RandomBits,
    /// `random --width`/`--height` out of range.
    RandomSide {
        /// The largest side.
        max: u32,
    },
    /// `--tile 0`.
    TileZero,
    /// `--inside` without `--order pixels`.
    InsideNeedsPixelOrder,
    /// `--tile` or `--threads` with a format other than `none`.
    TilesNeedFormatNone,
    /// `--format none` with a variant of the loop.
    FormatNoneIsPlain,
}

impl Flag {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: zsim::Lang) -> String {
        let path = |p: &PathBuf| zsim::shown_path(p);
        match self {
            Flag::ArithPlainLoopOnly => zsim::words!(lang, "usage-arith-plain-loop"),
            Flag::FigureFormat { path: p } => zsim::words!(lang, "usage-figure-format", path = path(p)),
            Flag::CheckNeedsAnswer => zsim::words!(lang, "usage-check-needs-answer"),
            Flag::AnswerWithoutBuffer { path: p } => zsim::words!(lang, "usage-answer-without-buffer", path = path(p)),
            Flag::IdentityColumn { column } => zsim::words!(lang, "usage-identity-column", column = *column),
            Flag::NoPoints => zsim::words!(lang, "usage-no-points"),
            Flag::HtmlQuiz => zsim::words!(lang, "usage-html-quiz"),
            Flag::NoPlayground => zsim::words!(lang, "usage-no-playground"),
            Flag::LineTooLong { max } => zsim::words!(lang, "usage-line-too-long", max = *max),
            Flag::GradeFolders { variants: true } => zsim::words!(lang, "usage-grade-variants-folder"),
            Flag::GradeFolders { variants: false } => zsim::words!(lang, "usage-grade-scene-and-class"),
            Flag::ScenesOutOfRange => zsim::words!(lang, "usage-scenes-range"),
            Flag::MemoryBits { option, bits } => {
                zsim::words!(lang, "usage-memory-bits", option = *option, bits = bits.to_string())
            }
            Flag::MemoryZeroSize => zsim::words!(lang, "usage-memory-zero"),
            Flag::MemoryTooLarge => zsim::words!(lang, "usage-memory-too-large"),
            Flag::RandomCount { count, max } => {
                zsim::words!(lang, "usage-random-count", count = count.to_string(), max = max.to_string())
            }
            Flag::RandomBits => zsim::words!(lang, "usage-random-bits"),
            Flag::RandomSide { max } => zsim::words!(lang, "usage-random-side", max = max.to_string()),
            Flag::TileZero => zsim::words!(lang, "usage-tile-zero"),
            Flag::InsideNeedsPixelOrder => zsim::words!(lang, "usage-inside-needs-pixel-order"),
            Flag::TilesNeedFormatNone => zsim::words!(lang, "usage-tiles-need-format-none"),
            Flag::FormatNoneIsPlain => zsim::words!(lang, "usage-format-none-is-plain"),
        }
    }
}
