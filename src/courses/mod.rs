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

use crate::words::Lang;

/// A problem in a course's file, with the line it is on (1-based).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CaseError {
    /// The line, when one is to blame.
    pub line: Option<usize>,
    /// What is wrong.
    pub message: String,
}

impl CaseError {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self.line {
            Some(line) => words!(lang, "case-line", line = line.to_string(), problem = self.message.as_str()),
            None => self.message.clone(),
        }
    }
}
