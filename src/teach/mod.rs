//! Teach.
pub mod exercise;
pub mod grade;
