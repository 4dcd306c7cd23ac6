//! The catalogue of paper 000 §2 (the committed one, as `kinsyn catalogue list`) and its
//! queries by motion pattern (as `kinsyn query`).

use crate::error::{Error, py_err};
use kinsyn::catalogue::Catalogue;
use kinsyn::motion::PatternQuery;
use kinsyn::synthesis::tables;
use pyo3::prelude::*;

/// The committed catalogue (compiled in, read in milliseconds).
fn committed() -> Result<Catalogue, Error> {
    Catalogue::committed().map_err(|e| {
        Error::Internal(format!(
            "the catalogue compiled into kinsyn cannot be read: {e} (a damaged build: regenerate catalogue/chains.json with `kinsyn catalogue generate` and rebuild)"
        ))
    })
}

/// Every catalogue entry, as `kinsyn catalogue list --json`.
#[pyfunction]
pub fn catalogue_json() -> PyResult<String> {
    let cat = committed().map_err(py_err)?;
    Ok(serde_json::to_string(&cat.entries).expect("serialisable"))
}

/// The entries whose legs give `pattern` with at most `max_locks` joints locked, one row per
/// (entry, pattern), as `kinsyn query PATTERN --max-locks K [--family F] --json`.
#[pyfunction]
#[pyo3(signature = (pattern, max_locks = 6, family = None))]
pub fn query_json(pattern: &str, max_locks: usize, family: Option<&str>) -> PyResult<String> {
    let q: PatternQuery = pattern
        .parse()
        .map_err(|e| py_err(Error::Input(format!("{e}"))))?;
    if let Some(f) = family
        && !tables::families().contains(&f)
    {
        return Err(py_err(Error::Input(format!(
            "unknown family {f:?}; the families are {}",
            tables::families().join(", ")
        ))));
    }
    if max_locks > 6 {
        return Err(py_err(Error::Input(format!(
            "--max-locks {max_locks}: a leg has six joints"
        ))));
    }
    let cat = committed().map_err(py_err)?;
    let rows: Vec<serde_json::Value> = cat
        .query(&q, max_locks, family)
        .iter()
        .map(|h| serde_json::json!({"id": h.entry.id, "notation": h.entry.notation, "family": h.entry.family, "word": h.entry.word, "axes": h.entry.axes, "pattern": h.pattern, "lock_sets": h.lock_sets}))
        .collect();
    Ok(serde_json::to_string(&rows).expect("serialisable"))
}
