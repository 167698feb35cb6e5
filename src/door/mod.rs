//! The one door in and the one door out: every file zsim reads or writes,
//! for every command, passes through this layer, so that each rule is
//! written once.
//!
//! **In** ([`inward`]). A path a user gives is read as a regular file only
//! (a FIFO, device or folder is refused before anything is read, so nothing
//! blocks), within [`MAX_INPUT_BYTES`], checked from its length and again
//! while reading. A name found *inside* a file (a CS 418 texture, a class
//! folder's entry) is opened through [`Folder`], relative to a handle on
//! that file's folder (`cap-std`): no `..`, no absolute path, no symbolic
//! link, nothing outside. An image's declared size is checked against
//! [`MAX_IMAGE_PIXELS`] before a byte of it is decoded ([`png_reader`]).
//! Every file read has an [`Identity`] (device and inode), so a file named
//! twice is one file.
//!
//! **Out** ([`outward`]). Everything a command writes is a [`Plan`]: all of
//! its files are named and checked first (none is one of the command's
//! inputs, compared as files; no two are one; each name fits the file
//! system; none replaces a file where the command replaces nothing), and
//! only then written, each to a temporary file in its folder renamed into
//! place, with interruptions (Ctrl-C, `SIGTERM`, `SIGHUP`) held until the
//! last file is in place: an interrupted run leaves the old files or none,
//! never a prefix.
//!
//! What is shown of a file (its path, names inside it) is escaped by
//! [`crate::words::printable`] and [`crate::words::shown_path`].

pub mod inward;
pub mod outward;
mod staged;

pub use inward::{
    Folder, Identity, Line, Links, MAX_IMAGE_PIXELS, MAX_INPUT_BYTES, PngProblem, png_reader, read_bytes,
    read_line_within, read_text, read_text_with,
};
pub use outward::{OutputRefused, Plan, Replace, same_folder, write_fresh};
