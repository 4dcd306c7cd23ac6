//! `kinsyn sweep`: the catalogue-wide multioperation sweep ([`kinsyn::sweep`]) written as files
//! in a directory (docs/sweep.md) — resumable, split into shards and merged again — and
//! `kinsyn sweep merge`.

mod files;
mod merge;
mod results;
mod run;
mod selection;

pub use files::{
    CHECKPOINT, Checkpoint, FILES, FORMAT, JSONL, MANIFEST, MAX_ROWS_BYTES, Manifest, PARQUET,
    ROW_FILES, read_checkpoint, read_manifest, read_rows, row_line, write_results,
};
pub use merge::merge;
pub use results::{SweepRows, check_rows, read_results, rows_file, with_known};
pub use run::{SweepOptions, SweepOutcome, sweep};

/// The encoder of `designs.parquet` ([`PARQUET`]): the rows of a finished sweep part (sorted by
/// design) and its manifest as the bytes of the file. The Parquet encoder is the front end's
/// (the command's, the Parquet crate's column writers; Python's, pyarrow), so that the reports
/// need neither.
pub type Table<'a> =
    &'a (dyn Fn(&Manifest, &[&kinsyn::sweep::DesignRow]) -> Result<Vec<u8>, Error> + Sync);
pub use selection::{Shard, SweepSelection};

use crate::Error;
use kinsyn::catalogue::Catalogue;
use kinsyn::manipulator::MAX_INPUTS;
use kinsyn::mechanism::SampleSettings;
use kinsyn::sweep::SweepSettings;
use std::path::Path;

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
/// [`Error::Input`] naming the option out of range.
pub fn sweep_settings(legs: usize, actuated: &[usize], seed: u64) -> Result<SweepSettings, Error> {
    if !kinsyn::sweep::LEGS.contains(&legs) {
        return Err(Error::Input(format!(
            "--legs {legs}: give 3 to 6 (as kinsyn build)"
        )));
    }
    let mut per_leg = actuated.to_vec();
    per_leg.sort_unstable();
    per_leg.dedup();
    if per_leg.is_empty() {
        return Err(Error::Input(
            "--actuated: give at least one count, e.g. 1,2".into(),
        ));
    }
    for &k in &per_leg {
        if !(1..=6).contains(&k) {
            return Err(Error::Input(format!(
                "--actuated {k}: each count of actuated joints per leg is 1 to 6"
            )));
        }
        if legs * k > MAX_INPUTS {
            return Err(Error::Input(format!(
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
pub(crate) fn catalogue() -> Result<Catalogue, Error> {
    Catalogue::committed()
        .map_err(|e| Error::Internal(format!("the compiled-in catalogue does not read: {e}")))
}

/// The sweep `request` asks for, checked against `catalogue`: its settings, selection, shard
/// and threads.
///
/// # Errors
/// [`Error::Input`] naming the option that is out of range or malformed (as
/// [`sweep_settings`], [`Shard::parse`], [`SweepSelection::new`]; `--threads` 0 or above
/// [`MAX_THREADS`](crate::solve::MAX_THREADS)).
pub fn options(catalogue: &Catalogue, request: &Request) -> Result<SweepOptions, Error> {
    let settings = sweep_settings(request.legs, request.actuated, request.seed)?;
    let shard = request.shard.map(Shard::parse).transpose()?;
    if request
        .threads
        .is_some_and(|t| t == 0 || t > crate::solve::MAX_THREADS)
    {
        return Err(Error::Input(format!(
            "--threads {}: give 1 to {}",
            request.threads.unwrap_or(0),
            crate::solve::MAX_THREADS
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
/// stderr is a terminal, `designs.parquet` encoded by `table`.
///
/// # Errors
/// As [`options`] and [`sweep()`].
pub fn run_request(
    out: &Path,
    request: &Request,
    progress: bool,
    table: Table,
) -> Result<SweepOutcome, Error> {
    let catalogue = catalogue()?;
    let options = options(&catalogue, request)?;
    let bar = if progress {
        crate::terminal::progress(0, "designs", "sweep")
    } else {
        indicatif::ProgressBar::hidden()
    };
    sweep(&catalogue, out, &options, &bar, table)
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
pub fn shard_manifests(request: &Request, count: usize) -> Result<Vec<Manifest>, Error> {
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
