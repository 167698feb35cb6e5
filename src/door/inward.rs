//! The one way in: every file zsim reads, a path a user gives or a name
//! found inside a file, is read here (a UTF-8 byte-order mark, as Windows
//! Notepad writes it, is skipped from text).

use crate::words::Lang;
use std::io::Read;
use std::path::{Path, PathBuf};

use crate::error::{Error, FileKind};

/// The largest input file zsim reads, 64 MiB: five times the
/// 100,000-triangle benchmark scene (12 MB), an answer for a 4096 × 4096
/// framebuffer, and a bound on the memory a file can make zsim take (a
/// scene takes about four times its file's size once read: the guide's
/// Safety chapter has the figures).
pub const MAX_INPUT_BYTES: u64 = 64 << 20;

/// The most pixels an image zsim reads may declare (a CS 418 texture, a
/// `--compare` reference): 4096 × 4096, 64 MiB as 8-bit RGBA. Checked from
/// the PNG header before anything is decoded, so a small file declaring a
/// huge image is refused without taking memory.
pub const MAX_IMAGE_PIXELS: u64 = 4096 * 4096;

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
pub fn read_text(path: &Path) -> Result<String, Error> {
    read_text_with(path, Links::Follow)
}

/// [`read_text`], refusing a symbolic link when `links` says so.
pub fn read_text_with(path: &Path, links: Links) -> Result<String, Error> {
    let bytes = read_bytes(path, links)?;
    let mut text = String::from_utf8(bytes).map_err(|_| Error::NotText { path: path.to_owned() })?;
    if text.starts_with('\u{feff}') {
        text.drain(..'\u{feff}'.len_utf8());
    }
    Ok(text)
}

/// Which file a file is, as the system knows it (device and inode on Unix):
/// two paths to one file, by a symbolic or a hard link, are one identity.
/// It holds the file open, so the identity cannot be reused meanwhile.
#[derive(Debug, PartialEq, Eq, Hash)]
pub struct Identity(same_file::Handle);

/// A file's identity as numbers (device and inode on Unix), kept without
/// keeping the file open: what a plan of thousands of files compares in a set.
pub type FileKey = (u64, u64);

impl Identity {
    /// The identity of the file at `path`; `None` when there is none to open.
    /// Opening it never waits (a FIFO is opened without blocking).
    pub fn of(path: &Path) -> Option<Identity> {
        let file = open_without_blocking(path).ok()?;
        same_file::Handle::from_file(file).ok().map(Identity)
    }

    /// The identity of zsim's standard input, where it is a file: an output
    /// must not be written onto what `-` reads.
    pub fn stdin() -> Option<Identity> {
        same_file::Handle::stdin().ok().filter(|_| std_is_file(0)).map(Identity)
    }

    /// The identity of zsim's standard output.
    pub fn stdout() -> Option<Identity> {
        same_file::Handle::stdout().ok().map(Identity)
    }

    /// The identity of zsim's standard error.
    pub fn stderr() -> Option<Identity> {
        same_file::Handle::stderr().ok().map(Identity)
    }

    /// The identity as numbers.
    pub fn key(&self) -> FileKey {
        #[cfg(unix)]
        {
            (self.0.dev(), self.0.ino())
        }
        #[cfg(not(unix))]
        {
            // Without device and inode numbers: the handle's hash, which same-file makes of them.
            use std::hash::{Hash, Hasher};
            let mut hasher = std::collections::hash_map::DefaultHasher::new();
            self.0.hash(&mut hasher);
            (hasher.finish(), 0)
        }
    }
}

/// Whether descriptor `fd` (0, 1, 2) is a regular file.
fn std_is_file(fd: i32) -> bool {
    #[cfg(unix)]
    {
        let link = std::fs::metadata(format!("/proc/self/fd/{fd}"));
        link.is_ok_and(|m| m.is_file())
    }
    #[cfg(not(unix))]
    {
        let _ = fd;
        false
    }
}

/// A folder whose files are named inside another file (a CS 418 case's
/// textures, a class folder's entries): every name is opened relative to a
/// handle on the folder, and must stay inside it.
pub struct Folder {
    path: PathBuf,
    #[cfg(not(target_arch = "wasm32"))]
    dir: cap_std::fs::Dir,
}

impl Folder {
    /// The folder at `path`.
    pub fn open(path: &Path) -> Result<Folder, Error> {
        #[cfg(target_arch = "wasm32")]
        return Err(Error::Read { path: path.to_owned(), source: std::io::ErrorKind::Unsupported.into() });
        #[cfg(not(target_arch = "wasm32"))]
        let dir = cap_std::fs::Dir::open_ambient_dir(path, cap_std::ambient_authority())
            .map_err(|source| Error::Read { path: path.to_owned(), source })?;
        #[cfg(not(target_arch = "wasm32"))]
        Ok(Folder { path: path.to_owned(), dir })
    }

    /// The folder that holds the file at `path`.
    pub fn beside(path: &Path) -> Result<Folder, Error> {
        let parent = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        Folder::open(parent)
    }

    /// The path of `name` in this folder, as messages show it.
    pub fn path_of(&self, name: &str) -> PathBuf {
        self.path.join(name)
    }

    /// Reads the file `name` names in this folder, with the rules of
    /// [`read_bytes`]: a plain relative name (no `..`, no absolute path), not
    /// a symbolic link, a regular file within [`MAX_INPUT_BYTES`]. Its
    /// identity comes with it, from the file read.
    pub fn read(&self, name: &str) -> Result<(Vec<u8>, Identity), Error> {
        let path = self.path_of(name);
        let relative = Path::new(name);
        let plain = !name.is_empty()
            && relative
                .components()
                .all(|part| matches!(part, std::path::Component::Normal(_) | std::path::Component::CurDir));
        if !plain {
            return Err(Error::OutsideFolder { path, folder: self.path.clone() });
        }
        #[cfg(target_arch = "wasm32")]
        return Err(Error::Read { path, source: std::io::ErrorKind::Unsupported.into() });
        #[cfg(not(target_arch = "wasm32"))]
        self.read_plain(path, relative)
    }

    /// [`Folder::read`] of a name known to be plain.
    #[cfg(not(target_arch = "wasm32"))]
    fn read_plain(&self, path: PathBuf, relative: &Path) -> Result<(Vec<u8>, Identity), Error> {
        let failed = |source| Error::Read { path: path.clone(), source };
        let metadata = self.dir.symlink_metadata(relative).map_err(failed)?;
        if metadata.is_symlink() {
            return Err(Error::NotRegular { path, kind: FileKind::Link });
        }
        let mut options = cap_std::fs::OpenOptions::new();
        options.read(true);
        #[cfg(target_os = "linux")]
        {
            use cap_std::fs::OpenOptionsExt;
            options.custom_flags(libc::O_NONBLOCK);
        }
        let file = self.dir.open_with(relative, &options).map_err(failed)?.into_std();
        let bytes = read_open_file(&path, &file)?;
        let identity = same_file::Handle::from_file(file).map_err(failed)?;
        Ok((bytes, Identity(identity)))
    }
}

/// A PNG reader for `bytes` once its header is known to declare at most
/// [`MAX_IMAGE_PIXELS`] pixels; decoding is also capped at what that many
/// 16-bit RGBA pixels take. Expands every colour type to 8 bits with alpha.
/// `Err` says why not.
pub fn png_reader(bytes: &[u8]) -> Result<png::Reader<std::io::Cursor<&[u8]>>, PngProblem> {
    let mut decoder = png::Decoder::new_with_limits(
        std::io::Cursor::new(bytes),
        png::Limits { bytes: (MAX_IMAGE_PIXELS * 8) as usize },
    );
    decoder.set_transformations(png::Transformations::normalize_to_color8() | png::Transformations::ALPHA);
    let header = decoder.read_header_info().map_err(|e| PngProblem::NotAnImage { reason: e.to_string() })?;
    if u64::from(header.width) * u64::from(header.height) > MAX_IMAGE_PIXELS {
        return Err(PngProblem::TooManyPixels { width: header.width, height: header.height });
    }
    decoder.read_info().map_err(|e| PngProblem::NotAnImage { reason: e.to_string() })
}

/// Why a PNG is not read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PngProblem {
    /// Not a PNG image: what the decoder said.
    NotAnImage {
        /// The decoder's words.
        reason: String,
    },
    /// An image that declares more than [`MAX_IMAGE_PIXELS`] pixels.
    TooManyPixels {
        /// Its declared width.
        width: u32,
        /// Its declared height.
        height: u32,
    },
    /// An image whose decoded pixels would not fit in memory's addresses.
    TooLarge,
    /// A broken image: what the decoder said.
    Broken {
        /// The decoder's words.
        reason: String,
    },
    /// A colour type the decoder does not expand to RGBA.
    ColourType {
        /// The type, as the decoder names it.
        kind: String,
    },
}

impl PngProblem {
    /// The problem in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            PngProblem::NotAnImage { reason } => words!(lang, "png-not-an-image", reason = reason.as_str()),
            PngProblem::TooManyPixels { width, height } => words!(
                lang,
                "png-declares-too-many-pixels",
                width = width.to_string(),
                height = height.to_string(),
                max = MAX_IMAGE_PIXELS.to_string()
            ),
            PngProblem::TooLarge => words!(lang, "png-too-large"),
            PngProblem::Broken { reason } => words!(lang, "png-broken", reason = reason.as_str()),
            PngProblem::ColourType { kind } => words!(lang, "png-colour-type", kind = kind.as_str()),
        }
    }
}

/// Reads a whole input file: a regular file only (a FIFO, device or folder is
/// refused before anything is read, so nothing blocks), at most
/// [`MAX_INPUT_BYTES`] (checked from its length and again while reading, for
/// files that grow or lie about it), and a symbolic link only where `links`
/// follows it. `-` reads standard input, with the same bound.
pub fn read_bytes(path: &Path, links: Links) -> Result<Vec<u8>, Error> {
    let failed = |source| Error::Read { path: path.to_owned(), source };
    if path == Path::new("-") {
        let mut bytes = Vec::new();
        std::io::stdin().lock().take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes).map_err(failed)?;
        return within_limit(path, bytes);
    }
    if links == Links::Refuse && std::fs::symlink_metadata(path).map_err(failed)?.file_type().is_symlink() {
        return Err(Error::NotRegular { path: path.to_owned(), kind: FileKind::Link });
    }
    let file = open_without_blocking(path).map_err(failed)?;
    read_open_file(path, &file)
}

/// `bytes`, read from `path`, unless they pass [`MAX_INPUT_BYTES`].
fn within_limit(path: &Path, bytes: Vec<u8>) -> Result<Vec<u8>, Error> {
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(Error::TooLarge { path: path.to_owned(), limit: MAX_INPUT_BYTES });
    }
    Ok(bytes)
}

/// Reads an opened file whole, as [`read_bytes`] says: a regular file only,
/// within [`MAX_INPUT_BYTES`] by its length and while reading.
fn read_open_file(path: &Path, file: &std::fs::File) -> Result<Vec<u8>, Error> {
    let failed = |source| Error::Read { path: path.to_owned(), source };
    let metadata = file.metadata().map_err(failed)?;
    if !metadata.is_file() {
        return Err(Error::NotRegular { path: path.to_owned(), kind: FileKind::of(&metadata.file_type()) });
    }
    if metadata.len() > MAX_INPUT_BYTES {
        return Err(Error::TooLarge { path: path.to_owned(), limit: MAX_INPUT_BYTES });
    }
    let bytes = match read_in_halves(file, metadata.len()) {
        Some(read) => read,
        None => {
            // Room for the length it claims (and one byte more, to see it grow), in one allocation.
            let mut bytes = Vec::with_capacity(metadata.len() as usize + 1);
            let mut file = file;
            std::io::Seek::rewind(&mut file).map_err(failed)?;
            file.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes).map_err(failed)?;
            bytes
        }
    };
    within_limit(path, bytes)
}

/// Files at least this long are read in two halves at once, where the
/// system allows it: copying a file out of the page cache into fresh memory
/// takes a core's time.
#[cfg(unix)]
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

#[cfg(all(test, unix))]
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
}

/// A line read from a stream within a bound, or why it is not one.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Line {
    /// A line of text, without its line end (`\n` or `\r\n`).
    Text(String),
    /// A line that is not UTF-8.
    NotText,
    /// A line longer than the bound: what is past it is not read.
    TooLong,
}

/// The next line of `reader`, holding at most `max` bytes of it (a stream
/// of no line end, as `/dev/zero`, costs `max` bytes, not all memory);
/// `None` at the end.
pub fn read_line_within(reader: &mut impl std::io::BufRead, max: usize) -> std::io::Result<Option<Line>> {
    let mut bytes = Vec::new();
    let read = std::io::BufRead::read_until(&mut std::io::Read::take(reader, max as u64 + 1), b'\n', &mut bytes)?;
    if read == 0 {
        return Ok(None);
    }
    if bytes.last() == Some(&b'\n') {
        bytes.pop();
        if bytes.last() == Some(&b'\r') {
            bytes.pop();
        }
    } else if bytes.len() > max {
        return Ok(Some(Line::TooLong));
    }
    Ok(Some(String::from_utf8(bytes).map_or(Line::NotText, Line::Text)))
}
