//! `kinsyn sweep` and `kinsyn sweep merge` as the command runs them (their text in
//! `render::sweep`), and
//! `designs.parquet`, the rows of a sweep as one flat table (docs/sweep.md lists the columns)
//! with the sweep's manifest in the file's key-value metadata, encoded by the Parquet crate's
//! own column writers (no Arrow): [`COLUMNS`] names each column and says how its cells come
//! from a row, which fixes its Parquet type; the schema and the writing both follow that list.

use super::sweep::{Manifest, Request, merge, outcome_json, run_request};
use super::{CliError, json, render};
use kinsyn::sweep::{DesignRow, Reached};
use parquet::basic::{Compression, LogicalType, Repetition, Type as PhysicalType};
use parquet::data_type::{ByteArray, ByteArrayType, DataType, Int32Type};
use parquet::errors::ParquetError;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use parquet::file::writer::{SerializedColumnWriter, SerializedFileWriter};
use parquet::schema::types::{Type, TypePtr};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Rows per row group: the whole committed sweep (9261 designs) is one group, and the groups
/// of a file depend on its rows only.
const ROW_GROUP: usize = 16_384;

/// How the cells of a column are taken from a row; this fixes the column's Parquet type (in
/// brackets, the type pyarrow and the Arrow readers give it).
#[derive(Clone, Copy)]
enum Cells {
    /// A count or an index: `INT32` annotated as an unsigned 32-bit integer, required
    /// (`uint32`).
    Count(fn(&DesignRow) -> usize),
    /// Text: `BYTE_ARRAY` annotated as UTF-8, required (`string`).
    Text(fn(&DesignRow) -> &str),
    /// Patterns reached, as compact JSON text (the array of objects `designs.jsonl` has):
    /// `BYTE_ARRAY` annotated as UTF-8, required (`string`).
    Patterns(fn(&DesignRow) -> &[Reached]),
    /// Text or nothing: `BYTE_ARRAY` annotated as UTF-8, optional (a nullable `string`, null
    /// for nothing).
    OptionalText(fn(&DesignRow) -> Option<&str>),
    /// A list of counts: a required list ([`list_type`]) of unsigned 32-bit integers
    /// (`list<uint32>`).
    Counts(fn(&DesignRow) -> &[usize]),
    /// A list of texts: a required list ([`list_type`]) of UTF-8 texts (`list<string>`).
    Texts(fn(&DesignRow) -> &[String]),
}

/// The table's columns in order, each a name and its cells (the fields of [`DesignRow`], whose
/// docs and docs/sweep.md say what they mean).
const COLUMNS: [(&str, Cells); 17] = [
    // The design's index in the sweep.
    ("design", Cells::Count(|r| r.design)),
    // The leg chain: its catalogue id, notation and family.
    ("chain", Cells::Text(|r| &r.chain)),
    ("notation", Cells::Text(|r| &r.notation)),
    ("family", Cells::Text(|r| &r.family)),
    ("legs", Cells::Count(|r| r.legs)),
    // The actuated primitive joints of each leg, 1-based.
    ("actuated", Cells::Counts(|r| &r.actuated)),
    ("inputs", Cells::Count(|r| r.inputs)),
    // The platform's dof with nothing locked.
    ("dof", Cells::Count(|r| r.dof)),
    // Distinct displacement subgroups reached, and how many kinds of group (the capacity).
    ("subgroups", Cells::Count(|r| r.subgroups)),
    ("kinds", Cells::Count(|r| r.kinds)),
    // The kinds of group reached, each once.
    ("group_kinds", Cells::Texts(|r| &r.group_kinds)),
    // The subgroups and the non-group patterns reached, with their minimal lock sets.
    ("groups", Cells::Patterns(|r| &r.groups)),
    ("non_groups", Cells::Patterns(|r| &r.non_groups)),
    // Lock subsets not sampled, and those whose start is singular (with their lock sets).
    ("unsampled", Cells::Count(|r| r.unsampled)),
    ("singular", Cells::Count(|r| r.singular)),
    (
        "singular_lock_sets",
        Cells::Texts(|r| &r.singular_lock_sets),
    ),
    // Why the design could not be built or sampled; null when it was.
    ("error", Cells::OptionalText(|r| r.error.as_deref())),
];

/// The name of the schema's root (which readers do not show): the one the Arrow writer, which
/// encoded this file before, gave it, so that the Parquet schema is the same as before.
const ROOT: &str = "arrow_schema";

/// The name of a list's element: Arrow's, which pyarrow and the Arrow readers give back
/// (`list<item: uint32>`).
const ITEM: &str = "item";

/// A count as a `u32` column value (counts and indices of a sweep are far below 2^32).
fn u32_of(v: usize) -> u32 {
    u32::try_from(v).unwrap_or(u32::MAX)
}

/// A count as the `INT32` value Parquet stores: the bits of its `u32` ([`u32_of`]), read back as
/// unsigned by the column's annotation.
fn int32_of(v: usize) -> i32 {
    u32_of(v).cast_signed()
}

/// Text as a `BYTE_ARRAY` value (its UTF-8 bytes).
fn bytes_of(text: &str) -> ByteArray {
    ByteArray::from(text.as_bytes().to_vec())
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

/// A leaf column `name`: `physical` values annotated `logical`, `repetition` required or
/// optional.
fn leaf_type(
    name: &str,
    physical: PhysicalType,
    logical: LogicalType,
    repetition: Repetition,
) -> Result<TypePtr, ParquetError> {
    let leaf = Type::primitive_type_builder(name, physical)
        .with_logical_type(Some(logical))
        .with_repetition(repetition)
        .build()?;
    Ok(Arc::new(leaf))
}

/// A required list column `name` of `element`s: Parquet's three-level list (a group annotated
/// LIST holding a repeated group `list` holding the element), laid out as the Arrow writer did
/// and pyarrow reads as `list<item: …>` (the element optional, though never null here).
fn list_type(name: &str, element: TypePtr) -> Result<TypePtr, ParquetError> {
    let repeated = Type::group_type_builder("list")
        .with_repetition(Repetition::REPEATED)
        .with_fields(vec![element])
        .build()?;
    let list = Type::group_type_builder(name)
        .with_repetition(Repetition::REQUIRED)
        .with_logical_type(Some(LogicalType::List))
        .with_fields(vec![Arc::new(repeated)])
        .build()?;
    Ok(Arc::new(list))
}

/// The Parquet type of the column `name` holding `cells` (see [`Cells`]).
fn column_type(name: &str, cells: Cells) -> Result<TypePtr, ParquetError> {
    let unsigned = || LogicalType::integer(32, false);
    let (int32, text) = (PhysicalType::INT32, PhysicalType::BYTE_ARRAY);
    let (required, optional) = (Repetition::REQUIRED, Repetition::OPTIONAL);
    match cells {
        Cells::Count(_) => leaf_type(name, int32, unsigned(), required),
        Cells::Text(_) | Cells::Patterns(_) => leaf_type(name, text, LogicalType::String, required),
        Cells::OptionalText(_) => leaf_type(name, text, LogicalType::String, optional),
        Cells::Counts(_) => list_type(name, leaf_type(ITEM, int32, unsigned(), optional)?),
        Cells::Texts(_) => list_type(name, leaf_type(ITEM, text, LogicalType::String, optional)?),
    }
}

/// The file's schema: [`COLUMNS`] in order under the root [`ROOT`].
fn schema() -> Result<TypePtr, ParquetError> {
    let fields = COLUMNS
        .iter()
        .map(|&(name, cells)| column_type(name, cells))
        .collect::<Result<_, _>>()?;
    Ok(Arc::new(
        Type::group_type_builder(ROOT).with_fields(fields).build()?,
    ))
}

/// The definition and repetition levels of list cells with `lengths` elements each, in a
/// required list of optional elements that are all present ([`list_type`]): an empty list is
/// one level (definition 0: no element; repetition 0: a new row); a list of n elements is n
/// levels, definition 2 (the element present), repetition 0 for the first and 1 (the same
/// list) for the others.
fn list_levels(lengths: impl Iterator<Item = usize>) -> (Vec<i16>, Vec<i16>) {
    let (mut definition, mut repetition) = (Vec::new(), Vec::new());
    for n in lengths {
        if n == 0 {
            definition.push(0);
            repetition.push(0);
        } else {
            definition.extend(std::iter::repeat_n(2, n));
            repetition.push(0);
            repetition.extend(std::iter::repeat_n(1, n - 1));
        }
    }
    (definition, repetition)
}

/// Writes one value per row to a required, unrepeated column of type `T`.
fn write_required<T: DataType>(
    column: &mut SerializedColumnWriter<'_>,
    values: &[T::T],
) -> Result<(), ParquetError> {
    column
        .typed::<T>()
        .write_batch(values, None, None)
        .map(drop)
}

/// Writes one text or null per row to an optional text column: the texts present, and one
/// definition level per row (1 present, 0 null).
fn write_optional_texts(
    column: &mut SerializedColumnWriter<'_>,
    texts: &[Option<&str>],
) -> Result<(), ParquetError> {
    let values: Vec<ByteArray> = texts.iter().flatten().map(|t| bytes_of(t)).collect();
    let definition: Vec<i16> = texts.iter().map(|t| i16::from(t.is_some())).collect();
    column
        .typed::<ByteArrayType>()
        .write_batch(&values, Some(&definition), None)
        .map(drop)
}

/// Writes one list per row to a list column of `T` elements ([`list_type`]): the elements of
/// every list, each as `value` gives it, with the levels that place them in rows
/// ([`list_levels`]).
fn write_lists<'a, T: DataType, E: 'a>(
    column: &mut SerializedColumnWriter<'_>,
    lists: &[&'a [E]],
    value: impl Fn(&E) -> T::T,
) -> Result<(), ParquetError> {
    let (definition, repetition) = list_levels(lists.iter().map(|l| l.len()));
    let values: Vec<T::T> = lists.iter().flat_map(|l| l.iter()).map(value).collect();
    column
        .typed::<T>()
        .write_batch(&values, Some(&definition), Some(&repetition))
        .map(drop)
}

/// Writes the cells of `rows` to their column, as [`Cells`] says.
fn write_cells(
    column: &mut SerializedColumnWriter<'_>,
    cells: Cells,
    rows: &[&DesignRow],
) -> Result<(), ParquetError> {
    match cells {
        Cells::Count(f) => {
            let values: Vec<i32> = rows.iter().map(|r| int32_of(f(r))).collect();
            write_required::<Int32Type>(column, &values)
        }
        Cells::Text(f) => {
            let values: Vec<ByteArray> = rows.iter().map(|r| bytes_of(f(r))).collect();
            write_required::<ByteArrayType>(column, &values)
        }
        Cells::Patterns(f) => {
            let values: Vec<ByteArray> = rows.iter().map(|r| bytes_of(&compact(&f(r)))).collect();
            write_required::<ByteArrayType>(column, &values)
        }
        Cells::OptionalText(f) => {
            let texts: Vec<Option<&str>> = rows.iter().map(|r| f(r)).collect();
            write_optional_texts(column, &texts)
        }
        Cells::Counts(f) => {
            let lists: Vec<&[usize]> = rows.iter().map(|r| f(r)).collect();
            write_lists::<Int32Type, _>(column, &lists, |&v| int32_of(v))
        }
        Cells::Texts(f) => {
            let lists: Vec<&[String]> = rows.iter().map(|r| f(r)).collect();
            write_lists::<ByteArrayType, _>(column, &lists, |t| bytes_of(t))
        }
    }
}

/// Writes `rows` as the file's next row group: each column of [`COLUMNS`] in turn (one leaf
/// column each).
fn write_row_group(
    file: &mut SerializedFileWriter<&mut Vec<u8>>,
    rows: &[&DesignRow],
) -> Result<(), ParquetError> {
    let mut group = file.next_row_group()?;
    for &(name, cells) in &COLUMNS {
        let mut column = group
            .next_column()?
            .ok_or_else(|| ParquetError::General(format!("no column {name} in the schema")))?;
        write_cells(&mut column, cells, rows)?;
        column.close()?;
    }
    group.close()?;
    Ok(())
}

/// `rows` (sorted by design) as the bytes of `designs.parquet`: one row group per 16,384 rows
/// (`ROW_GROUP`), snappy pages, the manifest's key-value metadata; the same bytes for the same
/// rows and manifest.
///
/// # Errors
/// [`CliError::Internal`] when the Parquet writer fails (a fault of the build).
pub fn parquet_bytes(manifest: &Manifest, rows: &[&DesignRow]) -> Result<Vec<u8>, CliError> {
    let encode = || -> Result<Vec<u8>, ParquetError> {
        let properties = WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .set_key_value_metadata(Some(metadata(manifest)))
            .build();
        let mut bytes = Vec::new();
        let mut file = SerializedFileWriter::new(&mut bytes, schema()?, Arc::new(properties))?;
        for group in rows.chunks(ROW_GROUP) {
            write_row_group(&mut file, group)?;
        }
        file.close()?;
        Ok(bytes)
    };
    encode().map_err(|e| CliError::Internal(format!("designs.parquet: {e}")))
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
