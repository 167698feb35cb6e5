//! A change the page makes to the scene's JSON, and the layout it writes
//! the scene in: the editor's side of the playground, apart from what it
//! shows.

use serde_json::Value;

use crate::words::Lang;

/// A change the page makes to the scene's JSON: the value at `path` (keys
/// and 0-based indices from the top) set to `value` (JSON text; text that
/// is not JSON, such as `43/4`, is kept as a string, which the scene format
/// reads as an exact number), or removed, or a value inserted before an
/// index of an array.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(tag = "op", rename_all = "lowercase")]
pub enum Edit {
    /// Set the value at `path`.
    Set {
        /// Where.
        path: Vec<Value>,
        /// The new value as JSON text.
        value: String,
    },
    /// Insert `value` before index `path`'s last entry of an array (at the end when past it).
    Insert {
        /// Where.
        path: Vec<Value>,
        /// The value as JSON text.
        value: String,
    },
    /// Remove the value at `path`.
    Remove {
        /// Where.
        path: Vec<Value>,
    },
}

/// The scene text after `edit` (given as JSON), laid out as [`layout`]
/// does; `Err` worded in `lang` when the text is not JSON or the edit does
/// not fit it.
pub fn edit(lang: Lang, text: &str, edit: &str) -> Result<String, String> {
    let not_json = |e: serde_json::Error| words!(lang, "scene-not-json", reason = e.to_string());
    let mut scene: Value = serde_json::from_str(text).map_err(not_json)?;
    let edit: Edit = serde_json::from_str(edit).map_err(|_| words!(lang, "edit-does-not-fit"))?;
    let value_of =
        |text: &str| serde_json::from_str(text.trim()).unwrap_or_else(|_| Value::String(text.trim().to_string()));
    let bad = || words!(lang, "edit-does-not-fit");
    let (last, path) = match &edit {
        Edit::Set { path, .. } | Edit::Insert { path, .. } | Edit::Remove { path } => {
            path.split_last().ok_or_else(bad)?
        }
    };
    let mut at = &mut scene;
    for step in path {
        at = match (at, step) {
            (Value::Object(map), Value::String(key)) => map.get_mut(key).ok_or_else(bad)?,
            (Value::Array(list), Value::Number(n)) => {
                list.get_mut(n.as_u64().ok_or_else(bad)? as usize).ok_or_else(bad)?
            }
            _ => return Err(bad()),
        };
    }
    match (at, last, &edit) {
        (Value::Object(map), Value::String(key), Edit::Set { value, .. }) => {
            map.insert(key.clone(), value_of(value));
        }
        (Value::Object(map), Value::String(key), Edit::Remove { .. }) => {
            map.remove(key);
        }
        (Value::Array(list), Value::Number(n), edit) => {
            let index = n.as_u64().ok_or_else(bad)? as usize;
            match edit {
                Edit::Set { value, .. } => *list.get_mut(index).ok_or_else(bad)? = value_of(value),
                Edit::Insert { value, .. } => list.insert(index.min(list.len()), value_of(value)),
                Edit::Remove { .. } if index < list.len() => drop(list.remove(index)),
                Edit::Remove { .. } => return Err(bad()),
            }
        }
        _ => return Err(bad()),
    }
    Ok(layout(&scene))
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
