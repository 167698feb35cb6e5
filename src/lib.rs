//! zsim simulates the z-buffer hidden-surface algorithm exactly as the
//! textbook teaches it (Rogers, *Procedural Elements for Computer Graphics*,
//! the worked example of a rectangle pierced by a triangle, as the Russian
//! coursework among this project's sources reproduces it).
//!
//! # Conventions
//!
//! Each convention below is pinned by a test named after it.
//!
//! - **Axes.** x to the right, y up, pixel (0, 0) at the bottom left ("the
//!   pixel (0, 0) is in the lower left corner"). Matrices are printed top row
//!   first (y = height − 1), columns x = 0 … width − 1, as the book prints them
//!   (`simulate::buffer::tests::pixel_origin_is_bottom_left_and_printed_last`).
//! - **Pixel centres.** Pixel (x, y) is sampled at its centre (x + 1/2, y + 1/2).
//! - **Scanlines** (Rogers' half-interval convention). Row `y` is scanned along
//!   the line through its centres, y + 1/2. An edge from y₁ to y₂ crosses it when
//!   `min(y₁, y₂) ≤ y + 1/2 < max(y₁, y₂)`: a vertex on a scanline counts only for
//!   the edge whose lower end it is, and horizontal edges never cross
//!   (`raster::scan::tests::vertex_on_scanline_counts_for_lower_edge_only`,
//!   `raster::scan::tests::horizontal_edges_never_cross`).
//! - **Spans.** The crossings on a scanline are sorted and paired 1st–2nd,
//!   3rd–4th, … (even-odd, so concave and self-intersecting polygons work).
//!   A pixel is covered when its centre lies within a pair, boundary included:
//!   "the pixel whose centre lies inside or on the boundary", `x₁ ≤ x ≤ x₂`
//!   (`raster::scan::tests::centre_on_right_edge_is_covered`).
//! - **Plane.** Newell's method on the vertices:
//!   `a = Σ(yᵢ − yᵢ₊₁)(zᵢ + zᵢ₊₁)`, `b = Σ(zᵢ − zᵢ₊₁)(xᵢ + xᵢ₊₁)`,
//!   `c = Σ(xᵢ − xᵢ₊₁)(yᵢ + yᵢ₊₁)`, d through vertex 1, printed reduced
//!   (the book's triangle: `3x + y + 4z - 120 = 0`). `c > 0` means the vertices
//!   run counter-clockwise seen from the viewer; `c = 0` means the polygon is
//!   seen edge-on and covers no pixel. A vertex off the plane is an error.
//! - **Depth.** The exact depth at a centre, `z = −(a·x + b·y + d)/c`, stepped
//!   along a scanline by `z₁ = z − a/c` with an exact whole part and remainder.
//! - **Which depth is nearer.** `greater` (the book's default): the viewer is at
//!   +∞ on z, larger z is nearer, the z-buffer is cleared to 0 and a pixel is
//!   written when its exact z is greater than the stored integer. `less`
//!   (the Russian text on loop order and the Ukrainian Wikipedia): cleared to `2^depth_bits − 1`, written when less.
//!   Equal depths never overwrite (`raster::depth::tests::equal_depth_does_not_overwrite`),
//!   except with `greater-equal` and `less-equal`, where they do
//!   (`raster::depth::tests::equal_depth_overwrites_with_greater_equal_and_less_equal`);
//!   the comparison uses the exact z, not the rounded one (the book's pixel
//!   (20, 17): z = 41/4 > 10 wins though it stores 10).
//! - **Rounding and saturation.** The z-buffer stores z rounded to the nearest
//!   integer, halves up (`raster::depth::tests::depth_half_rounds_up`), saturated to
//!   `0 … 2^depth_bits − 1` (`raster::depth::tests::depth_saturates_at_both_ends`).
//! - **Exactness.** No floating point anywhere: coordinates are rationals, each
//!   polygon is scaled to integers over its common denominator (see
//!   `geometry::plane`). A polygon whose integers all fit 64 bits
//!   (`Geometry::fits_i64`: most of them) runs on `i64`, the others
//!   within `MAX_SCALED` (2^34) on `i128`; the same code, with the same
//!   results (`raster::convert::tests::both_words_rasterize_alike`). Larger ones run
//!   on the big-integer tier (`geometry::big`, `raster::big`: the formulas in
//!   arbitrary-precision integers, same results, the same proptest), which
//!   reports crossings and depths beyond 128 bits as big rationals
//!   ([`Exact`]); only absurd input is refused (`MAX_SCALED_BITS`).
//!
//! # Layers
//!
//! The source tree follows the algorithm's pipeline, from the words and
//! exact numbers up through the raster, the scene, the simulation, its
//! effects and observers, to teaching and the courses; each layer imports
//! only the layers before it, and no import runs back up. The layers are
//! drawn in one place, the guide's Development chapter
//! (`docs/src/development.md`), which `tests/integration/layers.rs` holds to
//! the code.
//!
//! The modules are private; this page lists the API the command line, the
//! benchmarks, the fuzz target and the tests use. The library builds without
//! the command line (`cargo build --lib --no-default-features`: none of clap,
//! ratatui, crossterm, comfy-table, indicatif, clap_complete or clap_mangen),
//! holds no hidden state (the language is an argument, as is the time: a
//! clock is the caller's; the one process-wide effect is that [`Plan::write`]
//! holds Ctrl-C, `SIGTERM` and `SIGHUP` while it writes), and never prints:
//! printing happens only in the binary (`src/cli/`, and the full-screen app
//! in `src/app/`), which renders the library's facts.
//!
//! Every file is read and written through one door (`src/door/`): regular
//! files within [`MAX_INPUT_BYTES`], names inside a file opened through a
//! [`Folder`], images measured by [`png_reader`] before decoding, and every
//! output a [`Plan`], checked whole and written atomically, never onto an
//! input ([`Identity`]).
//!
//! # Example
//!
//! ```
//! use std::path::Path;
//! use zsim::{Lang, Scene, Simulation, Unobserved};
//!
//! let scene = Scene::from_json(
//!     r#"{"width": 4, "height": 3, "polygons": [
//!         {"value": 1, "vertices": [[0, 0, 5], [4, 0, 5], [0, 3, 5]]}]}"#,
//!     Path::new("inline.json"),
//! ).unwrap();
//! let mut simulation = Simulation::new(&scene);
//! simulation.finish(&mut Unobserved);
//! assert_eq!(simulation.buffers().frame_rows(), vec![
//!     vec![1, 0, 0, 0],
//!     vec![1, 1, 0, 0],
//!     vec![1, 1, 1, 0],
//! ]);
//!
//! // A scene that is not read is refused as facts, worded where it is shown.
//! let error = Scene::from_json(r#"{"width": 0, "polygons": []}"#, Path::new("bad.json")).unwrap_err();
//! let refused = error.refused::<zsim::SceneRefused>().unwrap();
//! assert_eq!(
//!     refused.problem,
//!     zsim::SceneProblem::Setting { key: "width", problem: zsim::SettingProblem::SideZero }
//! );
//! assert_eq!(error.message(Lang::En), "bad.json: width: must be at least 1 pixel");
//! ```
#![warn(missing_docs)]
#![warn(clippy::print_stdout, clippy::print_stderr)]

#[macro_use]
mod words;
#[cfg(feature = "courses")]
mod courses;
mod door;
mod effects;
mod error;
mod geometry;
mod numbers;
mod observe;
mod raster;
mod rules;
mod scene;
mod simulate;
mod teach;

#[cfg(feature = "courses")]
pub use courses::{buet, cs418, tinyrenderer};
pub use door::{
    Folder, Identity, Line, Links, MAX_IMAGE_PIXELS, MAX_INPUT_BYTES, OutputRefused, Plan, PngProblem, Replace,
    png_reader, read_bytes, read_line_within, read_text, read_text_with, same_folder, write_fresh,
};
pub use effects::{accuracy, antialias, arith, variants};
pub use error::{Error, FileKind, PolygonOrigin, PolygonProblem, Refusal};
pub use numbers::{
    Exact, NumberError, Q, decimal, exact_and_decimal, fraction, parse_exact, parse_number, short, to_f64,
};
#[cfg(feature = "gpu")]
pub use observe::gpu;
#[cfg(feature = "gpu")]
pub use observe::race;
pub use observe::render::variant_report;
pub use observe::trace::{PixelHistoryEntry, PixelWatcher, Recorder, ScanlineRecord, SpanRecord};
pub use observe::tracer::{PolygonTrace, Skip, Stop, Tracer};
pub use observe::{explain, figure, history, picture, report, tie, tikz};
pub use raster::convert::{Scratch, rasterize};
pub use raster::depth::{Depth, DepthTest, Stored};
pub use raster::scan::{Crossing, Span};
pub use raster::sink::{PixelRect, RasterSink};
pub use raster::{printed_row, row_y};
pub use rules::{ColumnRule, Compare, DepthStore, Preset, RowRule, Rules, Sample};
pub use scene::random::{RandomScene, memory};
pub use scene::refused::{FormatProblem, JsonKind, MissingComma, Place, SceneProblem, SceneRefused, SettingProblem};
pub use scene::{Antialias, MAX_SIDE, NoSuchPolygon, Polygon, Scene, max_for_bits};
pub use simulate::buffer::Buffers;
pub use simulate::events::{Fate, Observer, Outcome, PixelEvent, PolygonEvent, ScanlineEvent, Unobserved};
pub use simulate::setup::{Stats, fate};
pub use simulate::simulation::{Drawn, Simulation};
pub use simulate::stages::{StageSet, describe};
pub use teach::check::diagnose;
pub use teach::grade::{class, gradebooks, gradescope};
pub use teach::step::{lesson, page, table};
pub use teach::{check, course, exercise, grade, page_limits, playground, step};
pub use words::{
    Arg, Lang, localize_decimal, own_name, polygon_label, printable, shown_name, shown_path, text as message, token,
};

/// A written shape's snapshot in `snapshots/`: `value` as the pretty JSON
/// a page, a platform or a script reads, so that a change to its type shows.
#[cfg(test)]
fn shape_snapshot(name: &str, value: &impl serde::Serialize) {
    insta::with_settings!({snapshot_path => "../snapshots", prepend_module_to_snapshot => false, omit_expression => true}, {
        insta::assert_snapshot!(name, serde_json::to_string_pretty(value).expect("a shape serializes"));
    });
}
