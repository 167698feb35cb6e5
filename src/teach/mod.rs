//! Teach: exercises made from a seed (`exercise`) and a class graded from a
//! folder of answers (`grade`), and the misconception behind a wrong answer
//! named (`diagnose`), the stepper (`step`: stops, moves, the judges of
//! each kind of question) and the lesson over it (`lesson`: what may be
//! shown, what is asked, hints, the score). Imports: observe and the layers before it.
pub mod check;
pub mod class;
pub mod diagnose;
pub mod exercise;
pub mod grade;
pub mod gradebooks;
pub mod gradescope;
pub mod lesson;
pub mod page;
pub mod playground;
pub mod step;
pub mod stop;
