//! A sweep's results read back for use (`kinsyn sweep report`, Python's `kinsyn.sweep.read`):
//! the rows of a sweep directory or of a `.jsonl` file, each checked against the designs of
//! its sweep when the folder holds the manifest, else against the catalogue.

use super::files::{self, Manifest, read_manifest, read_rows};
use crate::Error;
use kinsyn::sweep::DesignRow;
use kinsyn::sweep::rows::Known;
use std::path::{Path, PathBuf};

/// The rows of a sweep and where they came from.
#[derive(Debug, Clone)]
pub struct SweepRows {
    /// The file of rows read.
    pub file: PathBuf,
    /// The folder of the results (the file's).
    pub folder: PathBuf,
    /// The rows, in the file's order.
    pub rows: Vec<DesignRow>,
    /// The folder's manifest (`sweep.json`), checked, when it has one.
    pub manifest: Option<Manifest>,
}

/// The file of rows `path` names (a sweep folder's `designs.jsonl`, or the file itself) and
/// its folder.
///
/// # Errors
/// [`Error::Input`] for a missing path or a folder without `designs.jsonl`.
pub fn rows_file(path: &Path) -> Result<(PathBuf, PathBuf), Error> {
    let shown = path.display();
    let metadata = std::fs::metadata(path).map_err(|e| Error::Input(format!("{shown}: {e}")))?;
    if metadata.is_dir() {
        let file = path.join(files::JSONL);
        if std::fs::symlink_metadata(&file).is_err() {
            return Err(Error::Input(format!(
                "{shown} has no designs.jsonl: give a sweep folder (kinsyn sweep --out) or a .jsonl file of design rows"
            )));
        }
        return Ok((file, path.to_path_buf()));
    }
    let folder = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    Ok((path.to_path_buf(), folder))
}

/// Runs `read` with the designs rows of `folder` may be: those of its manifest (checked,
/// [`Manifest::designs`]) when it has one, else any design of the committed catalogue; returns
/// the manifest with `read`'s result.
///
/// # Errors
/// A manifest that does not read or does not check, and `read`'s.
pub fn with_known<T>(
    folder: &Path,
    read: impl FnOnce(&Known) -> Result<T, Error>,
) -> Result<(Option<Manifest>, T), Error> {
    let catalogue = super::catalogue()?;
    let manifest = read_manifest(folder)?;
    let value = match &manifest {
        Some(m) => {
            let designs = m.designs(&catalogue, &folder.join(files::MANIFEST))?;
            read(&Known::sweep(&designs, m.settings.legs))?
        }
        None => read(&Known::catalogue(&catalogue))?,
    };
    Ok((manifest, value))
}

/// The rows of `path` (a sweep folder or a `.jsonl` file of rows), every one checked
/// ([`with_known`], [`read_rows`]); an empty file is refused.
///
/// # Errors
/// [`Error::Input`] for a file or manifest that does not read or check (one line naming
/// the file, and the line for a row), or no rows.
pub fn read_results(path: &Path) -> Result<SweepRows, Error> {
    let (file, folder) = rows_file(path)?;
    let (manifest, rows) = with_known(&folder, |known| read_rows(&file, known))?;
    if rows.is_empty() {
        return Err(Error::Input(format!(
            "{}: no design rows (the file is empty)",
            file.display()
        )));
    }
    Ok(SweepRows {
        file,
        folder,
        rows,
        manifest,
    })
}

/// The rows of `text` (JSON lines), read from a table beside the folder `folder` holds
/// (`designs.parquet`), checked as the rows of a file there are ([`with_known`]); `shown`
/// names the source in refusals.
///
/// # Errors
/// As [`read_results`].
pub fn check_rows(
    text: &str,
    folder: &Path,
    shown: &Path,
) -> Result<(Option<Manifest>, Vec<DesignRow>), Error> {
    with_known(folder, |known| {
        known
            .parse_rows(text)
            .map_err(|e| Error::Input(format!("{} {e}", shown.display())))
    })
}
