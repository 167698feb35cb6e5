//! Raster: the one scan converter (`convert`) and what it hands on (`sink`):
//! half-interval scanlines, crossings and spans (`scan`), the exact depth at
//! each covered centre and its stepper (`depth`), on 64- or 128-bit words or
//! on the big-integer tier (`big`). Imports: geometry, numbers, rules.
pub mod big;
pub mod convert;
pub mod depth;
pub mod scan;
pub mod sink;
