//! Geometry: a polygon's plane and edges in exact integers.
pub mod big;
pub mod equation;
pub mod newell;
pub mod plane;
