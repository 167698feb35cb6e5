//! Observe: what the rasterizer did, in words and pictures, in four kinds.
//! Imports: effects and the layers before it.
//!
//! - `record`: a run recorded as it happens (`trace`: scanlines, pixels, a
//!   watched pixel's events; `tracer`: polygons recorded as a student reaches
//!   them, the stops between them).
//! - `explain`: why a pixel holds what it holds (`explain`), its whole
//!   history (`history`), a centre on an edge and the rule that decides it
//!   (`tie`).
//! - `render`: the printed matrices and the run's JSON (`report`), figures
//!   (`figure`), their PNG, PDF and TeX (`picture`, `tikz`).
//! - `gpu`: a real GPU implementation drawing the same scene, as a
//!   reference (`gpu`) and as a peer for speed (`race`).
pub mod explain;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod record;
pub mod render;

pub use explain::{history, tie};
#[cfg(feature = "gpu")]
pub use gpu::race;
pub use record::{trace, tracer};
pub use render::{figure, picture, report, tikz};
