//! Geometry: a polygon's vertices scaled to integers over their common
//! denominator, its plane by Newell's method and its planarity check
//! (`newell`, written once over [`crate::numbers::Ring`]), the plane equation
//! as the book prints it (`equation`), and the big-integer tier's polygon
//! (`big`). Imports: numbers, rules.
pub mod big;
pub mod equation;
pub mod newell;
pub mod plane;
