//! Simulate: the driver.
pub mod buffer;
pub mod events;
mod levels;
pub mod simulation;
pub mod stages;
mod tiles;
