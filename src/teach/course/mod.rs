//! A course: each student of the roster the teacher already has gets an
//! exercise of their own, as hard as everyone else's, and is graded against
//! their own key.
//!
//! - `roster`: the roster read, by its header (Moodle, Canvas, Gradescope,
//!   PrairieLearn, or one identity a line).
//! - `manifest`: `variants.json`, the one record every command reads: each
//!   student's scene itself, never only the recipe.
//! - `fair`: the variants made, fair by construction and told apart.
//! - `folders`: the student's folder and the teacher's, planned whole.
//! - `grading`: a class folder graded student by student against the manifest.
//! - `report`: a graded class for programs (CSV, JSON) and what changed since.
//! - `platforms`: Gradescope's autograder and PrairieLearn's question for a class.
pub mod fair;
pub mod folders;
pub mod grading;
pub mod manifest;
pub mod platforms;
pub mod report;
pub mod roster;
