//! Rules as data: the choices that differ between courses, each written once
//! and named, so one rasterizer serves every rule set.
//!
//! | choice | `rogers` (the book) | `buet` (BUET CSE 410, Offline 2) |
//! |---|---|---|
//! | window | 0 … width × 0 … height, in pixel units | left … right × bottom … top from the config, mapped onto the raster |
//! | rows | half-open: an edge crosses when min ≤ y < max | closed: every row whose centre lies in [y_min, y_max]; every non-horizontal edge whose closed y range holds it |
//! | spans | crossings paired 1st–2nd, 3rd–4th, … | one span from the least to the greatest crossing |
//! | columns | centres inside [x_l, x_r] | from the column whose cell holds x_a to the one whose cell holds x_b |
//! | depth | quantized to depth_bits, rounded half up, saturated | stored exactly |
//! | test | `greater` (or `less`) | `less`, buffer cleared to z_max, fragments outside [z_front, z_rear] discarded |
//!
//! Two presets are the rules of GPU APIs, each named for the API whose
//! picture it reproduces, each checked against a real implementation of it
//! (Mesa's llvmpipe for OpenGL, `tests/integration/gpu.rs`). Both keep the
//! book's depth; they differ in which edge a centre exactly on it belongs to.
//!
//! | preset | zsim's raster (y up, row 0 at the bottom) | the API's framebuffer |
//! |---|---|---|
//! | `gl` | rows `half-open` (`y_min ≤ y < y_max`), columns `half-open` (`x_l ≤ x < x_r`): a centre on a bottom or left edge is in, on a top or right edge out | OpenGL's lower-left origin is zsim's: the same words |
//! | `vulkan` (also `d3d`, `webgpu`, and `gpu` as it was called) | rows `top-left` (`y_min < y ≤ y_max`), columns `half-open`: a centre on a top edge (largest y as drawn) or left edge is in | Vulkan, WebGPU and Direct3D count y down from the top: their top-left rule (Direct3D 11 functional specification 3.4.2.1) |
//!
//! OpenGL's rule is the mirror image in y of Direct3D's as the picture shows
//! it: llvmpipe draws a centre on the picture's bottom edge and leaves out
//! one on its top edge, and `glClipControl(GL_UPPER_LEFT)` flips the image
//! but not the rule. Shared edges are drawn once under either: a centre on
//! the edge two polygons share belongs to exactly one of them (tests in
//! `raster::convert`).
//!
//! Pixel centres are at the middle of each cell in both.

use serde::Deserialize;

/// Which rows a polygon covers, which edges cross a scanline and how the
/// crossings become spans.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum RowRule {
    /// Rogers' half-interval convention: an edge crosses when
    /// `min(y₁, y₂) ≤ y < max(y₁, y₂)`; crossings paired 1st–2nd, 3rd–4th, ….
    #[serde(rename = "half-open")]
    HalfOpen,
    /// BUET: every non-horizontal edge whose closed y range holds the
    /// scanline crosses; one span from the least to the greatest crossing.
    #[serde(rename = "closed")]
    Closed,
    /// The top half of the top-left rule, in zsim's y-up raster: an edge
    /// crosses when `min(y₁, y₂) < y ≤ max(y₁, y₂)`, so a centre exactly on
    /// a horizontal edge is covered when that edge is the top one as drawn
    /// (y largest) and not when it is the bottom one; crossings paired.
    #[serde(rename = "top-left")]
    TopLeft,
}

/// Which columns a span covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum ColumnRule {
    /// The book: columns whose centre lies within `[x_l, x_r]`, ends included.
    #[serde(rename = "centre")]
    CentreInside,
    /// BUET: from the column whose cell holds `x_a` to the one whose cell
    /// holds `x_b`, i.e. round-half-up of `(x − first centre)/dx`, which in
    /// pixel units is `⌊x⌋`; both included.
    #[serde(rename = "cell")]
    CellHolds,
    /// The left half of the top-left rule: columns whose centre lies within
    /// `[x_l, x_r)`, so a centre exactly on a left edge is covered and one
    /// on a right edge is not.
    #[serde(rename = "half-open")]
    HalfOpen,
}

/// What the z-buffer keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum DepthStore {
    /// The book: z rounded half up to an integer and saturated to
    /// `0 … 2^depth_bits − 1`.
    #[serde(rename = "quantized")]
    Quantized,
    /// BUET: z kept exactly (a rational); `depth_bits` does not apply.
    #[serde(rename = "exact")]
    Exact,
}

/// A named rule set.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Preset {
    /// The textbook's rules (the default).
    Rogers,
    /// BUET CSE 410's "Offline 2: Rasterization".
    Buet,
    /// OpenGL's picture (measured on Mesa's llvmpipe): rows
    /// [`RowRule::HalfOpen`], columns [`ColumnRule::HalfOpen`] in zsim's y-up
    /// raster, which is OpenGL's lower-left origin; depth as the book stores it.
    Gl,
    /// Vulkan's, WebGPU's and Direct3D's picture: their top-left rule in a
    /// y-down framebuffer, which in zsim's y-up raster is rows
    /// [`RowRule::TopLeft`], columns [`ColumnRule::HalfOpen`]; depth as the
    /// book stores it. Also read as `d3d`, `webgpu` and `gpu` (its old name).
    #[serde(alias = "d3d", alias = "webgpu", alias = "gpu")]
    Vulkan,
}

/// The rasterizer's choices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rules {
    /// The preset these choices started from.
    pub preset: Preset,
    /// Rows and crossings.
    pub rows: RowRule,
    /// Columns.
    pub columns: ColumnRule,
    /// What the z-buffer keeps.
    pub store: DepthStore,
}

impl Rules {
    /// The choices of a preset.
    pub fn preset(preset: Preset) -> Rules {
        match preset {
            Preset::Rogers => Rules {
                preset,
                rows: RowRule::HalfOpen,
                columns: ColumnRule::CentreInside,
                store: DepthStore::Quantized,
            },
            Preset::Buet => {
                Rules { preset, rows: RowRule::Closed, columns: ColumnRule::CellHolds, store: DepthStore::Exact }
            }
            Preset::Gl => {
                Rules { preset, rows: RowRule::HalfOpen, columns: ColumnRule::HalfOpen, store: DepthStore::Quantized }
            }
            Preset::Vulkan => {
                Rules { preset, rows: RowRule::TopLeft, columns: ColumnRule::HalfOpen, store: DepthStore::Quantized }
            }
        }
    }

    /// One line naming each choice, for reports.
    pub fn describe(&self) -> String {
        let preset = match self.preset {
            Preset::Rogers => "rogers",
            Preset::Buet => "buet",
            Preset::Gl => "gl",
            Preset::Vulkan => "vulkan",
        };
        let rows = match self.rows {
            RowRule::HalfOpen => words!("rules-rows-half-open"),
            RowRule::Closed => words!("rules-rows-closed"),
            RowRule::TopLeft => words!("rules-rows-top-left"),
        };
        let columns = match self.columns {
            ColumnRule::CentreInside => words!("rules-columns-centre-inside"),
            ColumnRule::CellHolds => words!("rules-columns-cell-holds"),
            ColumnRule::HalfOpen => words!("rules-columns-half-open"),
        };
        let store = match self.store {
            DepthStore::Quantized => words!("rules-store-quantized"),
            DepthStore::Exact => words!("rules-store-exact"),
        };
        words!("rules-describe", preset = preset, rows = rows, columns = columns, store = store)
    }
}

impl Default for Rules {
    fn default() -> Rules {
        Rules::preset(Preset::Rogers)
    }
}
