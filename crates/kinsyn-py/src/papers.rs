//! The commands of single papers: `kinsyn configurable inverse|forward|velocity` (paper 003's
//! planar 4-RRR with a configurable platform) and `kinsyn components` (the irreducible
//! components of a manipulator's constraint variety or of a polynomial system; paper 004's
//! operation modes), each by the command's own code (the crate `kinsyn_report`).

use crate::error::{Error, py_err};
use kinsyn::manipulator::DecompositionMethod;
use kinsyn_report::components::{ComponentsOptions, components_of};
use kinsyn_report::configurable::{forward_report, inverse_report, velocity_report};
use kinsyn_report::sorted_json;
use pyo3::prelude::*;
use std::path::PathBuf;

/// `kinsyn configurable inverse (--centre X,Y | --c4 X,Y) --theta T --phi P --json`, as JSON
/// text: the input sets that put paper 003's platform at a pose (lengths in mm, angles in
/// degrees).
#[pyfunction]
#[pyo3(signature = (theta, phi, centre = None, c4 = None))]
pub fn configurable_inverse_json(
    py: Python<'_>,
    theta: f64,
    phi: f64,
    centre: Option<&str>,
    c4: Option<&str>,
) -> PyResult<String> {
    py.detach(|| inverse_report(centre, c4, theta, phi))
        .map(|r| sorted_json(&r))
        .map_err(py_err)
}

/// `kinsyn configurable forward --q Q --method M --json`, as JSON text: every assembly of paper
/// 003's 4-RRR at the inputs `q` (degrees, comma-separated) by §3.2's method 1 or 2.
#[pyfunction]
#[pyo3(signature = (q, method = 2))]
pub fn configurable_forward_json(py: Python<'_>, q: &str, method: u8) -> PyResult<String> {
    py.detach(|| forward_report(q, method))
        .map(|r| sorted_json(&r))
        .map_err(py_err)
}

/// `kinsyn configurable velocity --q Q --qdot QDOT [--near N] --json`, as JSON text: the corner
/// velocities by screw theory (§4) at the assembly nearest `near` (C4x,C4y,θ,φ; default Table
/// 1's pose).
#[pyfunction]
#[pyo3(signature = (q, qdot, near = None))]
pub fn configurable_velocity_json(
    py: Python<'_>,
    q: &str,
    qdot: &str,
    near: Option<&str>,
) -> PyResult<String> {
    py.detach(|| velocity_report(q, qdot, near))
        .map(|r| sorted_json(&r))
        .map_err(py_err)
}

/// `kinsyn components FILE [--inputs I] [--free-inputs | --free F] [--body B] [--method M]
/// --seed S --json`, as JSON text: the irreducible components of a manipulator file's
/// constraint variety or of a Bertini input file's system. `method` is `by-dimension` (the
/// default) or `regeneration`; `max_paths` is `--max-paths` (the most paths tracked in all,
/// counted before any tracking; `None` for the command's default,
/// [`kinsyn::homotopy::DEFAULT_DECOMPOSE_PATHS`]); `free` the labels of `--free`, `body`
/// `--body`.
#[pyfunction]
#[pyo3(signature = (path, inputs = None, free_inputs = false, method = "by-dimension", seed = 1,
    max_paths = None, free = None, body = None))]
#[expect(
    clippy::needless_pass_by_value,
    reason = "PyO3 converts a Python path (str or os.PathLike) to an owned PathBuf"
)]
#[expect(
    clippy::too_many_arguments,
    reason = "one keyword argument per option of `kinsyn components`, as Python calls it"
)]
pub fn components_json(
    py: Python<'_>,
    path: PathBuf,
    inputs: Option<String>,
    free_inputs: bool,
    method: &str,
    seed: u64,
    max_paths: Option<u64>,
    free: Option<String>,
    body: Option<String>,
) -> PyResult<String> {
    // The command's clap parses these names.
    let method = match method {
        "by-dimension" => DecompositionMethod::ByDimension,
        "regeneration" => DecompositionMethod::Regeneration,
        other => {
            return Err(py_err(Error::Input(format!(
                "--method {other:?}: give by-dimension or regeneration"
            ))));
        }
    };
    let options = ComponentsOptions {
        seed,
        method,
        inputs,
        free_inputs,
        free,
        body,
        max_paths: max_paths.unwrap_or(kinsyn::homotopy::DEFAULT_DECOMPOSE_PATHS),
    };
    py.detach(|| components_of(&path, &options))
        .map(|c| sorted_json(&c.report()))
        .map_err(py_err)
}
