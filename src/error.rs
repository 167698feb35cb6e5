//! Errors a user can cause, with the context to fix them. Each message is one
//! line that starts lowercase and names the file and, where there is one, the
//! polygon. Broken invariants of zsim itself are `debug_assert!`s instead.

use std::fmt;
use std::path::PathBuf;

use crate::geometry::plane::GeometryError;

/// Everything that can go wrong with zsim's input.
#[derive(Debug)]
pub enum Error {
    /// A file could not be read.
    Read {
        /// The file.
        path: PathBuf,
        /// What the system said.
        source: std::io::Error,
    },
    /// A file could not be written.
    Write {
        /// The file.
        path: PathBuf,
        /// What the system said.
        source: std::io::Error,
    },
    /// The scene is not JSON of the scene format: bad syntax, a wrong type, an
    /// unknown key or effect, or a number that isn't one.
    SceneFormat {
        /// The scene file.
        path: PathBuf,
        /// Where in the file, e.g. `polygon 2: vertices[0][1]`.
        location: String,
        /// What is wrong.
        message: String,
    },
    /// A scene-wide setting is out of range.
    Setting {
        /// The scene file.
        path: PathBuf,
        /// The key, e.g. `frame_bits`.
        key: &'static str,
        /// What is wrong and what is allowed.
        message: String,
    },
    /// One polygon is unusable.
    Polygon {
        /// The scene file.
        path: PathBuf,
        /// 0-based index in the scene.
        index: usize,
        /// The polygon's name.
        name: String,
        /// What is wrong.
        problem: Box<PolygonProblem>,
    },
    /// A command-line argument that does not fit the scene.
    Usage(String),
    /// An answer file (for `check`) that is malformed or the wrong shape.
    Answer {
        /// The answer file.
        path: PathBuf,
        /// What was found.
        message: String,
    },
}

/// What is wrong with one polygon.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PolygonProblem {
    /// Its vertices (count, range, planarity).
    Geometry(GeometryError),
    /// Anything else, said in words.
    Other(String),
    /// Its value does not fit the framebuffer.
    ValueTooWide {
        /// The value given.
        value: u64,
        /// The scene's `frame_bits`.
        frame_bits: u32,
    },
}

impl fmt::Display for PolygonProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PolygonProblem::Geometry(error) => error.fmt(f),
            PolygonProblem::Other(message) => f.write_str(message),
            PolygonProblem::ValueTooWide { value, frame_bits } => f.write_str(&words!(
                "polygon-value-too-wide",
                value = value.to_string(),
                bits = frame_bits.to_string(),
                max = ((1u64 << frame_bits) - 1).to_string()
            )),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Read { path, source } => {
                f.write_str(&words!("error-read", path = path.display().to_string(), reason = source.to_string()))
            }
            Error::Write { path, source } => {
                f.write_str(&words!("error-write", path = path.display().to_string(), reason = source.to_string()))
            }
            Error::SceneFormat { path, location, message } => {
                if location.is_empty() {
                    write!(f, "{}: {message}", path.display())
                } else {
                    write!(f, "{}: {location}: {message}", path.display())
                }
            }
            Error::Setting { path, key, message } => write!(f, "{}: {key}: {message}", path.display()),
            Error::Polygon { path, index, name, problem } => f.write_str(&words!(
                "error-polygon",
                path = path.display().to_string(),
                polygon = crate::words::polygon_label("polygon-name", *index, name),
                problem = problem.to_string()
            )),
            Error::Usage(message) => f.write_str(message),
            Error::Answer { path, message } => write!(f, "{}: {message}", path.display()),
        }
    }
}

impl std::error::Error for Error {}
