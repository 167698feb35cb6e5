//! Observe.
pub mod check;
pub mod explain;
pub mod figure;
pub mod history;
pub mod report;
pub mod step;
pub mod tie;
pub mod trace;
