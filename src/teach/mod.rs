//! Teach: a room for each thing a student or a teacher does, so that a new
//! question, a new gradebook format or a new kind of exercise has one place
//! to go. Imports: observe and the layers before it.
//!
//! - `step`: the stepper (stops, moves, the judges of each kind of
//!   question), the lesson over it (`step::lesson`: what may be shown, what
//!   is asked, hints, the score; a new question goes there) and the recorded
//!   page (`step::page`).
//! - `check`: a homework answer read as the book prints it and compared
//!   (`check::answer`), the files of a submission, every wrong cell
//!   explained, and the misconception behind a wrong answer
//!   (`check::diagnose`).
//! - `grade`: a class folder graded once (`grade::class`), its table and
//!   common mistakes, the gradebooks (`grade::gradebooks`: a new format goes
//!   there) and Gradescope's autograder (`grade::gradescope`).
//! - `exercise`: a new exercise from a seed, with the hard cases asked for.
//! - `course`: a class from its roster, a variant each, fair by
//!   construction, and each student graded against their own key.
//! - `playground`: what the browser shows of all of them, as facts; and
//!   `page_limits`, what a page draws at all.
pub mod check;
pub mod course;
pub mod exercise;
pub mod grade;
pub mod page_limits;
pub mod playground;
pub mod step;
