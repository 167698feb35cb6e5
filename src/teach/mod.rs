//! Teach: exercises made from a seed (`exercise`) and a class graded from a
//! folder of answers (`grade`), and the misconception behind a wrong answer
//! named (`diagnose`). Imports: observe and the layers before it.
pub mod diagnose;
pub mod exercise;
pub mod grade;
