//! Errors a user can cause, with the context to fix them. Each message is one
//! line that starts lowercase and names the file and, where there is one, the
//! polygon. Broken invariants of zsim itself are `debug_assert!`s instead.

use crate::words::Lang;
use crate::words::shown_path;
use std::path::PathBuf;

use crate::geometry::equation::GeometryError;

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
    /// A text file that is not UTF-8.
    NotText {
        /// The file.
        path: PathBuf,
    },
    /// An input that is not a regular file (or a symbolic link where none is
    /// followed): refused before anything is read.
    NotRegular {
        /// The path.
        path: PathBuf,
        /// What it is.
        kind: FileKind,
    },
    /// An input larger than zsim reads.
    TooLarge {
        /// The path.
        path: PathBuf,
        /// The largest size read, in bytes.
        limit: u64,
    },
    /// A name inside a file that leads out of that file's folder (`..`, an
    /// absolute path): refused, nothing read.
    OutsideFolder {
        /// The path it names.
        path: PathBuf,
        /// The folder it must stay in.
        folder: PathBuf,
    },
    /// A file could not be written.
    Write {
        /// The file.
        path: PathBuf,
        /// What the system said.
        source: std::io::Error,
    },
    /// One polygon is unusable.
    Polygon {
        /// Where the polygon came from.
        origin: PolygonOrigin,
        /// 0-based index in the scene.
        index: usize,
        /// The polygon's name.
        name: String,
        /// What is wrong.
        problem: Box<PolygonProblem>,
    },
    /// A refusal a layer states as a fact of its own (the door's outputs, a
    /// scene's polygons, a figure's, a check's, grading's, the GPU's, an
    /// exercise's, an arithmetic mode's, the command line's).
    Refused(Box<dyn Refusal>),
}

/// A request a layer refuses, kept as that layer's fact and worded from its
/// own messages in the reader's language: each layer owns its errors, and
/// [`Error::Refused`] carries them to the front end that shows them.
pub trait Refusal: std::any::Any + std::fmt::Debug + Send + Sync {
    /// The message in `lang`, one line.
    fn message(&self, lang: Lang) -> String;
}

/// What an input that is not a regular file is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// A folder.
    Directory,
    /// A named pipe.
    Fifo,
    /// A device (`/dev/zero`, a terminal).
    Device,
    /// A socket.
    Socket,
    /// A symbolic link, where none is followed.
    Link,
    /// Something else.
    Other,
}

impl FileKind {
    /// The kind of a file that is not a regular one.
    pub fn of(kind: &std::fs::FileType) -> FileKind {
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if kind.is_fifo() {
                return FileKind::Fifo;
            }
            if kind.is_char_device() || kind.is_block_device() {
                return FileKind::Device;
            }
            if kind.is_socket() {
                return FileKind::Socket;
            }
        }
        if kind.is_dir() {
            FileKind::Directory
        } else if kind.is_symlink() {
            FileKind::Link
        } else {
            FileKind::Other
        }
    }
}

/// Where a polygon with a problem came from: a file, or zsim's own
/// transformation of one (named as such, not as an invented path).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PolygonOrigin {
    /// The scene file that gives it.
    File(PathBuf),
    /// The scene supersampled `factor`× for antialiasing.
    Supersampled {
        /// The factor.
        factor: u32,
    },
    /// The scene snapped to `bits` fractional bits (fixed-point arithmetic).
    Snapped {
        /// The fractional bits.
        bits: u32,
    },
}

impl<R: Refusal + 'static> From<R> for Error {
    fn from(refusal: R) -> Error {
        Error::Refused(Box::new(refusal))
    }
}

/// What is wrong with one polygon.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PolygonProblem {
    /// Its vertices (count, range, planarity).
    Geometry(GeometryError),
    /// Its opacity (written as a number) lies outside 0 … 1.
    Opacity {
        /// The opacity, as a fraction.
        alpha: String,
    },
    /// Four numbers among three-number vertices, that read as a decimal
    /// comma: `[1, 2, 9, 5]` for `[1, 2, 9.5]`.
    DecimalComma {
        /// The vertex as written, `[1, 2, 9, 5]`.
        written: String,
        /// The comma's numbers, `9,5`.
        comma: String,
        /// The vertex meant, `[1, 2, 9.5]`.
        meant: String,
    },
    /// Three-number vertices mixed with clip-space `[x, y, z, w]` ones.
    ClipSpaceMixed,
    /// Clip-space vertices in a scene with a window or the perspective effect.
    ClipSpaceAlone,
    /// Its value does not fit the framebuffer.
    ValueTooWide {
        /// The value given.
        value: u64,
        /// The scene's `frame_bits`.
        frame_bits: u32,
    },
}

impl PolygonProblem {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            PolygonProblem::Geometry(error) => error.message(lang),
            PolygonProblem::Opacity { alpha } => words!(lang, "polygon-opacity", alpha = alpha.as_str()),
            PolygonProblem::DecimalComma { written, comma, meant } => words!(
                lang,
                "vertex-decimal-comma",
                written = written.as_str(),
                comma = comma.as_str(),
                meant = meant.as_str()
            ),
            PolygonProblem::ClipSpaceMixed => words!(lang, "clip-space-mixed"),
            PolygonProblem::ClipSpaceAlone => words!(lang, "clip-space-alone"),
            PolygonProblem::ValueTooWide { value, frame_bits } => words!(
                lang,
                "polygon-value-too-wide",
                value = value.to_string(),
                bits = frame_bits.to_string(),
                max = ((1u64 << frame_bits) - 1).to_string()
            ),
        }
    }
}

impl Error {
    /// The refusal of type `R` this error carries, if it is one.
    pub fn refused<R: Refusal>(&self) -> Option<&R> {
        match self {
            Error::Refused(refusal) => (&**refusal as &dyn std::any::Any).downcast_ref::<R>(),
            _ => None,
        }
    }

    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            Error::Read { path, source } => {
                words!(lang, "error-read", path = shown_path(path), reason = crate::words::io_reason(lang, source))
            }
            Error::NotText { path } => {
                words!(lang, "error-read", path = shown_path(path), reason = words!(lang, "error-not-utf8"))
            }
            Error::NotRegular { path, kind } => {
                let kind = match kind {
                    FileKind::Directory => words!(lang, "file-kind-directory"),
                    FileKind::Fifo => words!(lang, "file-kind-fifo"),
                    FileKind::Device => words!(lang, "file-kind-device"),
                    FileKind::Socket => words!(lang, "file-kind-socket"),
                    FileKind::Link => words!(lang, "file-kind-link"),
                    FileKind::Other => words!(lang, "file-kind-other"),
                };
                words!(lang, "error-not-regular", path = shown_path(path), kind = kind)
            }
            Error::TooLarge { path, limit } => {
                words!(lang, "error-too-large", path = shown_path(path), limit = (limit >> 20).to_string())
            }
            Error::OutsideFolder { path, folder } => {
                words!(lang, "error-outside-folder", path = shown_path(path), folder = shown_path(folder))
            }
            Error::Write { path, source } => {
                words!(lang, "error-write", path = shown_path(path), reason = crate::words::io_reason(lang, source))
            }
            Error::Polygon { origin, index, name, problem } => words!(
                lang,
                "error-polygon",
                path = match origin {
                    PolygonOrigin::File(path) => shown_path(path),
                    PolygonOrigin::Supersampled { factor } =>
                        words!(lang, "origin-supersampled", factor = factor.to_string()),
                    PolygonOrigin::Snapped { bits } => words!(lang, "origin-snapped", bits = bits.to_string()),
                },
                polygon = crate::words::polygon_label(lang, "polygon-name", *index, name),
                problem = problem.message(lang)
            ),
            Error::Refused(refusal) => refusal.message(lang),
        }
    }
}
