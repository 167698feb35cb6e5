//! Raster: the one scan converter.
pub mod big;
pub mod convert;
pub mod depth;
pub mod scan;
pub mod sink;
