//! Effects and variants: what the sources add to the plain algorithm
//! (antialiasing by post-filtering, segmented z-buffers and pixel-order
//! loops, transparency's local errors) and what less exact arithmetic gives
//! (`arith`, measured by `accuracy`). Each drives the same scan converter.
//! Imports: simulate and the layers before it.
pub mod accuracy;
pub mod antialias;
pub mod arith;
pub mod variants;
