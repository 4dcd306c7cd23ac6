//! One run of a sweep into a directory: the designs not yet in its checkpoint evaluated in
//! parallel, each row checkpointed as soon as it is finished, then the result files.

use super::files::{self, Checkpoint, Manifest, read_checkpoint, read_manifest, write_results};
use super::selection::{Shard, SweepSelection};
use crate::Error;
use crate::output::{self, OutputFolder};
use kinsyn::catalogue::Catalogue;
use kinsyn::sweep::rows::Known;
use kinsyn::sweep::{Design, DesignRow, SweepSettings};
use rayon::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, PoisonError};
use std::time::Instant;

/// What `kinsyn sweep` evaluates and how.
#[derive(Debug, Clone, Default)]
pub struct SweepOptions {
    /// The manipulators and the sampling.
    pub settings: SweepSettings,
    /// The catalogue chains swept.
    pub selection: SweepSelection,
    /// This run's part of the sweep (`None`: all of it).
    pub shard: Option<Shard>,
    /// Worker threads (`None`: one per core).
    pub threads: Option<usize>,
    /// Stop, as an interruption would, once this many rows are checkpointed by this run
    /// (for tests of resuming).
    pub stop_after: Option<usize>,
    /// `--force`: a directory holding another sweep's files, or files of none, is started
    /// afresh (those files replaced) instead of refused. The same sweep is resumed or left
    /// complete either way.
    pub force: bool,
}

/// What a run did: its counts and timings (the `--json` summary and `--bench`'s figures).
#[derive(Debug, Clone, Serialize)]
pub struct SweepOutcome {
    /// The directory written.
    pub out: String,
    /// The manifest of the directory.
    pub manifest: Manifest,
    /// Rows found in the checkpoint of an earlier, interrupted run and not evaluated again.
    pub resumed: usize,
    /// Designs evaluated by this run.
    pub evaluated: usize,
    /// Rows (of the directory's) whose design could not be built or sampled.
    pub errors: usize,
    /// Lock subsets sampled by this run: 2^inputs per design evaluated without error.
    pub lock_subsets: u64,
    /// Wall-clock seconds of the evaluation.
    pub seconds: f64,
    /// Milliseconds spent writing the result files.
    pub write_ms: f64,
    /// Worker threads.
    pub threads: usize,
    /// Whether the directory's results are complete after this run.
    pub complete: bool,
    /// Whether they already were (nothing was evaluated or rewritten).
    pub already_complete: bool,
}

impl SweepOutcome {
    /// Designs evaluated per wall-clock second.
    #[must_use]
    pub fn designs_per_second(&self) -> f64 {
        self.evaluated as f64 / self.seconds.max(1e-9)
    }

    /// Lock subsets sampled per second of each worker thread.
    #[must_use]
    pub fn subsets_per_core_second(&self) -> f64 {
        self.lock_subsets as f64 / (self.seconds.max(1e-9) * self.threads.max(1) as f64)
    }
}

/// Why `dir`'s sweep is not the one asked for, in words, or `None` when it is.
fn difference(found: &Manifest, wanted: &Manifest) -> Option<String> {
    if found.same_run(wanted) {
        return None;
    }
    let shard = |s: Option<Shard>| s.map_or_else(|| "none".to_string(), |s| s.to_string());
    Some(if found.kinsyn != wanted.kinsyn {
        format!("written by kinsyn {}", found.kinsyn)
    } else if found.settings != wanted.settings {
        format!(
            "other settings ({})",
            serde_json::to_string(&found.settings).unwrap_or_default()
        )
    } else if found.selection != wanted.selection {
        format!("another selection ({})", found.selection)
    } else if found.shard != wanted.shard {
        format!(
            "shard {} (asked: {})",
            shard(found.shard),
            shard(wanted.shard)
        )
    } else {
        "another list of designs (a different catalogue?)".to_string()
    })
}

/// Runs the sweep of `options` over `catalogue` into `dir` (created if missing, not its
/// parent): resumes an interrupted run of the same sweep there from its checkpoint, evaluates
/// the remaining designs in parallel (each row appended to the checkpoint as soon as it is
/// done, `progress` advanced), then writes the result files (`files::write_results`, `designs.parquet` by `table`). A
/// directory already complete with the same sweep is left as it is. A fresh start refuses a
/// directory holding another sweep or any of the sweep's files ([`FILES`](super::FILES))
/// unless `options.force`, which replaces them.
///
/// # Errors
/// [`Error::Input`] for an empty selection, bad `--threads`, a directory holding another
/// sweep or files of one (without `force`), a path that is no folder or whose parent is
/// missing, or a damaged checkpoint; [`Error::Io`] when the directory cannot be written.
pub fn sweep(
    catalogue: &Catalogue,
    dir: &Path,
    options: &SweepOptions,
    progress: &indicatif::ProgressBar,
    table: super::Table,
) -> Result<SweepOutcome, Error> {
    let all = options.selection.designs(catalogue, &options.settings)?;
    let manifest = Manifest::new(
        &options.settings,
        &options.selection,
        options.shard,
        all.len(),
    );
    let mine: Vec<Design> = all
        .into_iter()
        .filter(|d| options.shard.is_none_or(|s| s.contains(d.index)))
        .collect();
    let mut outcome = SweepOutcome {
        out: dir.display().to_string(),
        manifest: manifest.clone(),
        resumed: 0,
        evaluated: 0,
        errors: 0,
        lock_subsets: 0,
        seconds: 0.0,
        write_ms: 0.0,
        threads: 0,
        complete: false,
        already_complete: false,
    };
    kinsyn::output::check_folder(dir).map_err(|e| output::error("--out", dir, e))?;
    let found = match read_manifest(dir) {
        // With --force a manifest that does not read is replaced too.
        Err(Error::Input(_)) if options.force => None,
        other => other?,
    };
    let found = match found {
        Some(found) => match difference(&found, &manifest) {
            None => Some(found),
            // Replaced: this sweep starts afresh there.
            Some(_) if options.force => None,
            Some(why) => {
                return Err(Error::Input(format!(
                    "{} holds another sweep: {why}; give another --out DIR, the options it was written with, or --force to replace it",
                    dir.display()
                )));
            }
        },
        None => None,
    };
    if let Some(found) = &found
        && found.complete
    {
        outcome.complete = true;
        outcome.already_complete = true;
        return Ok(outcome);
    }
    if found.is_none() {
        OutputFolder::check("--out", dir, files::FILES, options.force)?.create(&[])?;
        files::clear_rows(dir)?;
    }
    let checkpoint_path = dir.join(files::CHECKPOINT);
    let (done, keep) = if found.is_some() && checkpoint_path.exists() {
        checkpoint_rows(&checkpoint_path, &mine, options.settings.legs)?
    } else {
        (BTreeMap::new(), 0)
    };
    if found.is_none() {
        files::write_atomic(dir, files::MANIFEST, manifest.text().as_bytes())?;
    }
    outcome.resumed = done.len();
    let pending: Vec<&Design> = mine
        .iter()
        .filter(|d| !done.contains_key(&d.index))
        .collect();
    let checkpoint = Checkpoint::open(dir, keep)?;
    progress.set_length(pending.len() as u64);

    let start = Instant::now();
    let (new_rows, threads) = evaluate(&pending, options, checkpoint, progress)?;
    outcome.seconds = start.elapsed().as_secs_f64();
    outcome.threads = threads;
    outcome.evaluated = new_rows.len();
    outcome.lock_subsets = new_rows
        .iter()
        .filter(|r| r.error.is_none())
        .map(|r| 1u64 << r.inputs)
        .sum();
    let mut rows: Vec<DesignRow> = done.into_values().collect();
    rows.extend(new_rows);
    outcome.errors = rows.iter().filter(|r| r.error.is_some()).count();
    if rows.len() < mine.len() {
        return Ok(outcome);
    }
    let written = Instant::now();
    write_results(dir, &manifest, &rows, table)?;
    outcome.write_ms = written.elapsed().as_secs_f64() * 1e3;
    outcome.complete = true;
    outcome.manifest.complete = true;
    Ok(outcome)
}

/// The rows of `pending`, evaluated in parallel on `options.threads` workers, each appended to
/// `checkpoint` as soon as it is done (and `progress` advanced), until all are done or
/// `options.stop_after` rows are; with the number of workers.
fn evaluate(
    pending: &[&Design],
    options: &SweepOptions,
    checkpoint: Checkpoint,
    progress: &indicatif::ProgressBar,
) -> Result<(Vec<DesignRow>, usize), Error> {
    let state = Mutex::new((checkpoint, Vec::<DesignRow>::new(), None::<Error>));
    let stop = AtomicBool::new(false);
    let one = |d: &&Design| {
        if stop.load(Ordering::SeqCst) {
            return;
        }
        let row = d.evaluate(&options.settings);
        let mut guard = state.lock().unwrap_or_else(PoisonError::into_inner);
        let (checkpoint, rows, failure) = &mut *guard;
        if stop.load(Ordering::SeqCst) {
            return;
        }
        if let Err(e) = checkpoint.append(&row) {
            *failure = Some(e);
            stop.store(true, Ordering::SeqCst);
            return;
        }
        rows.push(row);
        if options.stop_after.is_some_and(|n| rows.len() >= n) {
            stop.store(true, Ordering::SeqCst);
        }
        progress.inc(1);
    };
    let threads = crate::solve::with_threads(options.threads, || {
        pending.par_iter().for_each(one);
        rayon::current_num_threads()
    })?;
    progress.finish_and_clear();
    let (_, rows, failure) = state.into_inner().unwrap_or_else(PoisonError::into_inner);
    match failure {
        Some(e) => Err(e),
        None => Ok((rows, threads)),
    }
}

/// The rows of an interrupted run's checkpoint, by design index (the complete lines, each a
/// design of `mine` built with `legs` legs, each once: [`read_checkpoint`]), and the length of
/// those lines in bytes.
fn checkpoint_rows(
    path: &Path,
    mine: &[Design],
    legs: usize,
) -> Result<(BTreeMap<usize, DesignRow>, u64), Error> {
    let (rows, keep) = read_checkpoint(path, &Known::sweep(mine, legs)).map_err(|e| {
        Error::Input(format!(
            "{e}; the checkpoint is damaged: remove it to start again"
        ))
    })?;
    Ok((rows.into_iter().map(|r| (r.design, r)).collect(), keep))
}
