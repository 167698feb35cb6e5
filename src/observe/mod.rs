//! Observe: what the rasterizer did, in words and pictures. Recorders
//! (`trace`), a centre on an edge and the rule that decides it (`tie`),
//! explanations (`explain`) and a pixel's whole history (`history`), the
//! printed matrices (`report`), figures (`figure`), homework answers
//! (`check`) and the stepper's model (`step`). Imports: effects and the layers before it.
pub mod check;
pub mod explain;
pub mod figure;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod history;
pub mod picture;
#[cfg(feature = "gpu")]
pub mod race;
pub mod report;
pub mod step;
pub mod tie;
pub mod tikz;
pub mod trace;
