//! `kinsyn sweep` and `kinsyn sweep merge` (docs/sweep.md) on small selections: the rows
//! against an independent path through the command line (`kinsyn build` + `kinsyn modes`) and
//! the 3-UPS's mobility by hand, and the files against themselves written in other ways (one
//! or two threads, shards merged, interrupted and resumed, Parquet read back).

use crate::common;
use common::{assert_refused, kinsyn, stderr, stdout};
use serde_json::Value;
use std::path::{Path, PathBuf};

const SMALL: &[&str] = &["--chains", "T1-001,T1-002", "--actuated", "1"];

/// Runs `kinsyn sweep --out DIR` with `args`, asserting success; returns stdout.
fn sweep(dir: &Path, args: &[&str]) -> String {
    let mut all = vec!["sweep", "--out", dir.to_str().unwrap()];
    all.extend_from_slice(args);
    let o = kinsyn(&all);
    assert_eq!(o.status.code(), Some(0), "{all:?}: {}", stderr(&o));
    stdout(&o)
}

/// The three result files of a directory, as bytes.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    ["designs.jsonl", "designs.parquet", "sweep.json"]
        .iter()
        .map(|f| {
            let bytes = std::fs::read(dir.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
            ((*f).to_string(), bytes)
        })
        .collect()
}

fn assert_same_files(a: &Path, b: &Path) {
    for ((name, x), (_, y)) in files(a).iter().zip(files(b)) {
        assert!(
            *x == y,
            "{name} differs between {} and {}",
            a.display(),
            b.display()
        );
    }
    assert!(
        !b.join("checkpoint.jsonl").exists(),
        "checkpoint left in {}",
        b.display()
    );
}

fn rows(dir: &Path) -> Vec<Value> {
    std::fs::read_to_string(dir.join("designs.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

fn temp() -> tempfile::TempDir {
    tempfile::tempdir().unwrap()
}

/// The patterns of a modes report or a row, as (pattern, dof, subsets, lock sets), sorted.
fn patterns(list: &Value) -> Vec<(String, u64, u64, Vec<String>)> {
    let mut v: Vec<_> = list
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            (
                p["pattern"].as_str().unwrap().to_string(),
                p["dof"].as_u64().unwrap(),
                p["subsets"].as_u64().unwrap(),
                p["lock_sets"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|s| s.as_str().unwrap().to_string())
                    .collect(),
            )
        })
        .collect();
    v.sort();
    v
}

/// A row equals what `kinsyn build` + `kinsyn modes --json` give for its design: the file
/// written and read back, the modes sampled by the `modes` command (a second path through the
/// command line, its own file reader and subset list).
#[test]
fn a_row_is_what_build_and_modes_give_for_its_design() {
    let dir = temp();
    let out = dir.path().join("s");
    sweep(&out, &["--chains", "T1-002,T4-034", "--actuated", "1"]);
    let rows = rows(&out);
    assert_eq!(rows.len(), 12);
    for design in [1, 6 + 2, 6 + 5] {
        let row = &rows[design];
        assert_eq!(row["design"], design);
        let chain = row["chain"].as_str().unwrap();
        let actuated = row["actuated"][0].to_string();
        let file = dir.path().join(format!("d{design}.json"));
        let o = kinsyn(&[
            "build",
            "--legs",
            "3",
            "--chain",
            chain,
            "--actuated",
            &actuated,
            "-o",
            file.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let o = kinsyn(&["modes", file.to_str().unwrap(), "--json"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let modes: Value = serde_json::from_str(&stdout(&o)).unwrap();
        let free = modes["modes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["locked"].as_array().unwrap().is_empty())
            .unwrap();
        assert_eq!(row["dof"], free["dof"], "design {design}");
        assert_eq!(row["group_kinds"], modes["group_kinds"], "design {design}");
        assert_eq!(row["kinds"], modes["group_kinds"].as_array().unwrap().len());
        assert_eq!(
            patterns(&row["groups"]),
            patterns(&modes["groups"]),
            "design {design}"
        );
        assert_eq!(
            patterns(&row["non_groups"]),
            patterns(&modes["non_groups"]),
            "design {design}"
        );
        assert_eq!(row["inputs"], modes["actuators"].as_array().unwrap().len());
        assert_eq!(
            row["singular_lock_sets"], modes["singular_starts"],
            "design {design}"
        );
    }
}

/// The 3-UPS (catalogue T4-034, UPS) with its sliders actuated, by hand (paper 000 §5 analyses
/// the 3-UPS): each leg has 2 (U) + 1 (P) + 3 (S) = 6 joint freedoms, 18 in all; the three
/// legs close 2 independent loops through ground and platform, 6 equations each, 12 in all;
/// so 18 − 12 = 6 dof with nothing locked (Grübler: 6(8 − 1 − 9) + 18 = 6 with 8 bodies and 9
/// joints), the whole displacement group D. Locking the three sliders removes 3 freedoms:
/// 15 − 12 = 3 dof; locking k of them leaves 6 − k.
#[test]
fn the_3_ups_with_sliders_actuated_has_6_dof_and_3_with_them_locked() {
    let dir = temp();
    let out = dir.path().join("ups");
    sweep(&out, &["--chains", "T4-034", "--actuated", "1"]);
    let rows = rows(&out);
    let row = rows
        .iter()
        .find(|r| r["actuated"] == serde_json::json!([3]))
        .unwrap();
    assert_eq!(row["notation"], "UPS");
    assert_eq!(row["inputs"], 3);
    assert_eq!(row["dof"], 6);
    assert_eq!(row["unsampled"], 0);
    let all: Vec<_> = patterns(&row["groups"])
        .into_iter()
        .chain(patterns(&row["non_groups"]))
        .collect();
    let dof_of = |set: &str| {
        all.iter()
            .find(|p| p.3.iter().any(|s| s == set))
            .unwrap_or_else(|| panic!("{set} in no pattern: {all:?}"))
            .1
    };
    assert_eq!(dof_of("-"), 6);
    assert_eq!(dof_of("P1.3"), 5);
    assert_eq!(dof_of("P1.3 P2.3"), 4);
    assert_eq!(dof_of("P1.3 P2.3 P3.3"), 3);
    assert!(row["group_kinds"].as_array().unwrap().contains(&"D".into()));
}

#[test]
fn one_and_two_threads_write_the_same_bytes() {
    let dir = temp();
    let (a, b) = (dir.path().join("t1"), dir.path().join("t2"));
    sweep(&a, &[SMALL, &["--threads", "1"]].concat());
    sweep(&b, &[SMALL, &["--threads", "2"]].concat());
    assert_same_files(&a, &b);
    assert_eq!(rows(&a).len(), 12);
    // Rows by design index, each once.
    for (i, r) in rows(&a).iter().enumerate() {
        assert_eq!(r["design"], i);
    }
}

#[test]
fn three_shards_merged_are_one_run() {
    let dir = temp();
    let whole = dir.path().join("whole");
    sweep(&whole, SMALL);
    let mut shards = Vec::new();
    for k in 1..=3 {
        let d = dir.path().join(format!("part{k}"));
        sweep(&d, &[SMALL, &["--shard", &format!("{k}/3")]].concat());
        let part = rows(&d);
        assert_eq!(part.len(), 4, "12 designs round robin over 3 shards");
        assert!(
            part.iter()
                .all(|r| r["design"].as_u64().unwrap() % 3 + 1 == k)
        );
        shards.push(d);
    }
    // Given in another order than 1, 2, 3.
    let merged = dir.path().join("merged");
    let o = kinsyn(&[
        "sweep",
        "merge",
        shards[2].to_str().unwrap(),
        shards[0].to_str().unwrap(),
        shards[1].to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_same_files(&whole, &merged);

    // Refusals: a missing shard, a repeated one, a whole sweep, not a sweep, mixed settings,
    // an incomplete shard.
    let p = |d: &PathBuf| d.to_str().unwrap().to_string();
    let out = p(&dir.path().join("bad"));
    let refused = |args: Vec<String>, what: &str, needles: &[&str]| {
        let mut all = vec!["sweep".to_string(), "merge".to_string()];
        all.extend(args);
        all.extend(["--out".to_string(), out.clone()]);
        let all: Vec<&str> = all.iter().map(String::as_str).collect();
        assert_refused(&kinsyn(&all), what, needles);
    };
    refused(
        vec![p(&shards[0]), p(&shards[1])],
        "missing",
        &["shard 3/3 missing"],
    );
    refused(
        vec![p(&shards[0]), p(&shards[0]), p(&shards[1])],
        "twice",
        &["shard 1/3 given twice"],
    );
    refused(vec![p(&whole), p(&shards[1])], "whole", &["not a shard"]);
    refused(
        vec![p(&dir.path().join("nothing"))],
        "not a sweep",
        &["not a sweep directory"],
    );
    let other = dir.path().join("other");
    sweep(
        &other,
        &[SMALL, &["--shard", "3/3", "--seed", "7"]].concat(),
    );
    refused(
        vec![p(&shards[0]), p(&shards[1]), p(&other)],
        "mixed",
        &["different sweeps"],
    );
    let partial = dir.path().join("partial");
    sweep(
        &partial,
        &[SMALL, &["--shard", "3/3", "--stop-after", "1"]].concat(),
    );
    refused(
        vec![p(&shards[0]), p(&shards[1]), p(&partial)],
        "incomplete",
        &["incomplete"],
    );
}

/// The checkpoint's complete lines.
fn checkpoint_lines(dir: &Path) -> usize {
    std::fs::read_to_string(dir.join("checkpoint.jsonl"))
        .map_or(0, |text| text.matches('\n').count())
}

fn resumed(json: &str) -> (u64, u64, bool) {
    let v: Value = serde_json::from_str(json).unwrap();
    (
        v["resumed"].as_u64().unwrap(),
        v["evaluated"].as_u64().unwrap(),
        v["complete"].as_bool().unwrap(),
    )
}

#[test]
fn an_interrupted_run_resumes_to_the_same_files() {
    let dir = temp();
    let whole = dir.path().join("whole");
    sweep(&whole, SMALL);
    let cut = dir.path().join("cut");
    let first = sweep(&cut, &[SMALL, &["--stop-after", "5", "--json"]].concat());
    assert_eq!(resumed(&first), (0, 5, false));
    assert_eq!(checkpoint_lines(&cut), 5);
    assert!(!cut.join("designs.jsonl").exists());
    // A torn last line (a write cut short) is ignored and cut away.
    let mut bytes = std::fs::read(cut.join("checkpoint.jsonl")).unwrap();
    bytes.extend_from_slice(b"{\"design\":11,\"chain\":\"T1-0");
    std::fs::write(cut.join("checkpoint.jsonl"), bytes).unwrap();
    let second = sweep(&cut, &[SMALL, &["--json"]].concat());
    assert_eq!(resumed(&second), (5, 7, true));
    assert_same_files(&whole, &cut);
    // Complete: said so, nothing rewritten.
    let before = std::fs::metadata(cut.join("designs.parquet"))
        .unwrap()
        .modified()
        .unwrap();
    let third = sweep(&cut, SMALL);
    assert!(third.contains("already complete"), "{third}");
    let after = std::fs::metadata(cut.join("designs.parquet"))
        .unwrap()
        .modified()
        .unwrap();
    assert_eq!(before, after);
    // Other settings in the same directory: refused.
    let o = kinsyn(
        &[
            &["sweep", "--out", cut.to_str().unwrap()][..],
            SMALL,
            &["--seed", "1"],
        ]
        .concat(),
    );
    assert_refused(
        &o,
        "other seed",
        &["holds another sweep", "another --out DIR"],
    );
}

#[test]
fn a_killed_run_resumes_to_the_same_files() {
    let args = ["--chains", "T1-001,T1-002,T4-034", "--threads", "1"];
    let dir = temp();
    let killed = dir.path().join("killed");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_kinsyn"))
        .args([&["sweep", "--out", killed.to_str().unwrap()][..], &args].concat())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while checkpoint_lines(&killed) < 2 {
        assert!(start.elapsed().as_secs() < 120, "no row checkpointed");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let done = checkpoint_lines(&killed);
    assert!(
        !killed.join("designs.jsonl").exists(),
        "the run finished before it was killed; make it longer"
    );
    let json = sweep(&killed, &[&args[..], &["--json"]].concat());
    let (resumed_rows, evaluated, complete) = resumed(&json);
    assert!(complete);
    assert_eq!(usize::try_from(resumed_rows).unwrap(), done);
    assert_eq!(resumed_rows + evaluated, 63, "3 chains × 21 actuated sets");
    let whole = dir.path().join("whole");
    sweep(&whole, &args);
    assert_same_files(&whole, &killed);
}

/// The columns of `designs.parquet`, in order (docs/sweep.md).
const PARQUET_COLUMNS: [&str; 17] = [
    "design",
    "chain",
    "notation",
    "family",
    "legs",
    "actuated",
    "inputs",
    "dof",
    "subgroups",
    "kinds",
    "group_kinds",
    "groups",
    "non_groups",
    "unsampled",
    "singular",
    "singular_lock_sets",
    "error",
];

/// A cell of an unsigned 32-bit column (the record reader's `UInt`: INT32 annotated unsigned).
fn uint32_cell(field: &parquet::record::Field) -> u64 {
    match field {
        parquet::record::Field::UInt(v) => u64::from(*v),
        other => panic!("not a uint32: {other:?}"),
    }
}

/// A cell of a UTF-8 column (the record reader's `Str`).
fn string_cell(field: &parquet::record::Field) -> &str {
    match field {
        parquet::record::Field::Str(s) => s,
        other => panic!("not a string: {other:?}"),
    }
}

/// The elements of a cell of a LIST column.
fn list_cell(field: &parquet::record::Field) -> &[parquet::record::Field] {
    match field {
        parquet::record::Field::ListInternal(list) => list.elements(),
        other => panic!("not a list: {other:?}"),
    }
}

/// The Parquet file read back with the parquet crate's record reader: the JSONL rows, column
/// by column (names in order, types and values), and the manifest in its metadata.
#[test]
fn the_parquet_file_holds_the_jsonl_rows() {
    use parquet::file::reader::{FileReader, SerializedFileReader};
    use parquet::record::Field;
    let dir = temp();
    let out = dir.path().join("p");
    sweep(&out, &["--chains", "T1-001,T4-034", "--actuated", "1,2"]);
    let rows = rows(&out);
    let file = std::fs::File::open(out.join("designs.parquet")).unwrap();
    let reader = SerializedFileReader::new(file).unwrap();
    let kv: std::collections::BTreeMap<String, String> = reader
        .metadata()
        .file_metadata()
        .key_value_metadata()
        .unwrap()
        .iter()
        .map(|k| (k.key.clone(), k.value.clone().unwrap_or_default()))
        .collect();
    let manifest: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("sweep.json")).unwrap()).unwrap();
    let settings: Value = serde_json::from_str(&kv["kinsyn.settings"]).unwrap();
    assert_eq!(settings, manifest["settings"]);
    assert_eq!(settings["sampling"]["seed"], 2026);
    let selection: Value = serde_json::from_str(&kv["kinsyn.selection"]).unwrap();
    assert_eq!(selection, manifest["selection"]);
    assert_eq!(kv["kinsyn.designs"], rows.len().to_string());
    assert_eq!(kv["kinsyn.version"], manifest["kinsyn"].as_str().unwrap());
    let mut n = 0;
    for record in reader.get_row_iter(None).unwrap() {
        let record = record.unwrap();
        let names: Vec<&str> = record.get_column_iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(names, PARQUET_COLUMNS);
        let cells: std::collections::BTreeMap<&str, &Field> = record
            .get_column_iter()
            .map(|(k, v)| (k.as_str(), v))
            .collect();
        let col = |name: &str| cells[name];
        let row = &rows[n];
        for name in [
            "design",
            "legs",
            "inputs",
            "dof",
            "subgroups",
            "kinds",
            "unsampled",
            "singular",
        ] {
            assert_eq!(
                uint32_cell(col(name)),
                row[name].as_u64().unwrap(),
                "{name}"
            );
        }
        for name in ["chain", "notation", "family"] {
            assert_eq!(string_cell(col(name)), row[name].as_str().unwrap());
        }
        let values: Vec<u64> = list_cell(col("actuated")).iter().map(uint32_cell).collect();
        assert_eq!(serde_json::json!(values), row["actuated"]);
        for name in ["group_kinds", "singular_lock_sets"] {
            let values: Vec<&str> = list_cell(col(name)).iter().map(string_cell).collect();
            assert_eq!(serde_json::json!(values), row[name], "{name}");
        }
        for name in ["groups", "non_groups"] {
            let v: Value = serde_json::from_str(string_cell(col(name))).unwrap();
            assert_eq!(v, row[name], "{name}");
        }
        match (col("error"), row.get("error")) {
            (Field::Null, None) => {}
            (field, Some(error)) => assert_eq!(string_cell(field), error.as_str().unwrap()),
            (field, None) => panic!("error {field:?} where the row has none"),
        }
        n += 1;
    }
    assert_eq!(n, rows.len());
    assert_eq!(n, 2 * 21);
}

/// The encoder on more rows than one row group holds, with errors and empty lists, read back
/// by the parquet crate's record reader: groups of 16,384 rows and the rest, every design
/// index, error (null or text) and list length in its row.
#[test]
fn a_table_of_more_than_one_row_group_reads_back_row_by_row() {
    use kinsyn::sweep::DesignRow;
    use parquet::file::reader::{FileReader, SerializedFileReader};
    use parquet::record::Field;
    let dir = temp();
    let out = dir.path().join("p");
    sweep(&out, &["--chains", "T1-001,T4-034", "--actuated", "1,2"]);
    let manifest: kinsyn_report::sweep::Manifest =
        serde_json::from_str(&std::fs::read_to_string(out.join("sweep.json")).unwrap()).unwrap();
    let base: Vec<DesignRow> = std::fs::read_to_string(out.join("designs.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    // Every third row failed (an error, its lists empty); the others as the sweep gave them.
    let rows: Vec<DesignRow> = (0..16_384 + 5)
        .map(|i| {
            let mut r = base[i % base.len()].clone();
            r.design = i;
            if i % 3 == 0 {
                r.error = Some(format!("failed {i}"));
                r.actuated.clear();
                r.group_kinds.clear();
                r.singular_lock_sets.clear();
            }
            r
        })
        .collect();
    assert!(
        rows.iter()
            .any(|r| r.error.is_none() && !r.actuated.is_empty())
    );
    let refs: Vec<&DesignRow> = rows.iter().collect();
    let file = dir.path().join("big.parquet");
    std::fs::write(&file, kinsyn_cli::parquet_bytes(&manifest, &refs).unwrap()).unwrap();
    let reader = SerializedFileReader::new(std::fs::File::open(&file).unwrap()).unwrap();
    let groups: Vec<i64> = reader
        .metadata()
        .row_groups()
        .iter()
        .map(parquet::file::metadata::RowGroupMetaData::num_rows)
        .collect();
    assert_eq!(groups, [16_384, 5]);
    let mut n = 0;
    for record in reader.get_row_iter(None).unwrap() {
        let record = record.unwrap();
        let cells: std::collections::BTreeMap<&str, &Field> = record
            .get_column_iter()
            .map(|(k, v)| (k.as_str(), v))
            .collect();
        let row = &rows[n];
        assert_eq!(uint32_cell(cells["design"]), n as u64);
        match (cells["error"], &row.error) {
            (Field::Null, None) => {}
            (field, Some(e)) => assert_eq!(string_cell(field), e),
            (field, None) => panic!("row {n}: error {field:?} where the row has none"),
        }
        assert_eq!(
            list_cell(cells["actuated"]).len(),
            row.actuated.len(),
            "row {n}"
        );
        assert_eq!(list_cell(cells["group_kinds"]).len(), row.group_kinds.len());
        assert_eq!(
            list_cell(cells["singular_lock_sets"]).len(),
            row.singular_lock_sets.len()
        );
        n += 1;
    }
    assert_eq!(n, rows.len());
}

#[test]
fn bad_input_is_refused_in_one_line() {
    let dir = temp();
    let out = dir.path().join("x");
    let o = out.to_str().unwrap();
    for (args, needles) in [
        (vec!["--shard", "0/3"], vec!["--shard", "0/3"]),
        (vec!["--shard", "4/3"], vec!["--shard", "4/3"]),
        (vec!["--shard", "x/y"], vec!["--shard", "x/y"]),
        (vec!["--shard", "3"], vec!["--shard"]),
        (vec!["--chains", "T1-001,T9-999"], vec!["T9-999"]),
        (vec!["--family", "PPPPPP"], vec!["PPPPPP", "PPPRRR"]),
        (vec!["--legs", "7"], vec!["--legs 7"]),
        (vec!["--legs", "2"], vec!["--legs 2"]),
        (vec!["--actuated", "0"], vec!["--actuated 0"]),
        (vec!["--threads", "0"], vec!["--threads 0"]),
        (
            vec!["--chains", "T1-001", "--family", "RRRRRR"],
            vec!["no design"],
        ),
    ] {
        let all = [&["sweep", "--out", o][..], &args].concat();
        assert_refused(&kinsyn(&all), &format!("{args:?}"), &needles);
    }
    assert!(!out.exists(), "a refused sweep wrote {}", out.display());
    assert_refused(&kinsyn(&["sweep"]), "no --out", &["--out"]);
}
