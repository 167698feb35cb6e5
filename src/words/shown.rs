//! Showing text that came from outside (a name in a file, a path, an
//! environment variable) without letting it steer the terminal or break a
//! one-line message.

use std::borrow::Cow;
use std::path::Path;

/// The text with every control character (escape, bell, newline, …) written
/// as Rust writes it, `\u{1b}`, so that a name from a scene file can neither
/// retitle nor recolour a terminal, nor break a one-line message.
///
/// ```
/// assert_eq!(zsim::printable("\u{1b}[31mred"), "\\u{1b}[31mred");
/// assert_eq!(zsim::printable("plain"), "plain");
/// ```
pub fn printable(text: &str) -> Cow<'_, str> {
    if !text.chars().any(char::is_control) {
        return Cow::Borrowed(text);
    }
    Cow::Owned(
        text.chars().map(|c| if c.is_control() { c.escape_unicode().to_string() } else { c.to_string() }).collect(),
    )
}

/// A path as a message shows it: each byte that is not UTF-8 written as
/// `\xff` (so that two names that differ only there stay two, where U+FFFD
/// would merge them), its control characters escaped as [`printable`]
/// escapes them (a file named `\u{1b}]0;x\u{7}.json` cannot retitle the
/// terminal).
///
/// ```
/// use std::path::Path;
/// assert_eq!(zsim::shown_path(Path::new("a\u{1b}[2J.json")), "a\\u{1b}[2J.json");
/// ```
pub fn path(path: &Path) -> String {
    match path.to_str() {
        Some(text) => printable(text).into_owned(),
        None => bytes(path.as_os_str().as_encoded_bytes()),
    }
}

/// Bytes as text: the UTF-8 runs as [`printable`] shows them, every other byte as `\xff`.
fn bytes(bytes: &[u8]) -> String {
    let mut shown = String::new();
    for chunk in bytes.utf8_chunks() {
        shown.push_str(&printable(chunk.valid()));
        for byte in chunk.invalid() {
            shown.push_str(&format!("\\x{byte:02x}"));
        }
    }
    shown
}

/// A file's name as a message shows it, without its folder (where a class
/// folder or an autograder keeps it is nobody's business): [`path`] of the
/// last component, or of the whole path when it has none.
pub fn name(file: &Path) -> String {
    path(file.file_name().map_or(file, Path::new))
}

/// A file's own name as a path (`class/ana.frame.txt` → `ana.frame.txt`):
/// how a student's report names the files they handed in, never where the
/// teacher keeps them.
pub fn own_name(path: &std::path::Path) -> &std::path::Path {
    path.file_name().map_or(path, std::path::Path::new)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped_and_others_kept() {
        assert_eq!(printable("a\nb\u{7}"), "a\\u{a}b\\u{7}");
        assert_eq!(printable("треугольник 三角形"), "треугольник 三角形");
    }

    /// Found by a careless teacher: two students whose names differed only in
    /// bytes that are not UTF-8 were shown, and named, alike (U+FFFD).
    #[cfg(unix)]
    #[test]
    fn names_that_differ_in_bytes_not_utf8_are_shown_apart() {
        use std::os::unix::ffi::OsStrExt;
        let (a, b) = (std::ffi::OsStr::from_bytes(b"Kl\xe4sse"), std::ffi::OsStr::from_bytes(b"Kl\xe5sse"));
        assert_eq!(path(Path::new(a)), "Kl\\xe4sse");
        assert_ne!(path(Path::new(a)), path(Path::new(b)));
        assert_eq!(path(Path::new(std::ffi::OsStr::from_bytes(b"\xff\x1b.json"))), "\\xff\\u{1b}.json");
    }

    #[test]
    fn a_path_is_shown_escaped() {
        assert_eq!(path(Path::new("x/\u{1b}]0;owned\u{7}.json")), "x/\\u{1b}]0;owned\\u{7}.json");
    }
}
