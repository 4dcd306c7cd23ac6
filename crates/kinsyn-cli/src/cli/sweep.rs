//! `kinsyn sweep`: the catalogue-wide multioperation sweep ([`kinsyn::sweep`]) written as files
//! in a directory (docs/sweep.md) — resumable, split into shards and merged again — and
//! `kinsyn sweep merge`.

mod files;
mod merge;
mod results;
mod run;
mod selection;
mod table;

pub use files::{
    CHECKPOINT, Checkpoint, FILES, FORMAT, JSONL, MANIFEST, MAX_ROWS_BYTES, Manifest, PARQUET,
    ROW_FILES, read_checkpoint, read_manifest, read_rows, row_line, write_results,
};
pub use merge::merge;
pub use results::{SweepRows, check_rows, read_results, rows_file, with_known};
pub use run::{SweepOptions, SweepOutcome, sweep};
pub use selection::{Shard, SweepSelection};
pub use table::parquet_bytes;

use crate::cli::{CliError, json};
use kinsyn::catalogue::Catalogue;
use kinsyn::manipulator::MAX_INPUTS;
use kinsyn::mechanism::SampleSettings;
use kinsyn::sweep::SweepSettings;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The options of `kinsyn sweep` as given on the command line (and by Python's
/// `kinsyn.sweep`), not yet checked.
#[derive(Debug, Clone)]
pub struct Request<'a> {
    /// `--legs`.
    pub legs: usize,
    /// `--actuated`: the counts of actuated joints per leg.
    pub actuated: &'a [usize],
    /// `--seed`.
    pub seed: u64,
    /// `--chains`: comma-separated catalogue ids.
    pub chains: Option<&'a str>,
    /// `--family`.
    pub family: Option<&'a str>,
    /// `--shard K/N`.
    pub shard: Option<&'a str>,
    /// `--threads`.
    pub threads: Option<usize>,
    /// `--stop-after` (hidden; for tests of resuming).
    pub stop_after: Option<usize>,
    /// `--force`: replace another sweep's files, or files of none, in the directory.
    pub force: bool,
}

/// The settings of `--legs`, `--actuated` and `--seed`, checked: 3 to 6 legs (as
/// `kinsyn build`), 1 to 6 actuated joints per leg (the catalogue's legs have 6) and at most
/// [`MAX_INPUTS`] inputs per manipulator.
///
/// # Errors
/// [`CliError::Input`] naming the option out of range.
pub fn sweep_settings(
    legs: usize,
    actuated: &[usize],
    seed: u64,
) -> Result<SweepSettings, CliError> {
    if !kinsyn::sweep::LEGS.contains(&legs) {
        return Err(CliError::Input(format!(
            "--legs {legs}: give 3 to 6 (as kinsyn build)"
        )));
    }
    let mut per_leg = actuated.to_vec();
    per_leg.sort_unstable();
    per_leg.dedup();
    if per_leg.is_empty() {
        return Err(CliError::Input(
            "--actuated: give at least one count, e.g. 1,2".into(),
        ));
    }
    for &k in &per_leg {
        if !(1..=6).contains(&k) {
            return Err(CliError::Input(format!(
                "--actuated {k}: each count of actuated joints per leg is 1 to 6"
            )));
        }
        if legs * k > MAX_INPUTS {
            return Err(CliError::Input(format!(
                "--actuated {k} with --legs {legs}: {} inputs, more than {MAX_INPUTS} (2^inputs lock subsets per design)",
                legs * k
            )));
        }
    }
    Ok(SweepSettings {
        legs,
        actuated_per_leg: per_leg,
        sampling: SampleSettings {
            seed,
            ..SampleSettings::default()
        },
    })
}

/// The committed catalogue, read once.
pub(crate) fn catalogue() -> Result<Catalogue, CliError> {
    Catalogue::committed()
        .map_err(|e| CliError::Internal(format!("the compiled-in catalogue does not read: {e}")))
}

/// The sweep `request` asks for, checked against `catalogue`: its settings, selection, shard
/// and threads.
///
/// # Errors
/// [`CliError::Input`] naming the option that is out of range or malformed (as
/// [`sweep_settings`], [`Shard::parse`], [`SweepSelection::new`]; `--threads` 0 or above
/// [`MAX_THREADS`](crate::MAX_THREADS)).
pub fn options(catalogue: &Catalogue, request: &Request) -> Result<SweepOptions, CliError> {
    let settings = sweep_settings(request.legs, request.actuated, request.seed)?;
    let shard = request.shard.map(Shard::parse).transpose()?;
    if request
        .threads
        .is_some_and(|t| t == 0 || t > crate::cli::solve::MAX_THREADS)
    {
        return Err(CliError::Input(format!(
            "--threads {}: give 1 to {}",
            request.threads.unwrap_or(0),
            crate::cli::solve::MAX_THREADS
        )));
    }
    let selection = SweepSelection::new(catalogue, request.chains, request.family)?;
    Ok(SweepOptions {
        settings,
        selection,
        shard,
        threads: request.threads,
        stop_after: request.stop_after,
        force: request.force,
    })
}

/// `kinsyn sweep --out OUT …` on the committed catalogue: runs (or resumes) the sweep
/// `request` asks for into `out`, with a progress bar on stderr when `progress` is true and
/// stderr is a terminal.
///
/// # Errors
/// As [`options`] and [`sweep()`].
pub fn run_request(
    out: &Path,
    request: &Request,
    progress: bool,
) -> Result<SweepOutcome, CliError> {
    let catalogue = catalogue()?;
    let options = options(&catalogue, request)?;
    let bar = if progress {
        crate::cli::terminal::progress(0, "designs", "sweep")
    } else {
        indicatif::ProgressBar::hidden()
    };
    sweep(&catalogue, out, &options, &bar)
}

/// The `--json` summary of a run: the outcome with `designs_per_second` and
/// `subsets_per_core_second`.
#[must_use]
pub fn outcome_json(outcome: &SweepOutcome) -> serde_json::Value {
    let mut value = serde_json::to_value(outcome).unwrap_or_default();
    if let Some(o) = value.as_object_mut() {
        o.insert(
            "designs_per_second".into(),
            outcome.designs_per_second().into(),
        );
        o.insert(
            "subsets_per_core_second".into(),
            outcome.subsets_per_core_second().into(),
        );
    }
    value
}

/// The manifests (not yet complete) of the shards 1/`count` … `count`/`count` of the sweep
/// `request` asks for (its `shard`, `threads` and `stop_after` are not used): what each
/// `kinsyn sweep --shard K/N` with these options writes into `sweep.json` when it starts.
///
/// # Errors
/// As [`options`]; `count` 0 is refused as `--shard 1/0` is.
pub fn shard_manifests(request: &Request, count: usize) -> Result<Vec<Manifest>, CliError> {
    Shard::parse(&format!("1/{count}"))?;
    let catalogue = catalogue()?;
    let options = options(
        &catalogue,
        &Request {
            shard: None,
            threads: None,
            stop_after: None,
            ..request.clone()
        },
    )?;
    let total = options
        .selection
        .designs(&catalogue, &options.settings)?
        .len();
    (1..=count)
        .map(|k| {
            let shard = Shard::parse(&format!("{k}/{count}"))?;
            Ok(Manifest::new(
                &options.settings,
                &options.selection,
                Some(shard),
                total,
            ))
        })
        .collect()
}

/// `kinsyn sweep --out DIR …`: runs (or resumes) the sweep and reports it.
pub(super) fn command(
    out: &Path,
    request: &Request,
    bench: bool,
    as_json: bool,
) -> Result<String, CliError> {
    let outcome = run_request(out, request, true)?;
    if as_json {
        return Ok(json(&outcome_json(&outcome)));
    }
    Ok(summary(&outcome, bench))
}

/// The text report of a run, with `--bench`'s figures.
fn summary(o: &SweepOutcome, bench: bool) -> String {
    let m = &o.manifest;
    let shard = m.shard.map_or_else(String::new, |s| format!(", shard {s}"));
    let what = format!(
        "{} designs of {} ({}; {} legs, {} actuated per leg, seed {}{shard})",
        m.designs,
        m.sweep_designs,
        m.selection,
        m.settings.legs,
        m.settings
            .actuated_per_leg
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(" or "),
        m.settings.sampling.seed,
    );
    if o.already_complete {
        return format!(
            "{}: already complete with {what}; nothing rewritten\n",
            o.out
        );
    }
    let mut s = format!(
        "{}: {what}: {} evaluated, resumed {} rows, {} errors; ",
        o.out, o.evaluated, o.resumed, o.errors
    );
    if o.complete {
        let _ = writeln!(s, "complete: {JSONL}, {PARQUET}, {MANIFEST}");
    } else {
        let _ = writeln!(
            s,
            "stopped with {} of {} rows in {CHECKPOINT}; run the same command again to resume",
            o.resumed + o.evaluated,
            m.designs
        );
    }
    if bench {
        let _ = writeln!(s, "designs evaluated      {}", o.evaluated);
        let _ = writeln!(s, "lock subsets sampled   {}", o.lock_subsets);
        let _ = writeln!(s, "wall seconds           {:.3}", o.seconds);
        let _ = writeln!(s, "designs/s              {:.2}", o.designs_per_second());
        let _ = writeln!(
            s,
            "subsets per core-s     {:.1}",
            o.subsets_per_core_second()
        );
        let _ = writeln!(s, "threads                {}", o.threads);
        let _ = writeln!(s, "writing ms             {:.1}", o.write_ms);
    }
    s
}

/// `kinsyn sweep merge DIR… --out OUT [--force]`.
pub(super) fn merge_command(
    dirs: &[PathBuf],
    out: &Path,
    force: bool,
    as_json: bool,
) -> Result<String, CliError> {
    let manifest = merge(dirs, out, force)?;
    if as_json {
        return Ok(json(&manifest));
    }
    Ok(format!(
        "{}: merged {} shards: {} designs ({}); {JSONL}, {PARQUET}, {MANIFEST}\n",
        out.display(),
        dirs.len(),
        manifest.designs,
        manifest.selection
    ))
}
