//! A file staged beside its place: written under a temporary name
//! (`.zsim-…`) in the folder it goes into, then renamed into place, or
//! removed when it is not placed. The folder is opened once as a handle and
//! the temporary file made and renamed relative to it, so that only the
//! folder's path must fit the system's limit: an output whose whole path is
//! as long as the system allows (4,095 bytes) is written, though a temporary
//! name longer than its own would not fit beside it as a path.

use std::ffi::OsStr;
use std::io;
use std::path::Path;

/// A folder files are staged in, opened once for all of them.
pub(super) struct Folder {
    /// Its path, to sync its file system by.
    path: std::path::PathBuf,
    #[cfg(not(target_arch = "wasm32"))]
    dir: cap_std::fs::Dir,
    #[cfg(target_arch = "wasm32")]
    dir: std::path::PathBuf,
}

impl Folder {
    /// The folder at `path`, opened.
    pub(super) fn open(path: &Path) -> io::Result<Folder> {
        #[cfg(not(target_arch = "wasm32"))]
        let dir = cap_std::fs::Dir::open_ambient_dir(path, cap_std::ambient_authority())?;
        #[cfg(target_arch = "wasm32")]
        let dir = path.to_path_buf();
        Ok(Folder { path: path.to_path_buf(), dir })
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
    folder: std::sync::Arc<Folder>,
    /// The temporary name; empty once placed.
    temporary: String,
    file: Option<std::fs::File>,
}

impl Staged {
    /// A new empty file in `folder` under a temporary name no other file
    /// has, with `mode` (less the umask) where the system has modes.
    pub(super) fn new(folder: &std::sync::Arc<Folder>, mode: u32) -> io::Result<Staged> {
        let seed =
            std::hash::BuildHasher::hash_one(&std::collections::hash_map::RandomState::new(), std::process::id());
        for attempt in 0u64..100 {
            let temporary = format!(".zsim-{:012x}", (seed ^ attempt.wrapping_mul(0x9e37_79b9_7f4a_7c15)) >> 16);
            match open_new(&folder.dir, &temporary, mode) {
                Ok(file) => return Ok(Staged { folder: std::sync::Arc::clone(folder), temporary, file: Some(file) }),
                Err(error) if error.kind() == io::ErrorKind::AlreadyExists => continue,
                Err(error) => return Err(error),
            }
        }
        Err(io::Error::new(io::ErrorKind::AlreadyExists, "no free temporary name"))
    }

    /// Writes `bytes` into it, syncs them where `sync` says, and closes it.
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
        let placed = match over {
            true => rename(&self.folder.dir, &self.temporary, name),
            false => rename_no_replace(&self.folder.dir, &self.temporary, name),
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
            #[cfg(not(target_arch = "wasm32"))]
            let _ = self.folder.dir.remove_file(&self.temporary);
            #[cfg(target_arch = "wasm32")]
            let _ = std::fs::remove_file(self.folder.dir.join(&self.temporary));
        }
    }
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
