//! Exact numbers: the rational type `Q`, the reported number [`Exact`] (a
//! `Q` where it fits, a big rational where not), reading numbers from scene
//! files, and overflow-free comparison and rounding helpers on `i128`
//! fractions.
//!
//! The rasterizer itself works on integer numerators over a known per-polygon
//! denominator (see [`crate::geometry::plane`]); `Q` and `Exact` are what it reports to
//! people.

mod exact;
mod format;
mod parse;
mod ring;
mod word;

pub use exact::*;
pub use format::*;
pub use parse::*;
pub use ring::Ring;
pub use word::*;
