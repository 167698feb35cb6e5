//! A scene's polygon list cut in pieces, each gone through on a core of
//! its own.
//!
//! The plain way ([`super::read`]'s fallback) finds each polygon's text in
//! one pass of serde over the whole file, on one thread, before the polygons
//! are read and made on every core. Here the list is cut in pieces gone
//! through at once, each finding where its polygons' texts start and end (a
//! polygon's `{` to the first `}` outside a string). A piece starts at the
//! first place after its cut that looks like a polygon's start (a `{` after
//! a `,`) and goes on until it reaches the next piece's start. Then, from
//! the list's first polygon on, the pieces are joined: a piece is taken only
//! where the one before it ended exactly at its start. A start that was not
//! one (a `{` after a `,` inside a name) is never reached that way, and the
//! stretch it began is gone through again on this thread. So the texts are
//! those a pass from the start finds, and each is read and made as the plain
//! way reads and makes it; a text found wrongly does not read.
//!
//! Only the common shape takes this way: `"polygons"` the file's last key,
//! and every polygon valid. Anything else (a setting after the polygons, a
//! polygon that does not read or is not valid, JSON that does not parse)
//! gives `None`, and the plain way reads the file and names the error.

use std::path::Path;

use rayon::prelude::*;

use super::{JSON_SPACE, SceneFile, after_space, from_text, with_made};
use crate::scene::Scene;

/// The text a piece goes through, at least: a few dozen pieces on a large
/// scene keep every core busy to the end.
const PIECE_BYTES: usize = 1 << 18;

/// The longest polygon text a piece reads past its end (about 8,000
/// vertices); a longer polygon there is read the plain way. So each piece
/// looks at no more than its own text and this much, even from a false start
/// in a string that never ends.
const LONGEST_POLYGON: usize = 1 << 18;

/// The scene, its polygons found in pieces on every core; `None` when the
/// file is not of the common shape or has an error (see the module's doc),
/// and in WebAssembly, which has one core: there the plain way reads it.
pub(super) fn read(text: &str, path: &Path) -> Option<Scene> {
    if cfg!(target_arch = "wasm32") {
        return None;
    }
    read_in(text, path, PIECE_BYTES)
}

/// [`read`] in pieces of `piece_bytes` or more.
pub(super) fn read_in(text: &str, path: &Path, piece_bytes: usize) -> Option<Scene> {
    let (settings, first) = settings_before_polygons(text)?;
    let file: SceneFile<&serde_json::value::RawValue> = serde_json::from_str(&settings).ok()?;
    let (scene, frame, _) = file.settings(path).ok()?;
    let bytes = text.as_bytes();
    let starts = piece_starts(bytes, first, piece_bytes);
    // A piece reads up to the next piece's start; its last polygon may run on past it.
    let stop = |i: usize| starts.get(i + 1).copied().unwrap_or(usize::MAX);
    let limit = |i: usize| stop(i).saturating_add(LONGEST_POLYGON);
    let mut pieces: Vec<Option<Piece>> =
        starts.par_iter().enumerate().map(|(i, &start)| Some(piece(bytes, start, stop(i), limit(i)))).collect();
    let mut polygons: Vec<&str> = Vec::new();
    let mut at = first;
    for i in 0.. {
        let piece = match pieces.get_mut(i).and_then(Option::take) {
            Some(piece) if piece.start == at => piece,
            // Its start was not a polygon's: go on from where the last piece ended.
            _ => self::piece(bytes, at, stop(i), limit(i)),
        };
        polygons.extend(piece.polygons.iter().map(|&(start, end)| &text[start..end]));
        match piece.end {
            End::Next(next) => at = next,
            End::Closed(end) => {
                // Nothing may follow the list but the file's closing brace.
                let brace = after_space(bytes, end);
                (bytes.get(brace) == Some(&b'}') && after_space(bytes, brace + 1) == bytes.len()).then_some(())?;
                break;
            }
            End::Failed => return None,
        }
    }
    with_made(scene, &frame, polygons, |text, index, frame| from_text(text, index, frame, path)).ok()
}

/// The settings written before the `"polygons"` key, as an object of their
/// own text with an empty polygon list (read as the plain way reads them),
/// and where the first polygon starts; `None` when there is no such key, or
/// its list is empty or not a list. Each key and value is read by serde;
/// only the punctuation between them is looked at here.
fn settings_before_polygons(text: &str) -> Option<(String, usize)> {
    let bytes = text.as_bytes();
    let mut settings = String::from("{");
    let mut at = after_space(bytes, 0);
    (bytes.get(at) == Some(&b'{')).then_some(())?;
    loop {
        let member = after_space(bytes, at + 1);
        let (key, after_key) = value_at::<String>(text, member)?;
        let colon = after_space(bytes, after_key);
        (bytes.get(colon) == Some(&b':')).then_some(())?;
        if key == "polygons" {
            let list = after_space(bytes, colon + 1);
            (bytes.get(list) == Some(&b'[')).then_some(())?;
            let first = after_space(bytes, list + 1);
            (bytes.get(first) != Some(&b']')).then_some(())?;
            settings.push_str(if settings.len() > 1 { r#","polygons":[]}"# } else { r#""polygons":[]}"# });
            return Some((settings, first));
        }
        let (serde::de::IgnoredAny, end) = value_at(text, colon + 1)?;
        if settings.len() > 1 {
            settings.push(',');
        }
        settings.push_str(&text[member..end]);
        at = after_space(bytes, end);
        (bytes.get(at) == Some(&b',')).then_some(())?;
    }
}

/// The JSON value that starts at `at` (after white space), read by serde,
/// and where it ends.
fn value_at<'a, T: serde::Deserialize<'a>>(text: &'a str, at: usize) -> Option<(T, usize)> {
    let mut json = serde_json::Deserializer::from_str(text.get(at..)?).into_iter::<T>();
    let value = json.next()?.ok()?;
    Some((value, at + json.byte_offset()))
}

/// Where each piece starts: the first polygon, then for each cut
/// `piece_bytes` (at least 1) after the last start, the first `{` after it
/// that follows a `,` (white space between).
fn piece_starts(bytes: &[u8], first: usize, piece_bytes: usize) -> Vec<usize> {
    let mut starts = vec![first];
    let mut cut = first + piece_bytes.max(1);
    while cut < bytes.len() {
        let Some(at) = polygon_start_from(bytes, cut) else { break };
        starts.push(at);
        cut = at + piece_bytes.max(1);
    }
    starts
}

/// The first `{` at or after `from` that follows a `,`: where a polygon after
/// another starts, unless it is inside a string.
fn polygon_start_from(bytes: &[u8], from: usize) -> Option<usize> {
    let mut at = from;
    loop {
        at += bytes.get(at..)?.iter().position(|&b| b == b'{')?;
        let before = bytes[..at].iter().rev().find(|b| !JSON_SPACE.contains(b));
        if before == Some(&b',') {
            return Some(at);
        }
        at += 1;
    }
}

/// The polygons one piece found, from its start on.
struct Piece {
    start: usize,
    /// Each polygon's text, from its `{` to just past its `}`.
    polygons: Vec<(usize, usize)>,
    end: End,
}

/// How a piece ended.
#[derive(Clone, Copy)]
enum End {
    /// At the next polygon's start, at or past the next piece's.
    Next(usize),
    /// At the end of the list, just past its `]`.
    Closed(usize),
    /// Where no object starts, or where something other than a `,` or the
    /// list's end follows one.
    Failed,
}

/// Finds polygon after polygon from `start`, until one starts at or past
/// `stop` or the list ends; nothing at or past `limit` is looked at, so that
/// a false start (in a string that does not end, say) cannot send every
/// piece to the end of the file.
fn piece(bytes: &[u8], start: usize, stop: usize, limit: usize) -> Piece {
    let bytes = &bytes[..limit.min(bytes.len())];
    let mut piece = Piece { start, polygons: Vec::new(), end: End::Failed };
    let mut at = start;
    piece.end = loop {
        if at >= stop {
            break End::Next(at);
        }
        let Some(end) = object_end(bytes, at) else { break End::Failed };
        piece.polygons.push((at, end));
        // White space, then a `,` and the next polygon's `{`, or the list's `]`.
        at = after_space(bytes, end);
        match bytes.get(at) {
            Some(b',') => at = after_space(bytes, at + 1),
            Some(b']') => break End::Closed(at + 1),
            _ => break End::Failed,
        }
    };
    piece
}

/// Just past the end of the object whose `{` is at `start`, found as the
/// first `}` outside a string: right for a polygon, which holds no object.
/// Any other text found this way (an object inside, a string that does not
/// end) does not read as a polygon, and then the plain way names the error;
/// a text that reads is a whole object, so its `}` is the one found.
fn object_end(bytes: &[u8], start: usize) -> Option<usize> {
    if bytes.get(start) != Some(&b'{') {
        return None;
    }
    let mut at = start + 1;
    loop {
        at += memchr::memchr2(b'"', b'}', &bytes[at..])?;
        if bytes[at] == b'}' {
            return Some(at + 1);
        }
        // A string: past its closing quote, over escapes.
        at += 1;
        loop {
            at += memchr::memchr2(b'"', b'\\', bytes.get(at..)?)?;
            if bytes[at] == b'"' {
                at += 1;
                break;
            }
            at += 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A polygon is looked for up to a piece's limit and no further: a text
    /// that ends only past it is left to the plain way.
    #[test]
    fn a_piece_looks_no_further_than_its_limit() {
        let text = format!(r#"{{"name": "{}", "value": 1, "vertices": []}}]"#, "x".repeat(100));
        let bytes = text.as_bytes();
        assert!(matches!(piece(bytes, 0, 10, bytes.len()).end, End::Closed(end) if end == bytes.len()));
        assert!(matches!(piece(bytes, 0, 10, 50).end, End::Failed));
    }
}
