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
//! keys anywhere are errors.

use std::fmt;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use serde::de::Error as _;

use num_traits::{CheckedDiv, CheckedMul, CheckedSub};

use crate::depth::{DepthTest, Stored};
use crate::error::{Error, PolygonProblem};
use crate::exact::{Q, fraction, parse_number};
use crate::perspective::{Clip, Perspective};
use crate::plane::Geometry;
use crate::rules::{DepthStore, Preset, Rules};

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
    /// Cross-section depth (seed 002): with `greater`, pixels are written only
    /// where `z ≤ section`; with `less`, only where `z ≥ section`.
    pub section: Option<Q>,
    /// Back-face culling: skip polygons whose vertices run this way.
    pub cull: Option<Winding>,
    /// Perspective with near-plane clipping (seed 002 §2.2, seed 004).
    pub perspective: Option<Perspective>,
    /// Antialiasing by post-filtering (seed 002).
    pub antialias: Option<Antialias>,
    /// Whether some polygon has an opacity (transparency, seeds 000 and 002).
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
    /// likewise y; z is unchanged. `None` when the result does not fit `i128`.
    pub fn to_pixels(&self, point: [Q; 3], width: u32, height: u32) -> Option<[Q; 3]> {
        let map = |v: Q, low: Q, high: Q, size: u32| -> Option<Q> {
            v.checked_sub(&low)?.checked_mul(&Q::from_integer(i128::from(size)))?.checked_div(&high.checked_sub(&low)?)
        };
        Some([map(point[0], self.left, self.right, width)?, map(point[1], self.bottom, self.top, height)?, point[2]])
    }
}

/// One validated polygon.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Polygon {
    /// Its name (from the file, or `polygon N`).
    pub name: String,
    /// The framebuffer value it writes; fits `frame_bits`.
    pub value: u32,
    /// Its vertices, exact, in pixel units (mapped through the scene's
    /// window when it has one).
    pub vertices: Vec<[Q; 3]>,
    /// Its scaled integer geometry and plane.
    pub geometry: Geometry,
    /// Its opacity α (0 … 1) when it is transparent; `None` is opaque.
    pub opacity: Option<Q>,
    /// With perspective: the vertices as given (eye space), before clipping
    /// and projection; `vertices` then holds the projected ones.
    pub eye_vertices: Option<Vec<[Q; 3]>>,
    /// How the polygon fared against the near plane.
    pub clip: Clip,
}

/// A validated scene: every guarantee the rasterizer relies on holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene {
    /// Raster width, 1 … [`MAX_SIDE`].
    pub width: u32,
    /// Raster height, 1 … [`MAX_SIDE`]; `width·height ≤` [`MAX_CELLS`].
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
        self.depth_range.is_some()
            || self.effects.section.is_some()
            || self.effects.transparency
            || self.effects.perspective.is_some_and(|p| p.store_w)
    }

    /// The largest value the z-buffer holds: `2^depth_bits − 1`.
    pub fn depth_max(&self) -> u32 {
        max_for_bits(self.depth_bits)
    }

    /// Reads and validates a scene file.
    pub fn load(path: &Path) -> Result<Scene, Error> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Read { path: path.to_owned(), source })?;
        Scene::from_json(&text, path)
    }

    /// Validates scene JSON; `path` is used in error messages only.
    pub fn from_json(text: &str, path: &Path) -> Result<Scene, Error> {
        let mut deserializer = serde_json::Deserializer::from_str(text);
        let file: SceneFile =
            serde_path_to_error::deserialize(&mut deserializer).map_err(|error| Error::SceneFormat {
                path: path.to_owned(),
                location: describe_location(&error.path().to_string()),
                message: json_message(error.inner()),
            })?;
        deserializer.end().map_err(|error| Error::SceneFormat {
            path: path.to_owned(),
            location: String::new(),
            message: json_message(&error),
        })?;
        file.validate(path)
    }

    /// Finds a polygon by 1-based number or by name.
    pub fn find_polygon(&self, spec: &str) -> Result<usize, Error> {
        if let Ok(number) = spec.parse::<usize>() {
            if (1..=self.polygons.len()).contains(&number) {
                return Ok(number - 1);
            }
            return Err(Error::Usage(format!(
                "there is no polygon {number}: the scene has {} (number them from 1)",
                self.polygons.len()
            )));
        }
        self.polygons.iter().position(|p| p.name == spec).ok_or_else(|| {
            let names: Vec<String> = self.polygons.iter().map(|p| format!("\"{}\"", p.name)).collect();
            Error::Usage(format!("there is no polygon named \"{spec}\": the scene has {}", names.join(", ")))
        })
    }
}

/// `2^bits − 1` for 1 ≤ bits ≤ 32.
pub fn max_for_bits(bits: u32) -> u32 {
    debug_assert!((1..=32).contains(&bits));
    (u64::MAX >> (64 - bits)) as u32
}

/// serde_json's message, saying "not valid JSON" when the syntax is at fault.
fn json_message(error: &serde_json::Error) -> String {
    match error.classify() {
        serde_json::error::Category::Syntax | serde_json::error::Category::Eof => format!("not valid JSON: {error}"),
        _ => error.to_string(),
    }
}

/// Turns serde's path `polygons[1].vertices[0][2]` into
/// `polygon 2: vertices[0][2]`, so messages name polygons as the CLI does.
fn describe_location(path: &str) -> String {
    if path == "." {
        return String::new();
    }
    if let Some(rest) = path.strip_prefix("polygons[")
        && let Some((index, tail)) = rest.split_once(']')
        && let Ok(index) = index.parse::<usize>()
    {
        let tail = tail.trim_start_matches('.');
        return if tail.is_empty() {
            format!("polygon {}", index + 1)
        } else {
            format!("polygon {}: {tail}", index + 1)
        };
    }
    path.to_string()
}

/// An exact number as written in a scene file.
#[derive(Debug, Clone, Copy)]
struct Number(Q);

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Number, D::Error> {
        // With serde_json's `arbitrary_precision`, a JSON number keeps its digits.
        let text = match serde_json::Value::deserialize(deserializer)? {
            serde_json::Value::Number(number) => number.to_string(),
            serde_json::Value::String(text) => text,
            other => return Err(D::Error::custom(format!("expected a number, found {}", kind(&other)))),
        };
        parse_number(&text).map(Number).map_err(D::Error::custom)
    }
}

fn kind(value: &serde_json::Value) -> &'static str {
    match value {
        serde_json::Value::Null => "null",
        serde_json::Value::Bool(_) => "a boolean",
        serde_json::Value::Number(_) => "a number",
        serde_json::Value::String(_) => "a string",
        serde_json::Value::Array(_) => "a list",
        serde_json::Value::Object(_) => "an object",
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    width: Option<u64>,
    height: Option<u64>,
    frame_bits: Option<u64>,
    depth_bits: Option<u64>,
    depth_test: Option<DepthTest>,
    background: Option<u64>,
    #[serde(default)]
    effects: EffectsFile,
    rules: Option<serde_json::Value>,
    window: Option<WindowFile>,
    depth_range: Option<[Number; 2]>,
    clear_depth: Option<Number>,
    polygons: Vec<PolygonFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct WindowFile {
    left: Number,
    right: Number,
    bottom: Number,
    top: Number,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RulesFile {
    preset: Option<Preset>,
    rows: Option<crate::rules::RowRule>,
    columns: Option<crate::rules::ColumnRule>,
    store: Option<DepthStore>,
}

/// Reads `"rules"`: a preset name, or an object naming a preset and overrides.
fn rules_from(value: Option<serde_json::Value>) -> Result<Rules, String> {
    let Some(value) = value else { return Ok(Rules::default()) };
    if value.is_string() {
        let preset: Preset = serde_json::from_value(value).map_err(|e| e.to_string())?;
        return Ok(Rules::preset(preset));
    }
    let file: RulesFile = serde_json::from_value(value).map_err(|e| e.to_string())?;
    let base = Rules::preset(file.preset.unwrap_or(Preset::Rogers));
    Ok(Rules {
        preset: base.preset,
        rows: file.rows.unwrap_or(base.rows),
        columns: file.columns.unwrap_or(base.columns),
        store: file.store.unwrap_or(base.store),
    })
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct EffectsFile {
    section: Option<Number>,
    cull: Option<Winding>,
    perspective: Option<PerspectiveFile>,
    antialias: Option<AntialiasFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PerspectiveFile {
    distance: Number,
    near: Number,
    store: Option<StoreFile>,
}

#[derive(Deserialize)]
enum StoreFile {
    #[serde(rename = "z'", alias = "z")]
    Projected,
    #[serde(rename = "w")]
    W,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AntialiasFile {
    samples: u32,
    depth: Option<AntialiasDepth>,
}

#[derive(Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
enum AntialiasDepth {
    Pixel,
    Sample,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PolygonFile {
    name: Option<String>,
    value: u64,
    opacity: Option<Number>,
    vertices: Vec<[Number; 3]>,
}

impl SceneFile {
    fn validate(self, path: &Path) -> Result<Scene, Error> {
        let setting = |key: &'static str, message: String| Error::Setting { path: path.to_owned(), key, message };
        let bits = |key: &'static str, value: Option<u64>, default: u32| -> Result<u32, Error> {
            match value.unwrap_or(u64::from(default)) {
                bits @ 1..=32 => Ok(bits as u32),
                other => Err(setting(key, format!("{other} is not supported: use 1 to 32 bits"))),
            }
        };
        let side = |key: &'static str, value: Option<u64>| -> Result<u32, Error> {
            match value.unwrap_or(32) {
                0 => Err(setting(key, "must be at least 1 pixel".into())),
                side if side > MAX_SIDE => {
                    Err(setting(key, format!("{side} is beyond the limit of {MAX_SIDE} pixels")))
                }
                side => Ok(side as u32),
            }
        };
        let width = side("width", self.width)?;
        let height = side("height", self.height)?;
        if u64::from(width) * u64::from(height) > MAX_CELLS {
            return Err(setting(
                "width",
                format!(
                    "{width}×{height} is {} pixels, beyond the limit of {MAX_CELLS}",
                    u64::from(width) * u64::from(height)
                ),
            ));
        }
        let frame_bits = bits("frame_bits", self.frame_bits, 2)?;
        let depth_bits = bits("depth_bits", self.depth_bits, 4)?;
        let frame_max = u64::from(max_for_bits(frame_bits));
        let background = self.background.unwrap_or(0);
        if background > frame_max {
            return Err(setting(
                "background",
                format!("{background} does not fit a {frame_bits}-bit framebuffer (at most {frame_max})"),
            ));
        }
        let rules = rules_from(self.rules).map_err(|message| setting("rules", message))?;
        let default_test = if rules.preset == Preset::Buet { DepthTest::Less } else { DepthTest::Greater };
        let depth_test = self.depth_test.unwrap_or(default_test);
        let window = match self.window {
            None => None,
            Some(w) => {
                let window = Window { left: w.left.0, right: w.right.0, bottom: w.bottom.0, top: w.top.0 };
                if window.left >= window.right || window.bottom >= window.top {
                    return Err(setting(
                        "window",
                        format!(
                            "left {} must be below right {} and bottom {} below top {}",
                            fraction(window.left),
                            fraction(window.right),
                            fraction(window.bottom),
                            fraction(window.top)
                        ),
                    ));
                }
                Some(window)
            }
        };
        let depth_range = match self.depth_range {
            Some([front, rear]) if front.0 > rear.0 => {
                return Err(setting(
                    "depth_range",
                    format!("[{}, {}]: the front must not exceed the rear", fraction(front.0), fraction(rear.0)),
                ));
            }
            Some([front, rear]) => Some((front.0, rear.0)),
            None => None,
        };
        let depth_max = max_for_bits(depth_bits);
        let clear_depth = match (rules.store, self.clear_depth) {
            (DepthStore::Quantized, None) => Stored::Level(depth_test.clear_value(depth_max)),
            (DepthStore::Quantized, Some(_)) => {
                return Err(setting(
                    "clear_depth",
                    "applies only to an exact z-buffer (rules with \"store\": \"exact\"); a quantized one is cleared to its farthest level".into(),
                ));
            }
            (DepthStore::Exact, Some(value)) => Stored::Exact(value.0),
            (DepthStore::Exact, None) => Stored::Exact(Q::from_integer(i128::from(depth_test.clear_value(depth_max)))),
        };
        let perspective = match self.effects.perspective {
            None => None,
            Some(p) => {
                let perspective = Perspective {
                    distance: p.distance.0,
                    near: p.near.0,
                    store_w: matches!(p.store, Some(StoreFile::W)),
                };
                let small = |v: Q| v.numer().abs() <= 1 << 20 && *v.denom() <= 1 << 20;
                if perspective.distance <= Q::from_integer(0) || perspective.near <= Q::from_integer(0) {
                    return Err(setting("effects", "perspective: distance and near must be positive".into()));
                }
                if !small(perspective.distance) || !small(perspective.near) {
                    return Err(setting(
                        "effects",
                        "perspective: distance and near must have numerators and denominators of at most 2^20".into(),
                    ));
                }
                Some(perspective)
            }
        };
        let antialias = match self.effects.antialias {
            None => None,
            Some(a) => {
                if !(1..=16).contains(&a.samples) {
                    return Err(setting(
                        "effects",
                        format!("antialias: samples {} is not supported: use 1 to 16", a.samples),
                    ));
                }
                if u64::from(width) * u64::from(height) * u64::from(a.samples).pow(2) > MAX_CELLS {
                    return Err(setting(
                        "effects",
                        format!(
                            "antialias: {width}×{height} pixels × {}² samples is beyond the limit of {MAX_CELLS} cells",
                            a.samples
                        ),
                    ));
                }
                if rules.store == DepthStore::Exact {
                    return Err(setting(
                        "effects",
                        "antialias averages a quantized z-buffer; it does not combine with an exact store".into(),
                    ));
                }
                Some(Antialias { samples: a.samples, depth_at_samples: a.depth != Some(AntialiasDepth::Pixel) })
            }
        };
        let transparency = self.polygons.iter().any(|p| p.opacity.is_some());
        let mut polygons = Vec::with_capacity(self.polygons.len());
        for (index, polygon) in self.polygons.into_iter().enumerate() {
            let frame = Frame {
                bits: frame_bits,
                window: window.map(|w| (w, width, height)),
                perspective,
                size: (width, height),
            };
            polygons.push(polygon.validate(index, &frame, path)?);
        }
        Ok(Scene {
            width,
            height,
            frame_bits,
            depth_bits,
            depth_test,
            background: background as u32,
            effects: Effects {
                section: self.effects.section.map(|n| n.0),
                cull: self.effects.cull,
                perspective,
                antialias,
                transparency,
            },
            rules,
            window,
            depth_range,
            clear_depth,
            polygons,
        })
    }
}

/// What a polygon's validation needs to know of the scene.
struct Frame {
    bits: u32,
    window: Option<(Window, u32, u32)>,
    perspective: Option<Perspective>,
    size: (u32, u32),
}

impl PolygonFile {
    fn validate(self, index: usize, frame: &Frame, path: &Path) -> Result<Polygon, Error> {
        let name = self.name.unwrap_or_else(|| format!("polygon {}", index + 1));
        let fail = |name: &str, problem: PolygonProblem| Error::Polygon {
            path: PathBuf::from(path),
            index,
            name: name.to_owned(),
            problem: Box::new(problem),
        };
        let frame_bits = frame.bits;
        if self.value > u64::from(max_for_bits(frame_bits)) {
            return Err(fail(&name, PolygonProblem::ValueTooWide { value: self.value, frame_bits }));
        }
        let opacity = self.opacity.map(|n| n.0);
        if let Some(alpha) = opacity
            && (alpha < Q::from_integer(0) || alpha > Q::from_integer(1))
        {
            return Err(fail(&name, PolygonProblem::Other(format!("opacity {} is outside 0 … 1", fraction(alpha)))));
        }
        let out_of_range = |number: usize, value: Q| {
            fail(
                &name,
                PolygonProblem::Geometry(crate::plane::GeometryError::OutOfRange {
                    vertex: number + 1,
                    value,
                    denominator: *value.denom(),
                }),
            )
        };
        let mut vertices: Vec<[Q; 3]> = self.vertices.iter().map(|v| v.map(|n| n.0)).collect();
        if let Some((window, width, height)) = frame.window {
            for (number, vertex) in vertices.iter_mut().enumerate() {
                *vertex = window.to_pixels(*vertex, width, height).ok_or_else(|| out_of_range(number, vertex[0]))?;
            }
        }
        if vertices.len() < 3 {
            let error = crate::plane::GeometryError::TooFewVertices(vertices.len());
            return Err(fail(&name, PolygonProblem::Geometry(error)));
        }
        let (eye_vertices, clip) = match frame.perspective {
            None => (None, Clip::NotClipped),
            Some(perspective) => {
                // Check planarity in eye space first, where the user wrote the polygon.
                Geometry::new(&vertices).map_err(|e| fail(&name, PolygonProblem::Geometry(e)))?;
                let eye = vertices.clone();
                let (kept, clip) = perspective.clip(&vertices).ok_or_else(|| out_of_range(0, vertices[0][0]))?;
                if clip == Clip::Away {
                    // Nothing is drawn; keep the eye-space geometry for reports.
                    let geometry = Geometry::new(&eye).map_err(|e| fail(&name, PolygonProblem::Geometry(e)))?;
                    return Ok(Polygon {
                        name,
                        value: self.value as u32,
                        vertices: eye.clone(),
                        geometry,
                        opacity,
                        eye_vertices: Some(eye),
                        clip,
                    });
                }
                let (width, height) = frame.size;
                let mut projected = Vec::with_capacity(kept.len());
                for (number, v) in kept.iter().enumerate() {
                    projected.push(perspective.project(*v, width, height).ok_or_else(|| out_of_range(number, v[0]))?);
                }
                vertices = projected;
                (Some(eye), clip)
            }
        };
        let geometry = Geometry::new(&vertices).map_err(|e| fail(&name, PolygonProblem::Geometry(e)))?;
        if let Some(perspective) = frame.perspective
            && perspective.store_w
            && !w_fits(&geometry)
        {
            return Err(fail(
                &name,
                PolygonProblem::Other(
                    "its projected coordinates are too fine for the w-buffer's exact arithmetic (use coarser coordinates or a smaller distance)".into(),
                ),
            ));
        }
        Ok(Polygon { name, value: self.value as u32, vertices, geometry, opacity, eye_vertices, clip })
    }
}

/// Whether the w-buffer's `p·n / (p·den + q·n)` fits `i128` for every pixel of
/// this geometry: the depth numerator is below `20·n·R³` (see `plane`), and
/// `p, q ≤ 2^20`.
fn w_fits(geometry: &Geometry) -> bool {
    let bits = |v: u128| 128 - v.leading_zeros();
    let r = geometry.points.iter().flatten().map(|v| v.unsigned_abs()).max().unwrap_or(0).max(1);
    let n = geometry.points.len() as u128;
    3 * bits(r) + bits(20 * n) + 21 <= 125
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

    fn parse(text: &str) -> Result<Scene, String> {
        Scene::from_json(text, Path::new("s.json")).map_err(|e| e.to_string())
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
        assert_eq!(scene.polygons[0].vertices[0][0], Q::new(1, 10));
        assert_eq!(scene.polygons[0].vertices[0][2], Q::new(21, 10));
        assert_eq!(scene.polygons[0].vertices[1][2], Q::new(5, 2));
    }

    #[test]
    fn errors_name_the_polygon() {
        let err = parse(r#"{"polygons": [{"value": 1, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}, {"value": 1, "vertices": [[0, 0, "abc"]]}]}"#)
            .unwrap_err();
        assert!(err.starts_with("s.json: polygon 2: vertices[0][2]: \"abc\" is not a number"), "{err}");
    }

    #[test]
    fn bits_of_32_are_supported() {
        let scene = parse(r#"{"frame_bits": 32, "depth_bits": 32, "background": 4294967295, "polygons": []}"#).unwrap();
        assert_eq!(scene.depth_max(), u32::MAX);
        assert_eq!(scene.background, u32::MAX);
    }
}
