//! The files of a sweep directory (docs/sweep.md): the manifest `sweep.json`, the rows as
//! `designs.jsonl` and `designs.parquet`, and the checkpoint of a run under way.

use super::selection::{Shard, SweepSelection};
use super::table;
use crate::cli::CliError;
use kinsyn::sweep::{DesignRow, SweepSettings};
use serde::{Deserialize, Serialize};
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// The format tag of `sweep.json`.
pub const FORMAT: &str = "kinsyn-sweep/1";
/// The manifest's file name.
pub const MANIFEST: &str = "sweep.json";
/// The rows as JSON lines.
pub const JSONL: &str = "designs.jsonl";
/// The rows as Parquet.
pub const PARQUET: &str = "designs.parquet";
/// The rows finished so far by a run under way, in any order.
pub const CHECKPOINT: &str = "checkpoint.jsonl";
/// Every file a sweep writes into its directory: what a fresh start or a merge may not find
/// there without `--force`.
pub const FILES: [&str; 4] = [MANIFEST, JSONL, PARQUET, CHECKPOINT];

/// `sweep.json`: what a sweep directory holds. Two directories with equal manifests hold the
/// same rows (a row depends on its design and the settings only).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    /// [`FORMAT`].
    pub format: String,
    /// The kinsyn version that evaluated the rows.
    pub kinsyn: String,
    /// The manipulators built and how their motions are sampled (the seed included).
    pub settings: SweepSettings,
    /// The catalogue chains swept.
    pub selection: SweepSelection,
    /// This directory's part of the sweep, or `None` for the whole.
    pub shard: Option<Shard>,
    /// The designs of the whole sweep (every shard).
    pub sweep_designs: usize,
    /// The designs of this directory.
    pub designs: usize,
    /// Which designs those are, in words.
    pub rule: String,
    /// Whether every row is written (`designs.jsonl` and `designs.parquet` exist); false while
    /// a run is under way or was interrupted (its rows are in `checkpoint.jsonl`).
    pub complete: bool,
}

impl Manifest {
    /// The manifest of a sweep with `sweep_designs` designs in all, of which `shard` (or all)
    /// are this directory's, not yet complete.
    #[must_use]
    pub fn new(
        settings: &SweepSettings,
        selection: &SweepSelection,
        shard: Option<Shard>,
        sweep_designs: usize,
    ) -> Self {
        let (designs, rule) = match shard {
            None => (
                sweep_designs,
                "every design of the sweep, 0 to designs - 1".to_string(),
            ),
            Some(s) => (
                (0..sweep_designs).filter(|&i| s.contains(i)).count(),
                format!(
                    "the designs i (0-based, in sweep order) with (i mod {}) + 1 = {}",
                    s.count, s.index
                ),
            ),
        };
        Manifest {
            format: FORMAT.to_string(),
            kinsyn: env!("CARGO_PKG_VERSION").to_string(),
            settings: settings.clone(),
            selection: selection.clone(),
            shard,
            sweep_designs,
            designs,
            rule,
            complete: false,
        }
    }

    /// Whether `other` describes the same sweep part (everything but completeness).
    #[must_use]
    pub fn same_run(&self, other: &Manifest) -> bool {
        Manifest {
            complete: other.complete,
            ..self.clone()
        } == *other
    }

    /// The manifest as written: pretty JSON, one trailing newline.
    #[must_use]
    pub fn text(&self) -> String {
        crate::cli::json(self)
    }
}

/// The manifest of directory `dir`, or `None` when it has none.
///
/// # Errors
/// [`CliError::Input`] when `sweep.json` exists but is not a sweep manifest of this format.
pub fn read_manifest(dir: &Path) -> Result<Option<Manifest>, CliError> {
    let path = dir.join(MANIFEST);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(CliError::Input(format!("{}: {e}", path.display()))),
    };
    let value: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| CliError::Input(format!("{}: not a sweep manifest: {e}", path.display())))?;
    let format = value.get("format").and_then(serde_json::Value::as_str);
    if format != Some(FORMAT) {
        return Err(CliError::Input(format!(
            "{}: not a sweep manifest (format {format:?}, expected {FORMAT:?})",
            path.display()
        )));
    }
    serde_json::from_value(value)
        .map(Some)
        .map_err(|e| CliError::Input(format!("{}: a damaged sweep manifest: {e}", path.display())))
}

/// One row as its line of `designs.jsonl` and of the checkpoint (with the newline).
///
/// # Panics
/// Never: a row is plain data (text, counts, lists), which always serialises.
#[must_use]
pub fn row_line(row: &DesignRow) -> String {
    let mut s = serde_json::to_string(row).expect("a row serialises");
    s.push('\n');
    s
}

/// The rows of a JSON-lines file: every line that ends with a newline (a last line without
/// one, torn by an interruption, is left out), and the length in bytes of those lines.
///
/// # Errors
/// [`CliError::Input`] when a complete line is not a row (a damaged file).
pub fn read_rows(path: &Path) -> Result<(Vec<DesignRow>, u64), CliError> {
    let bytes =
        std::fs::read(path).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    let end = bytes.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let text = std::str::from_utf8(&bytes[..end])
        .map_err(|e| CliError::Input(format!("{}: not UTF-8: {e}", path.display())))?;
    let rows = text
        .lines()
        .enumerate()
        .map(|(i, line)| {
            serde_json::from_str(line).map_err(|e| {
                CliError::Input(format!(
                    "{} line {}: not a design row: {e}",
                    path.display(),
                    i + 1
                ))
            })
        })
        .collect::<Result<Vec<DesignRow>, _>>()?;
    Ok((rows, end as u64))
}

/// Appends finished rows to a checkpoint, each written and flushed at once.
#[derive(Debug)]
pub struct Checkpoint {
    file: std::fs::File,
    path: PathBuf,
}

impl Checkpoint {
    /// The checkpoint of `dir`, cut to its first `keep` bytes (the complete lines read back),
    /// opened for appending.
    ///
    /// # Errors
    /// [`CliError::Io`] when it cannot be opened or cut.
    pub fn open(dir: &Path, keep: u64) -> Result<Self, CliError> {
        let path = dir.join(CHECKPOINT);
        if std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(CliError::Input(format!(
                "{}: is a symbolic link; kinsyn does not write through one",
                path.display()
            )));
        }
        let file = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(&path)
            .and_then(|f| f.set_len(keep).map(|()| f))
            .map_err(|e| io_error(&path, &e))?;
        Ok(Checkpoint { file, path })
    }

    /// Writes `row` as one line and flushes it to the file.
    ///
    /// # Errors
    /// [`CliError::Io`] when it cannot be written.
    pub fn append(&mut self, row: &DesignRow) -> Result<(), CliError> {
        self.file
            .write_all(row_line(row).as_bytes())
            .and_then(|()| self.file.flush())
            .map_err(|e| io_error(&self.path, &e))
    }
}

/// An I/O failure on `path` (exit 1).
pub(super) fn io_error(path: &Path, e: &std::io::Error) -> CliError {
    CliError::Io(std::io::Error::new(
        e.kind(),
        format!("{}: {e}", path.display()),
    ))
}

/// Writes `bytes` to `dir/name` whole or not at all ([`kinsyn::output::write`]: a temporary
/// file renamed into place), replacing the file there: one of the sweep's own files, whose
/// replacement the caller has decided (a fresh start or a merge checked for [`FILES`], a run
/// finishing its own sweep).
///
/// # Errors
/// [`CliError::Io`] when it cannot be written; [`CliError::Input`] when a folder is in the way.
pub fn write_atomic(dir: &Path, name: &str, bytes: &[u8]) -> Result<(), CliError> {
    kinsyn::output::write(&dir.join(name), bytes, kinsyn::output::Overwrite::Replace)
        .map_err(|e| crate::cli::output::error("--out", dir, e))
}

/// Removes the rows and checkpoint a directory holds (of another sweep, or of none, that
/// `--force` replaces), so that a fresh start never shows them beside its new manifest.
///
/// # Errors
/// [`CliError::Io`] when one cannot be removed.
pub fn clear_rows(dir: &Path) -> Result<(), CliError> {
    for name in [JSONL, PARQUET, CHECKPOINT] {
        let path = dir.join(name);
        match std::fs::remove_file(&path) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                return Err(io_error(&path, &e));
            }
            _ => {}
        }
    }
    Ok(())
}

/// Writes the results of a finished sweep part to `dir`: `designs.jsonl` and `designs.parquet`
/// with `rows` (sorted by design index), then `sweep.json` as `manifest` marked complete, then
/// removes the checkpoint. The files depend on the manifest and the rows only.
///
/// # Errors
/// [`CliError::Io`] when a file cannot be written; [`CliError::Internal`] when the Parquet
/// writer fails.
pub fn write_results(dir: &Path, manifest: &Manifest, rows: &[DesignRow]) -> Result<(), CliError> {
    let mut sorted: Vec<&DesignRow> = rows.iter().collect();
    sorted.sort_by_key(|r| r.design);
    let jsonl: String = sorted.iter().map(|r| row_line(r)).collect();
    write_atomic(dir, JSONL, jsonl.as_bytes())?;
    write_atomic(dir, PARQUET, &table::parquet_bytes(manifest, &sorted)?)?;
    let done = Manifest {
        complete: true,
        ..manifest.clone()
    };
    write_atomic(dir, MANIFEST, done.text().as_bytes())?;
    match std::fs::remove_file(dir.join(CHECKPOINT)) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(io_error(&dir.join(CHECKPOINT), &e))
        }
        _ => Ok(()),
    }
}
