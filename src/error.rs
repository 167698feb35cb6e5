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
    /// The scene is not JSON of the scene format: bad syntax, a wrong type, an
    /// unknown key or effect, or a number that isn't one.
    SceneFormat {
        /// The scene file.
        path: PathBuf,
        /// Where in the file, e.g. `polygon 2: vertices[0][1]`.
        location: String,
        /// The file's line where it is (from 1), where known.
        line: Option<usize>,
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
        /// Where the polygon came from.
        origin: PolygonOrigin,
        /// 0-based index in the scene.
        index: usize,
        /// The polygon's name.
        name: String,
        /// What is wrong.
        problem: Box<PolygonProblem>,
    },
    /// A command-line request that does not fit the command or the scene.
    Usage(Usage),
    /// An answer file (for `check`) that is malformed or the wrong shape.
    Answer {
        /// The answer file.
        path: PathBuf,
        /// What was found.
        message: String,
    },
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
    /// The scene snapped to `bits` fractional bits (`--arith fixed:K`).
    Snapped {
        /// The fractional bits.
        bits: u32,
    },
}

/// What a command needs done differently: each with the facts its message
/// states, worded by the catalogues in the reader's language.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Usage {
    /// An inexact `--arith` on a scene with other rules or effects.
    ArithNeedsPlainRules {
        /// The mode, as written.
        arith: String,
    },
    /// An inexact `--arith` on a scene with another depth test.
    ArithNeedsGreaterOrLess {
        /// The mode, as written.
        arith: String,
        /// The scene's depth test.
        test: String,
    },
    /// `--after N` past the last polygon.
    NoPolygonNumbered {
        /// N.
        number: usize,
        /// How many polygons the scene has.
        count: usize,
    },
    /// `--after NAME` that no polygon has.
    NoPolygonNamed {
        /// The name asked for.
        name: String,
        /// The scene's polygon names.
        names: Vec<String>,
    },
    /// A pixel outside the raster.
    PixelOutside {
        /// Its column.
        x: u32,
        /// Its row.
        y: u32,
        /// The raster's width.
        width: u32,
        /// The raster's height.
        height: u32,
    },
    /// A raster too large for a figure.
    FigureTooLarge {
        /// The scene file.
        path: PathBuf,
        /// The raster's width.
        width: u32,
        /// The raster's height.
        height: u32,
        /// The largest side a figure draws.
        max: u32,
    },
    /// The PNG renderer failed.
    PngFailed {
        /// The PNG asked for.
        path: PathBuf,
        /// What failed.
        reason: String,
    },
    /// A scene without polygons given to a command that needs one.
    NoPolygons {
        /// The scene file.
        path: PathBuf,
        /// The command.
        task: Task,
    },
    /// A scene keeping exact depths, whose z-buffer has no integer matrix.
    ExactDepthsHaveNoMatrix {
        /// The scene file.
        path: PathBuf,
        /// The command.
        task: Task,
    },
    /// `check --submission`: the folder holds no answer file.
    NoSubmission {
        /// The folder.
        folder: PathBuf,
    },
    /// A class folder without answer files.
    NoAnswersFound {
        /// The folder.
        class: PathBuf,
    },
    /// `exercise --hard` names an unknown case.
    NotAHardCase {
        /// The name given.
        name: String,
        /// The names of the hard cases.
        names: Vec<String>,
    },
    /// `exercise --size` out of range.
    ExerciseSize {
        /// The width given.
        width: u32,
        /// The height given.
        height: u32,
    },
    /// `exercise --polygons` out of range.
    ExercisePolygons {
        /// The count given.
        count: usize,
    },
    /// `exercise` bits out of range for work by hand.
    ExerciseBits,
    /// `hidden` or `intersecting` asked of one polygon.
    ExerciseNeedsTwoPolygons,
    /// No candidate scene showed every case asked for.
    ExerciseNotFound {
        /// Polygons asked for.
        polygons: usize,
        /// The raster's width.
        width: u32,
        /// The raster's height.
        height: u32,
        /// The cases asked for.
        cases: Vec<String>,
        /// Candidates tried.
        tries: usize,
    },
    /// `-o FOLDER` is the folder the command reads.
    OutputIsInput {
        /// The folder.
        folder: PathBuf,
    },
    /// Two files of a submission answer for one buffer of one state.
    SameAnswerTwice {
        /// The submission folder.
        folder: PathBuf,
        /// The two files, by name.
        files: Vec<String>,
    },
    /// Two files of a class folder that name one student for one buffer.
    SameStudentTwice {
        /// The class folder.
        class: PathBuf,
        /// The student, as shown.
        student: String,
        /// The two files, by name.
        files: Vec<String>,
    },
    /// Two students a gradebook import would take for one.
    GradebookCannotTell {
        /// One student, as shown.
        first: String,
        /// The other.
        second: String,
    },
    /// An output whose name the file system cannot hold.
    OutputNameTooLong {
        /// The path.
        path: PathBuf,
        /// The longest name, in bytes.
        max: usize,
    },
    /// One command asked to write one file twice.
    OutputTwice {
        /// The file.
        path: PathBuf,
    },
    /// `-o FOLDER` already holds files the command would write.
    OutputWouldReplace {
        /// The folder.
        folder: PathBuf,
        /// The files it would replace, by name.
        files: Vec<String>,
    },
    /// `--compare-gpu` on a scene with per-pixel effects or antialiasing.
    CompareGpuPlainOnly,
    /// `--compare-gpu` without a usable GPU.
    NoGpu {
        /// What went wrong.
        reason: String,
    },
    /// `step --polygon` on a polygon that is not drawn.
    NoScanlines {
        /// 0-based polygon index.
        index: usize,
        /// Its name.
        name: String,
        /// Why it is not drawn, in words.
        why: String,
    },
    /// `step --scanline` on a row the polygon does not reach.
    ScanlineNotReached {
        /// 0-based polygon index.
        index: usize,
        /// Its name.
        name: String,
        /// The row asked for.
        row: u32,
        /// The first and last rows it reaches, if any.
        rows: Option<(u32, u32)>,
    },
}

/// The command a [`Usage`] error comes from, where the wording depends on it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Task {
    /// `figure`.
    Draw,
    /// `grade`.
    Grade,
    /// `check`.
    Check,
}

impl From<Usage> for Error {
    fn from(usage: Usage) -> Error {
        Error::Usage(usage)
    }
}

fn quoted_list(items: &[String]) -> String {
    items.iter().map(|item| format!("\"{item}\"")).collect::<Vec<_>>().join(", ")
}

impl Usage {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        let path = |p: &PathBuf| shown_path(p);
        match self {
            Usage::ArithNeedsPlainRules { arith } => words!(lang, "usage-arith-plain-rules", arith = arith),
            Usage::ArithNeedsGreaterOrLess { arith, test } => {
                words!(lang, "usage-arith-greater-or-less", arith = arith, test = test)
            }
            Usage::NoPolygonNumbered { number, count } => {
                words!(lang, "usage-no-polygon-numbered", number = number.to_string(), count = count.to_string())
            }
            Usage::NoPolygonNamed { name, names } => {
                words!(lang, "usage-no-polygon-named", name = name, names = quoted_list(names))
            }
            Usage::PixelOutside { x, y, width, height } => words!(
                lang,
                "usage-pixel-outside",
                x = x.to_string(),
                y = y.to_string(),
                width = width.to_string(),
                height = height.to_string(),
                last_x = (width - 1).to_string(),
                last_y = (height - 1).to_string()
            ),
            Usage::FigureTooLarge { path: p, width, height, max } => words!(
                lang,
                "usage-figure-too-large",
                path = path(p),
                width = width.to_string(),
                height = height.to_string(),
                max = max.to_string()
            ),
            Usage::PngFailed { path: p, reason } => words!(lang, "usage-png-failed", path = path(p), reason = reason),
            Usage::NoPolygons { path: p, task } => match task {
                Task::Draw => words!(lang, "usage-no-polygons-draw", path = path(p)),
                Task::Grade => words!(lang, "usage-no-polygons-grade", path = path(p)),
                Task::Check => words!(lang, "usage-no-polygons-check", path = path(p)),
            },
            Usage::ExactDepthsHaveNoMatrix { path: p, task } => match task {
                Task::Grade => words!(lang, "usage-exact-depths-grade", path = path(p)),
                Task::Draw | Task::Check => words!(lang, "usage-exact-depths-check", path = path(p)),
            },
            Usage::NoSubmission { folder } => {
                words!(lang, "usage-no-submission", folder = shown_path(folder))
            }
            Usage::NoAnswersFound { class } => words!(lang, "usage-no-answers", path = path(class)),
            Usage::NotAHardCase { name, names } => {
                words!(lang, "usage-not-a-hard-case", name = name, names = names.join(", "))
            }
            Usage::ExerciseSize { width, height } => {
                words!(lang, "usage-exercise-size", width = width.to_string(), height = height.to_string())
            }
            Usage::ExercisePolygons { count } => words!(lang, "usage-exercise-polygons", count = count.to_string()),
            Usage::ExerciseBits => words!(lang, "usage-exercise-bits"),
            Usage::ExerciseNeedsTwoPolygons => words!(lang, "usage-exercise-two-polygons"),
            Usage::ExerciseNotFound { polygons, width, height, cases, tries } => words!(
                lang,
                "usage-exercise-not-found",
                polygons = polygons.to_string(),
                width = width.to_string(),
                height = height.to_string(),
                cases = cases.join(", "),
                tries = tries.to_string()
            ),
            Usage::OutputIsInput { folder } => words!(lang, "usage-output-is-input", path = path(folder)),
            Usage::OutputNameTooLong { path: p, max } => {
                words!(lang, "usage-output-name-too-long", path = path(p), max = max.to_string())
            }
            Usage::OutputTwice { path: p } => words!(lang, "usage-output-twice", path = path(p)),
            Usage::SameStudentTwice { class, student, files } => words!(
                lang,
                "usage-same-student-twice",
                path = path(class),
                student = student.as_str(),
                files = quoted_list(files)
            ),
            Usage::GradebookCannotTell { first, second } => {
                words!(lang, "usage-gradebook-cannot-tell", first = first.as_str(), second = second.as_str())
            }
            Usage::SameAnswerTwice { folder, files } => {
                words!(lang, "usage-same-answer-twice", path = path(folder), files = quoted_list(files))
            }
            Usage::OutputWouldReplace { folder, files } => {
                let shown: Vec<&str> = files.iter().take(5).map(String::as_str).collect();
                words!(
                    lang,
                    "usage-output-would-replace",
                    path = path(folder),
                    files = shown.join(", "),
                    more = files.len().saturating_sub(5)
                )
            }
            Usage::CompareGpuPlainOnly => words!(lang, "usage-compare-gpu-plain"),
            Usage::NoGpu { reason } => words!(lang, "usage-no-gpu", reason = reason.as_str()),
            Usage::NoScanlines { index, name, why } => {
                words!(
                    lang,
                    "usage-no-scanlines",
                    polygon = crate::words::polygon_label(lang, "polygon-name", *index, name),
                    why = why
                )
            }
            Usage::ScanlineNotReached { index, name, row, rows } => {
                let reach = words!(
                    lang,
                    "step-not-reach",
                    polygon = crate::words::polygon_label(lang, "polygon-name", *index, name),
                    scanline = words!(lang, "scanline", y = crate::words::localize_decimal(lang, format!("{row}.5")))
                );
                match rows {
                    Some((first, last)) => {
                        words!(
                            lang,
                            "usage-scanline-rows",
                            reach = reach,
                            first = first.to_string(),
                            last = last.to_string()
                        )
                    }
                    None => words!(lang, "usage-scanline-no-rows", reach = reach),
                }
            }
        }
    }
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

impl PolygonProblem {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            PolygonProblem::Geometry(error) => error.message(lang),
            PolygonProblem::Other(message) => message.to_string(),
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
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            Error::Read { path, source } => {
                words!(lang, "error-read", path = shown_path(path), reason = crate::words::io_reason(lang, source))
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
            Error::SceneFormat { path, location, message, .. } => {
                if location.is_empty() {
                    format!("{}: {message}", shown_path(path))
                } else {
                    format!("{}: {location}: {message}", shown_path(path))
                }
            }
            Error::Setting { path, key, message } => format!("{}: {key}: {message}", shown_path(path)),
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
            Error::Usage(usage) => usage.message(lang),
            Error::Answer { path, message } => format!("{}: {message}", shown_path(path)),
        }
    }
}
