//! `kinsyn solve FILE --shard K/N --out PART` and `kinsyn solve FILE --merge PART…`: a solve's
//! paths shared among processes or machines ([`kinsyn::homotopy::solve_shard`]) and merged into
//! the report of one process ([`kinsyn::homotopy::merge_shards`]).
//!
//! A shard file is JSON: the kind and kinsyn's version, the **fingerprint** of the system and
//! of the settings that fix the paths (XXH64 of the system's text, the start system asked, the
//! seed and the tracker's settings; the same file read anywhere gives the same system), the
//! shard, the start system tracked, the paths of the whole solve and each of the shard's path
//! ends (complex coordinates as `[re, im]`, written so that they read back bit for bit).
//! Shards of another version, system or settings are refused at the merge.

use crate::files::{SizeLimit, read_text_within};
use crate::output::OutputFile;
use crate::solve::{PathOption, SolveOptions, Solved, check_cost, check_solvable};
use crate::{Error, terminal};
use kinsyn::homotopy::{
    self, EndpointKind, PathEnd, PathFailure, Shard, ShardEnds, SolveSettings, StartSystem,
};
use kinsyn::poly::{C64, System};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The kind a shard file declares.
const KIND: &str = "kinsyn-solve-shard";

/// The most bytes a shard file may hold: 2³⁰ (a shard of 2²⁰ paths in 20 unknowns is about
/// 1 GB; shard a larger solve further).
pub const MAX_SHARD_BYTES: u64 = 1 << 30;

const SHARD_FILES: SizeLimit = SizeLimit {
    bytes: MAX_SHARD_BYTES,
    files: "shard files",
};

/// What a file that is not a shard file is, in refusals.
const NOT_SHARD: &str = "not a kinsyn solve shard file";

/// The most shards a solve is split into.
pub const MAX_SHARDS: usize = 1 << 16;

/// `K/N` as a shard (`K` 1-based), or the refusal of `--shard TEXT`.
///
/// # Errors
/// [`Error::Input`] unless `TEXT` is `K/N` with `1 ≤ K ≤ N ≤ MAX_SHARDS`.
pub fn parse_shard(text: &str) -> Result<Shard, Error> {
    let refuse = || {
        Error::Input(format!(
            "--shard {text:?}: give K/N with 1 ≤ K ≤ N ≤ {MAX_SHARDS}, e.g. 2/8 (K is 1-based)"
        ))
    };
    let (k, n) = text.split_once('/').ok_or_else(refuse)?;
    let (k, n) = (
        k.trim().parse::<usize>().map_err(|_| refuse())?,
        n.trim().parse::<usize>().map_err(|_| refuse())?,
    );
    if n > MAX_SHARDS {
        return Err(refuse());
    }
    Shard::new(k, n).ok_or_else(refuse)
}

/// The fingerprint of a solve's paths: XXH64 of the system's text (variables, groups,
/// equations), the start system asked for, the seed and the tracker's settings.
fn fingerprint(system: &System, settings: &SolveSettings) -> String {
    let mut text = format!(
        "{:?}\n{:?}\n{}\n{}\n{:?}\n",
        system.variables(),
        system.groups(),
        settings.start.name(),
        settings.seed,
        settings.tracker
    );
    for f in system.equations() {
        text.push_str(&f.display_with(system.variables()));
        text.push('\n');
    }
    format!("{:016x}", twox_hash::XxHash64::oneshot(0, text.as_bytes()))
}

#[derive(Serialize, Deserialize)]
struct ShardFile {
    kind: String,
    version: String,
    source: String,
    fingerprint: String,
    shard: usize,
    shards: usize,
    start: String,
    seed: u64,
    paths: usize,
    seconds: f64,
    ends: Vec<EndRecord>,
}

#[derive(Serialize, Deserialize)]
struct EndRecord {
    path: usize,
    kind: EndpointKind,
    x: Option<Vec<[f64; 2]>>,
    winding: usize,
    inverse_condition: f64,
    steps: usize,
    failure: Option<String>,
}

/// The names of the path failures in a shard file.
const FAILURES: [(PathFailure, &str); 4] = [
    (PathFailure::StepTooSmall, "step-too-small"),
    (PathFailure::TooManySteps, "too-many-steps"),
    (PathFailure::Endgame, "endgame"),
    (PathFailure::NotFinite, "not-finite"),
];

impl EndRecord {
    fn of(e: &PathEnd) -> Self {
        Self {
            path: e.path,
            kind: e.kind,
            x: e.x
                .as_ref()
                .map(|x| x.iter().map(|c| [c.re, c.im]).collect()),
            winding: e.winding,
            inverse_condition: e.inverse_condition,
            steps: e.steps,
            failure: e.failure.map(|f| {
                FAILURES
                    .iter()
                    .find(|(g, _)| *g == f)
                    .map_or("unknown", |(_, n)| *n)
                    .to_string()
            }),
        }
    }

    fn end(&self) -> Option<PathEnd> {
        let failure = match &self.failure {
            None => None,
            Some(name) => Some(FAILURES.iter().find(|(_, n)| n == name)?.0),
        };
        Some(PathEnd {
            path: self.path,
            kind: self.kind,
            x: self
                .x
                .as_ref()
                .map(|x| x.iter().map(|[re, im]| C64::new(*re, *im)).collect()),
            winding: self.winding,
            inverse_condition: self.inverse_condition,
            steps: self.steps,
            failure,
            retracked: false,
        })
    }
}

/// The settings of `kinsyn solve` with `options` (one run).
fn settings_of(options: &SolveOptions) -> SolveSettings {
    SolveSettings {
        seed: options.seed,
        start: options.start,
        certify: options.certify,
        max_paths: options.max_paths,
        ..SolveSettings::default()
    }
}

/// The system of a Bertini file checked for a solve (as `kinsyn solve` checks it).
fn system_of(path: &Path) -> Result<System, Error> {
    let input = crate::solve::read_input(path)?;
    check_solvable(&path.display().to_string(), &input)?;
    Ok(input.system)
}

/// What one shard did, for the command's report.
#[derive(Debug, Serialize)]
pub struct ShardSummary {
    /// The Bertini file.
    pub source: String,
    /// The shard file written.
    pub out: PathBuf,
    /// `K`.
    pub shard: usize,
    /// `N`.
    pub shards: usize,
    /// The start system tracked.
    pub start: &'static str,
    /// The paths of the whole solve.
    pub paths: usize,
    /// The shard's paths.
    pub tracked: usize,
    /// Wall seconds.
    pub seconds: f64,
}

/// `kinsyn solve FILE --shard K/N --out PART`: the shard's paths of the solve of `path` with
/// `options` tracked once each and written to `out` (whole or not at all), the limit of paths
/// applied to the shard's share. A progress bar over the shard's paths on a terminal.
///
/// # Errors
/// As `kinsyn solve` before it tracks; `--runs` above 1; an output refused (it exists without
/// `force`, or its folder is missing).
pub fn solve_shard_file(
    path: &Path,
    options: &SolveOptions,
    shard: Shard,
    out: &Path,
    force: bool,
) -> Result<ShardSummary, Error> {
    if options.runs != 1 {
        return Err(Error::Input(format!(
            "--runs {} with --shard: a sharded solve is one run",
            options.runs
        )));
    }
    let target = OutputFile::check("--out", out, force)?;
    let source = path.display().to_string();
    let system = system_of(path)?;
    let settings = settings_of(options);
    let sharded = SolveSettings {
        max_paths: options
            .max_paths
            .saturating_mul(u64::try_from(shard.count).unwrap_or(u64::MAX)),
        ..settings.clone()
    };
    let paths = check_cost(&source, &system, &sharded, PathOption::MaxPaths)?;
    let share = usize::try_from(paths.div_ceil(shard.count as u128)).unwrap_or(usize::MAX);
    let ends = crate::solve::with_threads(options.threads, || {
        let bar = terminal::progress(share, "paths", "solve shard");
        let ends = homotopy::solve_shard(&system, &settings, shard, &|| bar.inc(1));
        bar.finish_and_clear();
        ends
    })?
    .map_err(|e| Error::Input(format!("{source}: {e}")))?;
    let file = ShardFile {
        kind: KIND.into(),
        version: env!("CARGO_PKG_VERSION").into(),
        source: source.clone(),
        fingerprint: fingerprint(&system, &settings),
        shard: shard.index,
        shards: shard.count,
        start: ends.start.name().into(),
        seed: ends.seed,
        paths: ends.paths,
        seconds: ends.seconds,
        ends: ends.ends.iter().map(EndRecord::of).collect(),
    };
    let bytes =
        serde_json::to_vec(&file).map_err(|e| Error::Internal(format!("the shard file: {e}")))?;
    target.write(&bytes)?;
    Ok(ShardSummary {
        source,
        out: out.to_path_buf(),
        shard: shard.index,
        shards: shard.count,
        start: ends.start.name(),
        paths: ends.paths,
        tracked: ends.ends.len(),
        seconds: ends.seconds,
    })
}

/// Reads a shard file, checked against the solve's fingerprint and kinsyn's version.
fn read_shard(part: &Path, fingerprint: &str) -> Result<ShardEnds, Error> {
    let shown = part.display();
    let text = read_text_within(part, NOT_SHARD, SHARD_FILES)?;
    let file: ShardFile = serde_json::from_str(&text)
        .map_err(|e| Error::Input(format!("{shown} is {NOT_SHARD} ({e})")))?;
    if file.kind != KIND {
        return Err(Error::Input(format!(
            "{shown} is {NOT_SHARD} (kind {:?})",
            crate::terminal::one_line(&file.kind)
        )));
    }
    if file.version != env!("CARGO_PKG_VERSION") {
        return Err(Error::Input(format!(
            "{shown} was written by kinsyn {}, this is {}: run every shard and the merge with one version",
            crate::terminal::one_line(&file.version),
            env!("CARGO_PKG_VERSION")
        )));
    }
    if file.fingerprint != fingerprint {
        return Err(Error::Input(format!(
            "{shown} is a shard of another solve (another system, --start, --seed or version): its fingerprint is {}, this solve's {fingerprint}",
            crate::terminal::one_line(&file.fingerprint)
        )));
    }
    let shard = Shard::new(file.shard, file.shards).ok_or_else(|| {
        Error::Input(format!(
            "{shown}: shard {}/{} is no shard",
            file.shard, file.shards
        ))
    })?;
    let start = StartSystem::from_name(&file.start)
        .filter(|s| *s != StartSystem::Auto)
        .ok_or_else(|| {
            Error::Input(format!(
                "{shown}: no start system {:?}",
                crate::terminal::one_line(&file.start)
            ))
        })?;
    let ends = file
        .ends
        .iter()
        .map(EndRecord::end)
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| Error::Input(format!("{shown}: a path failure kinsyn does not know")))?;
    Ok(ShardEnds {
        shard,
        start,
        seed: file.seed,
        paths: file.paths,
        ends,
        seconds: file.seconds,
    })
}

/// `kinsyn solve FILE --merge PART…`: the shards' ends of the solve of `path` with `options`
/// merged and finished ([`homotopy::merge_shards`]): the report of one process.
///
/// # Errors
/// A part that is not a shard file of this solve and version, shards that do not make one
/// solve (one missing or given twice), `--runs` above 1; as `kinsyn solve` otherwise.
pub fn merge_shard_files(
    path: &Path,
    options: &SolveOptions,
    parts: &[PathBuf],
) -> Result<Solved, Error> {
    if options.runs != 1 {
        return Err(Error::Input(format!(
            "--runs {} with --merge: a sharded solve is one run",
            options.runs
        )));
    }
    let source = path.display().to_string();
    let system = system_of(path)?;
    let settings = settings_of(options);
    let print = fingerprint(&system, &settings);
    let shards = parts
        .iter()
        .map(|p| read_shard(p, &print))
        .collect::<Result<Vec<_>, _>>()?;
    let count = shards.first().map_or(1, |s| s.shard.count);
    let sharded = SolveSettings {
        max_paths: options
            .max_paths
            .saturating_mul(u64::try_from(count).unwrap_or(u64::MAX)),
        ..settings.clone()
    };
    check_cost(&source, &system, &sharded, PathOption::MaxPaths)?;
    let report = crate::solve::with_threads(options.threads, || {
        homotopy::merge_shards(&system, &settings, &shards)
    })?
    .map_err(|e| Error::Input(format!("{source}: {e}")))?;
    let threads = options.threads.unwrap_or_else(rayon::current_num_threads);
    Ok(Solved {
        source,
        system,
        options: options.clone(),
        threads,
        runs: homotopy::combine_runs(vec![report]),
    })
}
