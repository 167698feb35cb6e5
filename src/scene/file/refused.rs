//! A scene file zsim does not read, as facts (where in the file, what is
//! wrong, with its values), worded only where it is shown
//! ([`Refusal::message`]): the scene is read without a language.

use std::path::PathBuf;

use crate::error::Refusal;
use crate::numbers::{Q, fraction};
use crate::words::{Lang, shown_path};

/// A scene file that is not read: its path and why.
#[derive(Clone, PartialEq, Eq)]
pub struct SceneRefused {
    /// The scene file.
    pub path: PathBuf,
    /// What is wrong.
    pub problem: SceneProblem,
}

/// What is wrong with a scene file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SceneProblem {
    /// Valid-looking JSON whose first value is not an object.
    NotObject(JsonKind),
    /// Not JSON of the scene format: bad syntax, a wrong type, an unknown key
    /// or effect, or a number that isn't one.
    Format(FormatProblem),
    /// A scene-wide setting is out of range.
    Setting {
        /// The key, e.g. `frame_bits`.
        key: &'static str,
        /// What is wrong with it.
        problem: SettingProblem,
    },
}

/// What a JSON value is, when it is not an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JsonKind {
    /// `[…]`.
    Array,
    /// `"…"`.
    String,
    /// A number.
    Number,
    /// `true` or `false`.
    Bool,
    /// `null`.
    Null,
}

/// Where and how the file is not JSON of the scene format.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FormatProblem {
    /// Where in the scene's structure (none for a syntax error: its line
    /// says where).
    pub place: Option<Place>,
    /// The file's line where it is (from 1), where known.
    pub line: Option<usize>,
    /// Whether the JSON itself is broken (rather than a value of the wrong
    /// kind).
    pub syntax: bool,
    /// serde_json's description, as it gives it (worded through
    /// [`crate::words::json_reason`]).
    pub reason: String,
    /// For a missing comma, where it belongs.
    pub comma: Option<MissingComma>,
}

/// A place in the scene's structure: a polygon's number and the path within
/// it, or a path from the top (`window.left`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Place {
    /// The polygon, from 0, when the place is in one.
    pub polygon: Option<usize>,
    /// The path (within the polygon, if one), e.g. `vertices[0][1]`.
    pub path: String,
}

/// Where a missing comma belongs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MissingComma {
    /// At the end of this line (from 1).
    EndOfLine(usize),
    /// After this line and column (both from 1).
    After(usize, usize),
}

/// What is wrong with a setting, with its values.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SettingProblem {
    /// Bits outside 1 … 32.
    Bits(u64),
    /// A side of 0.
    SideZero,
    /// A side past the largest.
    SideLarge {
        /// The side asked for.
        side: u64,
        /// The largest.
        max: u64,
    },
    /// More cells than the largest raster.
    Cells {
        /// The width.
        width: u32,
        /// The height.
        height: u32,
        /// The most cells.
        max: u64,
    },
    /// A background past the framebuffer's largest value.
    Background {
        /// The background.
        value: u64,
        /// The framebuffer's bits.
        bits: u32,
        /// Its largest value.
        max: u64,
    },
    /// `rules` that do not read: serde_json's description.
    Rules(String),
    /// A window with its sides the wrong way round.
    Window {
        /// Left, right, bottom and top.
        sides: [Q; 4],
    },
    /// A depth range whose front lies past its rear.
    DepthRange {
        /// The front.
        front: Q,
        /// The rear.
        rear: Q,
    },
    /// `clear_depth` with a quantized z-buffer.
    ClearDepth,
    /// A perspective's distance or near plane not positive.
    PerspectiveNotPositive,
    /// Antialiasing's samples outside 1 … 16.
    AntialiasSamples(u32),
    /// Antialiasing's sample cells past the largest raster.
    AntialiasCells {
        /// The width.
        width: u32,
        /// The height.
        height: u32,
        /// The samples per side.
        samples: u32,
        /// The most cells.
        max: u64,
    },
    /// Antialiasing with an exact z-buffer.
    AntialiasExact,
}

/// The path and the English message: what a panic or a failed test prints
/// (the facts themselves are compared, not printed; a derived form would put
/// every problem's formatting into the browser's module).
impl std::fmt::Debug for SceneRefused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SceneRefused")
            .field("path", &self.path)
            .field("problem", &format_args!("{}", self.message(Lang::En)))
            .finish()
    }
}

impl Refusal for SceneRefused {
    fn message(&self, lang: Lang) -> String {
        let path = shown_path(&self.path);
        match &self.problem {
            SceneProblem::NotObject(kind) => {
                let found = match kind {
                    JsonKind::Array => words!(lang, "json-array"),
                    JsonKind::String => words!(lang, "json-string"),
                    JsonKind::Number => words!(lang, "json-number"),
                    JsonKind::Bool => words!(lang, "json-bool"),
                    JsonKind::Null => words!(lang, "json-null"),
                };
                format!("{path}: {}", words!(lang, "scene-not-object", found = found))
            }
            SceneProblem::Format(problem) => {
                let reason = crate::words::json_reason(lang, &problem.reason);
                let mut message = if problem.syntax { words!(lang, "json-invalid", error = reason) } else { reason };
                match problem.comma {
                    Some(MissingComma::EndOfLine(line)) => {
                        message.push_str(&words!(lang, "json-comma-end", line = line.to_string()));
                    }
                    Some(MissingComma::After(line, column)) => message.push_str(&words!(
                        lang,
                        "json-comma-after",
                        line = line.to_string(),
                        column = column.to_string()
                    )),
                    None => {}
                }
                match &problem.place {
                    None => format!("{path}: {message}"),
                    Some(place) => format!("{path}: {}: {message}", place.shown(lang)),
                }
            }
            SceneProblem::Setting { key, problem } => format!("{path}: {key}: {}", problem.message(lang)),
        }
    }
}

impl Place {
    /// `polygon 2: vertices[0][2]`, as the command line names polygons.
    fn shown(&self, lang: Lang) -> String {
        match self.polygon {
            None => self.path.clone(),
            Some(index) => {
                let polygon = words!(lang, "location-polygon", number = (index + 1).to_string());
                if self.path.is_empty() { polygon } else { format!("{polygon}: {}", self.path) }
            }
        }
    }
}

impl SettingProblem {
    /// What is wrong and what is allowed, in `lang`.
    fn message(&self, lang: Lang) -> String {
        match self {
            SettingProblem::Bits(value) => words!(lang, "setting-bits", value = value.to_string()),
            SettingProblem::SideZero => words!(lang, "setting-side-zero"),
            SettingProblem::SideLarge { side, max } => {
                words!(lang, "setting-side-large", side = side.to_string(), max = max.to_string())
            }
            SettingProblem::Cells { width, height, max } => words!(
                lang,
                "setting-cells",
                width = width.to_string(),
                height = height.to_string(),
                cells = (u64::from(*width) * u64::from(*height)).to_string(),
                max = max.to_string()
            ),
            SettingProblem::Background { value, bits, max } => words!(
                lang,
                "setting-background",
                value = value.to_string(),
                bits = bits.to_string(),
                max = max.to_string()
            ),
            SettingProblem::Rules(reason) => crate::words::json_reason(lang, reason),
            SettingProblem::Window { sides: [left, right, bottom, top] } => words!(
                lang,
                "setting-window",
                left = fraction(*left),
                right = fraction(*right),
                bottom = fraction(*bottom),
                top = fraction(*top)
            ),
            SettingProblem::DepthRange { front, rear } => {
                words!(lang, "setting-depth-range", front = fraction(*front), rear = fraction(*rear))
            }
            SettingProblem::ClearDepth => words!(lang, "setting-clear-depth"),
            SettingProblem::PerspectiveNotPositive => words!(lang, "setting-perspective-positive"),
            SettingProblem::AntialiasSamples(samples) => {
                words!(lang, "setting-antialias-samples", samples = samples.to_string())
            }
            SettingProblem::AntialiasCells { width, height, samples, max } => words!(
                lang,
                "setting-antialias-cells",
                width = width.to_string(),
                height = height.to_string(),
                samples = samples.to_string(),
                max = max.to_string()
            ),
            SettingProblem::AntialiasExact => words!(lang, "setting-antialias-exact"),
        }
    }
}
