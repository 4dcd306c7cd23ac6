//! `kinsyn sweep` and `kinsyn sweep merge` (docs/sweep.md): the catalogue-wide multioperation
//! sweep run into a directory (whole or one shard, resumable), shard directories merged, the
//! shards of a sweep listed, and a sweep's rows read back (checked as `kinsyn sweep report`
//! reads them), each by the command's own code ([`kinsyn_report::sweep`]).

use crate::error::{Error, py_err};
use kinsyn::mechanism::SampleSettings;
use kinsyn::sweep::DesignRow;
use kinsyn_report::files::check_file;
use kinsyn_report::sweep::{
    Manifest, ROW_FILES, Request, Shard, check_rows, merge, outcome_json, read_results, rows_file,
    run_request, shard_manifests,
};
use pyo3::prelude::*;
use std::path::PathBuf;

/// The chain ids as `--chains` takes them: comma-separated.
fn chains_text(chains: Option<&[String]>) -> Option<String> {
    chains.map(|c| c.join(","))
}

/// `value` as JSON text.
fn to_json(value: Result<serde_json::Value, serde_json::Error>) -> PyResult<String> {
    value
        .and_then(|v| serde_json::to_string(&v))
        .map_err(|e| py_err(Error::Internal(format!("the sweep report: {e}"))))
}

/// `row` as a JSON line whose `groups` and `non_groups` are their compact JSON text, as
/// `designs.parquet` holds them.
fn table_line(row: &DesignRow) -> String {
    let mut value = serde_json::to_value(row).unwrap_or_default();
    if let Some(o) = value.as_object_mut() {
        for (name, reached) in [("groups", &row.groups), ("non_groups", &row.non_groups)] {
            o.insert(
                name.into(),
                serde_json::to_string(reached).unwrap_or_default().into(),
            );
        }
    }
    let mut line = value.to_string();
    line.push('\n');
    line
}

/// `rows` (sorted by design) and `manifest` as the bytes of `designs.parquet`, encoded by pyarrow
/// (`kinsyn.sweep._parquet_bytes`): the command's columns, types and key-value metadata
/// ([`Manifest::table_metadata`]), so that the file reads back to the same frame as the
/// command's. Called with the GIL taken again while a sweep or merge runs without it.
fn parquet_by_pyarrow(manifest: &Manifest, rows: &[&DesignRow]) -> Result<Vec<u8>, Error> {
    let rows: String = rows.iter().map(|r| table_line(r)).collect();
    let metadata: Vec<(String, String)> = manifest
        .table_metadata()
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect();
    Python::attach(|py| -> PyResult<Vec<u8>> {
        py.import("kinsyn.sweep")?
            .getattr("_parquet_bytes")?
            .call1((rows, metadata))?
            .extract()
    })
    .map_err(|e| Error::Internal(format!("designs.parquet (pyarrow): {e}")))
}

/// `kinsyn sweep --out OUT [--shard K/N] … --json`, as JSON text: runs (or resumes, or finds
/// complete) the sweep of `legs` legs with `actuated` actuated joints per leg over the chosen
/// catalogue chains into the directory `out`, and reports the run. `seed` `None` is the
/// command's default; `force` is `--force` (another sweep's files in `out` replaced). No
/// progress bar is drawn.
#[pyfunction]
#[pyo3(signature = (out, legs = 3, actuated = vec![1, 2], seed = None, chains = None,
    family = None, shard = None, threads = None, stop_after = None, force = false))]
#[expect(clippy::too_many_arguments, reason = "the options of `kinsyn sweep`")]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts Python paths and lists to owned values"
)]
pub fn sweep_json(
    py: Python<'_>,
    out: PathBuf,
    legs: usize,
    actuated: Vec<usize>,
    seed: Option<u64>,
    chains: Option<Vec<String>>,
    family: Option<String>,
    shard: Option<String>,
    threads: Option<usize>,
    stop_after: Option<usize>,
    force: bool,
) -> PyResult<String> {
    let chains = chains_text(chains.as_deref());
    let request = Request {
        legs,
        actuated: &actuated,
        seed: seed.unwrap_or(SampleSettings::default().seed),
        chains: chains.as_deref(),
        family: family.as_deref(),
        shard: shard.as_deref(),
        threads,
        stop_after,
        force,
    };
    let outcome = py
        .detach(|| run_request(&out, &request, false, &parquet_by_pyarrow))
        .map_err(py_err)?;
    to_json(Ok(outcome_json(&outcome)))
}

/// `kinsyn sweep merge DIRS… --out OUT [--force] --json`, as JSON text: the complete shard
/// directories `dirs` of one sweep merged into `out` (the files one run of the whole sweep
/// writes; existing ones replaced only when `force`); the merged manifest.
#[pyfunction]
#[pyo3(signature = (dirs, out, force = false))]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts Python paths and lists to owned values"
)]
pub fn sweep_merge_json(
    py: Python<'_>,
    dirs: Vec<PathBuf>,
    out: PathBuf,
    force: bool,
) -> PyResult<String> {
    let manifest = py
        .detach(|| merge(&dirs, &out, force, &parquet_by_pyarrow))
        .map_err(py_err)?;
    to_json(serde_json::to_value(&manifest))
}

/// The manifests of the shards 1/`count` … `count`/`count` of the sweep with these options, as a
/// JSON array: what `kinsyn sweep --shard K/N` writes into `sweep.json` when it starts (the
/// chains in the catalogue's spelling and order, the seed, each shard's design count).
#[pyfunction]
#[pyo3(signature = (count, legs = 3, actuated = vec![1, 2], seed = None, chains = None,
    family = None))]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts Python lists to owned values"
)]
pub fn sweep_partitions_json(
    py: Python<'_>,
    count: i64,
    legs: usize,
    actuated: Vec<usize>,
    seed: Option<u64>,
    chains: Option<Vec<String>>,
    family: Option<String>,
) -> PyResult<String> {
    // A negative count is refused as `--shard 1/-1` is.
    let Ok(count) = usize::try_from(count) else {
        let refused = Shard::parse(&format!("1/{count}")).err();
        return Err(py_err(refused.unwrap_or_else(|| {
            Error::Input(format!("{count} shards: give 1 or more"))
        })));
    };
    let chains = chains_text(chains.as_deref());
    let request = Request {
        legs,
        actuated: &actuated,
        seed: seed.unwrap_or(SampleSettings::default().seed),
        chains: chains.as_deref(),
        family: family.as_deref(),
        shard: None,
        threads: None,
        stop_after: None,
        force: false,
    };
    let manifests = py
        .detach(|| shard_manifests(&request, count))
        .map_err(py_err)?;
    to_json(serde_json::to_value(&manifests))
}

/// The manifest and rows read back, as `{"manifest": …, "rows": […]}`.
fn rows_json(manifest: Option<&Manifest>, rows: &[DesignRow]) -> PyResult<String> {
    to_json(Ok(
        serde_json::json!({ "manifest": manifest, "rows": rows }),
    ))
}

/// The rows of `path` (a sweep directory or a `.jsonl` file of rows), read and checked as
/// `kinsyn sweep report` reads them (the file checks of every input, each row a design of the
/// folder's sweep, or of the catalogue without a manifest), as JSON text `{"manifest": …,
/// "rows": […]}`.
#[pyfunction]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts Python paths to owned values"
)]
pub fn sweep_rows_json(py: Python<'_>, path: PathBuf) -> PyResult<String> {
    let read = py.detach(|| read_results(&path)).map_err(py_err)?;
    rows_json(read.manifest.as_ref(), &read.rows)
}

/// Checks that the table `path` (`designs.parquet`) may be read: a regular file within the
/// size limit of files of rows.
#[pyfunction]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts Python paths to owned values"
)]
pub fn sweep_check_table(path: PathBuf) -> PyResult<()> {
    check_file(&path, "not a table of kinsyn sweep rows", ROW_FILES)
        .map(|_| ())
        .map_err(py_err)
}

/// The rows read from the table `path` (`designs.parquet`), given as JSON lines `rows`,
/// checked as the rows of a file in its folder are, as JSON text `{"manifest": …, "rows":
/// […]}`.
#[pyfunction]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts Python paths and strings to owned values"
)]
pub fn sweep_table_rows_json(py: Python<'_>, path: PathBuf, rows: String) -> PyResult<String> {
    let (_, folder) = rows_file(&path).map_err(py_err)?;
    let (manifest, rows) = py
        .detach(|| check_rows(&rows, &folder, &path))
        .map_err(py_err)?;
    rows_json(manifest.as_ref(), &rows)
}
