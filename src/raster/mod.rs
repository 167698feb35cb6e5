//! Raster: the one scan converter.
pub mod big;
pub mod depth;
pub mod scan;
