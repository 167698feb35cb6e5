//! The one way out: everything a command writes is planned first, then
//! written atomically, never onto one of its inputs.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::inward::Identity;
use super::staged::{Staged, StagingFolder};
use crate::error::{Error, Refusal};
use crate::words::{Lang, shown_path};

/// A command's outputs refused before anything is written: each with the
/// facts its message states.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum OutputRefused {
    /// An output in the folder the command reads, or an input itself.
    IsInput {
        /// The folder (or the input).
        folder: PathBuf,
    },
    /// An output whose name the file system cannot hold.
    NameTooLong {
        /// The path.
        path: PathBuf,
        /// The longest name, in bytes.
        max: usize,
    },
    /// One file planned twice.
    Twice {
        /// The file.
        path: PathBuf,
    },
    /// Files that would be replaced where a command replaces none.
    WouldReplace {
        /// Their folder.
        folder: PathBuf,
        /// Their names.
        files: Vec<String>,
    },
}

impl Refusal for OutputRefused {
    fn message(&self, lang: Lang) -> String {
        match self {
            OutputRefused::IsInput { folder } => words!(lang, "usage-output-is-input", path = shown_path(folder)),
            OutputRefused::NameTooLong { path, max } => {
                words!(lang, "usage-output-name-too-long", path = shown_path(path), max = max.to_string())
            }
            OutputRefused::Twice { path } => words!(lang, "usage-output-twice", path = shown_path(path)),
            OutputRefused::WouldReplace { folder, files } => {
                let shown: Vec<&str> = files.iter().take(5).map(String::as_str).collect();
                words!(
                    lang,
                    "usage-output-would-replace",
                    path = shown_path(folder),
                    files = shown.join(", "),
                    more = files.len().saturating_sub(5)
                )
            }
        }
    }
}

/// Whether a planned file may replace one that is there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Replace {
    /// It may (`-o FILE`: the user named the file).
    Allowed,
    /// It may not: the command makes a folder of files (feedback, an
    /// exercise) and replaces nothing; refused, before anything is written,
    /// when one is there.
    Never,
}

/// The longest file name the file systems zsim writes to accept, in bytes.
pub const MAX_NAME_BYTES: usize = 255;

/// The longest path the system opens, in bytes.
pub const MAX_PATH_BYTES: usize = 4095;

/// One file to write.
#[derive(Debug)]
struct Planned<'a> {
    path: PathBuf,
    contents: Contents<'a>,
    executable: bool,
}

/// What a planned file holds: its bytes, or what makes them, called when
/// the file is written (so that a command writing thousands of files, a
/// class's feedback, holds one at a time).
enum Contents<'a> {
    Bytes(Vec<u8>),
    Later(Box<dyn FnOnce() -> Result<Vec<u8>, Error> + 'a>),
}

impl Contents<'_> {
    /// The bytes, made now where they are made later.
    fn take(&mut self) -> Result<Vec<u8>, Error> {
        match std::mem::replace(self, Contents::Bytes(Vec::new())) {
            Contents::Bytes(bytes) => Ok(bytes),
            Contents::Later(make) => make(),
        }
    }
}

impl std::fmt::Debug for Contents<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Contents::Bytes(bytes) => write!(f, "{} bytes", bytes.len()),
            Contents::Later(_) => write!(f, "made when written"),
        }
    }
}

/// Everything one command writes, planned before the first byte is written.
///
/// [`Plan::write`] checks every file first: none is one of the command's
/// inputs or in one of its input folders (compared as files, by
/// [`Identity`], so another name or a hard link is caught), no two are the
/// same, each name fits the file system ([`MAX_NAME_BYTES`],
/// [`MAX_PATH_BYTES`]), and none replaces a file where [`Replace::Never`]
/// says so. Only then does it write each to a temporary file beside its
/// place and rename it there, with Ctrl-C, `SIGTERM` and `SIGHUP` held
/// until the last is in place, so an interrupted command leaves the old
/// files or none, never half of one.
#[derive(Debug)]
pub struct Plan<'a> {
    inputs: Vec<Identity>,
    files: Vec<Planned<'a>>,
    replace: Replace,
}

impl<'a> Plan<'a> {
    /// A plan that must not write onto any of `inputs` (files, or folders
    /// whose files it must not write into).
    pub fn new(inputs: &[&Path], replace: Replace) -> Plan<'a> {
        let mut inputs: Vec<Identity> = inputs.iter().filter_map(|p| Identity::of(p)).collect();
        // Standard input is an input too (`-`), where it is a file.
        inputs.extend(Identity::stdin());
        Plan { inputs, files: Vec::new(), replace }
    }

    /// One more input not to write onto, known by its identity (a file
    /// named inside another, read through [`super::Folder`]).
    pub fn input(&mut self, identity: Identity) {
        self.inputs.push(identity);
    }

    /// Plans `bytes` into the file at `path`.
    pub fn file(&mut self, path: impl Into<PathBuf>, bytes: impl Into<Vec<u8>>) {
        self.files.push(Planned { path: path.into(), contents: Contents::Bytes(bytes.into()), executable: false });
    }

    /// Plans the file at `path`, its bytes made by `make` when it is written
    /// (after the whole plan is checked), one file at a time.
    pub fn file_made(&mut self, path: impl Into<PathBuf>, make: impl FnOnce() -> Result<Vec<u8>, Error> + 'a) {
        self.files.push(Planned { path: path.into(), contents: Contents::Later(Box::new(make)), executable: false });
    }

    /// Plans an executable file (a script): mode 0777 less the umask on Unix.
    pub fn executable(&mut self, path: impl Into<PathBuf>, bytes: impl Into<Vec<u8>>) {
        self.files.push(Planned { path: path.into(), contents: Contents::Bytes(bytes.into()), executable: true });
    }

    /// Checks the whole plan, as [`Plan`] says, and tells which planned files
    /// are streams: an existing device or FIFO (`/dev/null`, `/dev/stdout`
    /// on a pipe), written into as it is, never replaced by a rename. A
    /// folder is refused.
    fn check(&self) -> Result<Vec<Stream>, Error> {
        let mut streams = Vec::with_capacity(self.files.len());
        let mut existing = Vec::new();
        // Each planned file's place, compared in a set (not each with every earlier one), and each
        // folder's identity looked up once: a class of 10,000 students plans 10,000 files.
        let mut places = std::collections::HashSet::with_capacity(self.files.len());
        let mut folders: std::collections::HashMap<&Path, Option<super::inward::FileKey>> =
            std::collections::HashMap::new();
        let own = Own::streams();
        let inputs: std::collections::HashSet<_> = self.inputs.iter().map(Identity::key).collect();
        for file in &self.files {
            let path = &file.path;
            let name = path.file_name().map_or(0, |n| n.len());
            if name == 0 || name > MAX_NAME_BYTES || path.as_os_str().len() > MAX_PATH_BYTES {
                return Err(OutputRefused::NameTooLong { path: path.clone(), max: MAX_NAME_BYTES }.into());
            }
            let folder = folder_of(path);
            // Each folder's key, not its open handle: a class of a thousand folders holds no thousand descriptors.
            let folder_key = *folders.entry(folder).or_insert_with(|| Identity::of(folder).map(|i| i.key()));
            if folder_key.is_some_and(|key| inputs.contains(&key)) {
                return Err(OutputRefused::IsInput { folder: folder.to_owned() }.into());
            }
            let identity = Identity::of(path);
            if identity.as_ref().is_some_and(|identity| inputs.contains(&identity.key())) {
                return Err(OutputRefused::IsInput { folder: path.clone() }.into());
            }
            let place = match (&identity, folder_key) {
                (Some(identity), _) => Place::File(identity.key()),
                (None, Some(folder)) => Place::InFolder(folder, path.file_name().unwrap_or_default().to_owned()),
                (None, None) => Place::Path(path.clone()),
            };
            if !places.insert(place) {
                return Err(OutputRefused::Twice { path: path.clone() }.into());
            }
            let followed = std::fs::metadata(path).ok();
            if followed.as_ref().is_some_and(std::fs::Metadata::is_dir) {
                let source = std::io::Error::new(std::io::ErrorKind::IsADirectory, "a folder");
                return Err(Error::Write { path: path.clone(), source });
            }
            // zsim's own standard output or error under another name (`-o /dev/stdout` redirected to
            // a file): written into, never renamed over (as root that replaced the link itself).
            // Or one of its open descriptors by its name (`/dev/fd/3`, `/proc/self/fd/3`): written
            // through the descriptor, at its offset (a file there cannot be renamed into).
            let stream = match identity.as_ref().and_then(|identity| own.which(identity)) {
                Some(which) => Stream::Own(which),
                None => match descriptor_named(path, &own) {
                    Some(descriptor) if followed.is_some() => Stream::Descriptor(descriptor),
                    _ if followed.is_some_and(|m| !m.is_file()) => Stream::Device,
                    _ => Stream::No,
                },
            };
            let is_file = stream == Stream::No;
            streams.push(stream);
            if is_file && std::fs::symlink_metadata(path).is_ok() {
                existing.push(path.clone());
            }
        }
        if self.replace == Replace::Never && !existing.is_empty() {
            let folder = folder_of(&existing[0]).to_owned();
            let files = existing.iter().map(|p| crate::words::shown_name(p)).collect();
            return Err(OutputRefused::WouldReplace { folder, files }.into());
        }
        Ok(streams)
    }

    /// Checks the plan, then writes it (see [`Plan`]); the paths written.
    pub fn write(self) -> Result<Vec<PathBuf>, Error> {
        let is_stream = self.check()?;
        let (replace, count) = (self.replace, self.files.len());
        let (streams, mut files): (Vec<_>, Vec<_>) =
            self.files.into_iter().zip(is_stream).partition(|(_, stream)| *stream != Stream::No);
        let _held = held::Interruptions::hold();
        let mut staged = Vec::with_capacity(files.len());
        // Each folder made and opened once, however many files go into it; its handle closed when
        // the files move on to another (a class writes a folder a student, more folders than a
        // process may hold open), reopened, and checked to be the same folder, when its files are
        // placed (the design note on a course has the class that found it).
        let mut folders: std::collections::HashMap<PathBuf, std::sync::Arc<StagingFolder>> =
            std::collections::HashMap::new();
        let mut open: Option<std::sync::Arc<StagingFolder>> = None;
        for (file, _) in &mut files {
            let path = folder_of(&file.path);
            let folder = match folders.get(path) {
                Some(folder) => std::sync::Arc::clone(folder),
                None => {
                    let failed = |source| Error::Write { path: path.to_owned(), source };
                    std::fs::create_dir_all(path).map_err(failed)?;
                    let folder = std::sync::Arc::new(StagingFolder::open(path).map_err(failed)?);
                    folders.insert(path.to_path_buf(), std::sync::Arc::clone(&folder));
                    folder
                }
            };
            if let Some(previous) =
                open.replace(std::sync::Arc::clone(&folder)).filter(|p| !std::sync::Arc::ptr_eq(p, &folder))
            {
                previous.close();
            }
            let failed = |source| Error::Write { path: file.path.clone(), source };
            // The mode a new file gets (0666, or 0777 for a script, less the umask), not a temporary file's 0600.
            let mode = if file.executable { 0o777 } else { 0o666 };
            let bytes = file.contents.take()?;
            let mut temporary = Staged::new(&folder, mode).map_err(failed)?;
            temporary.write_and_close(&bytes, !SYNC_BY_FILE_SYSTEM).map_err(failed)?;
            staged.push(temporary);
        }
        // Every staged file on disk before the first is renamed into place: on Linux one sync of
        // each folder's file system (a class's feedback is thousands of files), elsewhere each
        // file was synced as it was written.
        if SYNC_BY_FILE_SYSTEM {
            let mut synced = std::collections::HashSet::new();
            for (path, folder) in &folders {
                if synced.insert(folder.file_system()) {
                    folder.sync_file_system().map_err(|source| Error::Write { path: path.clone(), source })?;
                }
            }
        }
        let mut written = Vec::with_capacity(count);
        for ((file, _), temporary) in files.into_iter().zip(staged) {
            if let Some(previous) =
                open.replace(temporary.folder()).filter(|p| !std::sync::Arc::ptr_eq(p, &temporary.folder()))
            {
                previous.close();
            }
            let name = file.path.file_name().expect("a planned file has a name (checked)");
            if let Err(error) = temporary.place(name, replace == Replace::Allowed) {
                // Undo what this plan placed: it replaced nothing, so nothing is lost.
                if replace == Replace::Never {
                    for path in &written {
                        let _ = std::fs::remove_file(path);
                    }
                }
                return Err(Error::Write { path: file.path.clone(), source: error });
            }
            written.push(file.path.clone());
        }
        // Streams last: what is written into them cannot be taken back.
        for (mut file, stream) in streams {
            let bytes = file.contents.take()?;
            let failed = |source| Error::Write { path: file.path.clone(), source };
            match stream {
                Stream::Own(Which::Output) => std::io::stdout().lock().write_all(&bytes).map_err(failed)?,
                Stream::Own(Which::Error) => std::io::stderr().lock().write_all(&bytes).map_err(failed)?,
                Stream::Descriptor(descriptor) => write_descriptor(descriptor, &bytes).map_err(failed)?,
                _ => write_stream(&file.path, &bytes).map_err(failed)?,
            }
            written.push(file.path.clone());
        }
        Ok(written)
    }
}

/// Whether staged files are made durable by one sync of their file system
/// (Linux's `syncfs`) rather than one by one.
const SYNC_BY_FILE_SYSTEM: bool = cfg!(target_os = "linux");

/// Writes `bytes` into an existing device or FIFO, opened without waiting
/// for a reader (a FIFO nobody reads is an error, not a hang).
fn write_stream(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true);
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let mut file = options.open(path)?;
    #[cfg(target_os = "linux")]
    {
        // Back to blocking writes once open: a pipe's reader sets the pace.
        use std::os::fd::AsRawFd;
        // SAFETY: F_GETFL/F_SETFL on a descriptor this function owns.
        unsafe {
            let flags = libc::fcntl(file.as_raw_fd(), libc::F_GETFL);
            libc::fcntl(file.as_raw_fd(), libc::F_SETFL, flags & !libc::O_NONBLOCK);
        }
    }
    file.write_all(bytes)
}

/// The descriptor `path` names, if it is one of this process's open
/// descriptors by the folder that lists them (`/dev/fd/N`, `/proc/self/fd/N`).
fn descriptor_named(path: &Path, own: &Own) -> Option<i32> {
    let number: i32 = path.file_name()?.to_str()?.parse().ok()?;
    let listed = own.descriptors.as_ref()?;
    (std::fs::canonicalize(folder_of(path)).ok()? == *listed).then_some(number)
}

/// Writes `bytes` through this process's open descriptor `descriptor`, where
/// it stands (a shell's `3>>file` appends).
#[cfg(unix)]
fn write_descriptor(descriptor: i32, bytes: &[u8]) -> std::io::Result<()> {
    use std::os::fd::BorrowedFd;
    // SAFETY: the descriptor was found open (its name resolved to a file) while the plan was
    // checked, and nothing of zsim closes descriptors it did not open; it is borrowed only to be
    // duplicated, and the duplicate is what is written and closed.
    let borrowed = unsafe { BorrowedFd::borrow_raw(descriptor) };
    std::fs::File::from(borrowed.try_clone_to_owned()?).write_all(bytes)
}

#[cfg(not(unix))]
fn write_descriptor(_: i32, _: &[u8]) -> std::io::Result<()> {
    Err(std::io::ErrorKind::Unsupported.into())
}

/// Writes `files` (name, contents) into `folder` as one plan that replaces
/// nothing and writes nowhere among `inputs`: the folder of outputs most
/// commands make.
pub fn write_fresh(folder: &Path, files: &[(String, Vec<u8>)], inputs: &[&Path]) -> Result<Vec<PathBuf>, Error> {
    let mut plan = Plan::new(inputs, Replace::Never);
    for (name, bytes) in files {
        plan.file(folder.join(name), bytes.clone());
    }
    plan.write()
}

/// Whether two folders are one: the same folder if both exist, else the
/// same path.
pub fn same_folder(a: &Path, b: &Path) -> bool {
    match (Identity::of(a), Identity::of(b)) {
        (Some(a), Some(b)) => a == b,
        _ => a.components().eq(b.components()),
    }
}

/// The folder a path is in (`.` for a bare name).
fn folder_of(path: &Path) -> &Path {
    path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."))
}

/// Where a planned file goes, as a key: the file (device and inode) where it
/// is, else its folder's and its name, else its path.
#[derive(Debug, PartialEq, Eq, Hash)]
enum Place {
    File(super::inward::FileKey),
    InFolder(super::inward::FileKey, std::ffi::OsString),
    Path(PathBuf),
}

/// How a planned file is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Stream {
    /// A file: to a temporary file, then renamed into place.
    No,
    /// A device or FIFO: written into as it is.
    Device,
    /// zsim's own standard output or error: written through it.
    Own(Which),
    /// Another of zsim's open descriptors, named by its number: written through it.
    Descriptor(i32),
}

/// Which of zsim's own streams.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Which {
    Output,
    Error,
}

/// zsim's own standard output and error, as files, and the folder that
/// lists its open descriptors (Linux's `/proc/self/fd`, resolved).
struct Own {
    output: Option<Identity>,
    error: Option<Identity>,
    descriptors: Option<PathBuf>,
}

impl Own {
    fn streams() -> Own {
        let descriptors = std::fs::canonicalize("/proc/self/fd").ok();
        Own { output: Identity::stdout(), error: Identity::stderr(), descriptors }
    }

    /// Which of them `identity` is, if one.
    fn which(&self, identity: &Identity) -> Option<Which> {
        match (&self.output, &self.error) {
            (Some(output), _) if output == identity => Some(Which::Output),
            (_, Some(error)) if error == identity => Some(Which::Error),
            _ => None,
        }
    }
}

/// Interruptions held while a plan is written.
mod held {
    /// While one of these lives, `SIGINT`, `SIGTERM` and `SIGHUP` are only
    /// noted; when the last one goes, the former handlers come back and a
    /// signal noted meanwhile is raised again, so the process ends as it
    /// would have, after the files are in place.
    pub struct Interruptions(());

    #[cfg(unix)]
    mod unix {
        use std::sync::Mutex;
        use std::sync::atomic::{AtomicI32, Ordering};

        pub const SIGNALS: [libc::c_int; 3] = [libc::SIGINT, libc::SIGTERM, libc::SIGHUP];
        /// The signal noted while held (0: none).
        pub static NOTED: AtomicI32 = AtomicI32::new(0);
        /// How many holds are open, and the handlers they replaced.
        pub static HOLDS: Mutex<(usize, Vec<libc::sigaction>)> = Mutex::new((0, Vec::new()));

        pub extern "C" fn note(signal: libc::c_int) {
            NOTED.store(signal, Ordering::SeqCst);
        }
    }

    impl Interruptions {
        /// Holds interruptions until the value is dropped.
        pub fn hold() -> Interruptions {
            #[cfg(unix)]
            {
                let mut holds = unix::HOLDS.lock().unwrap_or_else(|e| e.into_inner());
                if holds.0 == 0 {
                    holds.1 = unix::SIGNALS
                        .iter()
                        .map(|&signal| {
                            // SAFETY: sigaction with a handler that only stores to an atomic,
                            // which is async-signal-safe; the old action is kept to restore.
                            unsafe {
                                let mut action: libc::sigaction = std::mem::zeroed();
                                action.sa_sigaction = unix::note as extern "C" fn(libc::c_int) as usize;
                                libc::sigemptyset(&mut action.sa_mask);
                                let mut old: libc::sigaction = std::mem::zeroed();
                                libc::sigaction(signal, &action, &mut old);
                                old
                            }
                        })
                        .collect();
                }
                holds.0 += 1;
            }
            Interruptions(())
        }
    }

    impl Drop for Interruptions {
        fn drop(&mut self) {
            #[cfg(unix)]
            {
                use std::sync::atomic::Ordering;
                let mut holds = unix::HOLDS.lock().unwrap_or_else(|e| e.into_inner());
                holds.0 -= 1;
                if holds.0 == 0 {
                    for (signal, old) in unix::SIGNALS.iter().zip(&holds.1) {
                        // SAFETY: puts back the action taken in `hold`.
                        unsafe { libc::sigaction(*signal, old, std::ptr::null_mut()) };
                    }
                    let noted = unix::NOTED.swap(0, Ordering::SeqCst);
                    if noted != 0 {
                        // SAFETY: raising a signal the process was sent, now with its own handler.
                        unsafe { libc::raise(noted) };
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("zsim-plan-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn a_hard_link_to_an_input_is_the_input() {
        let dir = scratch("hard-link");
        let (model, link) = (dir.join("m.obj"), dir.join("h.obj"));
        std::fs::write(&model, "v 0 0 0\n").unwrap();
        std::fs::hard_link(&model, &link).unwrap();
        let mut plan = Plan::new(&[&model], Replace::Allowed);
        plan.file(&link, "overwritten");
        assert!(matches!(plan.write().unwrap_err().refused(), Some(OutputRefused::IsInput { .. })));
        assert_eq!(std::fs::read_to_string(&model).unwrap(), "v 0 0 0\n");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn nothing_is_written_when_one_file_is_refused() {
        let dir = scratch("refused");
        std::fs::write(dir.join("b.txt"), "old").unwrap();
        let mut plan = Plan::new(&[], Replace::Never);
        plan.file(dir.join("a.txt"), "new");
        plan.file(dir.join("b.txt"), "new");
        assert!(matches!(plan.write().unwrap_err().refused(), Some(OutputRefused::WouldReplace { .. })));
        assert!(!dir.join("a.txt").exists());
        assert_eq!(std::fs::read_to_string(dir.join("b.txt")).unwrap(), "old");
        let mut plan = Plan::new(&[], Replace::Never);
        plan.file(dir.join(format!("{}.txt", "x".repeat(300))), "new");
        plan.file(dir.join("c.txt"), "new");
        assert!(matches!(plan.write().unwrap_err().refused(), Some(OutputRefused::NameTooLong { .. })));
        assert!(!dir.join("c.txt").exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_plan_names_no_file_twice() {
        let dir = scratch("twice");
        let mut plan = Plan::new(&[], Replace::Allowed);
        plan.file(dir.join("a.txt"), "1");
        plan.file(dir.join(".").join("a.txt"), "2");
        assert!(matches!(plan.write().unwrap_err().refused(), Some(OutputRefused::Twice { .. })));
        assert!(!dir.join("a.txt").exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_written_file_replaces_the_old_one_whole_and_leaves_no_temporary_file() {
        let dir = scratch("whole");
        std::fs::write(dir.join("a.txt"), "old").unwrap();
        let mut plan = Plan::new(&[], Replace::Allowed);
        plan.file(dir.join("a.txt"), "new");
        assert_eq!(plan.write().unwrap(), vec![dir.join("a.txt")]);
        assert_eq!(std::fs::read_to_string(dir.join("a.txt")).unwrap(), "new");
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
