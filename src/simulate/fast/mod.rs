//! The fast paths: loops that make the reference's decisions without its
//! generality, each beside the one reference and held to it by a named test.
//!
//! The reference is the scan converter ([`crate::raster::convert::rasterize`]:
//! which centres a polygon covers, and their exact depths) and the per-pixel
//! rule ([`crate::simulate::stages::Plain::decide`]: the depth test, then the
//! store); every observer, the stepper and the explanations run on it, and
//! it is held to an independent reference in rationals
//! (`exact_mode_matches_an_independent_reference`).
//!
//! | path | what it does | when it is taken | the test that holds it to the reference |
//! |---|---|---|---|
//! | the plain loop ([`levels`]) | the reference's decisions on the cells themselves, a covered centre at a time | the plain stages on a quantized z-buffer (no per-pixel effect) | `every_path_draws_alike` (a watched run against an unwatched one) |
//! | the 64-bit span ([`levels`], [`branch_free`]) | a span's cells without a branch, the depth stepped by whole part and remainder | nobody watches pixels and the span's values fit 2^61 | `every_path_draws_alike`; `branch_free_tests_are_the_tests` (the cell's test is the reference's) |
//! | eight 32-bit lanes ([`lanes`] over [`wide`]) | spans of up to 32 cells eight at a time | AVX2, and the polygon's values fit 2^28 | `lanes_decide_as_the_cell_does`, `lanes_decide_as_the_cell_does_at_their_bounds` (AVX2's lanes and the plain ones, the same loops; in CI also without AVX2 and in wasm32) |
//! | four 64-bit lanes ([`lanes`] over [`wide`]) | spans of 16 cells or more four at a time | AVX2's registers: longer spans or values past 2^28; the plain lanes (every other target but WebAssembly): spans of 16 cells or more | the same two; `without_avx2_the_lanes_are_the_plain_ones` (CI, under qemu) |
//! | small triangles ([`triangle`]) | edge functions over a triangle's box, no scan converter setup | the book's rules, a box of at most 24 × 24 centres, buffers within a core's cache, nobody watching | `small_triangles_draw_as_the_scan_converter_draws_them` |
//! | streaming stores ([`wide::stream_copy`]) | a drawn tile's rows back into the buffers past the cache | tiles, on x86-64 (a plain copy elsewhere) | `a_streamed_copy_is_a_copy` |
//! | tiles on threads ([`tiles`]) | polygons binned by tile, each band of tiles one job, each tile in cache | an unobserved run with a tile side (`--tile`, `--threads`, large rasters) | `every_path_draws_alike` (tiled runs on 1 to 4 threads), `a_redraw_clears_each_tile_as_it_draws_it` |
//!
//! Which path runs is decided once a run ([`crate::simulate::simulation`]:
//! the plain loop or the reference, tiles or not) and once a span
//! ([`levels::LevelSink::span`]: 64-bit or one centre at a time;
//! [`lanes::span`]: which lanes, in which registers). Imports: the layers `simulate` may use.
pub(super) mod branch_free;
pub(super) mod lanes;
pub(super) mod levels;
pub(super) mod tiles;
pub(super) mod triangle;
pub(super) mod wide;
