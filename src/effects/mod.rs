//! Effects.
pub mod accuracy;
pub mod antialias;
pub mod arith;
pub mod variants;
