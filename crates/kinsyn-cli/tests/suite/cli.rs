//! The `kinsyn` command line: output, exit codes and one-line errors.

use crate::common;

use common::{kinsyn, stderr, stdout};

#[test]
fn summary_reports_table_1_at_63() {
    let o = kinsyn(&["catalogue", "summary"]);
    assert!(o.status.success(), "{}", stderr(&o));
    // Paper 000 §2.1: 63 chains; printed, letters only and letters + marks all 63.
    assert!(
        stdout(&o).contains("| 1 | PPPRRR | 63 | 63 | 63 | 63 |"),
        "{}",
        stdout(&o)
    );
    let o = kinsyn(&["catalogue", "summary", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["tables"][0]["letters_only"], 63);
    assert_eq!(v["published_total"], 347);
}

/// The default reading is the committed catalogue compiled into the binary, found from any
/// working directory; another reading is enumerated afresh (§2's perpendicular guides: Table 1
/// falls below 63, docs/synthesis.md).
#[test]
fn summary_reads_the_compiled_in_catalogue_from_anywhere() {
    let dir = tempfile::tempdir().unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_kinsyn"))
        .current_dir(dir.path())
        .args(["catalogue", "summary", "--json"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["tables"][0]["letters_only"], 63);
    // Table 1's 63 chains less the 6 whose every reading has rank 5 (docs/deviations.md, "Chains
    // that are not 3T3R"; each confirmed by finite differences in tests/suite/verification.rs).
    assert_eq!(v["tables"][0]["verified_3t3r"], 57);
    let o = kinsyn(&[
        "catalogue",
        "summary",
        "--json",
        "--prismatics",
        "perpendicular",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert!(v["tables"][0]["letters_only"].as_u64().unwrap() < 63, "{v}");
}

#[test]
fn show_list_and_notation() {
    let o = kinsyn(&["catalogue", "show", "T1-001"]);
    assert!(o.status.success());
    assert!(stdout(&o).starts_with("T1-001  PPPS\n"), "{}", stdout(&o));
    let o = kinsyn(&["catalogue", "show", "PPCU", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["letters"], "PPCU");
    let o = kinsyn(&["catalogue", "list", "--family", "PPPRRR"]);
    assert!(o.status.success());
    assert_eq!(stdout(&o).lines().count(), 63);
    let o = kinsyn(&["catalogue", "list", "--table", "8", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert!(
        v.as_array()
            .unwrap()
            .iter()
            .all(|e| e["family"] == "RRRRRR")
    );
    let o = kinsyn(&["notation", "U(!,-)P!S"]);
    assert!(stdout(&o).contains("actuated  [1, 3]"), "{}", stdout(&o));
}

#[test]
fn generate_writes_the_committed_files() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("cat");
    let o = kinsyn(&["catalogue", "generate", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let committed = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("catalogue");
    for name in ["chains.json", "chains.csv", "README.md"] {
        assert_eq!(
            std::fs::read(out.join(name)).unwrap(),
            std::fs::read(committed.join(name)).unwrap(),
            "{name}"
        );
    }
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    let cases: &[&[&str]] = &[
        &["catalogue", "show", "PXR"],
        &["catalogue", "show", "T9-999"],
        &["catalogue", "show", "SS"],
        &["catalogue", "show", "RaRRa"],
        &["catalogue", "list", "--family", "PPPPRR"],
        &["catalogue", "list", "--table", "5"],
        &["catalogue", "summary", "--prismatics", "sideways"],
        &["notation", ""],
        &["notation", "PPPRRRR"],
        &["catalogue", "frobnicate"],
        &[],
    ];
    for args in cases {
        let o = kinsyn(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("kinsyn: error: "), "{args:?}: {err}");
        assert!(stdout(&o).is_empty(), "{args:?}");
    }
}

/// A folder under a file is the user's mistake (exit 2, the file named); a place the system
/// does not let anyone write (here /proc/self, where not even root can add a folder) is the
/// environment failing (exit 1, the folder named).
#[test]
fn generate_into_a_file_or_an_unwritable_place() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    std::fs::write(&file, "x").unwrap();
    let o = kinsyn(&[
        "catalogue",
        "generate",
        "--out",
        file.join("sub").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(stderr(&o).lines().count(), 1);
    assert!(
        stderr(&o).contains(&format!("{} is not a folder", file.display())),
        "{}",
        stderr(&o)
    );
    if cfg!(target_os = "linux") {
        let o = kinsyn(&["catalogue", "generate", "--out", "/proc/self/cat"]);
        assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
        assert_eq!(stderr(&o).lines().count(), 1);
        assert!(
            stderr(&o).contains("cannot write /proc/self/cat: "),
            "{}",
            stderr(&o)
        );
    }
}

#[test]
fn help_teaches() {
    let o = kinsyn(&["catalogue", "show", "--help"]);
    assert!(o.status.success());
    let h = stdout(&o);
    assert!(h.contains("T2-017") && h.contains("notation"), "{h}");
}

#[test]
fn query_and_locks() {
    // PPPS with its S locked translates (hand derivation).
    let o = kinsyn(&[
        "query",
        "--pattern",
        "T3",
        "--max-locks",
        "3",
        "--family",
        "PPPRRR",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o)
            .lines()
            .any(|l| l.contains("PPPS") && l.contains("lock 456")),
        "{}",
        stdout(&o)
    );
    let o = kinsyn(&["query", "--pattern", "X(z)", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert!(v.as_array().unwrap().iter().all(|h| h["pattern"] == "X(z)"));
    let o = kinsyn(&["catalogue", "show", "T1-001", "--lock", "4,5"]);
    assert!(stdout(&o).contains("locked 45     X(z)"), "{}", stdout(&o));
    for args in [
        &["query", "--pattern", "Q(z)"][..],
        &["query", "--pattern", "X(w)"],
        &["query", "--pattern", "T3", "--family", "PPP"],
        &["query", "--pattern", "T3", "--max-locks", "9"],
        &["catalogue", "show", "T1-001", "--lock", "7"],
        &["catalogue", "show", "T1-001", "--lock", "11"],
    ] {
        let o = kinsyn(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr(&o).lines().count(), 1, "{args:?}: {}", stderr(&o));
    }
}
