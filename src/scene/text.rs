//! Text at the edges: reading input files (a UTF-8 byte-order mark, as
//! Windows Notepad writes it, is skipped), and showing text that came from a
//! file without letting it steer the terminal.

use std::borrow::Cow;
use std::path::Path;

use crate::error::Error;

/// Reads a whole input file as UTF-8, skipping a leading byte-order mark;
/// `-` reads standard input, as Unix tools do. Every file zsim reads (scenes,
/// answers, course files) comes through here.
pub fn read_text(path: &Path) -> Result<String, Error> {
    let read = || {
        if path == Path::new("-") { std::io::read_to_string(std::io::stdin()) } else { std::fs::read_to_string(path) }
    };
    let mut text = read().map_err(|source| Error::Read { path: path.to_owned(), source })?;
    if text.starts_with('\u{feff}') {
        text.drain(..'\u{feff}'.len_utf8());
    }
    Ok(text)
}

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped_and_others_kept() {
        assert_eq!(printable("a\nb\u{7}"), "a\\u{a}b\\u{7}");
        assert_eq!(printable("треугольник 三角形"), "треугольник 三角形");
    }
}
