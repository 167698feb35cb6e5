//! Courses: other courses' rules and files end to end. BUET CSE 410 reads its
//! `config.txt` and `scene.txt`, runs the course's transformations and writes
//! `z_buffer.txt`; UIUC CS 418 runs the course's pipeline over a number type
//! (its f64 arithmetic, or exact). Both end in the scene the simulator draws.
//! tinyrenderer's z-buffer lesson reads an OBJ model and writes the lesson's
//! two TGA images, in its f64 arithmetic or exactly.
//! Imports: the layers before it.
pub mod buet;
pub mod cs418;
pub mod tinyrenderer;

use std::path::{Path, PathBuf};

use crate::error::{Error, Refusal};
use crate::words::Lang;

/// A problem in a course's file, with the line it is on (1-based): `P` is
/// the course's own kind of problem, a [`Refusal`] worded where it is shown.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseError<P> {
    /// The line, when one is to blame.
    pub line: Option<usize>,
    /// What is wrong.
    pub problem: P,
}

impl<P: Refusal> CaseError<P> {
    /// The message in `lang`, one line, with the line to blame.
    pub fn message(&self, lang: Lang) -> String {
        let problem = self.problem.message(lang);
        match self.line {
            Some(line) => words!(lang, "case-line", line = line.to_string(), problem = problem),
            None => problem,
        }
    }

    /// The problem as zsim's error, naming the file it is in.
    pub fn in_file(self, path: &Path) -> Error {
        Error::Refused(Box::new(CourseFileRefused { path: path.to_owned(), line: self.line, problem: self.problem }))
    }
}

/// A course's file refused (a BUET case or answer, a CS 418 case or
/// reference image, a tinyrenderer model): the file, the line to blame
/// where there is one, and what is wrong.
#[derive(Debug)]
pub struct CourseFileRefused<P> {
    /// The file.
    pub path: PathBuf,
    /// The line, when one is to blame.
    pub line: Option<usize>,
    /// What is wrong.
    pub problem: P,
}

impl<P: Refusal> Refusal for CourseFileRefused<P> {
    fn message(&self, lang: Lang) -> String {
        let (path, problem) = (crate::words::shown_path(&self.path), self.problem.message(lang));
        match self.line {
            Some(line) => format!("{path}: {}: {problem}", words!(lang, "file-line", line = line)),
            None => format!("{path}: {problem}"),
        }
    }
}
