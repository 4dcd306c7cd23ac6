//! `kinsyn sweep` and `kinsyn sweep merge` as the command runs them (their text in
//! `render::sweep`), and
//! `designs.parquet`, the rows of a sweep as one flat table (docs/sweep.md lists the columns)
//! with the sweep's manifest in the file's key-value metadata, encoded by the Parquet crate's
//! Arrow writer.

use super::sweep::{Manifest, Request, merge, outcome_json, run_request};
use super::{CliError, json, render};
use arrow_array::builder::{ListBuilder, StringBuilder, UInt32Builder};
use arrow_array::{ArrayRef, RecordBatch, StringArray, UInt32Array};
use kinsyn::sweep::DesignRow;
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Rows per row group: the whole committed sweep (9261 designs) is one group, and the groups
/// of a file depend on its rows only.
const ROW_GROUP: usize = 16_384;

/// A count as a `u32` column value (counts and indices of a sweep are far below 2^32).
fn u32_of(v: usize) -> u32 {
    u32::try_from(v).unwrap_or(u32::MAX)
}

/// A column of counts taken from each row.
fn counts(rows: &[&DesignRow], f: impl Fn(&DesignRow) -> usize) -> ArrayRef {
    Arc::new(UInt32Array::from_iter_values(
        rows.iter().map(|r| u32_of(f(r))),
    ))
}

/// A column of text taken from each row.
fn texts<'a>(rows: &[&'a DesignRow], f: impl Fn(&'a DesignRow) -> &'a str) -> ArrayRef {
    Arc::new(StringArray::from_iter_values(rows.iter().map(|r| f(r))))
}

/// A value as compact JSON.
fn compact<T: serde::Serialize>(value: &T) -> String {
    serde_json::to_string(value).expect("serialisable")
}

/// The file's key-value metadata ([`Manifest::table_metadata`]).
fn metadata(manifest: &Manifest) -> Vec<KeyValue> {
    manifest
        .table_metadata()
        .into_iter()
        .map(|(k, v)| KeyValue::new(k.into(), v))
        .collect()
}

/// `rows` (sorted by design) as the bytes of `designs.parquet`: snappy pages, the same bytes
/// for the same rows and manifest.
///
/// # Errors
/// [`CliError::Internal`] when the Arrow or Parquet writer fails (a fault of the build).
pub fn parquet_bytes(manifest: &Manifest, rows: &[&DesignRow]) -> Result<Vec<u8>, CliError> {
    let internal = |e: &dyn std::fmt::Display| CliError::Internal(format!("designs.parquet: {e}"));
    let mut actuated = ListBuilder::new(UInt32Builder::new());
    let mut kinds = ListBuilder::new(StringBuilder::new());
    let mut singular = ListBuilder::new(StringBuilder::new());
    for r in rows {
        for set in &r.singular_lock_sets {
            singular.values().append_value(set);
        }
        singular.append(true);
        for &j in &r.actuated {
            actuated.values().append_value(u32_of(j));
        }
        actuated.append(true);
        for k in &r.group_kinds {
            kinds.values().append_value(k);
        }
        kinds.append(true);
    }
    let json_of = |v: &[kinsyn::sweep::Reached]| compact(&v);
    let groups: ArrayRef = Arc::new(StringArray::from_iter_values(
        rows.iter().map(|r| json_of(&r.groups)),
    ));
    let non_groups: ArrayRef = Arc::new(StringArray::from_iter_values(
        rows.iter().map(|r| json_of(&r.non_groups)),
    ));
    let error: ArrayRef = Arc::new(
        rows.iter()
            .map(|r| r.error.as_deref())
            .collect::<StringArray>(),
    );
    let batch = RecordBatch::try_from_iter_with_nullable([
        ("design", counts(rows, |r| r.design), false),
        ("chain", texts(rows, |r| &r.chain), false),
        ("notation", texts(rows, |r| &r.notation), false),
        ("family", texts(rows, |r| &r.family), false),
        ("legs", counts(rows, |r| r.legs), false),
        ("actuated", Arc::new(actuated.finish()) as ArrayRef, false),
        ("inputs", counts(rows, |r| r.inputs), false),
        ("dof", counts(rows, |r| r.dof), false),
        ("subgroups", counts(rows, |r| r.subgroups), false),
        ("kinds", counts(rows, |r| r.kinds), false),
        ("group_kinds", Arc::new(kinds.finish()) as ArrayRef, false),
        ("groups", groups, false),
        ("non_groups", non_groups, false),
        ("unsampled", counts(rows, |r| r.unsampled), false),
        ("singular", counts(rows, |r| r.singular), false),
        (
            "singular_lock_sets",
            Arc::new(singular.finish()) as ArrayRef,
            false,
        ),
        ("error", error, true),
    ])
    .map_err(|e| internal(&e))?;
    let properties = WriterProperties::builder()
        .set_compression(Compression::SNAPPY)
        .set_max_row_group_row_count(Some(ROW_GROUP))
        .set_key_value_metadata(Some(metadata(manifest)))
        .build();
    let mut bytes = Vec::new();
    let mut writer = ArrowWriter::try_new(&mut bytes, batch.schema(), Some(properties))
        .map_err(|e| internal(&e))?;
    writer.write(&batch).map_err(|e| internal(&e))?;
    writer.close().map_err(|e| internal(&e))?;
    Ok(bytes)
}

/// `kinsyn sweep --out DIR …`: runs (or resumes) the sweep and reports it.
pub(super) fn command(
    out: &Path,
    request: &Request,
    bench: bool,
    as_json: bool,
) -> Result<String, CliError> {
    let outcome = run_request(out, request, true, &parquet_bytes)?;
    if as_json {
        return Ok(json(&outcome_json(&outcome)));
    }
    Ok(render::sweep::run(&outcome, bench))
}

/// `kinsyn sweep merge DIR… --out OUT [--force]`.
pub(super) fn merge_command(
    dirs: &[PathBuf],
    out: &Path,
    force: bool,
    as_json: bool,
) -> Result<String, CliError> {
    let manifest = merge(dirs, out, force, &parquet_bytes)?;
    if as_json {
        return Ok(json(&manifest));
    }
    Ok(render::sweep::merged(out, dirs.len(), &manifest))
}
