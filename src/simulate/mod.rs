//! Simulate: the driver.
pub mod buffer;
pub mod pipeline;
pub mod stages;
