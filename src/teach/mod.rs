//! Teach: exercises made from a seed (`exercise`) and a class graded from a
//! folder of answers (`grade`), and the misconception behind a wrong answer
//! named (`diagnose`), and the stepper's teaching model (`step`: stops,
//! moves, the quiz and its judge). Imports: observe and the layers before it.
pub mod check;
pub mod class;
pub mod diagnose;
pub mod exercise;
pub mod grade;
pub mod gradebooks;
pub mod gradescope;
pub mod page;
pub mod playground;
pub mod step;
pub mod stop;
