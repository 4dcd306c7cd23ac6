//! `kinsyn sweep merge`: the shard directories of one sweep joined into the files one run of
//! the whole sweep writes.

use super::files::{self, Manifest, read_manifest, read_rows, write_results};
use super::selection::Shard;
use crate::Error;
use crate::output::OutputFolder;
use kinsyn::sweep::DesignRow;
use kinsyn::sweep::rows::Known;
use std::path::{Path, PathBuf};

/// The manifests of `dirs`, each a complete shard of the same sweep, each shard once, with
/// its shard.
fn shard_manifests(dirs: &[PathBuf]) -> Result<Vec<(&Path, Manifest, Shard)>, Error> {
    let mut shards: Vec<(&Path, Manifest, Shard)> = Vec::new();
    for dir in dirs {
        let manifest = read_manifest(dir)?.ok_or_else(|| {
            Error::Input(format!(
                "{} is not a sweep directory (no {})",
                dir.display(),
                files::MANIFEST
            ))
        })?;
        let Some(shard) = manifest.shard else {
            return Err(Error::Input(format!(
                "{} holds a whole sweep, not a shard (written without --shard)",
                dir.display()
            )));
        };
        if !manifest.complete {
            return Err(Error::Input(format!(
                "{}: shard {shard} is incomplete; run its kinsyn sweep again to finish it",
                dir.display()
            )));
        }
        if let Some((first_dir, first, _)) = shards.first() {
            let as_whole =
                |m: &Manifest| Manifest::new(&m.settings, &m.selection, None, m.sweep_designs);
            if as_whole(first) != as_whole(&manifest) || first.kinsyn != manifest.kinsyn {
                return Err(Error::Input(format!(
                    "{} and {} are shards of different sweeps (settings, selection or kinsyn version differ)",
                    first_dir.display(),
                    dir.display()
                )));
            }
            if first.shard.map(|s| s.count) != Some(shard.count) {
                return Err(Error::Input(format!(
                    "{} is shard {shard} but {} is of {} shards",
                    dir.display(),
                    first_dir.display(),
                    first.shard.map_or(0, |s| s.count)
                )));
            }
        }
        if let Some((other, _, _)) = shards.iter().find(|(_, _, s)| *s == shard) {
            return Err(Error::Input(format!(
                "shard {shard} given twice: {} and {}",
                other.display(),
                dir.display()
            )));
        }
        shards.push((dir, manifest, shard));
    }
    Ok(shards)
}

/// Merges the shard directories `dirs` of one sweep (the same settings and selection, shards
/// 1 to N each once, each complete) into the folder `out` (created if missing, not its
/// parent): the same `designs.jsonl`, `designs.parquet` and `sweep.json` as one run of the
/// whole sweep. A sweep's file already in `out` ([`FILES`](super::FILES)) is refused unless
/// `force`, which replaces it. Returns the merged manifest.
///
/// # Errors
/// [`Error::Input`] for a directory that is not a sweep or not a shard, an incomplete
/// shard, shards of different sweeps, a missing or repeated shard, rows that do not match
/// their manifest, or an `out` holding a sweep's files (without `force`), no folder or with a
/// missing parent; [`Error::Io`] when `out` cannot be written.
pub fn merge(
    dirs: &[PathBuf],
    out: &Path,
    force: bool,
    table: super::Table,
) -> Result<Manifest, Error> {
    let shards = shard_manifests(dirs)?;
    let Some((_, first, first_shard)) = shards.first() else {
        return Err(Error::Input(
            "kinsyn sweep merge needs shard directories".into(),
        ));
    };
    let count = first_shard.count;
    let missing: Vec<String> = (1..=count)
        .filter(|k| !shards.iter().any(|(_, _, s)| s.index == *k))
        .map(|k| format!("{k}/{count}"))
        .collect();
    if !missing.is_empty() {
        return Err(Error::Input(format!(
            "shard {} missing: merge takes every shard of the sweep",
            missing.join(", ")
        )));
    }
    let whole = Manifest::new(&first.settings, &first.selection, None, first.sweep_designs);
    let catalogue = super::catalogue()?;
    let mut bytes = 0u64;
    for (dir, _, _) in &shards {
        let path = dir.join(files::JSONL);
        bytes += std::fs::metadata(&path).map_or(0, |m| m.len());
        if bytes > files::MAX_ROWS_BYTES {
            return Err(Error::Input(format!(
                "the shards' {} files hold more than {} bytes, the most a file of sweep rows may hold (docs/limits.md): the merged file could not be read back",
                files::JSONL,
                files::MAX_ROWS_BYTES
            )));
        }
    }
    let mut rows: Vec<DesignRow> = Vec::with_capacity(whole.designs);
    for (dir, manifest, shard) in &shards {
        let designs = manifest.designs(&catalogue, &dir.join(files::MANIFEST))?;
        let path = dir.join(files::JSONL);
        let part = read_rows(&path, &Known::sweep(&designs, manifest.settings.legs))?;
        if part.len() != manifest.designs {
            return Err(Error::Input(format!(
                "{}: {} rows, not the {} designs of shard {shard}; the directory is damaged",
                path.display(),
                part.len(),
                manifest.designs
            )));
        }
        rows.extend(part);
    }
    rows.sort_by_key(|r| r.design);
    if rows.iter().enumerate().any(|(i, r)| r.design != i) || rows.len() != whole.designs {
        return Err(Error::Input(format!(
            "the shards' rows are not designs 0 to {} each once; a directory is damaged",
            whole.designs.saturating_sub(1)
        )));
    }
    OutputFolder::check("--out", out, files::FILES, force)?.create(&[])?;
    write_results(out, &whole, &rows, table)?;
    Ok(Manifest {
        complete: true,
        ..whole
    })
}
