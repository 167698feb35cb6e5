//! Teach: exercises made from a seed (`exercise`) and a class graded from a
//! folder of answers (`grade`). Imports: observe and the layers before it.
pub mod exercise;
pub mod grade;
