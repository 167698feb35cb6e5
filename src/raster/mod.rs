//! Raster: the one scan converter (`convert`) and what it hands on (`sink`):
//! half-interval scanlines, crossings and spans (`scan`), the exact depth at
//! each covered centre and its stepper (`depth`), on 64- or 128-bit words or
//! on the big-integer tier (`big`). Imports: geometry, numbers, rules.
pub mod big;
pub mod convert;
pub mod depth;
pub mod scan;
pub mod sink;

/// The printed row (matrices are printed top row first, as the book prints
/// them) that holds pixel row `y` of a raster `height` rows high, y running
/// up from the bottom, counted from the top. The conversion is written here
/// only; [`row_y`] undoes it.
pub fn printed_row(height: u32, y: u32) -> usize {
    (height - 1 - y) as usize
}

/// The pixel row `y` printed as row `row` (top first): [`printed_row`] undone.
pub fn row_y(height: u32, row: usize) -> u32 {
    printed_row(height, row as u32) as u32
}
