//! A change the page makes to the scene's JSON, and the layout it writes
//! the scene in: the editor's side of the playground, apart from what it
//! shows.

use serde_json::Value;

use crate::words::Lang;

/// A change the page makes to the scene's JSON (`{"op": …}`): the value at
/// `path` (keys and 0-based indices from the top) set to `value` (JSON text;
/// text that is not JSON, such as `43/4`, is kept as a string, which the
/// scene format reads as an exact number), or removed, or a value inserted
/// before an index of an array; or a vertex dragged, a vertex or a polygon
/// added, a vertex removed, where the library decides the numbers.
#[derive(Debug, Clone, PartialEq)]
pub enum Edit {
    /// Set the value at `path` (`"set"`).
    Set {
        /// Where.
        path: Vec<Value>,
        /// The new value as JSON text.
        value: String,
    },
    /// Insert `value` before index `path`'s last entry of an array (at the end when past it) (`"insert"`).
    Insert {
        /// Where.
        path: Vec<Value>,
        /// The value as JSON text.
        value: String,
    },
    /// Remove the value at `path` (`"remove"`).
    Remove {
        /// Where.
        path: Vec<Value>,
    },
    /// Move vertex `vertex` (from 1) of polygon `polygon` (from 1) to the
    /// point `to` of the page's raster (x, and y down from its top), snapped
    /// to multiples of `snap` (`1`, `0.5`, `0.25`, `0.1`) (`"drag"`).
    Drag {
        /// The polygon's number, from 1.
        polygon: usize,
        /// The vertex's number, from 1.
        vertex: usize,
        /// Where the pointer is, in the page's coordinates.
        to: [f64; 2],
        /// The step the coordinates snap to, as text.
        snap: String,
    },
    /// Add a polygon: a triangle of value 1 across the middle of the raster (`"add-polygon"`).
    AddPolygon,
    /// Add a vertex to polygon `polygon` (from 1) where its last one is (the origin for none) (`"add-vertex"`).
    AddVertex {
        /// The polygon's number, from 1.
        polygon: usize,
    },
    /// Remove the last vertex of polygon `polygon` (from 1) (`"remove-vertex"`).
    RemoveVertex {
        /// The polygon's number, from 1.
        polygon: usize,
    },
}

impl Edit {
    /// The edit of the page's JSON text; `None` for text that is not one.
    pub fn parse(text: &str) -> Option<Edit> {
        let edit: Value = serde_json::from_str(text).ok()?;
        let path = || edit.get("path")?.as_array().cloned();
        let value = || Some(edit.get("value")?.as_str()?.to_string());
        let number = |key: &str| usize::try_from(edit.get(key)?.as_u64()?).ok();
        Some(match edit.get("op")?.as_str()? {
            "set" => Edit::Set { path: path()?, value: value()? },
            "insert" => Edit::Insert { path: path()?, value: value()? },
            "remove" => Edit::Remove { path: path()? },
            "drag" => {
                let to = edit.get("to")?;
                Edit::Drag {
                    polygon: number("polygon")?,
                    vertex: number("vertex")?,
                    to: [to.get(0)?.as_f64()?, to.get(1)?.as_f64()?],
                    snap: edit.get("snap")?.as_str()?.to_string(),
                }
            }
            "add-polygon" => Edit::AddPolygon,
            "add-vertex" => Edit::AddVertex { polygon: number("polygon")? },
            "remove-vertex" => Edit::RemoveVertex { polygon: number("polygon")? },
            _ => return None,
        })
    }
}

/// The scene text after `edit` (given as JSON), laid out as [`layout`]
/// does; `Err` worded in `lang` when the text is not JSON or the edit does
/// not fit it.
pub fn edit(lang: Lang, text: &str, edit: &str) -> Result<String, String> {
    let not_json = |e: serde_json::Error| words!(lang, "scene-not-json", reason = e.to_string());
    let mut scene: Value = serde_json::from_str(text).map_err(not_json)?;
    let edit = Edit::parse(edit).ok_or_else(|| words!(lang, "edit-does-not-fit"))?;
    let bad = || words!(lang, "edit-does-not-fit");
    // The raster's size as the scene is drawn (a preset's and the defaults resolved).
    let size = || {
        let drawn = crate::scene::Scene::from_json(text, std::path::Path::new(&super::scene_name(lang)));
        drawn.map(|scene| (scene.width, scene.height)).map_err(|error| error.message(lang))
    };
    let index = |number: usize| number.checked_sub(1).ok_or_else(bad);
    // What the library decides, as the plain edits that carry it out.
    let edits = match edit {
        Edit::Drag { polygon, vertex, to, snap } => {
            let (_, height) = size()?;
            let step = crate::numbers::parse_number(&snap).ok().filter(|step| *step > crate::numbers::Q::ZERO);
            let step = step.ok_or_else(bad)?;
            let snapped = |v: f64| {
                let steps = (v / crate::numbers::to_f64(step)).round();
                if !steps.is_finite() || steps.abs() > 1e9 {
                    return None;
                }
                let exact = crate::numbers::Q::from_integer(steps as i128) * step;
                let text = crate::numbers::decimal(exact, 4);
                Some(text.trim_end_matches('0').trim_end_matches('.').to_string())
            };
            // The page's y runs down from the raster's top; the scene's up from its bottom.
            let (x, y) = (snapped(to[0]).ok_or_else(bad)?, snapped(f64::from(height) - to[1]).ok_or_else(bad)?);
            let (polygon, vertex) = (index(polygon)?, index(vertex)?);
            let at = |c: usize| vec!["polygons".into(), polygon.into(), "vertices".into(), vertex.into(), c.into()];
            vec![Edit::Set { path: at(0), value: x }, Edit::Set { path: at(1), value: y }]
        }
        Edit::AddVertex { polygon } | Edit::RemoveVertex { polygon } => {
            let adding = matches!(edit, Edit::AddVertex { .. });
            let polygon = index(polygon)?;
            let vertices = scene.pointer(&format!("/polygons/{polygon}/vertices")).and_then(Value::as_array);
            let vertices = vertices.ok_or_else(bad)?;
            let path = |at: usize| vec!["polygons".into(), polygon.into(), "vertices".into(), at.into()];
            match (adding, vertices.last()) {
                (true, last) => {
                    let value = last.cloned().unwrap_or_else(|| Value::from(vec![0, 0, 0])).to_string();
                    vec![Edit::Insert { path: path(vertices.len()), value }]
                }
                (false, Some(_)) => vec![Edit::Remove { path: path(vertices.len() - 1) }],
                (false, None) => return Err(bad()),
            }
        }
        Edit::AddPolygon => {
            let (width, height) = size()?;
            let polygon = NewPolygon::within(width, height);
            let count = scene.get("polygons").and_then(Value::as_array).map_or(0, Vec::len);
            let value = serde_json::to_string(&polygon).expect("plain data");
            vec![Edit::Insert { path: vec!["polygons".into(), count.into()], value }]
        }
        plain => vec![plain],
    };
    for edit in &edits {
        apply(&mut scene, edit).ok_or_else(bad)?;
    }
    Ok(layout(&scene))
}

/// The polygon the page's "add a polygon" puts in a scene: a triangle of
/// value 1 at depth 1 across the middle of the raster, its vertices at
/// quarters of the sides, rounded.
#[derive(Debug, serde::Serialize)]
struct NewPolygon {
    value: u32,
    vertices: [(f64, f64, u32); 3],
}

impl NewPolygon {
    fn within(width: u32, height: u32) -> NewPolygon {
        let at = |part: u32, of: u32| (f64::from(of) * f64::from(part) / 4.0).round();
        let vertices =
            [(at(1, width), at(1, height), 1), (at(2, width), at(3, height), 1), (at(3, width), at(1, height), 1)];
        NewPolygon { value: 1, vertices }
    }
}

/// A plain edit (set, insert, remove) carried out on `scene`; `None` where it does not fit.
fn apply(scene: &mut Value, edit: &Edit) -> Option<()> {
    let value_of =
        |text: &str| serde_json::from_str(text.trim()).unwrap_or_else(|_| Value::String(text.trim().to_string()));
    let (last, path) = match edit {
        Edit::Set { path, .. } | Edit::Insert { path, .. } | Edit::Remove { path } => path.split_last()?,
        _ => return None,
    };
    let mut at = scene;
    for step in path {
        at = match (at, step) {
            (Value::Object(map), Value::String(key)) => map.get_mut(key)?,
            (Value::Array(list), Value::Number(n)) => list.get_mut(usize::try_from(n.as_u64()?).ok()?)?,
            _ => return None,
        };
    }
    match (at, last, edit) {
        (Value::Object(map), Value::String(key), Edit::Set { value, .. }) => {
            map.insert(key.clone(), value_of(value));
        }
        (Value::Object(map), Value::String(key), Edit::Remove { .. }) => {
            map.remove(key);
        }
        (Value::Array(list), Value::Number(n), edit) => {
            let index = usize::try_from(n.as_u64()?).ok()?;
            match edit {
                Edit::Set { value, .. } => *list.get_mut(index)? = value_of(value),
                Edit::Insert { value, .. } => list.insert(index.min(list.len()), value_of(value)),
                Edit::Remove { .. } if index < list.len() => drop(list.remove(index)),
                _ => return None,
            }
        }
        _ => return None,
    }
    Some(())
}

/// The order of a scene's keys as the page writes them (the others follow, in order of name).
const KEY_ORDER: [&str; 10] =
    ["width", "height", "frame_bits", "depth_bits", "depth_test", "background", "rules", "name", "value", "vertices"];

/// A scene's JSON laid out as the examples are: one key a line, one
/// polygon a line, `polygons` last; numbers kept exactly as written.
pub fn layout(scene: &Value) -> String {
    fn compact(value: &Value) -> String {
        match value {
            Value::Array(list) => format!("[{}]", list.iter().map(compact).collect::<Vec<_>>().join(", ")),
            Value::Object(map) => {
                let entries: Vec<String> = ordered(map)
                    .into_iter()
                    .map(|(k, v)| format!("{}: {}", Value::String(k.clone()), compact(v)))
                    .collect();
                format!("{{{}}}", entries.join(", "))
            }
            other => other.to_string(),
        }
    }
    fn ordered(map: &serde_json::Map<String, Value>) -> Vec<(&String, &Value)> {
        let mut entries: Vec<_> = map.iter().collect();
        let rank = |key: &str| (key == "polygons", KEY_ORDER.iter().position(|k| *k == key).unwrap_or(KEY_ORDER.len()));
        entries.sort_by(|a, b| rank(a.0).cmp(&rank(b.0)).then(a.0.cmp(b.0)));
        entries
    }
    let Value::Object(map) = scene else { return compact(scene) };
    let lines: Vec<String> = ordered(map)
        .into_iter()
        .map(|(key, value)| match value {
            Value::Array(polygons) if key == "polygons" && !polygons.is_empty() => {
                let rows: Vec<String> = polygons.iter().map(|p| format!("    {}", compact(p))).collect();
                format!("  \"polygons\": [\n{}\n  ]", rows.join(",\n"))
            }
            _ => format!("  {}: {}", Value::String(key.clone()), compact(value)),
        })
        .collect();
    format!("{{\n{}\n}}\n", lines.join(",\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SMALL: &str =
        r#"{"width": 4, "height": 3, "polygons": [{"value": 1, "vertices": [[0, 0, 1], [4, 0, 1], [0, 3, 1]]}]}"#;

    fn vertices(text: &str) -> Value {
        serde_json::from_str::<Value>(text).unwrap()["polygons"][0]["vertices"].clone()
    }

    /// A drag is given in the page's coordinates (y down from the top) and
    /// snapped here; polygons and vertices are numbered from 1.
    #[test]
    fn a_drag_snaps_and_turns_the_pages_y_into_the_scenes() {
        let drag = |to: [f64; 2], snap: &str| {
            let change = serde_json::json!({"op": "drag", "polygon": 1, "vertex": 3, "to": to, "snap": snap});
            vertices(&edit(Lang::En, SMALL, &change.to_string()).unwrap())[2].to_string()
        };
        assert_eq!(drag([1.3, 0.4], "1"), "[1,3,1]");
        assert_eq!(drag([1.3, 0.4], "0.5"), "[1.5,2.5,1]");
        assert_eq!(drag([1.3, 0.4], "0.25"), "[1.25,2.5,1]");
        assert_eq!(drag([1.33, 0.44], "0.1"), "[1.3,2.6,1]");
        let off = serde_json::json!({"op": "drag", "polygon": 2, "vertex": 1, "to": [0, 0], "snap": "1"});
        assert_eq!(
            edit(Lang::En, SMALL, &off.to_string()),
            Err("That change does not fit this scene's JSON.".to_string())
        );
    }

    /// A vertex added repeats the last; one removed is the last; a polygon
    /// added is a triangle across the middle of the raster as it is drawn.
    #[test]
    fn vertices_and_polygons_are_added_where_the_library_says() {
        let added = edit(Lang::En, SMALL, r#"{"op": "add-vertex", "polygon": 1}"#).unwrap();
        assert_eq!(vertices(&added).as_array().unwrap().len(), 4);
        assert_eq!(vertices(&added)[3], vertices(SMALL)[2]);
        let removed = edit(Lang::En, SMALL, r#"{"op": "remove-vertex", "polygon": 1}"#).unwrap();
        assert_eq!(vertices(&removed).as_array().unwrap().len(), 2);
        let polygon = edit(Lang::En, SMALL, r#"{"op": "add-polygon"}"#).unwrap();
        let second = &serde_json::from_str::<Value>(&polygon).unwrap()["polygons"][1];
        assert_eq!(second.to_string(), r#"{"value":1,"vertices":[[1.0,1.0,1],[2.0,2.0,1],[3.0,1.0,1]]}"#);
        crate::shape_snapshot("playground_new_polygon", &NewPolygon::within(32, 32));
    }
}
