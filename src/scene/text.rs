//! Text at the edges: reading input files (a UTF-8 byte-order mark, as
//! Windows Notepad writes it, is skipped), and showing text that came from a
//! file without letting it steer the terminal.

use crate::words::Lang;
use std::borrow::Cow;
use std::io::Read;
use std::path::Path;

use crate::error::{Error, FileKind};

/// The largest input file zsim reads, 1 GiB: far above any real scene (the
/// 100,000-triangle benchmark scene is 12 MB) or answer, and a bound on the
/// memory a file can make zsim take.
pub const MAX_INPUT_BYTES: u64 = 1 << 30;

/// Whether a symbolic link is followed: a path the user names is; a file
/// found inside a folder others fill (a class folder) is not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Links {
    /// Follow it to what it points at.
    Follow,
    /// Refuse it, reading nothing through it.
    Refuse,
}

/// Reads a whole input file as UTF-8, skipping a leading byte-order mark;
/// `-` reads standard input, as Unix tools do. Every file zsim reads (scenes,
/// answers, course files) comes through here or [`read_bytes`].
pub fn read_text(lang: Lang, path: &Path) -> Result<String, Error> {
    read_text_with(lang, path, Links::Follow)
}

/// [`read_text`], refusing a symbolic link when `links` says so.
pub fn read_text_with(lang: Lang, path: &Path, links: Links) -> Result<String, Error> {
    let bytes = read_bytes(path, links)?;
    let mut text = String::from_utf8(bytes).map_err(|_| Error::Read {
        path: path.to_owned(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, words!(lang, "error-not-utf8")),
    })?;
    if text.starts_with('\u{feff}') {
        text.drain(..'\u{feff}'.len_utf8());
    }
    Ok(text)
}

/// Reads a whole input file: a regular file only (a FIFO, device or folder is
/// refused before anything is read, so nothing blocks), at most
/// [`MAX_INPUT_BYTES`] (checked from its length and again while reading, for
/// files that grow or lie about it), and a symbolic link only where `links`
/// follows it. `-` reads standard input, with the same bound.
pub fn read_bytes(path: &Path, links: Links) -> Result<Vec<u8>, Error> {
    let failed = |source| Error::Read { path: path.to_owned(), source };
    let mut bytes = Vec::new();
    if path == Path::new("-") {
        std::io::stdin().lock().take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes).map_err(failed)?;
    } else {
        if links == Links::Refuse && std::fs::symlink_metadata(path).map_err(failed)?.file_type().is_symlink() {
            return Err(Error::NotRegular { path: path.to_owned(), kind: FileKind::Link });
        }
        let file = open_without_blocking(path).map_err(failed)?;
        let metadata = file.metadata().map_err(failed)?;
        if !metadata.is_file() {
            return Err(Error::NotRegular { path: path.to_owned(), kind: FileKind::of(&metadata.file_type()) });
        }
        if metadata.len() > MAX_INPUT_BYTES {
            return Err(Error::TooLarge { path: path.to_owned(), limit: MAX_INPUT_BYTES });
        }
        match read_in_halves(&file, metadata.len()) {
            Some(read) => bytes = read,
            None => {
                // Room for the length it claims (and one byte more, to see it grow), in one allocation.
                bytes.reserve_exact(metadata.len() as usize + 1);
                let mut file = file;
                std::io::Seek::rewind(&mut file).map_err(failed)?;
                file.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes).map_err(failed)?;
            }
        }
    }
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(Error::TooLarge { path: path.to_owned(), limit: MAX_INPUT_BYTES });
    }
    Ok(bytes)
}

/// Files at least this long are read in two halves at once, where the
/// system allows it: copying a file out of the page cache into fresh memory
/// takes a core's time.
const READ_IN_HALVES: u64 = 1 << 22;

/// A file of `length` bytes read in two halves on two threads, when it is
/// that long and still exactly that long once read; `None` otherwise (a file
/// that grew or shrank meanwhile, or a read that failed), and the caller
/// reads it from the start as it reads any file.
#[cfg(unix)]
fn read_in_halves(file: &std::fs::File, length: u64) -> Option<Vec<u8>> {
    use std::os::unix::fs::FileExt;
    if length < READ_IN_HALVES {
        return None;
    }
    let mut bytes = vec![0; usize::try_from(length).ok()?];
    let half = bytes.len() / 2;
    let (first, second) = bytes.split_at_mut(half);
    let (first, second) = rayon::join(|| file.read_exact_at(first, 0), || file.read_exact_at(second, half as u64));
    let mut past_the_end = [0];
    (first.is_ok() && second.is_ok() && file.read_at(&mut past_the_end, length).ok()? == 0).then_some(bytes)
}

#[cfg(not(unix))]
fn read_in_halves(_file: &std::fs::File, _length: u64) -> Option<Vec<u8>> {
    None
}

/// Opens a file for reading without waiting for a writer: opening a FIFO
/// blocks until one comes, so on Linux it is opened non-blocking (which
/// changes nothing for a regular file) and refused by its type before any
/// read.
fn open_without_blocking(path: &Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
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

    /// A long file is read in halves, and whole; one that is not the length
    /// it was (grown, or shrunk) is left to the reading from the start.
    #[test]
    fn a_long_file_is_read_in_halves_only_at_its_length() {
        let path = std::env::temp_dir().join(format!("zsim-halves-{}.txt", std::process::id()));
        let content: Vec<u8> = (0..READ_IN_HALVES + 12_345).map(|i| (i % 251) as u8).collect();
        std::fs::write(&path, &content).unwrap();
        let file = std::fs::File::open(&path).unwrap();
        let length = content.len() as u64;
        assert!(read_in_halves(&file, length) == Some(content.clone()));
        assert!(read_in_halves(&file, length - 1).is_none(), "grown since its length was taken");
        assert!(read_in_halves(&file, length + 1).is_none(), "shrunk since its length was taken");
        assert_eq!(read_bytes(&path, Links::Follow).unwrap(), content);
        std::fs::remove_file(&path).unwrap();
    }

    #[test]
    fn control_characters_are_escaped_and_others_kept() {
        assert_eq!(printable("a\nb\u{7}"), "a\\u{a}b\\u{7}");
        assert_eq!(printable("треугольник 三角形"), "треугольник 三角形");
    }
}
