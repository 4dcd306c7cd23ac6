//! `kinsyn solve`: every isolated solution of a polynomial system in Bertini's input format,
//! by homotopy continuation, certified; the report of `kinsyn solve --json`, computed by the
//! command's own code ([`kinsyn_report::solve::solve_system`]).

use crate::error::{Error, py_err};
use kinsyn::homotopy::StartSystem;
use kinsyn_report::files::read_text;
use kinsyn_report::solve::{Show, SolveOptions, solve_system};
use pyo3::prelude::*;
use std::path::PathBuf;

/// The start system named `text` (as `kinsyn solve --start`).
fn start_system(text: &str) -> Result<StartSystem, Error> {
    StartSystem::from_name(text).ok_or_else(|| {
        Error::Input(format!(
            "--start {text:?}: give auto, total-degree, multi-homogeneous, linear-product or polyhedral"
        ))
    })
}

/// `kinsyn solve --json` for the system of `text` (named `source` in messages), with the GIL
/// released while it runs.
fn solve_report(
    py: Python<'_>,
    text: &str,
    source: &str,
    (seed, start, runs, threads, certify): (u64, &str, usize, Option<usize>, bool),
) -> PyResult<String> {
    let options = options(seed, start, runs, threads, certify).map_err(py_err)?;
    let solved = py
        .detach(|| solve_system(text, source, &options))
        .map_err(py_err)?;
    serde_json::to_string(&solved.json())
        .map_err(|e| py_err(Error::Internal(format!("the solve report: {e}"))))
}

/// Every isolated solution of the Bertini input `text` (named `source` in messages), as
/// `kinsyn solve FILE --json`, as JSON text.
#[pyfunction]
#[pyo3(signature = (text, source = "<string>", seed = 1, start = "auto", runs = 1,
    threads = None, certify = true))]
#[expect(clippy::too_many_arguments, reason = "the options of `kinsyn solve`")]
pub fn solve_json(
    py: Python<'_>,
    text: &str,
    source: &str,
    seed: u64,
    start: &str,
    runs: usize,
    threads: Option<usize>,
    certify: bool,
) -> PyResult<String> {
    solve_report(py, text, source, (seed, start, runs, threads, certify))
}

/// [`solve_json`] for the Bertini input file at `path` (messages name the file).
#[pyfunction]
#[pyo3(signature = (path, seed = 1, start = "auto", runs = 1, threads = None,
    certify = true))]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts a Python path (str or os.PathLike) to an owned PathBuf"
)]
pub fn solve_file_json(
    py: Python<'_>,
    path: PathBuf,
    seed: u64,
    start: &str,
    runs: usize,
    threads: Option<usize>,
    certify: bool,
) -> PyResult<String> {
    let text = read_text(&path, "not a Bertini input file").map_err(py_err)?;
    let source = path.display().to_string();
    solve_report(py, &text, &source, (seed, start, runs, threads, certify))
}

/// `kinsyn solve PATH --shard SHARD/SHARDS --out OUT --json`: the shard's paths tracked once
/// and written to `out`; the summary as JSON text. The GIL is released while it runs.
#[pyfunction]
#[pyo3(signature = (path, shard, shards, out, seed = 1, start = "auto", threads = None,
    force = false))]
#[expect(
    clippy::too_many_arguments,
    reason = "the options of `kinsyn solve --shard`"
)]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts a Python path (str or os.PathLike) to an owned PathBuf"
)]
pub fn solve_shard_json(
    py: Python<'_>,
    path: PathBuf,
    shard: usize,
    shards: usize,
    out: PathBuf,
    seed: u64,
    start: &str,
    threads: Option<usize>,
    force: bool,
) -> PyResult<String> {
    let shard =
        kinsyn_report::solve_shards::parse_shard(&format!("{shard}/{shards}")).map_err(py_err)?;
    let options = options(seed, start, 1, threads, true).map_err(py_err)?;
    let summary = py
        .detach(|| {
            kinsyn_report::solve_shards::solve_shard_file(&path, &options, shard, &out, force)
        })
        .map_err(py_err)?;
    serde_json::to_string(&summary)
        .map_err(|e| py_err(Error::Internal(format!("the shard summary: {e}"))))
}

/// `kinsyn solve PATH --merge PARTS… --json`: the solve finished from its shard files, as JSON
/// text (the report of one process). The GIL is released while it runs.
#[pyfunction]
#[pyo3(signature = (path, parts, seed = 1, start = "auto", threads = None, certify = true))]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts Python paths (str or os.PathLike) to owned PathBufs"
)]
pub fn merge_shards_json(
    py: Python<'_>,
    path: PathBuf,
    parts: Vec<PathBuf>,
    seed: u64,
    start: &str,
    threads: Option<usize>,
    certify: bool,
) -> PyResult<String> {
    let options = options(seed, start, 1, threads, certify).map_err(py_err)?;
    let solved = py
        .detach(|| kinsyn_report::solve_shards::merge_shard_files(&path, &options, &parts))
        .map_err(py_err)?;
    serde_json::to_string(&solved.json())
        .map_err(|e| py_err(Error::Internal(format!("the solve report: {e}"))))
}

/// The options of `kinsyn solve` as the Python calls give them.
fn options(
    seed: u64,
    start: &str,
    runs: usize,
    threads: Option<usize>,
    certify: bool,
) -> Result<SolveOptions, Error> {
    Ok(SolveOptions {
        start: start_system(start)?,
        seed,
        runs,
        threads,
        max_paths: kinsyn::homotopy::DEFAULT_MAX_PATHS,
        certify,
        show: Show::None,
    })
}
