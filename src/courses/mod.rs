//! Courses.
pub mod buet;
pub mod cs418;
