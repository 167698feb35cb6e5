//! Scene files: the JSON format (serde types) and its validation, once, into
//! the domain type [`Scene`].
//!
//! ```json
//! {
//!   "width": 32, "height": 32, "frame_bits": 2, "depth_bits": 4,
//!   "depth_test": "greater", "background": 0,
//!   "effects": {"section": 12, "cull": "cw"},
//!   "polygons": [
//!     {"name": "triangle", "value": 2, "vertices": [[15, 15, 15], [25, 25, 5], [30, 10, 5]]}
//!   ]
//! }
//! ```
//!
//! Numbers are JSON integers, JSON decimals read exactly (`2.1` is `21/10`),
//! or strings holding a fraction (`"5/2"`) or a decimal (`"2.5"`). Unknown
//! keys anywhere are errors. A file that is not read is refused as facts
//! ([`refused::SceneRefused`]), worded only where it is shown: the scene is
//! read without a language.

pub mod clip_space;
mod file;
pub(crate) mod pages;
pub mod perspective;
pub mod random;

/// A scene file that is not read, as facts ([`refused::SceneRefused`]).
pub mod refused {
    pub use super::file::refused::*;
}

use crate::words::Lang;
use std::borrow::Cow;
use std::fmt;
use std::path::Path;

use num_bigint::BigInt;
use num_traits::{CheckedDiv, CheckedMul, CheckedSub};
use serde::Deserialize;

use crate::error::{Error, Refusal};
use crate::geometry::equation::GeometryError;
use crate::geometry::plane::Geometry;
use crate::numbers::{Exact, Q};
use crate::raster::depth::{DepthTest, Stored};
use crate::rules::Rules;
use crate::scene::perspective::{Clip, Perspective};

/// Largest width or height.
pub const MAX_SIDE: u64 = 16_384;
/// Largest number of pixels, checked before any buffer is allocated
/// (2^26 pixels: 512 MiB for both buffers).
pub const MAX_CELLS: u64 = 1 << 26;

/// Which way a polygon's vertices run, seen from the viewer (x right, y up).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Winding {
    /// Clockwise: Newell's `c < 0`.
    Cw,
    /// Counter-clockwise: Newell's `c > 0`.
    Ccw,
}

impl Winding {
    /// The winding of a polygon with Newell's `c`, or `None` when edge-on.
    pub fn of(c: i128) -> Option<Winding> {
        match c.signum() {
            -1 => Some(Winding::Cw),
            1 => Some(Winding::Ccw),
            _ => None,
        }
    }

    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Winding::Cw => "cw",
            Winding::Ccw => "ccw",
        }
    }
}

/// The optional effects a scene asks for; the plain algorithm runs when all
/// are absent.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Effects {
    /// Cross-section depth (the Russian coursework): with `greater`, pixels are written only
    /// where `z ≤ section`; with `less`, only where `z ≥ section`.
    pub section: Option<Q>,
    /// Back-face culling: skip polygons whose vertices run this way.
    pub cull: Option<Winding>,
    /// Perspective with near-plane clipping (the Russian coursework §2.2, the Ukrainian Wikipedia).
    pub perspective: Option<Perspective>,
    /// Antialiasing by post-filtering (the Russian coursework).
    pub antialias: Option<Antialias>,
    /// Whether some polygon has an opacity (transparency, the Russian lecture notes and the Russian coursework).
    pub transparency: bool,
}

/// Antialiasing by post-filtering: k×k sub-pixel samples per pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Antialias {
    /// k: samples per pixel along each axis.
    pub samples: u32,
    /// Where depth is kept: at each sample, or once per pixel at its centre.
    pub depth_at_samples: bool,
}

impl Effects {
    /// The names of the effects the scene asks for, in a fixed order.
    pub fn names(&self) -> Vec<&'static str> {
        let mut names = Vec::new();
        if self.section.is_some() {
            names.push("section");
        }
        if self.cull.is_some() {
            names.push("cull");
        }
        if self.perspective.is_some() {
            names.push("perspective");
        }
        if self.antialias.is_some() {
            names.push("antialias");
        }
        if self.transparency {
            names.push("transparency");
        }
        names
    }
}

/// The world rectangle mapped onto the raster: `left … right` onto columns
/// `0 … width`, `bottom … top` onto rows `0 … height`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Window {
    /// World x of the raster's left edge.
    pub left: Q,
    /// World x of the raster's right edge.
    pub right: Q,
    /// World y of the raster's bottom edge.
    pub bottom: Q,
    /// World y of the raster's top edge.
    pub top: Q,
}

impl Window {
    /// Maps a world point to pixel units: `x_px = (x − left)·width/(right − left)`,
    /// likewise y; z is unchanged. Exact however large (in big rationals
    /// where 128 bits overflow).
    pub fn to_pixels(self, point: &[Exact; 3], width: u32, height: u32) -> [Exact; 3] {
        let map = |v: &Exact, low: Q, high: Q, size: u32| -> Exact {
            let words = |v: Q| {
                v.checked_sub(&low)?
                    .checked_mul(&Q::from_integer(i128::from(size)))?
                    .checked_div(&high.checked_sub(&low)?)
            };
            v.word().and_then(words).map_or_else(
                || {
                    let (low, high) = (Exact::Word(low).to_big(), Exact::Word(high).to_big());
                    Exact::from((v.to_big() - &low) * BigInt::from(size) / (high - low))
                },
                Exact::Word,
            )
        };
        [map(&point[0], self.left, self.right, width), map(&point[1], self.bottom, self.top, height), point[2].clone()]
    }
}

/// One validated polygon.
///
/// Laid out as written (`repr(C)`): in its first cache line what binning
/// reads of every polygon (its bounding cells and which way it faces, made
/// with its geometry, and how it was clipped), then what drawing reads (its
/// value and geometry) within [`Polygon::DRAWN_BYTES`], then what only
/// reports and effects read, so that a run asks the memory for those parts
/// alone ([`crate::simulate::setup::prefetch_polygon`]).
#[derive(Debug, Clone, PartialEq, Eq)]
#[repr(C)]
pub struct Polygon {
    /// The framebuffer value it writes; fits `frame_bits`.
    pub value: u32,
    /// Whether Newell's normal vanishes ([`Geometry::is_degenerate`]).
    degenerate: bool,
    /// Which way it faces (the sign of Newell's `c`); `None` edge-on.
    winding: Option<Winding>,
    /// The cells holding its bounding box ([`Geometry::cells`]), beyond
    /// 64 bits as the nearest that fit.
    cells: [i64; 4],
    /// How the polygon fared against the near plane.
    pub clip: Clip,
    /// Its scaled integer geometry and plane, made from its vertices.
    geometry: Geometry,
    /// Its name (from the file, or `crate::words::default_name`), with control characters
    /// escaped as `\u{1b}` ([`crate::words::printable`]) so that no report can
    /// carry them to a terminal.
    pub name: String,
    /// Where its vertices are kept ([`Polygon::vertices`]); private, so that
    /// they and the geometry made from them never disagree
    /// ([`Polygon::with_vertices`]).
    vertices: Vertices,
    /// Its opacity α (0 … 1) when it is transparent; `None` is opaque.
    pub opacity: Option<Q>,
    /// With perspective: the vertices as given (eye space, through the
    /// window when there is one), before clipping and projection; `vertices`
    /// then holds the projected ones.
    pub eye_vertices: Option<Vec<[Exact; 3]>>,
}

impl Polygon {
    /// How many bytes from its start hold every field the plain loop reads
    /// of a drawn polygon (see the type's layout).
    pub(crate) const DRAWN_BYTES: usize = std::mem::offset_of!(Polygon, geometry) + std::mem::size_of::<Geometry>();

    /// A polygon on its vertices: their geometry is made here, once, so the
    /// two always agree; the error when the vertices are unusable.
    pub(crate) fn new(
        name: String,
        value: u32,
        vertices: Vec<[Exact; 3]>,
        opacity: Option<Q>,
        eye_vertices: Option<Vec<[Exact; 3]>>,
        clip: Clip,
    ) -> Result<Polygon, GeometryError> {
        let geometry = Geometry::from_exact(&vertices)?;
        let vertices = Vertices::beside(&geometry, vertices);
        Ok(Polygon::made(name, value, (vertices, geometry), opacity, eye_vertices, clip))
    }

    /// The polygon with what binning reads made from its geometry.
    fn made(
        name: String,
        value: u32,
        (vertices, geometry): (Vertices, Geometry),
        opacity: Option<Q>,
        eye_vertices: Option<Vec<[Exact; 3]>>,
        clip: Clip,
    ) -> Polygon {
        let nearest = |cell: i128| cell.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64;
        Polygon {
            value,
            degenerate: geometry.is_degenerate(),
            winding: Winding::of(geometry.c()),
            cells: geometry.cells().map(nearest),
            clip,
            geometry,
            name,
            vertices,
            opacity,
            eye_vertices,
        }
    }

    /// A polygon given in clip space that lies wholly outside the view
    /// volume: no vertices on the raster, and a placeholder geometry (a unit
    /// triangle) that keeps it in the reports.
    pub(crate) fn outside_view(name: String, value: u32, opacity: Option<Q>) -> Polygon {
        let (zero, one) = (Q::from_integer(0), Q::from_integer(1));
        let geometry = Geometry::new(&[[zero, zero, zero], [one, zero, zero], [zero, one, zero]])
            .expect("a unit triangle is a polygon");
        Polygon::made(name, value, (Vertices::Kept(Vec::new()), geometry), opacity, None, Clip::ViewAway)
    }

    /// Its vertices, exact, in pixel units (mapped through the scene's
    /// window when it has one); beyond 128-bit fractions only where clip
    /// space made them so; none when clip space clipped it away. Made here
    /// from the scaled points when they fit 128 bits (almost always), which
    /// are then the polygon's only copy.
    pub fn vertices(&self) -> Cow<'_, [[Exact; 3]]> {
        match &self.vertices {
            Vertices::Kept(vertices) => Cow::Borrowed(vertices),
            Vertices::Scaled => {
                let scale = self.geometry.scale();
                let unscaled = |p: &[i128; 3]| p.map(|c| Exact::Word(Q::new(c, scale)));
                Cow::Owned(self.geometry.points.iter().map(unscaled).collect())
            }
        }
    }

    /// Its scaled integer geometry and plane, made from its vertices.
    pub fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    /// The same polygon on other vertices (supersampled, snapped), its
    /// geometry made anew from them; the error when they are unusable.
    pub fn with_vertices(&self, vertices: Vec<[Exact; 3]>) -> Result<Polygon, GeometryError> {
        let geometry = Geometry::from_exact(&vertices)?;
        let vertices = Vertices::beside(&geometry, vertices);
        let (name, opacity, eye_vertices) = (self.name.clone(), self.opacity, self.eye_vertices.clone());
        Ok(Polygon::made(name, self.value, (vertices, geometry), opacity, eye_vertices, self.clip))
    }

    /// Whether Newell's normal vanishes (as [`Geometry::is_degenerate`], read
    /// from the polygon's first cache line).
    pub fn is_degenerate(&self) -> bool {
        self.degenerate
    }

    /// Which way it faces, `None` edge-on (as `Winding::of` Newell's `c`).
    pub fn winding(&self) -> Option<Winding> {
        self.winding
    }

    /// The cells holding its bounding box: lowest and highest column, lowest
    /// and highest row (as [`Geometry::cells`], beyond 64 bits the nearest
    /// that fit).
    pub fn cells(&self) -> [i64; 4] {
        self.cells
    }

    /// The same polygon moved by `by` in x and in y (z unchanged): where
    /// rules that sample at pixel corners see it against centres, and back.
    pub fn shifted(&self, by: Q) -> Result<Polygon, GeometryError> {
        let by = Exact::Word(by);
        self.with_vertices(self.vertices().iter().map(|[x, y, z]| [x.plus(&by), y.plus(&by), z.clone()]).collect())
    }
}

/// Where a polygon's vertices are kept.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Vertices {
    /// Only as its geometry's scaled points, `vertex = point / 2D` (every
    /// polygon whose scaled points fit 128 bits): no second copy.
    Scaled,
    /// Here: on the big-integer tier, and none for a polygon clip space
    /// clipped away.
    Kept(Vec<[Exact; 3]>),
}

impl Vertices {
    /// Where to keep `vertices`, of which `geometry` was made.
    fn beside(geometry: &Geometry, vertices: Vec<[Exact; 3]>) -> Vertices {
        if geometry.is_big() { Vertices::Kept(vertices) } else { Vertices::Scaled }
    }
}

/// A validated scene: every guarantee the rasterizer relies on holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene {
    /// Raster width, 1 … [`MAX_SIDE`].
    pub width: u32,
    /// Raster height, 1 … [`MAX_SIDE`]; `width·height ≤` `MAX_CELLS`.
    pub height: u32,
    /// Bits per framebuffer cell, 1 … 32.
    pub frame_bits: u32,
    /// Bits per z-buffer cell, 1 … 32.
    pub depth_bits: u32,
    /// Which depth is nearer.
    pub depth_test: DepthTest,
    /// The framebuffer's clear value; fits `frame_bits`.
    pub background: u32,
    /// The effects asked for.
    pub effects: Effects,
    /// The rasterizer's rule choices.
    pub rules: Rules,
    /// The world rectangle mapped onto the raster, when not pixel units.
    pub window: Option<Window>,
    /// Fragments with z outside `[front, rear]` are discarded (BUET).
    pub depth_range: Option<(Q, Q)>,
    /// What the z-buffer is cleared to: a level, or an exact value with an
    /// exact store.
    pub clear_depth: Stored,
    /// The polygons in drawing order.
    pub polygons: Vec<Polygon>,
}

impl Scene {
    /// Whether the scene asks for a stage between the depth and the store
    /// (depth range, w-buffer, cross-section, opacity); if not, the plain
    /// loop runs.
    pub fn has_pixel_effects(&self) -> bool {
        self.rules.store == crate::rules::DepthStore::Truncated
            || self.rules.compare == crate::rules::Compare::Level
            || self.depth_range.is_some()
            || self.effects.section.is_some()
            || self.effects.transparency
            || self.effects.perspective.is_some_and(|p| p.store_w)
    }

    /// The bytes this scene holds in memory: its own struct, and for each
    /// polygon its struct and the heap blocks it owns (name, vertices, scaled
    /// points, eye-space vertices), counted by their capacities. The
    /// allocator's bookkeeping per block (a few bytes) is not counted.
    pub fn memory_bytes(&self) -> u64 {
        use std::mem::size_of;
        let polygons: usize = self
            .polygons
            .iter()
            .map(|p| {
                p.name.capacity()
                    + match &p.vertices {
                        Vertices::Kept(vertices) => vertices.capacity() * size_of::<[Exact; 3]>(),
                        Vertices::Scaled => 0,
                    }
                    + if p.geometry.points.spilled() {
                        p.geometry.points.capacity() * size_of::<[i128; 3]>()
                    } else {
                        0
                    }
                    + p.eye_vertices.as_ref().map_or(0, |v| v.capacity() * size_of::<[Exact; 3]>())
            })
            .sum();
        (size_of::<Scene>() + self.polygons.capacity() * size_of::<Polygon>() + polygons) as u64
    }

    /// The largest value the z-buffer holds: `2^depth_bits − 1`.
    pub fn depth_max(&self) -> u32 {
        max_for_bits(self.depth_bits)
    }

    /// Reads and validates a scene file.
    pub fn load(path: &Path) -> Result<Scene, Error> {
        let text = crate::door::read_text(path)?;
        Scene::from_json(&text, path)
    }

    /// Validates scene JSON; `path` is used in error messages only.
    pub fn from_json(text: &str, path: &Path) -> Result<Scene, Error> {
        crate::scene::file::read(text, path)
    }

    /// Finds a polygon by 1-based number or by name.
    pub fn find_polygon(&self, spec: &str) -> Result<usize, Error> {
        if let Ok(number) = spec.parse::<usize>() {
            if (1..=self.polygons.len()).contains(&number) {
                return Ok(number - 1);
            }
            return Err(NoSuchPolygon::Numbered { number, count: self.polygons.len() }.into());
        }
        self.polygons.iter().position(|p| p.name == spec).ok_or_else(|| {
            let names = self.polygons.iter().map(|p| p.name.clone()).collect();
            NoSuchPolygon::Named { name: spec.to_string(), names }.into()
        })
    }
}

/// A polygon asked for that the scene does not have.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NoSuchPolygon {
    /// A number past the last polygon.
    Numbered {
        /// The number asked for, from 1.
        number: usize,
        /// How many polygons the scene has.
        count: usize,
    },
    /// A name no polygon has.
    Named {
        /// The name asked for.
        name: String,
        /// The scene's polygon names.
        names: Vec<String>,
    },
}

impl Refusal for NoSuchPolygon {
    fn message(&self, lang: Lang) -> String {
        match self {
            NoSuchPolygon::Numbered { number, count } => {
                words!(lang, "usage-no-polygon-numbered", number = number.to_string(), count = count.to_string())
            }
            NoSuchPolygon::Named { name, names } => {
                let names: Vec<String> = names.iter().map(|name| format!("\"{name}\"")).collect();
                words!(lang, "usage-no-polygon-named", name = name, names = names.join(", "))
            }
        }
    }
}

/// `2^bits − 1` for 1 ≤ bits ≤ 32.
pub fn max_for_bits(bits: u32) -> u32 {
    debug_assert!((1..=32).contains(&bits));
    (u64::MAX >> (64 - bits)) as u32
}

impl fmt::Display for Winding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Winding::Cw => "clockwise",
            Winding::Ccw => "counter-clockwise",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What binning reads of a polygon fits its first cache line; what
    /// drawing reads comes next and takes fewer lines than the whole record
    /// (the names, opacity and eye-space vertices after it are read only by
    /// reports and effects).
    #[test]
    fn what_binning_and_drawing_read_of_a_polygon_comes_first() {
        use std::mem::{offset_of, size_of};
        let (binned, drawn) = (offset_of!(Polygon, clip) + size_of::<Clip>(), Polygon::DRAWN_BYTES);
        assert!(binned <= 64, "{binned} bytes binned");
        for field in [offset_of!(Polygon, degenerate), offset_of!(Polygon, winding), offset_of!(Polygon, cells)] {
            assert!(field < binned);
        }
        for field in [offset_of!(Polygon, value), offset_of!(Polygon, clip), offset_of!(Polygon, geometry)] {
            assert!(field < drawn);
        }
        for field in [
            offset_of!(Polygon, name),
            offset_of!(Polygon, vertices),
            offset_of!(Polygon, opacity),
            offset_of!(Polygon, eye_vertices),
        ] {
            assert!(field >= drawn, "{field} within the first {drawn} bytes");
        }
        assert!(drawn.div_ceil(64) < size_of::<Polygon>().div_ceil(64), "{drawn} of {} bytes", size_of::<Polygon>());
    }

    /// What binning reads is what the geometry says, on every tier: a
    /// polygon, a degenerate one, an edge-on one, each winding, one beyond
    /// 64-bit cells.
    #[test]
    fn what_binning_reads_agrees_with_the_geometry() {
        let e = |v: i128| Exact::Word(Q::from_integer(v));
        let polygon = |points: [[i128; 3]; 3]| {
            let vertices = points.iter().map(|p| p.map(e)).collect();
            Polygon::new(String::new(), 1, vertices, None, None, Clip::NotClipped).expect("a polygon")
        };
        let huge = 1i128 << 70;
        for points in [
            [[0, 0, 0], [4, 0, 1], [0, 3, 2]],
            [[0, 0, 0], [0, 3, 2], [4, 0, 1]],
            [[0, 0, 0], [1, 1, 1], [2, 2, 2]],
            [[0, 0, 0], [0, 0, 5], [4, 0, 1]],
            [[-huge, 0, 0], [huge, 0, 1], [0, huge, 2]],
        ] {
            let polygon = polygon(points);
            let geometry = polygon.geometry();
            assert_eq!(polygon.is_degenerate(), geometry.is_degenerate(), "{points:?}");
            assert_eq!(polygon.winding(), Winding::of(geometry.c()), "{points:?}");
            let nearest = geometry.cells().map(|c| c.clamp(i128::from(i64::MIN), i128::from(i64::MAX)));
            assert_eq!(polygon.cells().map(i128::from), nearest, "{points:?}");
        }
    }

    fn parse(text: &str) -> Result<Scene, String> {
        Scene::from_json(text, Path::new("s.json")).map_err(|e| e.message(Lang::En))
    }

    #[test]
    fn defaults_are_the_books() {
        let scene = parse(r#"{"polygons": []}"#).unwrap();
        assert_eq!((scene.width, scene.height, scene.frame_bits, scene.depth_bits), (32, 32, 2, 4));
        assert_eq!(scene.depth_test, DepthTest::Greater);
        assert_eq!(scene.depth_max(), 15);
    }

    #[test]
    fn json_decimals_keep_their_digits() {
        let scene =
            parse(r#"{"polygons": [{"value": 1, "vertices": [[0.1, 0, 2.1], [3, 0, "5/2"], [0, 3, 0]]}]}"#).unwrap();
        assert_eq!(scene.polygons[0].vertices()[0][0], Q::new(1, 10));
        assert_eq!(scene.polygons[0].vertices()[0][2], Q::new(21, 10));
        assert_eq!(scene.polygons[0].vertices()[1][2], Q::new(5, 2));
    }

    proptest::proptest! {
        /// A polygon keeps its vertices only as scaled points when they fit
        /// 128 bits: the vertices made back from them are the ones given,
        /// whatever their denominators, and so is the geometry made again.
        #[test]
        fn vertices_kept_as_scaled_points_are_the_ones_given(
            given in proptest::collection::vec(
                proptest::array::uniform3((-10_000i128..10_000, 1i128..=12)), 3..6)
        ) {
            let vertices: Vec<[Exact; 3]> = given.iter().map(|v| v.map(|(n, d)| Exact::Word(Q::new(n, d)))).collect();
            // Planar by construction: z is made from x and y on one plane.
            let vertices: Vec<[Exact; 3]> = vertices
                .into_iter()
                .map(|[x, y, _]| {
                    let z = x.times(3).plus(&y.times(-2)).plus(&Exact::Word(Q::new(7, 5)));
                    [x, y, z]
                })
                .collect();
            let polygon = Polygon::new("p".into(), 1, vertices.clone(), None, None, Clip::NotClipped).unwrap();
            proptest::prop_assert!(matches!(polygon.vertices, Vertices::Scaled));
            proptest::prop_assert_eq!(&*polygon.vertices(), &vertices[..]);
            let again = polygon.with_vertices(polygon.vertices().into_owned()).unwrap();
            proptest::prop_assert_eq!(again, polygon);
        }
    }

    /// A vertex of the wrong length, or with a coordinate that is not a
    /// number, is named with its place and what was found there.
    #[test]
    fn a_vertex_of_the_wrong_shape_is_named() {
        let want = "where a vertex [x, y, z] (or [x, y, z, w] in clip space) was expected";
        for (vertex, error) in [
            ("[]", format!("vertices[0]: 0 entries {want}")),
            ("[0, 0]", format!("vertices[0]: 2 entries {want}")),
            ("[0, 0, 0, 1, 2]", format!("vertices[0]: 5 entries {want}")),
            ("[0, 0, 0, 1, true]", "vertices[0][4]: expected a number, found a boolean".to_string()),
            ("[0, 0, null]", "vertices[0][2]: expected a number, found null".to_string()),
        ] {
            let text = format!(r#"{{"polygons": [{{"value": 1, "vertices": [{vertex}, [1, 0, 0], [0, 1, 0]]}}]}}"#);
            let err = parse(&text).unwrap_err();
            assert!(err.starts_with(&format!("s.json: polygon 1: {error} (line 1, column")), "{vertex}: {err}");
        }
    }

    #[test]
    fn errors_name_the_polygon() {
        let err = parse(r#"{"polygons": [{"value": 1, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}, {"value": 1, "vertices": [[0, 0, "abc"]]}]}"#)
            .unwrap_err();
        assert!(err.starts_with("s.json: polygon 2: vertices[0][2]: \"abc\" is not a number"), "{err}");
    }

    /// An unnamed polygon is `polygon N` in every report, not `polygon N
    /// "polygon N"` (nor, in Russian, `многоугольник 1 «polygon 1»`); a named
    /// one keeps its name, and both can be found by number or name.
    #[test]
    fn an_unnamed_polygon_is_reported_by_its_number_alone() {
        let text = r#"{"polygons": [{"value": 1, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
            {"name": "roof", "value": 2, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]}"#;
        let scene = parse(text).unwrap();
        assert_eq!(scene.polygons[0].name, crate::words::default_name(0));
        let labels = |lang| [0, 1].map(|i| crate::observe::explain::polygon_name(lang, &scene, i));
        assert_eq!(labels(Lang::En), ["polygon 1".to_string(), "polygon 2 \"roof\"".to_string()]);
        assert_eq!(labels(Lang::Ru), ["многоугольник 1".to_string(), "многоугольник 2 «roof»".to_string()]);
        assert_eq!((scene.find_polygon("polygon 1").unwrap(), scene.find_polygon("roof").unwrap()), (0, 1));
    }

    #[test]
    fn bits_of_32_are_supported() {
        let scene = parse(r#"{"frame_bits": 32, "depth_bits": 32, "background": 4294967295, "polygons": []}"#).unwrap();
        assert_eq!(scene.depth_max(), u32::MAX);
        assert_eq!(scene.background, u32::MAX);
    }
}
