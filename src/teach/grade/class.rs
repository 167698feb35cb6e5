//! A class graded in one pass: the answer files of a class folder found and
//! read on every core, each student graded against the buffers after the
//! chosen polygon, the cells most students got wrong, and zsim's reason for
//! each. The command line's table, the gradebook formats and the feedback
//! files all render this one result.

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::door::Links;
use crate::error::{Error, Refusal};
use crate::observe::explain::{Buffer, why};
use crate::observe::trace::PixelWatcher;
use crate::scene::Scene;
use crate::simulate::simulation::Simulation;
use crate::teach::check::diagnose::Diagnoser;
use crate::teach::check::{as_the_student_sees, read_answer};
use crate::teach::grade::{CommonMistake, Grade, Handed, Key, Submission, WrongCells, file_kind, grade};
use crate::words::Lang;
use crate::words::printable;

/// How many common mistakes are listed.
pub const MISTAKES_LISTED: usize = 10;

/// One answer file of a class folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AnswerFile {
    /// The student: the file name's stem, as found.
    pub student: String,
    /// The buffer it answers for.
    pub buffer: Buffer,
    /// Where it is.
    pub path: PathBuf,
}

/// A class graded: each student's row with the wrong cells, the common
/// mistakes and zsim's reason for each (in the language graded in).
#[derive(Debug, Clone)]
pub struct ClassGrades {
    /// The polygon (0-based) the answers are the state after.
    pub last: usize,
    /// The answer files found, by student, the framebuffer's first.
    pub files: Vec<AnswerFile>,
    /// Each student's grade and wrong cells (the first
    /// [`crate::teach::check::MAX_EXPLAINED`] of each buffer), in the
    /// students' order.
    pub graded: Vec<(Grade, Vec<WrongCells>)>,
    /// The cells at least two students got wrong, most first (at most
    /// [`MISTAKES_LISTED`]).
    pub mistakes: Vec<CommonMistake>,
    /// How many more cells at least two students got wrong, not listed.
    pub mistakes_left_out: usize,
    /// zsim's reason for each common mistake.
    pub reasons: Vec<String>,
    /// The folder's other files, by name: none of them was graded.
    pub skipped: Vec<Skipped>,
}

/// A file of a class folder that is not an answer file, so nobody's work:
/// named in the report, so that a misnamed answer (`frank.depht.txt`,
/// `ana.FRAME.txt`) does not leave its student ungraded unnoticed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Skipped {
    /// Its name, as shown ([`printable`]).
    pub name: String,
    /// The student and buffer it was probably meant for, when its name is one
    /// letter or letter case away from an answer file's.
    pub meant: Option<(String, Buffer)>,
}

impl Skipped {
    /// One line in `lang`: the file and why it was not graded.
    pub fn text(&self, lang: Lang) -> String {
        match &self.meant {
            Some((student, buffer)) => words!(
                lang,
                "grade-skipped-near",
                file = self.name.as_str(),
                student = student.as_str(),
                buffer = buffer.name(lang),
                name = format!("{student}.{}.txt", file_kind(*buffer))
            ),
            None => words!(lang, "grade-skipped", file = self.name.as_str()),
        }
    }
}

/// The student and buffer a file name nearly names: `STUDENT.KIND.txt`
/// where `KIND` is `frame` or `depth` but for letter case or one letter
/// (added, left out, changed or two swapped), or the extension is `txt` in
/// another case.
fn near_miss(name: &str) -> Option<(String, Buffer)> {
    let (rest, extension) = name.rsplit_once('.')?;
    // A double extension (`ivan.frame.txt.txt`, as Windows hides the first): the name without the last.
    if extension.eq_ignore_ascii_case("txt")
        && let Some((_, inner)) = rest.rsplit_once('.')
        && inner.eq_ignore_ascii_case("txt")
    {
        return near_miss(rest);
    }
    let (student, kind) = rest.rsplit_once('.')?;
    if student.is_empty() || student.starts_with('.') || !extension.eq_ignore_ascii_case("txt") {
        return None;
    }
    let kind = kind.to_ascii_lowercase();
    let buffer = [Buffer::Frame, Buffer::Depth].into_iter().find(|b| one_edit(&kind, file_kind(*b)))?;
    Some((printable(student).into_owned(), buffer))
}

/// Whether `a` is `b`, or `b` with one letter added, left out, changed, or two neighbours swapped.
pub(crate) fn one_edit(a: &str, b: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let start = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let (a, b) = (&a[start..], &b[start..]);
    let end = a.iter().rev().zip(b.iter().rev()).take_while(|(x, y)| x == y).count().min(a.len().min(b.len()));
    let (a, b) = (&a[..a.len() - end], &b[..b.len() - end]);
    let swapped = a.len() == 2 && b.len() == 2 && a[0] == b[1] && a[1] == b[0];
    a.len() <= 1 && b.len() <= 1 || swapped
}

impl ClassGrades {
    /// The students' rows.
    pub fn rows(&self) -> Vec<&Grade> {
        self.graded.iter().map(|(grade, _)| grade).collect()
    }
}

/// Grades the answers in `class` for the state after polygon `last` of
/// `scene` (read from `scene_path`), messages in `lang`.
pub fn grade_class(
    lang: Lang,
    scene: &Scene,
    scene_path: &Path,
    class: &Path,
    last: usize,
) -> Result<ClassGrades, Error> {
    let (files, skipped) = answer_files(class)?;
    let mut simulation = Simulation::new(scene);
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    simulation.draw_parallel_through(last, simulation.default_tile(threads), threads, &|| {});
    let mut expected = Vec::new();
    for buffer in [Buffer::Frame, Buffer::Depth] {
        if !files.iter().any(|file| file.buffer == buffer) {
            continue;
        }
        let matrix = match buffer {
            Buffer::Frame => simulation.buffers().frame_rows(),
            Buffer::Depth => simulation
                .buffers()
                .depth_level_rows()
                .ok_or_else(|| Error::from(GradeRefused::ExactDepths { path: scene_path.to_owned() }))?,
        };
        expected.push(Key { buffer, matrix, cleared: crate::teach::grade::cleared(scene, buffer) });
    }
    // The usual wrong rules, drawn once for the whole class.
    let diagnoser = Diagnoser::new(scene, last);
    // A few students at a time, one a core: only their answers are held in
    // memory at once, whatever the size of the class.
    let mut students: Vec<&str> = files.iter().map(|file| file.student.as_str()).collect();
    // A student whose only file is misnamed (`frank.depht.txt`) gets a row too, with nothing
    // handed in; the skipped file's line says which name it was probably meant to have.
    students.extend(skipped.iter().filter_map(|s| s.meant.as_ref().map(|(student, _)| student.as_str())));
    students.sort_unstable();
    students.dedup();
    // Each student's wrong cells are counted per cell and kept only up to
    // MAX_EXPLAINED: a class wrong everywhere on a large raster would
    // otherwise hold every student's every cell at once.
    let cells = scene.width as usize * scene.height as usize;
    let mut counts: Vec<(Buffer, Vec<u32>)> = expected.iter().map(|key| (key.buffer, vec![0; cells])).collect();
    let mut graded = Vec::with_capacity(students.len());
    for batch in students.chunks(threads.max(1)) {
        for (grade, mut wrong) in
            grade(&submissions(lang, &files, batch, &expected, scene), &expected, diagnoser.as_ref())
        {
            for WrongCells { buffer, cells } in &mut wrong {
                let (_, count) = counts.iter_mut().find(|(b, _)| b == buffer).expect("a buffer handed in");
                for cell in cells.iter() {
                    count[cell.y as usize * scene.width as usize + cell.x as usize] += 1;
                }
                cells.truncate(crate::teach::check::MAX_EXPLAINED);
            }
            graded.push((grade, wrong));
        }
    }
    let (mistakes, mistakes_left_out) = common_mistakes(lang, scene, &files, &students, &expected, &counts);
    let reasons = reasons(lang, scene, last, &mistakes);
    Ok(ClassGrades { last, files, graded, mistakes, mistakes_left_out, reasons, skipped })
}

/// The answer files in the class folder, by student then framebuffer before
/// z-buffer, and the other files by name (but for zsim's own feedback). A student is named once, by one
/// normalisation of the file name's stem: bytes that are not UTF-8 written
/// as `\xff` and control characters escaped ([`crate::words::shown_name`]),
/// as every table, gradebook and feedback file shows them, so `a\xff` and
/// `a\xfe` are two students. Two stems that come to one name once shown (a
/// real newline and a written `\u{a}`) are two students named apart: the
/// one shown as it is keeps the name, the other is numbered (`b\u{a} (2)`).
fn answer_files(class: &Path) -> Result<(Vec<AnswerFile>, Vec<Skipped>), Error> {
    let entries = std::fs::read_dir(class).map_err(|source| Error::Read { path: class.to_owned(), source })?;
    let (mut files, mut skipped) = (Vec::new(), Vec::new());
    let mut names = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|source| Error::Read { path: class.to_owned(), source })?;
        names.push((entry.file_name(), entry.path()));
    }
    // Names shown as they are first, so that one escaped to look like them is the one numbered.
    names.sort_by_key(|(raw, _)| (crate::words::shown_name(Path::new(raw)) != raw.to_string_lossy(), raw.clone()));
    // Each raw stem's student, and the students' names taken.
    let mut students: std::collections::HashMap<Vec<u8>, String> = std::collections::HashMap::new();
    let mut taken: std::collections::HashSet<String> = std::collections::HashSet::new();
    for (raw, path) in names {
        // As shown, bytes that are not UTF-8 escaped (`\xff`): two names that differ there are two students.
        let name = crate::words::shown_name(Path::new(&raw));
        let answers = files.len();
        for buffer in [Buffer::Frame, Buffer::Depth] {
            let suffix = format!(".{}.txt", file_kind(buffer));
            if let Some(shown) = name.strip_suffix(&suffix)
                && !shown.is_empty()
                && !shown.starts_with('.')
            {
                let stem = raw.as_encoded_bytes()[..raw.len() - suffix.len()].to_vec();
                let student = students
                    .entry(stem)
                    .or_insert_with(|| {
                        let name = (1..)
                            .map(|k| if k == 1 { shown.to_owned() } else { format!("{shown} ({k})") })
                            .find(|name| !taken.contains(name))
                            .expect("numbers enough to tell a class apart");
                        taken.insert(name.clone());
                        name
                    })
                    .clone();
                files.push(AnswerFile { student, buffer, path: path.clone() });
            }
        }
        let zsims_own = name.ends_with(".feedback.txt") || name == "common-mistakes.txt";
        if files.len() == answers && !zsims_own {
            skipped.push(Skipped { name: printable(&name).into_owned(), meant: near_miss(&name) });
        }
    }
    if files.is_empty() {
        return Err(GradeRefused::NoAnswers { class: class.to_path_buf() }.into());
    }
    files.sort_by(|a, b| a.student.cmp(&b.student).then((a.buffer == Buffer::Depth).cmp(&(b.buffer == Buffer::Depth))));
    skipped.sort_by(|a, b| a.name.cmp(&b.name));
    Ok((files, skipped))
}

/// The answers of `students` for the buffers the class hands in, read on
/// every core and checked for shape, in the students' order.
fn submissions(
    lang: Lang,
    files: &[AnswerFile],
    students: &[&str],
    expected: &[Key],
    scene: &Scene,
) -> Vec<Submission> {
    students
        .par_iter()
        .map(|student| {
            let answers = expected
                .iter()
                .map(|Key { buffer, .. }| {
                    // The files are sorted by student: this student's are found by a binary search.
                    let first = files.partition_point(|file| file.student.as_str() < *student);
                    let file = files[first..]
                        .iter()
                        .take_while(|file| file.student == *student)
                        .find(|file| file.buffer == *buffer);
                    let handed = match file {
                        None => Handed::Missing,
                        Some(file) => match read_answer(&file.path, scene, *buffer, Links::Refuse) {
                            Ok(matrix) => Handed::Matrix(matrix),
                            Err(error) => Handed::Malformed(as_the_student_sees(lang, &error, &file.path)),
                        },
                    };
                    (*buffer, handed)
                })
                .collect();
            Submission { student: student.to_string(), answers }
        })
        .collect()
}

/// The name of a student's feedback file: `NAME.feedback.txt`, which never
/// ends as a submitted `NAME.frame.txt` or `NAME.depth.txt` does, nor is
/// `common-mistakes.txt`. A name too long for a file system
/// ([`crate::door::outward::MAX_NAME_BYTES`]) is cut at a character and
/// told apart by a hash of the whole: `NAME~1a2b3c4d.feedback.txt`.
pub fn feedback_name(student: &str) -> String {
    feedback_name_numbered(student, 0)
}

/// The feedback files' names of a class's students, in their order: each
/// [`feedback_name`], and where one would take a name an earlier student
/// has (a long name cut to another's, or a short name written as another's
/// cut one), the later student's cut and numbered apart
/// (`NAME~1a2b3c4d-2.feedback.txt`), so that no student's feedback is lost
/// and the class is graded.
pub fn feedback_names<'s>(students: impl IntoIterator<Item = &'s str>) -> Vec<String> {
    let mut taken = std::collections::HashSet::new();
    students
        .into_iter()
        .map(|student| {
            let name = (0..)
                .map(|k| feedback_name_numbered(student, k))
                .find(|name| !taken.contains(name))
                .expect("numbers enough to tell a class apart");
            taken.insert(name.clone());
            name
        })
        .collect()
}

/// [`feedback_name`], numbered `k` (from 1, past 0) when told apart from another.
fn feedback_name_numbered(student: &str, k: u32) -> String {
    const SUFFIX: &str = ".feedback.txt";
    let whole = format!("{student}{SUFFIX}");
    if k == 0 && whole.len() <= crate::door::outward::MAX_NAME_BYTES {
        return whole;
    }
    // FNV-1a, 32 bits: the same name gives the same file on every run.
    let hash = student.bytes().fold(0x811c_9dc5u32, |h, b| (h ^ u32::from(b)).wrapping_mul(0x0100_0193));
    let tail = match k {
        0 => format!("~{hash:08x}{SUFFIX}"),
        k => format!("~{hash:08x}-{}{SUFFIX}", k + 1),
    };
    let room = crate::door::outward::MAX_NAME_BYTES - tail.len();
    let mut cut = String::new();
    for c in student.chars() {
        if cut.len() + c.len_utf8() > room {
            break;
        }
        cut.push(c);
    }
    format!("{cut}{tail}")
}

/// The cells at least two students got wrong, most students first (then
/// the framebuffer before the z-buffer, top row first, left to right), at
/// most [`MISTAKES_LISTED`], from the counts per cell; who gave which value
/// there is read again from the answers, a few students at a time, so the
/// memory taken is the counts and a few answers whatever the class's size.
fn common_mistakes(
    lang: Lang,
    scene: &Scene,
    files: &[AnswerFile],
    students: &[&str],
    expected: &[Key],
    counts: &[(Buffer, Vec<u32>)],
) -> (Vec<CommonMistake>, usize) {
    let (width, height) = (scene.width, scene.height);
    let mut cells: Vec<(u32, Buffer, u32, u32)> = Vec::new();
    for buffer in [Buffer::Frame, Buffer::Depth] {
        let Some((_, count)) = counts.iter().find(|(b, _)| *b == buffer) else { continue };
        for y in (0..height).rev() {
            for x in 0..width {
                let n = count[y as usize * width as usize + x as usize];
                if n >= 2 {
                    cells.push((n, buffer, x, y));
                }
            }
        }
    }
    // Stable: equal counts keep the order above.
    cells.sort_by_key(|(n, ..)| std::cmp::Reverse(*n));
    let left_out = cells.len().saturating_sub(MISTAKES_LISTED);
    cells.truncate(MISTAKES_LISTED);
    let mut mistakes: Vec<CommonMistake> = cells
        .iter()
        .map(|&(_, buffer, x, y)| {
            let key = expected.iter().find(|key| key.buffer == buffer).expect("a buffer handed in");
            let right = key.matrix[crate::raster::printed_row(height, y)][x as usize];
            CommonMistake { buffer, x, y, right, students: Vec::new(), answers: Vec::new() }
        })
        .collect();
    if mistakes.is_empty() {
        return (mistakes, left_out);
    }
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    for batch in students.chunks(threads) {
        for submission in submissions(lang, files, batch, expected, scene) {
            for mistake in &mut mistakes {
                let answer = submission.answers.iter().find(|(b, _)| *b == mistake.buffer).and_then(|(_, h)| match h {
                    Handed::Matrix(m) => {
                        let (row, x) = (crate::raster::printed_row(height, mistake.y), mistake.x as usize);
                        m.answered(row, x).then(|| m.rows[row][x])
                    }
                    _ => None,
                });
                if let Some(value) = answer.filter(|v| *v != mistake.right) {
                    mistake.students.push(submission.student.clone());
                    match mistake.answers.iter_mut().find(|(v, _)| *v == value) {
                        Some((_, n)) => *n += 1,
                        None => mistake.answers.push((value, 1)),
                    }
                }
            }
        }
    }
    for mistake in &mut mistakes {
        mistake.students.sort();
        // Most given first; equal counts by value.
        mistake.answers.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    }
    (mistakes, left_out)
}

/// zsim's reason for each common mistake, from one watched run.
fn reasons(lang: Lang, scene: &Scene, last: usize, mistakes: &[CommonMistake]) -> Vec<String> {
    let mut watcher = PixelWatcher::new(mistakes.iter().map(|m| (m.x, m.y)));
    if !mistakes.is_empty() {
        Simulation::new(scene).draw_through(last, &mut watcher);
    }
    mistakes.iter().map(|m| why(lang, scene, m.buffer, m.x, m.y, watcher.history(m.x, m.y))).collect()
}

/// Grading refused: each with the facts its message states.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GradeRefused {
    /// A scene without polygons: no state to grade against.
    NoPolygons {
        /// The scene file.
        path: PathBuf,
    },
    /// A scene keeping exact depths, whose z-buffer has no integer matrix to grade.
    ExactDepths {
        /// The scene file.
        path: PathBuf,
    },
    /// A class folder without answer files.
    NoAnswers {
        /// The folder.
        class: PathBuf,
    },
}

impl Refusal for GradeRefused {
    fn message(&self, lang: Lang) -> String {
        let path = |p: &PathBuf| crate::words::shown_path(p);
        match self {
            GradeRefused::NoPolygons { path: p } => words!(lang, "usage-no-polygons-grade", path = path(p)),
            GradeRefused::ExactDepths { path: p } => words!(lang, "usage-exact-depths-grade", path = path(p)),
            GradeRefused::NoAnswers { class } => words!(lang, "usage-no-answers", path = path(class)),
        }
    }
}
