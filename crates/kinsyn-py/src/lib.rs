//! The Python module `kinsyn._native`: kinsyn's catalogue, manipulators, homotopy solver and the
//! commands of single papers (paper 003's configurable 4-RRR, `components`) and the
//! catalogue-wide sweep (`kinsyn sweep`, as files in a directory) for the pure-Python
//! package `kinsyn`, which turns the reports into pandas and numpy objects.
//!
//! Each function gives the report the `kinsyn` command gives with `--json`, as JSON text, and
//! refuses bad input with the command's one-line message (without its `kinsyn: error: `
//! prefix) as a `kinsyn.InputError`. Long computations run with the GIL released.

mod catalogue;
mod error;
mod manipulator;
mod papers;
mod solve;
mod sweep;

use pyo3::prelude::*;

/// The module `kinsyn._native`.
#[pymodule]
#[pyo3(name = "_native")]
fn kinsyn_native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("KinsynError", py.get_type::<error::KinsynError>())?;
    m.add("InputError", py.get_type::<error::InputError>())?;
    m.add_function(wrap_pyfunction!(catalogue::catalogue_json, m)?)?;
    m.add_function(wrap_pyfunction!(catalogue::query_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve::solve_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve::solve_file_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve::solve_shard_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve::merge_shards_json, m)?)?;
    m.add_function(wrap_pyfunction!(papers::configurable_inverse_json, m)?)?;
    m.add_function(wrap_pyfunction!(papers::configurable_forward_json, m)?)?;
    m.add_function(wrap_pyfunction!(papers::configurable_velocity_json, m)?)?;
    m.add_function(wrap_pyfunction!(papers::components_json, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_json, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_merge_json, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_partitions_json, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_rows_json, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_check_table, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_table_rows_json, m)?)?;
    m.add_class::<manipulator::Manipulator>()?;
    Ok(())
}
