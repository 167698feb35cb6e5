//! A file staged beside its place: written under a temporary name
//! (`.zsim-…`) in the folder it goes into, then renamed into place, or
//! removed when it is not placed. The folder is opened once as a handle and
//! the temporary file made and renamed relative to it (the handle closed
//! while other folders are written, and reopened only if the path still
//! names the same folder), so that only the
//! folder's path must fit the system's limit: an output whose whole path is
//! as long as the system allows (4,095 bytes) is written, though a temporary
//! name longer than its own would not fit beside it as a path.

use std::ffi::OsStr;
use std::io;
use std::path::Path;

/// A folder files are staged in, opened once for all of them.
pub(super) struct StagingFolder {
    /// Its path, to sync its file system by and to reopen it by.
    path: std::path::PathBuf,
    /// Its handle while open; closed ([`StagingFolder::close`]) and reopened by
    /// [`StagingFolder::with`], which checks that the path still names this folder.
    #[cfg(not(target_arch = "wasm32"))]
    dir: std::sync::Mutex<Option<cap_std::fs::Dir>>,
    /// The folder's identity, as first opened.
    #[cfg(not(target_arch = "wasm32"))]
    key: super::inward::FileKey,
    #[cfg(target_arch = "wasm32")]
    dir: std::path::PathBuf,
}

impl StagingFolder {
    /// The folder at `path`, opened.
    pub(super) fn open(path: &Path) -> io::Result<StagingFolder> {
        #[cfg(not(target_arch = "wasm32"))]
        {
            let (dir, key) = open_dir(path)?;
            Ok(StagingFolder { path: path.to_path_buf(), dir: std::sync::Mutex::new(Some(dir)), key })
        }
        #[cfg(target_arch = "wasm32")]
        Ok(StagingFolder { path: path.to_path_buf(), dir: path.to_path_buf() })
    }

    /// Runs `f` on the folder's handle, reopening it if it was closed; a
    /// path that no longer names the folder first opened is an error.
    #[cfg(not(target_arch = "wasm32"))]
    fn with<T>(&self, f: impl FnOnce(&cap_std::fs::Dir) -> io::Result<T>) -> io::Result<T> {
        let mut dir = self.dir.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if dir.is_none() {
            let (reopened, key) = open_dir(&self.path)?;
            if key != self.key {
                return Err(io::Error::other("the folder was replaced while zsim wrote into it"));
            }
            *dir = Some(reopened);
        }
        f(dir.as_ref().expect("opened above"))
    }

    #[cfg(target_arch = "wasm32")]
    fn with<T>(&self, f: impl FnOnce(&std::path::PathBuf) -> io::Result<T>) -> io::Result<T> {
        f(&self.dir)
    }

    /// Closes the folder's handle until it is needed again.
    pub(super) fn close(&self) {
        #[cfg(not(target_arch = "wasm32"))]
        {
            *self.dir.lock().unwrap_or_else(std::sync::PoisonError::into_inner) = None;
        }
    }

    /// Which file system the folder is on (its device), so that each is synced once.
    pub(super) fn file_system(&self) -> u64 {
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.key.0
        }
        #[cfg(target_arch = "wasm32")]
        0
    }

    /// Makes everything written into its file system durable (Linux's
    /// `syncfs` on the folder), where files are not synced one by one.
    pub(super) fn sync_file_system(&self) -> io::Result<()> {
        #[cfg(target_os = "linux")]
        {
            use std::os::fd::AsRawFd;
            // The handle is for naming files in the folder only (O_PATH): syncfs takes an opened one.
            let opened = std::fs::File::open(&self.path)?;
            // SAFETY: syncfs on a descriptor this function holds open.
            if unsafe { libc::syncfs(opened.as_raw_fd()) } != 0 {
                return Err(io::Error::last_os_error());
            }
        }
        #[cfg(not(target_os = "linux"))]
        let _ = &self.path;
        Ok(())
    }
}

/// A staged file (see the module): its folder, its temporary name, and
/// while it is written, the file itself (closed once written, so that a
/// folder of thousands of files holds one descriptor, the folder's).
pub(super) struct Staged {
    folder: std::sync::Arc<StagingFolder>,
    /// The temporary name; empty once placed.
    temporary: String,
    file: Option<std::fs::File>,
}

impl Staged {
    /// A new empty file in `folder` under a temporary name no other file
    /// has, with `mode` (less the umask) where the system has modes.
    pub(super) fn new(folder: &std::sync::Arc<StagingFolder>, mode: u32) -> io::Result<Staged> {
        let seed =
            std::hash::BuildHasher::hash_one(&std::collections::hash_map::RandomState::new(), std::process::id());
        for attempt in 0u64..100 {
            let temporary = format!(".zsim-{:012x}", (seed ^ attempt.wrapping_mul(0x9e37_79b9_7f4a_7c15)) >> 16);
            match folder.with(|dir| open_new(dir, &temporary, mode)) {
                Ok(file) => return Ok(Staged { folder: std::sync::Arc::clone(folder), temporary, file: Some(file) }),
                Err(error) if error.kind() == io::ErrorKind::AlreadyExists => continue,
                Err(error) => return Err(error),
            }
        }
        Err(io::Error::new(io::ErrorKind::AlreadyExists, "no free temporary name"))
    }

    /// Writes `bytes` into it, syncs them where `sync` says, and closes it.
    /// The folder it is staged in.
    pub(super) fn folder(&self) -> std::sync::Arc<StagingFolder> {
        std::sync::Arc::clone(&self.folder)
    }

    pub(super) fn write_and_close(&mut self, bytes: &[u8], sync: bool) -> io::Result<()> {
        use std::io::Write;
        let mut file = self.file.take().ok_or_else(|| io::Error::other("written already"))?;
        file.write_all(bytes)?;
        if sync {
            file.sync_data()?;
        }
        Ok(())
    }

    /// Renamed into place as `name` in its folder: over a file there where
    /// `over` says so, else only where none is (the rename refuses to
    /// replace, or on file systems without such a rename, a hard link is made
    /// and the temporary name removed).
    pub(super) fn place(mut self, name: &OsStr, over: bool) -> io::Result<()> {
        let temporary = &self.temporary;
        let placed = match over {
            true => self.folder.with(|dir| rename(dir, temporary, name)),
            false => self.folder.with(|dir| rename_no_replace(dir, temporary, name)),
        };
        if placed.is_ok() {
            self.temporary.clear();
        }
        placed
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.temporary.is_empty() {
            let temporary = &self.temporary;
            #[cfg(not(target_arch = "wasm32"))]
            let _ = self.folder.with(|dir| dir.remove_file(temporary));
            #[cfg(target_arch = "wasm32")]
            let _ = self.folder.with(|dir| std::fs::remove_file(dir.join(temporary)));
        }
    }
}

/// The folder at `path` opened, and its identity.
#[cfg(not(target_arch = "wasm32"))]
fn open_dir(path: &Path) -> io::Result<(cap_std::fs::Dir, super::inward::FileKey)> {
    let dir = cap_std::fs::Dir::open_ambient_dir(path, cap_std::ambient_authority())?;
    let key = super::inward::Identity::of(path)
        .map(|identity| identity.key())
        .ok_or_else(|| io::Error::new(io::ErrorKind::NotFound, "the folder went away"))?;
    Ok((dir, key))
}

#[cfg(not(target_arch = "wasm32"))]
fn open_new(folder: &cap_std::fs::Dir, name: &str, mode: u32) -> io::Result<std::fs::File> {
    let mut options = cap_std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use cap_std::fs::OpenOptionsExt;
        options.mode(mode);
    }
    #[cfg(not(unix))]
    let _ = mode;
    Ok(folder.open_with(name, &options)?.into_std())
}

#[cfg(target_arch = "wasm32")]
fn open_new(folder: &Path, name: &str, _mode: u32) -> io::Result<std::fs::File> {
    std::fs::OpenOptions::new().write(true).create_new(true).open(folder.join(name))
}

#[cfg(not(target_arch = "wasm32"))]
fn rename(folder: &cap_std::fs::Dir, from: &str, to: &OsStr) -> io::Result<()> {
    folder.rename(from, folder, to)
}

#[cfg(target_arch = "wasm32")]
fn rename(folder: &Path, from: &str, to: &OsStr) -> io::Result<()> {
    std::fs::rename(folder.join(from), folder.join(to))
}

#[cfg(not(target_arch = "wasm32"))]
fn rename_no_replace(folder: &cap_std::fs::Dir, from: &str, to: &OsStr) -> io::Result<()> {
    #[cfg(target_os = "linux")]
    {
        use std::os::fd::AsRawFd;
        use std::os::unix::ffi::OsStrExt;
        let from = std::ffi::CString::new(from).map_err(io::Error::other)?;
        let to = std::ffi::CString::new(to.as_bytes()).map_err(io::Error::other)?;
        let fd = folder.as_raw_fd();
        // SAFETY: renameat2 on a descriptor the handle holds open, with two terminated names.
        if unsafe { libc::renameat2(fd, from.as_ptr(), fd, to.as_ptr(), libc::RENAME_NOREPLACE) } == 0 {
            return Ok(());
        }
        let error = io::Error::last_os_error();
        // A file system without the flag: a hard link, which refuses an existing name too.
        if !matches!(error.raw_os_error(), Some(libc::EINVAL) | Some(libc::ENOSYS)) {
            return Err(error);
        }
    }
    folder.hard_link(from, folder, to)?;
    folder.remove_file(from)
}

#[cfg(target_arch = "wasm32")]
fn rename_no_replace(folder: &Path, from: &str, to: &OsStr) -> io::Result<()> {
    std::fs::hard_link(folder.join(from), folder.join(to))?;
    std::fs::remove_file(folder.join(from))
}
