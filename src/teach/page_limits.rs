//! What a page draws: the limits the browser playground and the recorded
//! page (`step --html`) hold a scene to, checked before any work, so that no
//! scene keeps a tab busy for more than a second or makes a page too large
//! to open; a scene past them is refused in one line that names the limit
//! and says what draws it instead. The command line's own limits (the
//! raster's side and cells, a polygon's vertices, a file's size) hold too.

use std::path::{Path, PathBuf};

use serde_json::Value;

use crate::error::Refusal;
use crate::numbers::to_f64;
use crate::scene::Scene;
use crate::words::{Lang, shown_path};

/// The largest raster the page shows cell by cell (each polygon's buffers,
/// every stop): 128 × 128. A larger scene is still drawn and its final
/// buffers shown.
pub const MAX_SHOWN_CELLS: u64 = 128 * 128;

/// The most polygons whose buffers the page shows one by one.
pub const MAX_SHOWN_POLYGONS: usize = 64;

/// The largest raster whose final buffers the page prints as text and
/// draws as a figure: 512 × 512 (a 1024 × 1024 raster's text, and a 2048 ×
/// 2048 raster's figure, kept a tab busy past a second). A larger scene is
/// drawn, and the page says why its buffers are not printed.
pub const MAX_PRINTED_CELLS: u64 = 512 * 512;

/// The longest scene text the page reads, typed or in its address: 1 MiB
/// (thousands of polygons; a longer one is for `zsim run`, and reading it
/// kept a tab busy for seconds). Refused in one line naming the limit.
pub const MAX_PAGE_SCENE_BYTES: usize = 1 << 20;

/// The largest raster the page draws at all: 2048 × 2048 (4,194,304
/// pixels); a larger one is for `zsim run`.
pub const MAX_PAGE_CELLS: u64 = 2048 * 2048;

/// The most polygons the page draws.
pub const MAX_PAGE_POLYGONS: usize = 20_000;

/// The most vertices of one polygon the page draws (a polygon of many
/// vertices can cross a scanline at each).
pub const MAX_PAGE_VERTICES: usize = 1_000;

/// The most pixels a scene's polygons may reach in all, each counted by
/// its bounding box on the raster: four times the largest raster. What the
/// page's drawing costs grows with it (a scene of raster-sized polygons
/// within every other limit kept a tab busy for minutes).
pub const MAX_PAGE_REACH: u64 = 4 * MAX_PAGE_CELLS;

/// The most pixels the polygons of a scene the recorded page steps may
/// reach in all (each counted by its bounding box): four times its largest
/// raster. The page records every pixel of every stop, so it grows with
/// them (the design note on every limit tested has what it took).
pub const MAX_RECORDED_REACH: u64 = 4 * MAX_SHOWN_CELLS;

/// A scene larger than a page draws.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PageLimit {
    /// A text longer than [`MAX_PAGE_SCENE_BYTES`].
    Bytes {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// Its length in bytes.
        bytes: usize,
    },
    /// More pixels than [`MAX_PAGE_CELLS`].
    Cells {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// Its pixels.
        cells: u64,
    },
    /// More polygons than [`MAX_PAGE_POLYGONS`].
    Polygons {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// Its polygons.
        count: usize,
    },
    /// A polygon of more vertices than [`MAX_PAGE_VERTICES`].
    Vertices {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// The polygon, from 1.
        polygon: usize,
        /// Its vertices.
        count: usize,
    },
    /// Polygons that reach more than [`MAX_PAGE_REACH`] pixels in all.
    Reach {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// The pixels they reach (each polygon's bounding box on the raster).
        reach: u64,
    },
    /// Polygons that reach more than [`MAX_RECORDED_REACH`] pixels in all,
    /// for the recorded page.
    RecordedReach {
        /// The scene file.
        path: PathBuf,
        /// The pixels they reach.
        reach: u64,
    },
    /// More than the recorded page steps (a page without the playground):
    /// [`MAX_SHOWN_CELLS`] pixels, [`MAX_SHOWN_POLYGONS`] polygons.
    Recorded {
        /// The scene file.
        path: PathBuf,
        /// Its pixels.
        cells: u64,
        /// Its polygons.
        polygons: usize,
    },
}

impl Refusal for PageLimit {
    fn message(&self, lang: Lang) -> String {
        let (path, said) = match self {
            PageLimit::Bytes { path, bytes } => (
                path.as_deref(),
                words!(lang, "limit-scene-bytes", max = MAX_PAGE_SCENE_BYTES.to_string(), bytes = bytes.to_string()),
            ),
            PageLimit::Cells { path, cells } => (
                path.as_deref(),
                words!(lang, "limit-page-cells", max = MAX_PAGE_CELLS.to_string(), cells = cells.to_string()),
            ),
            PageLimit::Polygons { path, count } => (
                path.as_deref(),
                words!(lang, "limit-page-polygons", max = MAX_PAGE_POLYGONS.to_string(), count = count.to_string()),
            ),
            PageLimit::Vertices { path, polygon, count } => (
                path.as_deref(),
                words!(
                    lang,
                    "limit-page-vertices",
                    max = MAX_PAGE_VERTICES.to_string(),
                    polygon = polygon.to_string(),
                    count = count.to_string()
                ),
            ),
            PageLimit::Reach { path, reach } => (
                path.as_deref(),
                words!(lang, "limit-page-reach", max = MAX_PAGE_REACH.to_string(), reach = reach.to_string()),
            ),
            PageLimit::RecordedReach { path, reach } => (
                Some(path.as_path()),
                words!(lang, "limit-recorded-reach", max = MAX_RECORDED_REACH.to_string(), reach = reach.to_string()),
            ),
            PageLimit::Recorded { path, cells, polygons } => (
                Some(path.as_path()),
                words!(
                    lang,
                    "limit-recorded-page",
                    cells = MAX_SHOWN_CELLS.to_string(),
                    polygons = MAX_SHOWN_POLYGONS.to_string(),
                    has_cells = cells.to_string(),
                    has_polygons = *polygons
                ),
            ),
        };
        match path {
            Some(path) => format!("{}: {said}", shown_path(path)),
            None => said,
        }
    }
}

/// The page's limits on a scene's text, read as plain JSON before the scene
/// is (whose validation is the work a limit spares): its length, its raster,
/// its polygons, each polygon's vertices. Text that is not a scene's JSON passes,
/// for the scene's reader to say what is wrong with it.
pub fn check_text(text: &str, path: Option<&Path>) -> Result<(), PageLimit> {
    let path = || path.map(Path::to_path_buf);
    if text.len() > MAX_PAGE_SCENE_BYTES {
        return Err(PageLimit::Bytes { path: path(), bytes: text.len() });
    }
    let Ok(shape) = serde_json::from_str::<Shape>(text) else { return Ok(()) };
    let side = |value: &Option<Value>| value.as_ref().and_then(Value::as_u64).unwrap_or(32);
    let cells = side(&shape.width).saturating_mul(side(&shape.height));
    if cells > MAX_PAGE_CELLS {
        return Err(PageLimit::Cells { path: path(), cells });
    }
    let polygons = shape.polygons.0;
    if polygons.len() > MAX_PAGE_POLYGONS {
        return Err(PageLimit::Polygons { path: path(), count: polygons.len() });
    }
    match polygons.iter().position(|&count| count > MAX_PAGE_VERTICES) {
        Some(index) => Err(PageLimit::Vertices { path: path(), polygon: index + 1, count: polygons[index] }),
        None => Ok(()),
    }
}

/// What [`check_text`] reads of a scene's JSON: its raster's sides and how
/// many vertices each polygon lists, counted without keeping them (read as
/// a JSON value, every number of the scene was kept as a string).
#[derive(serde::Deserialize)]
struct Shape {
    #[serde(default)]
    width: Option<Value>,
    #[serde(default)]
    height: Option<Value>,
    #[serde(default)]
    polygons: Counts,
}

/// Each polygon's count of vertices (0 for anything that is not a polygon
/// listing its vertices, for the scene's reader to word).
#[derive(Default)]
struct Counts(Vec<usize>);

/// How many items a JSON array holds (0 for anything else).
struct Items(usize);

/// A polygon's count of vertices.
struct Vertices(usize);

/// A visitor's answer to any scalar JSON value: `$value`.
macro_rules! scalars {
    ($value:expr) => {
        fn visit_bool<E>(self, _: bool) -> Result<Self::Value, E> {
            Ok($value)
        }
        fn visit_i64<E>(self, _: i64) -> Result<Self::Value, E> {
            Ok($value)
        }
        fn visit_u64<E>(self, _: u64) -> Result<Self::Value, E> {
            Ok($value)
        }
        fn visit_f64<E>(self, _: f64) -> Result<Self::Value, E> {
            Ok($value)
        }
        fn visit_str<E>(self, _: &str) -> Result<Self::Value, E> {
            Ok($value)
        }
        fn visit_unit<E>(self) -> Result<Self::Value, E> {
            Ok($value)
        }
    };
}

/// A visitor's answer to anything but a list (an object, a number with
/// arbitrary precision among them, drained): `$value`.
macro_rules! not_a_list {
    ($value:expr) => {
        scalars!($value);
        fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
            while map.next_entry::<serde::de::IgnoredAny, serde::de::IgnoredAny>()?.is_some() {}
            Ok($value)
        }
    };
}

impl<'de> serde::Deserialize<'de> for Counts {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visit;
        impl<'de> serde::de::Visitor<'de> for Visit {
            type Value = Counts;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a list of polygons")
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Counts, A::Error> {
                let mut counts = Vec::new();
                while let Some(Vertices(count)) = seq.next_element()? {
                    counts.push(count);
                }
                Ok(Counts(counts))
            }
        }
        deserializer.deserialize_seq(Visit)
    }
}

impl<'de> serde::Deserialize<'de> for Vertices {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visit;
        impl<'de> serde::de::Visitor<'de> for Visit {
            type Value = Vertices;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a polygon")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Vertices, A::Error> {
                let mut count = 0;
                while let Some(key) = map.next_key::<std::borrow::Cow<'de, str>>()? {
                    match key.as_ref() {
                        "vertices" => count = map.next_value::<Items>()?.0,
                        _ => _ = map.next_value::<serde::de::IgnoredAny>()?,
                    }
                }
                Ok(Vertices(count))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Vertices, A::Error> {
                while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {}
                Ok(Vertices(0))
            }
            scalars!(Vertices(0));
        }
        deserializer.deserialize_any(Visit)
    }
}

impl<'de> serde::Deserialize<'de> for Items {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visit;
        impl<'de> serde::de::Visitor<'de> for Visit {
            type Value = Items;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a list")
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Items, A::Error> {
                let mut count = 0;
                while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {
                    count += 1;
                }
                Ok(Items(count))
            }
            not_a_list!(Items(0));
        }
        deserializer.deserialize_any(Visit)
    }
}

/// The page's limit on what a scene's polygons reach ([`MAX_PAGE_REACH`]),
/// once the scene is read (its polygons in pixels, whatever space the file
/// gave them) and before anything is drawn.
pub fn check_reach(scene: &Scene, path: Option<&Path>) -> Result<(), PageLimit> {
    match reaches_past(scene, MAX_PAGE_REACH) {
        true => Err(PageLimit::Reach { path: path.map(Path::to_path_buf), reach: total_reach(scene) }),
        false => Ok(()),
    }
}

/// Whether `scene`'s polygons reach more than `max` pixels in all (counted
/// until they do).
fn reaches_past(scene: &Scene, max: u64) -> bool {
    let mut reach = 0u64;
    scene.polygons.iter().any(|polygon| {
        reach = reach.saturating_add(bounding_cells(polygon, scene.width, scene.height));
        reach > max
    })
}

/// The pixels of the raster within `polygon`'s bounding box (rounded out).
fn bounding_cells(polygon: &crate::scene::Polygon, width: u32, height: u32) -> u64 {
    let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for vertex in polygon.vertices().iter() {
        for axis in 0..2 {
            let c = to_f64(&vertex[axis]);
            low[axis] = low[axis].min(c);
            high[axis] = high[axis].max(c);
        }
    }
    let span = |axis: usize, side: u32| {
        let side = f64::from(side);
        (high[axis].ceil().clamp(0.0, side) - low[axis].floor().clamp(0.0, side)).max(0.0) as u64
    };
    span(0, width) * span(1, height)
}

/// What all of a scene's polygons reach, for the refusal to say.
fn total_reach(scene: &Scene) -> u64 {
    scene.polygons.iter().map(|p| bounding_cells(p, scene.width, scene.height)).fold(0, u64::saturating_add)
}

/// The recorded page's limits (`step --html` without the playground): a
/// scene it steps pixel by pixel, at most [`MAX_SHOWN_CELLS`] pixels and
/// [`MAX_SHOWN_POLYGONS`] polygons, as the playground's stepper, whose
/// polygons reach at most [`MAX_RECORDED_REACH`] pixels.
pub fn check_recorded(scene: &Scene, path: &Path) -> Result<(), PageLimit> {
    let cells = u64::from(scene.width) * u64::from(scene.height);
    if cells > MAX_SHOWN_CELLS || scene.polygons.len() > MAX_SHOWN_POLYGONS {
        return Err(PageLimit::Recorded { path: path.to_path_buf(), cells, polygons: scene.polygons.len() });
    }
    if reaches_past(scene, MAX_RECORDED_REACH) {
        return Err(PageLimit::RecordedReach { path: path.to_path_buf(), reach: total_reach(scene) });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Text that is not a scene's JSON passes, for the scene's reader to
    /// word; what the shape reader counts is counted wherever the polygons
    /// keep other keys. (Each limit at its value and one past is held by the
    /// integration test that reads the Safety chapter's table.)
    #[test]
    fn text_that_is_not_a_scene_passes_for_its_reader_to_word() {
        // The default raster is 32 × 32.
        assert_eq!(check_text(r#"{"polygons": []}"#, None), Ok(()));
        for text in ["{not json", r#"{"width": "wide"}"#, r#"{"polygons": {}}"#, r#"{"polygons": [7]}"#, "[]"] {
            assert_eq!(check_text(text, None), Ok(()), "{text}");
        }
        let corners = vec!["[0, 0, 1]"; MAX_PAGE_VERTICES + 1].join(", ");
        let text = format!(
            r#"{{"width": 8.0, "polygons": [{{"vertices": "none"}}, {{"name": "x", "vertices": [{corners}], "value": 1e400}}]}}"#
        );
        assert_eq!(
            check_text(&text, Some(Path::new("v.json"))),
            Err(PageLimit::Vertices { path: Some(PathBuf::from("v.json")), polygon: 2, count: MAX_PAGE_VERTICES + 1 })
        );
    }
}
