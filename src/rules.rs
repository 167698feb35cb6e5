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
//! The `gpu` preset is the book's with the top-left rule of Direct3D and
//! OpenGL for coverage: rows `top-left` (`y_min < y ≤ y_max`) and columns
//! `half-open` (`x_l ≤ x < x_r`). zsim's raster is y-up and drawn with row 0
//! at the bottom, so its *top* edge is the one with the largest y: a centre
//! exactly on a horizontal edge is covered when that edge is the polygon's
//! top as drawn, and a centre on a slanted edge when the polygon lies to its
//! right. This is the Direct3D 11 functional specification's rule (3.4.2.1:
//! a top edge is exactly horizontal and above the other edges, a left edge is
//! not horizontal and on the left side of the triangle; a centre on an edge
//! is drawn only when the edge is top or left), with "above" meaning above
//! on the screen. Shared edges are drawn once: a centre on the edge two
//! polygons share belongs to exactly one of them (tests in `pipeline`).
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
    /// The top-left rule of Direct3D and OpenGL, as displayed: centre
    /// samples, rows [`RowRule::TopLeft`], columns [`ColumnRule::HalfOpen`];
    /// depth as the book stores it.
    Gpu,
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
            Preset::Gpu => {
                Rules { preset, rows: RowRule::TopLeft, columns: ColumnRule::HalfOpen, store: DepthStore::Quantized }
            }
        }
    }

    /// One line naming each choice, for reports.
    pub fn describe(&self) -> String {
        let preset = match self.preset {
            Preset::Rogers => "rogers",
            Preset::Buet => "buet",
            Preset::Gpu => "gpu",
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
