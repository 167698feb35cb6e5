//! Simulate: the driver.
pub mod buffer;
pub mod events;
pub mod pipeline;
pub mod stages;
