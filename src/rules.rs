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

use crate::words::Lang;

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
    /// tinyrenderer's lesson: z truncated (rounded down) to an integer and
    /// saturated to `0 … 2^depth_bits − 1`.
    #[serde(rename = "truncated")]
    Truncated,
    /// BUET: z kept exactly (a rational); `depth_bits` does not apply.
    #[serde(rename = "exact")]
    Exact,
}

impl DepthStore {
    /// Whether the z-buffer holds integer levels (rounded or truncated).
    pub fn holds_levels(self) -> bool {
        self != DepthStore::Exact
    }
}

/// Where a pixel is sampled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum Sample {
    /// The book: at the pixel's centre (x + 1/2, y + 1/2).
    #[serde(rename = "centre")]
    Centre,
    /// tinyrenderer's lesson: at the integer point (x, y), the pixel's
    /// lower-left corner. zsim draws such a scene shifted by 1/2 in x and y,
    /// so that each pixel's centre is the lesson's sample.
    #[serde(rename = "corner")]
    Corner,
}

/// What the depth test compares with the stored level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum Compare {
    /// The book: the exact depth (10.25 > 10 passes).
    #[serde(rename = "exact")]
    Exact,
    /// tinyrenderer's lesson: the level the depth would be stored as (10.25
    /// truncated to 10 does not pass 10 > 10).
    #[serde(rename = "level")]
    Level,
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
    /// tinyrenderer's z-buffer lesson: samples at integer corners, rows and
    /// columns closed (a sample on any edge is in), z truncated and compared
    /// as the level it is stored as, triangles of area below 1 skipped.
    Tinyrenderer,
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
    /// Where pixels are sampled.
    pub sample: Sample,
    /// What the depth test compares.
    pub compare: Compare,
    /// Polygons whose signed area (counter-clockwise positive, in pixels) is
    /// below this are skipped: back faces and slivers.
    pub min_area: Option<crate::numbers::Q>,
}

impl Preset {
    /// Every preset, the book's first.
    pub const ALL: [Preset; 5] = [Preset::Rogers, Preset::Buet, Preset::Gl, Preset::Vulkan, Preset::Tinyrenderer];

    /// The name a scene file gives it (`rogers`, `gl`, …).
    pub fn key(self) -> &'static str {
        match self {
            Preset::Rogers => "rogers",
            Preset::Buet => "buet",
            Preset::Gl => "gl",
            Preset::Vulkan => "vulkan",
            Preset::Tinyrenderer => "tinyrenderer",
        }
    }

    /// The preset named in the reader's language (`the book's`, `OpenGL's`).
    pub fn name(self, lang: Lang) -> String {
        match self {
            Preset::Rogers => words!(lang, "preset-rogers"),
            Preset::Buet => words!(lang, "preset-buet"),
            Preset::Gl => words!(lang, "preset-gl"),
            Preset::Vulkan => words!(lang, "preset-vulkan"),
            Preset::Tinyrenderer => words!(lang, "preset-tinyrenderer"),
        }
    }

    /// The preset a name chooses, as a scene file names it ([`Preset::key`],
    /// or the aliases `d3d`, `webgpu` and `gpu`).
    pub fn parse(text: &str) -> Result<Preset, NotAPreset> {
        serde_json::from_value(serde_json::Value::String(text.to_string()))
            .map_err(|_| NotAPreset { text: text.to_string() })
    }
}

/// A name that is no rule preset ([`Preset::parse`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotAPreset {
    /// The name given.
    pub text: String,
}

impl NotAPreset {
    /// The refusal in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        words!(lang, "usage-not-a-preset", text = crate::words::token(lang, &self.text))
    }
}

impl Rules {
    /// The choices of a preset.
    pub fn preset(preset: Preset) -> Rules {
        let book = Rules {
            preset,
            rows: RowRule::HalfOpen,
            columns: ColumnRule::CentreInside,
            store: DepthStore::Quantized,
            sample: Sample::Centre,
            compare: Compare::Exact,
            min_area: None,
        };
        match preset {
            Preset::Rogers => book,
            Preset::Buet => {
                Rules { rows: RowRule::Closed, columns: ColumnRule::CellHolds, store: DepthStore::Exact, ..book }
            }
            Preset::Gl => Rules { columns: ColumnRule::HalfOpen, ..book },
            Preset::Vulkan => Rules { rows: RowRule::TopLeft, columns: ColumnRule::HalfOpen, ..book },
            Preset::Tinyrenderer => Rules {
                rows: RowRule::Closed,
                store: DepthStore::Truncated,
                sample: Sample::Corner,
                compare: Compare::Level,
                min_area: Some(crate::numbers::Q::from_integer(1)),
                ..book
            },
        }
    }

    /// One line naming each choice, for reports.
    pub fn describe(&self, lang: crate::words::Lang) -> String {
        let preset = match self.preset {
            Preset::Rogers => "rogers",
            Preset::Buet => "buet",
            Preset::Gl => "gl",
            Preset::Vulkan => "vulkan",
            Preset::Tinyrenderer => "tinyrenderer",
        };
        let rows = match self.rows {
            RowRule::HalfOpen => words!(lang, "rules-rows-half-open"),
            RowRule::Closed => words!(lang, "rules-rows-closed"),
            RowRule::TopLeft => words!(lang, "rules-rows-top-left"),
        };
        let columns = match self.columns {
            ColumnRule::CentreInside => words!(lang, "rules-columns-centre-inside"),
            ColumnRule::CellHolds => words!(lang, "rules-columns-cell-holds"),
            ColumnRule::HalfOpen => words!(lang, "rules-columns-half-open"),
        };
        let store = match self.store {
            DepthStore::Quantized => words!(lang, "rules-store-quantized"),
            DepthStore::Truncated => words!(lang, "rules-store-truncated"),
            DepthStore::Exact => words!(lang, "rules-store-exact"),
        };
        let mut text = words!(lang, "rules-describe", preset = preset, rows = rows, columns = columns, store = store);
        if self.sample == Sample::Corner {
            text.push_str(&words!(lang, "rules-sample-corner"));
        }
        if self.compare == Compare::Level {
            text.push_str(&words!(lang, "rules-compare-level"));
        }
        if let Some(area) = self.min_area {
            text.push_str(&words!(lang, "rules-min-area", area = crate::numbers::fraction(area)));
        }
        text
    }
}

impl Default for Rules {
    fn default() -> Rules {
        Rules::preset(Preset::Rogers)
    }
}
