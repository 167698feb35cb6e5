//! Simulate: the [`simulation::Simulation`] driver draws a scene polygon by
//! polygon into the buffers (`buffer`) through the per-pixel stages the scene
//! asks for (`stages`, whose `Plain::decide` is the book's rule), telling an
//! observer what happens (`events`). The fast paths, each held to that rule
//! by a named test, are in `fast` (its table says which is taken when).
//! Imports: scene and the layers before it.
pub mod buffer;
pub mod events;
mod fast;
pub mod setup;
pub mod simulation;
pub mod stages;
