//! The files of a sweep directory (docs/sweep.md): the manifest `sweep.json`, the rows as
//! `designs.jsonl` and `designs.parquet`, and the checkpoint of a run under way.

use super::selection::{Shard, SweepSelection};
use crate::Error;
use crate::files::{SizeLimit, read_bytes_within, read_text, read_text_within, text_of};
use kinsyn::catalogue::Catalogue;
use kinsyn::sweep::rows::Known;
use kinsyn::sweep::{Design, DesignRow, SweepSettings};
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

/// The largest file of rows read (`designs.jsonl`, `checkpoint.jsonl`, `designs.parquet`),
/// 512 MiB: twice the largest sweep docs/scale.md plans (6 legs with 2 actuated joints per
/// leg, about 250 MB measured on a shard; the 3-legged sweep is 13.7 MB). Reading holds the
/// text and the rows in memory, about 4.6 times the file (docs/limits.md, "Files").
pub const MAX_ROWS_BYTES: u64 = 1 << 29;

/// The size limit of the files of rows: [`MAX_ROWS_BYTES`].
pub const ROW_FILES: SizeLimit = SizeLimit {
    bytes: MAX_ROWS_BYTES,
    files: "files of sweep rows",
};

/// What a file of rows that does not read is not.
const NOT_ROWS: &str = "not a file of kinsyn sweep rows";

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

    /// The key-value metadata of `designs.parquet`: the manifest's fields that say what the
    /// rows are (`kinsyn.format`, `kinsyn.version`, `kinsyn.settings` and `kinsyn.selection`
    /// as compact JSON, `kinsyn.shard` as `K/N` or `none`, `kinsyn.designs`), the same pairs
    /// whichever front end encodes the table.
    ///
    /// # Panics
    /// Never: the settings and the selection serialise (string keys, finite numbers).
    #[must_use]
    pub fn table_metadata(&self) -> Vec<(&'static str, String)> {
        vec![
            ("kinsyn.format", self.format.clone()),
            ("kinsyn.version", self.kinsyn.clone()),
            (
                "kinsyn.settings",
                serde_json::to_string(&self.settings).expect("serialisable"),
            ),
            (
                "kinsyn.selection",
                serde_json::to_string(&self.selection).expect("serialisable"),
            ),
            (
                "kinsyn.shard",
                self.shard
                    .map_or_else(|| "none".to_string(), |s| s.to_string()),
            ),
            ("kinsyn.designs", self.designs.to_string()),
        ]
    }

    /// The manifest as written: pretty JSON, one trailing newline.
    #[must_use]
    pub fn text(&self) -> String {
        crate::json(self)
    }

    /// The designs of this directory (its shard of the sweep, or all of it), by index, once
    /// the manifest is checked to be one kinsyn writes: settings within the options' ranges
    /// (`--legs`, `--actuated`, the default sampling with its seed), a selection of verified
    /// `catalogue` chains in catalogue order, a shard K/N with 1 ≤ K ≤ N, and counts and rule
    /// those of that sweep. `path` names the manifest in refusals.
    ///
    /// # Errors
    /// [`Error::Input`] naming what does not match.
    pub fn designs(&self, catalogue: &Catalogue, path: &Path) -> Result<Vec<Design>, Error> {
        let damaged = |why: String| {
            Error::Input(format!(
                "{}: a damaged sweep manifest: {why}",
                path.display()
            ))
        };
        let s = &self.settings;
        let settings = super::sweep_settings(s.legs, &s.actuated_per_leg, s.sampling.seed)
            .map_err(|e| damaged(e.to_string()))?;
        if settings != *s {
            return Err(damaged(format!(
                "the settings are not those kinsyn sweep writes ({})",
                serde_json::to_string(&settings).unwrap_or_default()
            )));
        }
        let chains = self.selection.chains.as_ref().map(|c| c.join(","));
        let selection = SweepSelection::new(
            catalogue,
            chains.as_deref(),
            self.selection.family.as_deref(),
        )
        .map_err(|e| damaged(e.to_string()))?;
        if selection != self.selection {
            return Err(damaged(format!(
                "the selection is not in the catalogue's spelling and order ({selection})"
            )));
        }
        if let Some(shard) = self.shard {
            Shard::parse(&shard.to_string()).map_err(|e| damaged(e.to_string()))?;
        }
        let all = selection.designs(catalogue, &settings)?;
        let expected = Manifest {
            kinsyn: self.kinsyn.clone(),
            complete: self.complete,
            ..Manifest::new(&settings, &selection, self.shard, all.len())
        };
        if (expected.sweep_designs, expected.designs) != (self.sweep_designs, self.designs) {
            return Err(Error::Input(format!(
                "{}: the sweep it describes has {} designs ({} in this directory) with this kinsyn's catalogue, not the {} ({}) it records: the results of another catalogue, or a damaged manifest",
                path.display(),
                expected.sweep_designs,
                expected.designs,
                self.sweep_designs,
                self.designs
            )));
        }
        if expected != *self {
            return Err(damaged(format!(
                "the rule is not that of its shard ({:?})",
                expected.rule
            )));
        }
        Ok(all
            .into_iter()
            .filter(|d| self.shard.is_none_or(|s| s.contains(d.index)))
            .collect())
    }
}

/// The manifest of directory `dir`, or `None` when it has none, read as every input file is
/// ([`read_text`]: a regular UTF-8 file of at most 1 MiB).
///
/// # Errors
/// [`Error::Input`] when `sweep.json` exists but is not a sweep manifest of this format.
pub fn read_manifest(dir: &Path) -> Result<Option<Manifest>, Error> {
    let path = dir.join(MANIFEST);
    if let Err(e) = std::fs::symlink_metadata(&path)
        && e.kind() == std::io::ErrorKind::NotFound
    {
        return Ok(None);
    }
    let text = read_text(&path, "not a sweep manifest")?;
    let value: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| Error::Input(format!("{}: not a sweep manifest: {e}", path.display())))?;
    let format = value.get("format").and_then(serde_json::Value::as_str);
    if format != Some(FORMAT) {
        return Err(Error::Input(format!(
            "{}: not a sweep manifest (format {format:?}, expected {FORMAT:?})",
            path.display()
        )));
    }
    serde_json::from_value(value)
        .map(Some)
        .map_err(|e| Error::Input(format!("{}: a damaged sweep manifest: {e}", path.display())))
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

/// The rows of the file of rows `path` (`designs.jsonl`, or any JSON-lines file of rows),
/// every non-blank line a row of a design `known` ([`Known::parse_rows`]), each design once.
/// The file is read as every input file is, within [`ROW_FILES`].
///
/// # Errors
/// [`Error::Input`] for a file that does not read, or naming the first line that is not
/// such a row (`FILE line 3: design 7: dof: 99 is more than 6`).
pub fn read_rows(path: &Path, known: &Known) -> Result<Vec<DesignRow>, Error> {
    let text = read_text_within(path, NOT_ROWS, ROW_FILES)?;
    known
        .parse_rows(&text)
        .map_err(|e| Error::Input(format!("{} {e}", path.display())))
}

/// The rows of a run's checkpoint `path`, as [`read_rows`] reads them, from the lines that end
/// with a newline (a last line without one, torn by an interruption, is left out), and the
/// length in bytes of those lines.
///
/// # Errors
/// As [`read_rows`].
pub fn read_checkpoint(path: &Path, known: &Known) -> Result<(Vec<DesignRow>, u64), Error> {
    let mut bytes = read_bytes_within(path, NOT_ROWS, ROW_FILES)?;
    let end = bytes.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    bytes.truncate(end);
    let text = text_of(path, NOT_ROWS, bytes)?;
    let rows = known
        .parse_rows(&text)
        .map_err(|e| Error::Input(format!("{} {e}", path.display())))?;
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
    /// [`Error::Io`] when it cannot be opened or cut.
    pub fn open(dir: &Path, keep: u64) -> Result<Self, Error> {
        let path = dir.join(CHECKPOINT);
        if std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(Error::Input(format!(
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
    /// [`Error::Io`] when it cannot be written.
    pub fn append(&mut self, row: &DesignRow) -> Result<(), Error> {
        self.file
            .write_all(row_line(row).as_bytes())
            .and_then(|()| self.file.flush())
            .map_err(|e| io_error(&self.path, &e))
    }
}

/// An I/O failure on `path` (exit 1).
pub(super) fn io_error(path: &Path, e: &std::io::Error) -> Error {
    Error::Io(std::io::Error::new(
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
/// [`Error::Io`] when it cannot be written; [`Error::Input`] when a folder is in the way.
pub fn write_atomic(dir: &Path, name: &str, bytes: &[u8]) -> Result<(), Error> {
    kinsyn::output::write(&dir.join(name), bytes, kinsyn::output::Overwrite::Replace)
        .map_err(|e| crate::output::error("--out", dir, e))
}

/// Removes the rows and checkpoint a directory holds (of another sweep, or of none, that
/// `--force` replaces), so that a fresh start never shows them beside its new manifest.
///
/// # Errors
/// [`Error::Io`] when one cannot be removed.
pub fn clear_rows(dir: &Path) -> Result<(), Error> {
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
/// with `rows` (sorted by design index; the Parquet bytes by `table`), then `sweep.json` as `manifest` marked complete, then
/// removes the checkpoint. The files depend on the manifest and the rows only.
///
/// # Errors
/// [`Error::Io`] when a file cannot be written; `table`'s error when the Parquet encoder
/// fails.
pub fn write_results(
    dir: &Path,
    manifest: &Manifest,
    rows: &[DesignRow],
    table: super::Table,
) -> Result<(), Error> {
    let mut sorted: Vec<&DesignRow> = rows.iter().collect();
    sorted.sort_by_key(|r| r.design);
    let jsonl: String = sorted.iter().map(|r| row_line(r)).collect();
    write_atomic(dir, JSONL, jsonl.as_bytes())?;
    write_atomic(dir, PARQUET, &table(manifest, &sorted)?)?;
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
