//! Simulate: the [`simulation::Simulation`] driver draws a scene polygon by
//! polygon into the buffers (`buffer`) through the per-pixel stages the scene
//! asks for (`stages`), telling an observer what happens (`events`); the
//! plain loop writes the cells directly (`levels`), in tiles on several
//! threads when nobody watches (`tiles`), small triangles by edge functions
//! (`triangle`), both over one branch-free cell (`branch_free`), a span's
//! cells four at a time where the processor has AVX2 (`lanes`). Imports:
//! scene and the layers before it.
mod branch_free;
pub mod buffer;
pub mod events;
mod lanes;
mod levels;
pub mod setup;
pub mod simulation;
pub mod stages;
mod tiles;
mod triangle;
