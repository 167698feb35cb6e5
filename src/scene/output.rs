//! Writing what a command makes: never onto one of its inputs (the same
//! file by another name included), and, for a folder of outputs, nothing
//! replaced and nothing written until every file is known to be new.

use std::io::Write;
use std::path::Path;

use crate::error::{Error, Usage};

/// Refuses an output file that is one of the command's inputs (the same file
/// by another name included): writing it would destroy what was read.
pub fn not_an_input(output: &Path, inputs: &[&Path]) -> Result<(), Error> {
    if inputs.iter().any(|input| same_file(output, input)) {
        return Err(Usage::OutputIsInput { folder: output.to_owned() }.into());
    }
    Ok(())
}

/// Whether two paths name the same existing file or folder.
fn same_file(a: &Path, b: &Path) -> bool {
    matches!((std::fs::canonicalize(a), std::fs::canonicalize(b)), (Ok(a), Ok(b)) if a == b)
}

/// Writes `files` (name, contents) into `folder`, made if missing, replacing
/// nothing: refused, before anything is written, when `folder` is one of the
/// folders the command reads (`inputs`) or already holds one of the files.
pub fn write_fresh(folder: &Path, files: &[(String, Vec<u8>)], inputs: &[&Path]) -> Result<(), Error> {
    not_an_input(folder, inputs)?;
    let existing: Vec<String> = files
        .iter()
        .filter(|(name, _)| std::fs::symlink_metadata(folder.join(name)).is_ok())
        .map(|(n, _)| n.clone())
        .collect();
    if !existing.is_empty() {
        return Err(Usage::OutputWouldReplace { folder: folder.to_owned(), files: existing }.into());
    }
    std::fs::create_dir_all(folder).map_err(|source| Error::Write { path: folder.to_owned(), source })?;
    for (name, contents) in files {
        let path = folder.join(name);
        // create_new: a file that appeared since the check is not replaced either.
        let written = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
            .and_then(|mut file| file.write_all(contents));
        written.map_err(|source| Error::Write { path, source })?;
    }
    Ok(())
}
