//! The scene file's JSON (serde types, exact numbers, unknown keys refused)
//! and its validation, once, into the domain type [`Scene`].

mod numbers;
mod pieces;
pub(super) mod refused;
mod strict;
#[cfg(test)]
mod tests;

use std::path::{Path, PathBuf};

use rayon::prelude::*;
use serde::Deserialize;
use serde::de::Error as _;

use crate::error::{Error, PolygonOrigin, PolygonProblem};
use crate::geometry::equation::GeometryError;
use crate::geometry::plane::Geometry;
use crate::numbers::{Exact, Q, fraction};
use crate::raster::depth::{DepthTest, Stored};
use crate::rules::{DepthStore, Preset, Rules};
use crate::scene::clip_space::Clipped;
use crate::scene::perspective::{Clip, Perspective};
use crate::scene::{Antialias, Effects, MAX_CELLS, MAX_SIDE, Polygon, Scene, Winding, Window, max_for_bits};
use crate::words::printable;
use numbers::{Coordinate, Number, ReadNumber};
use refused::{FormatProblem, JsonKind, MissingComma, Place, SceneProblem, SceneRefused, SettingProblem};

/// Reads and validates scene JSON; `path` is used in error messages only.
pub(crate) fn read(text: &str, path: &Path) -> Result<Scene, Error> {
    if let Some(found) = top_level_kind(text) {
        return Err(refused(path, SceneProblem::NotObject(found)));
    }
    // A scene of the common shape is read in pieces on every core; any
    // other, or one with an error, the plain way, which names the error.
    match pieces::read(text, path) {
        Some(scene) => Ok(scene),
        None => plain(text, path),
    }
}

/// The scene file at `path` refused for `problem`.
fn refused(path: &Path, problem: SceneProblem) -> Error {
    SceneRefused { path: path.to_owned(), problem }.into()
}

/// Reads and validates scene JSON of any shape, naming the first error.
fn plain(text: &str, path: &Path) -> Result<Scene, Error> {
    // Read at full speed first: the settings, with each polygon's text only
    // found; then each polygon read from its text and made at once, on every
    // core. Only a file with a polygon that does not read is read again, in
    // one piece, tracking where in its structure the failure is (that costs a
    // third of the time).
    let mut deserializer = serde_json::Deserializer::from_str(text);
    if let Ok(file) = SceneFile::<&serde_json::value::RawValue>::deserialize(&mut deserializer)
        && deserializer.end().is_ok()
    {
        let made = file.validate(path, |text, index, frame| from_text(text.get(), index, frame, path));
        match made {
            Ok(scene) => return Ok(scene),
            Err(Unmade::Invalid(error)) => return Err(*error),
            Err(Unmade::Unread) => {}
        }
    }
    let mut deserializer = serde_json::Deserializer::from_str(text);
    let file: SceneFile<PolygonFile> = serde_path_to_error::deserialize(&mut deserializer).map_err(|error| {
        // A syntax error has no place in the scene's structure: its line and column say where.
        let syntax = is_syntax(error.inner());
        let place = if syntax { None } else { place_of(&error.path().to_string()) };
        refused(path, SceneProblem::Format(FormatProblem { place, ..format_problem(text, error.inner()) }))
    })?;
    deserializer.end().map_err(|error| {
        refused(path, SceneProblem::Format(FormatProblem { comma: None, ..format_problem(text, &error) }))
    })?;
    file.validate(path, |polygon, index, frame| {
        polygon.validate(index, frame, path).map_err(|e| Unmade::Invalid(Box::new(e)))
    })
    .map_err(|unmade| match unmade {
        Unmade::Invalid(error) => *error,
        Unmade::Unread => unreachable!("every polygon of this file was read"),
    })
}

/// Whether serde_json's error is one of the JSON's syntax.
fn is_syntax(error: &serde_json::Error) -> bool {
    matches!(error.classify(), serde_json::error::Category::Syntax | serde_json::error::Category::Eof)
}

/// The facts of serde_json's `error` in `text`, with no place in the scene's structure.
fn format_problem(text: &str, error: &serde_json::Error) -> FormatProblem {
    FormatProblem {
        place: None,
        line: (error.line() > 0).then(|| error.line()),
        syntax: is_syntax(error),
        reason: error.to_string(),
        comma: missing_comma(text, error),
    }
}

/// Why a polygon of the file did not become a [`Polygon`].
enum Unmade {
    /// Its text does not read as a polygon: the file is read again to say where.
    Unread,
    /// It reads, and is not a valid polygon (or a setting is not valid).
    Invalid(Box<Error>),
}

/// What the file's first value is when it is valid-looking JSON but not an
/// object; `None` for an object or for text that the JSON reader should
/// report itself.
fn top_level_kind(text: &str) -> Option<JsonKind> {
    match text.trim_start().bytes().next()? {
        b'[' => Some(JsonKind::Array),
        b'"' => Some(JsonKind::String),
        b'-' | b'0'..=b'9' => Some(JsonKind::Number),
        b't' | b'f' if text.trim().parse::<bool>().is_ok() => Some(JsonKind::Bool),
        b'n' if text.trim() == "null" => Some(JsonKind::Null),
        _ => None,
    }
}

/// For "expected `,`", where the comma belongs: serde_json reports the
/// token after the gap, often on the next line; the comma is missing after
/// the last character before it.
fn missing_comma(text: &str, error: &serde_json::Error) -> Option<MissingComma> {
    if !error.to_string().starts_with("expected `,`") || error.line() == 0 {
        return None;
    }
    // The offset of (line, column), both from 1; then back over white space.
    let line_start: usize = text.split_inclusive('\n').take(error.line() - 1).map(str::len).sum();
    let at = text[line_start..]
        .char_indices()
        .nth(error.column().saturating_sub(1))
        .map_or(text.len(), |(i, _)| line_start + i);
    let (before, _) = text[..at].char_indices().rev().find(|(_, c)| !c.is_whitespace())?;
    let line = text[..before].matches('\n').count() + 1;
    if line < error.line() {
        Some(MissingComma::EndOfLine(line))
    } else {
        let column = text[..before].rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        Some(MissingComma::After(line, column))
    }
}

/// serde's path `polygons[1].vertices[0][2]` as a place: polygon 1 (from
/// 0), `vertices[0][2]`; `None` for the top (`.`).
fn place_of(path: &str) -> Option<Place> {
    if path == "." {
        return None;
    }
    if let Some(rest) = path.strip_prefix("polygons[")
        && let Some((index, tail)) = rest.split_once(']')
        && let Ok(index) = index.parse::<usize>()
    {
        return Some(Place { polygon: Some(index), path: tail.trim_start_matches('.').to_string() });
    }
    Some(Place { polygon: None, path: path.to_string() })
}

/// The scene file as read: its settings, and its polygons as `P` (each
/// polygon's text, or the polygon read from it).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile<P> {
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
    polygons: Vec<P>,
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
    sample: Option<crate::rules::Sample>,
    compare: Option<crate::rules::Compare>,
    min_area: Option<Number>,
}

/// Reads `"rules"`: a preset name, or an object naming a preset and
/// overrides; serde_json's description where they do not read.
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
        sample: file.sample.unwrap_or(base.sample),
        compare: file.compare.unwrap_or(base.compare),
        min_area: file.min_area.map(|n| n.0).or(base.min_area),
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
    vertices: VerticesFile,
}

/// A polygon's vertices as read: those given in pixel units (whose scaled
/// points the polygon then keeps) and those in clip space; both at once is
/// an error found in validation.
#[derive(Debug, Default)]
struct VerticesFile {
    xyz: Vec<[Exact; 3]>,
    clip: Vec<[Exact; 4]>,
}

impl<'de> Deserialize<'de> for VerticesFile {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<VerticesFile, D::Error> {
        deserializer.deserialize_seq(VerticesVisitor)
    }
}

struct VerticesVisitor;

impl<'de> serde::de::Visitor<'de> for VerticesVisitor {
    type Value = VerticesFile;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a sequence")
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<VerticesFile, A::Error> {
        let mut vertices = VerticesFile::default();
        // Each vertex read straight into its list: a large scene is nearly all vertices.
        while seq.next_element_seed(VertexInto(&mut vertices))?.is_some() {}
        Ok(vertices)
    }
}

/// A vertex as written, `[x, y, z]` in pixel units (or the window's) or
/// `[x, y, z, w]` in clip space ([`crate::scene::clip_space`]), read into
/// its polygon's list of that kind.
struct VertexInto<'a>(&'a mut VerticesFile);

impl<'de> serde::de::DeserializeSeed<'de> for VertexInto<'_> {
    type Value = ();

    fn deserialize<D: serde::Deserializer<'de>>(self, deserializer: D) -> Result<(), D::Error> {
        deserializer.deserialize_seq(self)
    }
}

impl<'de> serde::de::Visitor<'de> for VertexInto<'_> {
    type Value = ();

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a vertex [x, y, z], or [x, y, z, w] in clip space")
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let mut next = || seq.next_element::<Coordinate>().map(|c| c.map(|Coordinate(value)| value));
        let Some(x) = next()? else { return Err(A::Error::invalid_length(0, &self)) };
        let Some(y) = next()? else { return Err(A::Error::invalid_length(1, &self)) };
        let Some(z) = next()? else { return Err(A::Error::invalid_length(2, &self)) };
        match next()? {
            None => {
                // A triangle's three, not the four a first push would make room for.
                if self.0.xyz.capacity() == 0 {
                    self.0.xyz.reserve_exact(3);
                }
                self.0.xyz.push([x, y, z]);
            }
            Some(w) => {
                if next()?.is_some() {
                    return Err(A::Error::invalid_length(5, &self));
                }
                self.0.clip.push([x, y, z, w]);
            }
        }
        Ok(())
    }
}

/// A four-entry vertex among (more) three-entry ones that reads as a decimal comma
/// (`[1, 1, 2,5]`, natural in Russian and Ukrainian, is JSON's four numbers
/// `[1, 1, 2, 5]`): whole `z` and `w`, `w` not negative. The vertex as read,
/// the number with its comma (`2,5`) and the vertex as probably meant (`[1, 1, 2.5]`).
fn decimal_comma([x, y, z, w]: &[Exact; 4]) -> Option<(String, String, String)> {
    let (z, w) = (fraction(z.clone()), fraction(w.clone()));
    let whole = |text: &str| text.parse::<i128>().is_ok();
    if !whole(&z) || !whole(&w) || w.starts_with('-') {
        return None;
    }
    let (x, y) = (fraction(x.clone()), fraction(y.clone()));
    Some((format!("[{x}, {y}, {z}, {w}]"), format!("{z},{w}"), format!("[{x}, {y}, {z}.{w}]")))
}

impl<P: Send> SceneFile<P> {
    /// The scene: its settings validated, then each polygon made by `make`
    /// on every core; the error named is the first setting's, else the first
    /// polygon's in the file.
    fn validate(
        self,
        path: &Path,
        make: impl Fn(P, usize, &Frame) -> Result<Polygon, Unmade> + Sync,
    ) -> Result<Scene, Unmade> {
        let (scene, frame, polygons) = self.settings(path)?;
        with_made(scene, &frame, polygons, make)
    }

    /// Its settings validated: the scene they make, with no polygons yet
    /// ([`Scene::with_polygons`]), what its polygons are made in, and its
    /// polygons as read.
    fn settings(self, path: &Path) -> Result<(Scene, Frame, Vec<P>), Unmade> {
        let setting = |key: &'static str, problem: SettingProblem| {
            Unmade::Invalid(Box::new(refused(path, SceneProblem::Setting { key, problem })))
        };
        let bits = |key: &'static str, value: Option<u64>, default: u32| -> Result<u32, Unmade> {
            match value.unwrap_or(u64::from(default)) {
                bits @ 1..=32 => Ok(bits as u32),
                other => Err(setting(key, SettingProblem::Bits(other))),
            }
        };
        let side = |key: &'static str, value: Option<u64>| -> Result<u32, Unmade> {
            match value.unwrap_or(32) {
                0 => Err(setting(key, SettingProblem::SideZero)),
                side if side > MAX_SIDE => Err(setting(key, SettingProblem::SideLarge { side, max: MAX_SIDE })),
                side => Ok(side as u32),
            }
        };
        let width = side("width", self.width)?;
        let height = side("height", self.height)?;
        if u64::from(width) * u64::from(height) > MAX_CELLS {
            return Err(setting("width", SettingProblem::Cells { width, height, max: MAX_CELLS }));
        }
        let frame_bits = bits("frame_bits", self.frame_bits, 2)?;
        let depth_bits = bits("depth_bits", self.depth_bits, 4)?;
        let frame_max = u64::from(max_for_bits(frame_bits));
        let background = self.background.unwrap_or(0);
        if background > frame_max {
            return Err(setting(
                "background",
                SettingProblem::Background { value: background, bits: frame_bits, max: frame_max },
            ));
        }
        let rules = rules_from(self.rules).map_err(|reason| setting("rules", SettingProblem::Rules(reason)))?;
        let default_test = if rules.preset == Preset::Buet { DepthTest::Less } else { DepthTest::Greater };
        let depth_test = self.depth_test.unwrap_or(default_test);
        let window = match self.window {
            None => None,
            Some(w) => {
                let window = Window { left: w.left.0, right: w.right.0, bottom: w.bottom.0, top: w.top.0 };
                if window.left >= window.right || window.bottom >= window.top {
                    let sides = [window.left, window.right, window.bottom, window.top];
                    return Err(setting("window", SettingProblem::Window { sides }));
                }
                Some(window)
            }
        };
        let depth_range = match self.depth_range {
            Some([front, rear]) if front.0 > rear.0 => {
                return Err(setting("depth_range", SettingProblem::DepthRange { front: front.0, rear: rear.0 }));
            }
            Some([front, rear]) => Some((front.0, rear.0)),
            None => None,
        };
        let depth_max = max_for_bits(depth_bits);
        let clear_depth = match (rules.store, self.clear_depth) {
            (DepthStore::Quantized | DepthStore::Truncated, None) => Stored::Level(depth_test.clear_value(depth_max)),
            (DepthStore::Quantized | DepthStore::Truncated, Some(_)) => {
                return Err(setting("clear_depth", SettingProblem::ClearDepth));
            }
            (DepthStore::Exact, Some(value)) => Stored::Exact(Exact::Word(value.0)),
            (DepthStore::Exact, None) => {
                Stored::Exact(Exact::Word(Q::from_integer(i128::from(depth_test.clear_value(depth_max)))))
            }
        };
        let perspective = match self.effects.perspective {
            None => None,
            Some(p) => {
                let perspective = Perspective {
                    distance: p.distance.0,
                    near: p.near.0,
                    store_w: matches!(p.store, Some(StoreFile::W)),
                };
                if perspective.distance <= Q::from_integer(0) || perspective.near <= Q::from_integer(0) {
                    return Err(setting("effects", SettingProblem::PerspectiveNotPositive));
                }
                Some(perspective)
            }
        };
        let antialias = match self.effects.antialias {
            None => None,
            Some(a) => {
                if !(1..=16).contains(&a.samples) {
                    return Err(setting("effects", SettingProblem::AntialiasSamples(a.samples)));
                }
                if u64::from(width) * u64::from(height) * u64::from(a.samples).pow(2) > MAX_CELLS {
                    let cells = SettingProblem::AntialiasCells { width, height, samples: a.samples, max: MAX_CELLS };
                    return Err(setting("effects", cells));
                }
                if rules.store == DepthStore::Exact {
                    return Err(setting("effects", SettingProblem::AntialiasExact));
                }
                Some(Antialias { samples: a.samples, depth_at_samples: a.depth != Some(AntialiasDepth::Pixel) })
            }
        };
        let frame = Frame {
            bits: frame_bits,
            depth_max,
            window: window.map(|w| (w, width, height)),
            perspective,
            size: (width, height),
            corner_samples: rules.sample == crate::rules::Sample::Corner,
        };
        let scene = Scene {
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
                transparency: false,
            },
            rules,
            window,
            depth_range,
            clear_depth,
            polygons: Vec::new(),
        };
        Ok((scene, frame, self.polygons))
    }
}

/// The scene of [`SceneFile::settings`] with `polygons` made by `make` on
/// every core (transparency is an
/// effect when one of them has an opacity); the error named is that of the
/// first polygon in the file that failed, and any polygon that did not read
/// comes first ([`Unmade::Unread`]: the file is then read again to say where).
fn with_made<P: Send>(
    mut scene: Scene,
    frame: &Frame,
    polygons: Vec<P>,
    make: impl Fn(P, usize, &Frame) -> Result<Polygon, Unmade> + Sync,
) -> Result<Scene, Unmade> {
    // Each polygon made straight into its place in the list, no second pass
    // over it: a polygon that failed leaves a stand-in there and its error
    // aside, and the list is then dropped.
    let failed = std::sync::Mutex::new(Vec::new());
    let transparency = std::sync::atomic::AtomicBool::new(false);
    // In memory offered huge pages: drawing in tiles reads the polygons out of order.
    let mut made: Vec<Polygon> = crate::scene::pages::with_huge_pages(polygons.len());
    let one = |(index, polygon)| match make(polygon, index, frame) {
        Ok(polygon) => {
            if polygon.opacity.is_some() {
                transparency.store(true, std::sync::atomic::Ordering::Relaxed);
            }
            polygon
        }
        Err(unmade) => {
            failed.lock().unwrap_or_else(std::sync::PoisonError::into_inner).push((index, unmade));
            Polygon::outside_view(String::new(), 0, None)
        }
    };
    // On every core; in WebAssembly, which has one, in order.
    if cfg!(target_arch = "wasm32") {
        made.extend(polygons.into_iter().enumerate().map(one));
    } else {
        made.par_extend(polygons.into_par_iter().enumerate().map(one));
    }
    let mut failed = failed.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner);
    if failed.iter().any(|(_, unmade)| matches!(unmade, Unmade::Unread)) {
        return Err(Unmade::Unread);
    }
    failed.sort_unstable_by_key(|(index, _)| *index);
    if let Some((_, unmade)) = failed.into_iter().next() {
        return Err(unmade);
    }
    scene.effects.transparency = transparency.into_inner();
    scene.polygons = made;
    Ok(scene)
}

/// JSON's white space.
const JSON_SPACE: &[u8] = b" \t\n\r";

/// Past JSON's white space from `at`.
fn after_space(bytes: &[u8], at: usize) -> usize {
    at + bytes.get(at..).unwrap_or_default().iter().take_while(|b| JSON_SPACE.contains(b)).count()
}

/// The polygon whose text is `text`, made; [`Unmade::Unread`] when the text
/// does not read as a polygon.
fn from_text(text: &str, index: usize, frame: &Frame, path: &Path) -> Result<Polygon, Unmade> {
    let polygon = match strict::polygon(text) {
        Some(polygon) => polygon,
        None => serde_json::from_str::<PolygonFile>(text).map_err(|_| Unmade::Unread)?,
    };
    polygon.validate(index, frame, path).map_err(|e| Unmade::Invalid(Box::new(e)))
}

/// What a polygon's validation needs to know of the scene.
struct Frame {
    bits: u32,
    depth_max: u32,
    window: Option<(Window, u32, u32)>,
    perspective: Option<Perspective>,
    size: (u32, u32),
    /// The rules sample at integer points: the polygon is shifted by 1/2.
    corner_samples: bool,
}

impl PolygonFile {
    fn validate(self, index: usize, frame: &Frame, path: &Path) -> Result<Polygon, Error> {
        // Names reach terminals in every report: control characters are kept escaped (`\u{1b}`).
        let name = match self.name {
            None => crate::words::default_name(index),
            // The name as read, unless it has control characters to escape: no copy of it.
            Some(name) => match printable(&name) {
                std::borrow::Cow::Borrowed(_) => name,
                std::borrow::Cow::Owned(escaped) => escaped,
            },
        };
        let fail = |name: &str, problem: PolygonProblem| Error::Polygon {
            origin: PolygonOrigin::File(PathBuf::from(path)),
            index,
            name: name.to_owned(),
            problem: Box::new(problem),
        };
        // The name is given to the polygon once made: no copy kept for an error that did not happen.
        let named = |made: Result<Polygon, GeometryError>, name: String| match made {
            Ok(mut polygon) => {
                polygon.name = name;
                Ok(polygon)
            }
            Err(e) => Err(fail(&name, PolygonProblem::Geometry(e))),
        };
        let frame_bits = frame.bits;
        if self.value > u64::from(max_for_bits(frame_bits)) {
            return Err(fail(&name, PolygonProblem::ValueTooWide { value: self.value, frame_bits }));
        }
        let opacity = self.opacity.map(|n| n.0);
        if let Some(alpha) = opacity
            && (alpha < Q::from_integer(0) || alpha > Q::from_integer(1))
        {
            return Err(fail(&name, PolygonProblem::Opacity { alpha: fraction(alpha) }));
        }
        let VerticesFile { xyz: given, clip: clip_space } = self.vertices;
        let count = given.len() + clip_space.len();
        let mut vertices: Vec<[Exact; 3]> = if clip_space.is_empty() {
            given
        } else if clip_space.len() < count {
            // Four numbers where most vertices have three: a decimal comma, when it reads as one.
            let odd_ones_out = clip_space.len() < given.len();
            let problem = match clip_space.first().filter(|_| odd_ones_out).and_then(decimal_comma) {
                Some((written, comma, meant)) => PolygonProblem::DecimalComma { written, comma, meant },
                None => PolygonProblem::ClipSpaceMixed,
            };
            return Err(fail(&name, problem));
        } else if frame.window.is_some() || frame.perspective.is_some() {
            return Err(fail(&name, PolygonProblem::ClipSpaceAlone));
        } else {
            let value = self.value as u32;
            return match crate::scene::clip_space::to_raster(&clip_space, frame.size.0, frame.size.1, frame.depth_max) {
                Clipped::Outside => Ok(Polygon::outside_view(name, value, opacity)),
                Clipped::Inside { vertices, inside } => {
                    let clip = Clip::View { inside, of: clip_space.len() };
                    named(Polygon::new(String::new(), value, vertices, opacity, None, clip), name)
                }
            };
        };
        if let Some((window, width, height)) = frame.window {
            for vertex in &mut vertices {
                *vertex = window.to_pixels(vertex, width, height);
            }
        }
        if frame.corner_samples {
            // Sampled at integer points: drawn shifted by 1/2, so that each centre is that point.
            let half = Exact::Word(Q::new(1, 2));
            for vertex in &mut vertices {
                vertex[0] = vertex[0].plus(&half);
                vertex[1] = vertex[1].plus(&half);
            }
        }
        if vertices.len() < 3 {
            let error = GeometryError::TooFewVertices(vertices.len());
            return Err(fail(&name, PolygonProblem::Geometry(error)));
        }
        let geometry_error = |e| fail(&name, PolygonProblem::Geometry(e));
        let (eye_vertices, clip) = match frame.perspective {
            None => (None, Clip::NotClipped),
            Some(perspective) => {
                // Check planarity in eye space first, where the user wrote the polygon.
                Geometry::from_exact(&vertices).map_err(geometry_error)?;
                let (kept, clip) = perspective.clip(&vertices);
                if clip == Clip::Away {
                    // Nothing is drawn; keep the eye-space polygon for reports.
                    let eye_vertices = Some(vertices.clone());
                    let made = Polygon::new(String::new(), self.value as u32, vertices, opacity, eye_vertices, clip);
                    return named(made, name);
                }
                let (width, height) = frame.size;
                let projected = kept.iter().map(|v| perspective.project(v, width, height)).collect();
                (Some(std::mem::replace(&mut vertices, projected)), clip)
            }
        };
        named(Polygon::new(String::new(), self.value as u32, vertices, opacity, eye_vertices, clip), name)
    }
}
