//! What kinsyn reads and what it writes, under hostile input (docs/limits.md, "Files", "How
//! input is echoed", "Documents"):
//!
//! - every reader of files passes the same checks: `sweep report` refuses `/dev/zero`, a named
//!   pipe and a file over the size limit of files of rows in one line, without reading them;
//! - rows read back (a checkpoint resumed, shards merged, a report) are checked: an edited but
//!   well-formed row (`"dof": 99`, a chain that is not the design's, a lock set that names no
//!   input) is refused naming the file and line, and never reaches the result files;
//! - text from files reaches a terminal, a JSON report, Markdown, HTML, SVG and XML escaped by
//!   the one escaper of each format ([`kinsyn::markup`]): no control or bidirectional
//!   character raw on stdout, JSON that is still JSON of the same value, no markup from the
//!   input in a document, and XML that is well-formed.

use crate::common;

use common::{assert_refused, kinsyn, stderr, stdout};
use kinsyn::markup;
use kinsyn::sweep::rows::{Known, RowError, RowFault};
use kinsyn::sweep::{DesignRow, Reached};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A hostile text: markup of each format, a terminal colour, NUL, a right-to-left override.
const HOSTILE: &str =
    "T1-001\"><script>alert(1)</script><img src=x>|*b*_`c`[l](j)\u{1b}[31m\u{0}\u{202e}!";

/// Whether `c` may not reach a terminal raw: a control character other than the line break
/// and tab that lay out text, or a bidirectional or invisible formatting character.
fn unsafe_on_a_terminal(c: char) -> bool {
    (c.is_control() && c != '\n' && c != '\t')
        || matches!(c, '\u{061c}' | '\u{200b}'..='\u{200f}' | '\u{2028}'..='\u{202e}' | '\u{2066}'..='\u{2069}' | '\u{feff}')
}

fn assert_terminal_safe(text: &str, what: &str) {
    assert!(
        !text.chars().any(unsafe_on_a_terminal),
        "{what}: raw control or bidirectional character in {text:?}"
    );
}

/// Asserts that `text` is well-formed XML 1.0 as far as these documents go: only characters
/// XML allows, comments and declarations closed, every element closed in order, attribute
/// values quoted, and `<` and `&` only as markup or entities.
fn assert_well_formed_xml(text: &str) {
    for c in text.chars() {
        let allowed = matches!(c, '\t' | '\n' | '\r')
            || (!c.is_control() && c != '\u{fffe}' && c != '\u{ffff}')
            || ('\u{7f}'..='\u{9f}').contains(&c);
        assert!(allowed, "character {c:?} is not allowed in XML");
    }
    let entity_ok = |s: &str| {
        s.match_indices('&').all(|(i, _)| {
            let rest = &s[i + 1..];
            let Some(end) = rest.find(';') else {
                return false;
            };
            let name = &rest[..end];
            matches!(name, "amp" | "lt" | "gt" | "quot" | "apos")
                || name
                    .strip_prefix("#x")
                    .is_some_and(|h| !h.is_empty() && h.chars().all(|c| c.is_ascii_hexdigit()))
                || name
                    .strip_prefix('#')
                    .is_some_and(|d| !d.is_empty() && d.chars().all(|c| c.is_ascii_digit()))
        })
    };
    let mut stack: Vec<String> = Vec::new();
    let mut rest = text;
    while let Some(start) = rest.find('<') {
        assert!(
            entity_ok(&rest[..start]),
            "a raw '&' in text {:?}",
            &rest[..start]
        );
        let after = &rest[start + 1..];
        if let Some(comment) = after.strip_prefix("!--") {
            let end = comment.find("-->").expect("an unclosed comment");
            assert!(!comment[..end].contains("--"), "'--' inside a comment");
            rest = &comment[end + 3..];
            continue;
        }
        if after.starts_with('?') || after.starts_with('!') {
            let end = after.find('>').expect("an unclosed declaration");
            rest = &after[end + 1..];
            continue;
        }
        // A tag: its name, then name="value" pairs, each value free of '<' and raw '&'.
        let mut chars = after.char_indices();
        let mut quote: Option<char> = None;
        let end = loop {
            let (i, c) = chars.next().expect("an unclosed tag");
            match (quote, c) {
                (None, '"' | '\'') => quote = Some(c),
                (Some(q), c) if c == q => quote = None,
                (Some(_), '<') => panic!("'<' in an attribute value of <{}", &after[..i]),
                (None, '>') => break i,
                (None, '<') => panic!("'<' inside the tag <{}", &after[..i]),
                _ => {}
            }
        };
        let tag = &after[..end];
        assert!(entity_ok(tag), "a raw '&' in <{tag}>");
        rest = &after[end + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(
                stack.pop().as_deref(),
                Some(name.trim()),
                "closing </{name}>"
            );
            continue;
        }
        let name = tag
            .split_whitespace()
            .next()
            .expect("a tag name")
            .trim_end_matches('/');
        assert!(
            name.chars()
                .all(|c| c.is_ascii_alphanumeric() || matches!(c, ':' | '-' | '_' | '.')),
            "tag name {name:?}"
        );
        // Attributes: name="value" or name='value'.
        let mut attributes = tag[tag.find(name).unwrap() + name.len()..]
            .trim()
            .trim_end_matches('/');
        while !attributes.is_empty() {
            let eq = attributes.find('=').expect("an attribute without a value");
            let key = attributes[..eq].trim();
            assert!(
                !key.is_empty() && !key.contains(char::is_whitespace),
                "attribute name {key:?} in <{tag}>"
            );
            let value = attributes[eq + 1..].trim_start();
            let q = value.chars().next().expect("a value");
            assert!(q == '"' || q == '\'', "an unquoted attribute in <{tag}>");
            let close = value[1..].find(q).expect("an unclosed value") + 1;
            attributes = value[close + 1..].trim_start();
        }
        if !tag.ends_with('/') {
            stack.push(name.to_string());
        }
    }
    assert!(entity_ok(rest), "a raw '&' in text {rest:?}");
    assert!(stack.is_empty(), "unclosed elements {stack:?}");
}

fn write(path: &Path, text: &str) -> PathBuf {
    std::fs::write(path, text).unwrap();
    path.to_path_buf()
}

/// The 3-UPS description with `name` as its name.
fn named_3ups(dir: &Path, file: &str, name: &str) -> PathBuf {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../mechanisms/3-ups.json"
    ))
    .unwrap();
    let mut v: Value = serde_json::from_str(&text).unwrap();
    v["name"] = name.into();
    write(&dir.join(file), &serde_json::to_string(&v).unwrap())
}

/// Runs kinsyn with `args`, waiting at most `limit`; `None` when it had to be killed.
fn run_within(args: &[&str], limit: Duration) -> Option<std::process::Output> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinsyn"))
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while start.elapsed() < limit {
        if child.try_wait().unwrap().is_some() {
            return Some(child.wait_with_output().unwrap());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    None
}

// ---------------------------------------------------------------------------------------------
// 1. Every reader checks its files the same way.

#[test]
fn sweep_report_reads_only_regular_files_within_the_limit() {
    let dir = tempfile::tempdir().unwrap();
    // /dev/zero: a device, refused on its metadata (before, it was read until memory ran out).
    let o = run_within(&["sweep", "report", "/dev/zero"], Duration::from_secs(20))
        .expect("sweep report /dev/zero did not return");
    assert_refused(&o, "/dev/zero", &["/dev/zero", "not a regular file"]);
    // A named pipe with no writer: refused without opening it (before, it blocked forever).
    let fifo = dir.path().join("designs.jsonl");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let o = run_within(
        &["sweep", "report", fifo.to_str().unwrap()],
        Duration::from_secs(20),
    )
    .expect("sweep report on a named pipe did not return");
    assert_refused(&o, "named pipe", &["designs.jsonl", "not a regular file"]);
    // The same through the folder that holds it.
    let o = run_within(
        &["sweep", "report", dir.path().to_str().unwrap()],
        Duration::from_secs(20),
    )
    .expect("sweep report on a folder with a named pipe did not return");
    assert_refused(&o, "folder with a pipe", &["not a regular file"]);
    // A file one byte over the limit (sparse: nothing is written or read): refused on its size.
    let big = dir.path().join("big.jsonl");
    let f = std::fs::File::create(&big).unwrap();
    f.set_len(kinsyn_report::sweep::MAX_ROWS_BYTES + 1).unwrap();
    let o = run_within(
        &["sweep", "report", big.to_str().unwrap()],
        Duration::from_secs(20),
    )
    .expect("sweep report on a large file did not return");
    assert_refused(
        &o,
        "over the limit",
        &[
            &format!("{} bytes", (1u64 << 29) + 1),
            "files of sweep rows are at most 536870912 bytes",
        ],
    );
    // A manifest that is a directory or a device is refused as every input file is.
    let folder = dir.path().join("sweep");
    std::fs::create_dir_all(folder.join("sweep.json")).unwrap();
    write(&folder.join("designs.jsonl"), "\n");
    let o = kinsyn(&["sweep", "report", folder.to_str().unwrap()]);
    assert_refused(&o, "manifest a directory", &["sweep.json", "a directory"]);
}

#[test]
fn every_sweep_file_reader_refuses_a_device() {
    // A checkpoint or a shard's rows replaced by a symbolic link to /dev/zero.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("cut");
    let small = [
        "sweep",
        "--out",
        out.to_str().unwrap(),
        "--chains",
        "T1-001",
        "--actuated",
        "1",
    ];
    let o = kinsyn(&[&small[..], &["--stop-after", "2"]].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let checkpoint = out.join("checkpoint.jsonl");
    std::fs::remove_file(&checkpoint).unwrap();
    std::os::unix::fs::symlink("/dev/zero", &checkpoint).unwrap();
    let o = run_within(&small, Duration::from_secs(30)).expect("resume on /dev/zero hung");
    assert_refused(
        &o,
        "checkpoint /dev/zero",
        &["checkpoint.jsonl", "not a regular file"],
    );
}

// ---------------------------------------------------------------------------------------------
// 2. Rows read back are checked.

/// The rows of the 6 designs of T1-001 with one actuated joint per leg, from a run of kinsyn.
fn small_sweep(out: &Path, extra: &[&str]) -> std::process::Output {
    let args = [
        &[
            "sweep",
            "--out",
            out.to_str().unwrap(),
            "--chains",
            "T1-001",
            "--actuated",
            "1",
        ][..],
        extra,
    ]
    .concat();
    kinsyn(&args)
}

/// `file` with line `line` (1-based) edited as JSON by `edit`.
fn edit_line(file: &Path, line: usize, edit: impl FnOnce(&mut Value)) {
    let text = std::fs::read_to_string(file).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let mut v: Value = serde_json::from_str(&lines[line - 1]).unwrap();
    edit(&mut v);
    lines[line - 1] = serde_json::to_string(&v).unwrap();
    std::fs::write(file, lines.join("\n") + "\n").unwrap();
}

#[test]
fn an_edited_checkpoint_row_is_refused_and_never_reaches_the_results() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("cut");
    let o = small_sweep(&out, &["--stop-after", "2"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let checkpoint = out.join("checkpoint.jsonl");
    // A well-formed row with a platform of 99 degrees of freedom (a body has at most 6).
    edit_line(&checkpoint, 1, |v| v["dof"] = 99.into());
    let o = small_sweep(&out, &[]);
    assert_refused(
        &o,
        "dof 99",
        &[
            "checkpoint.jsonl line 1",
            "dof: 99 is more than 6",
            "remove it",
        ],
    );
    assert!(
        !out.join("designs.jsonl").exists(),
        "the edited row was kept"
    );
    // Another design's chain under this index.
    edit_line(&checkpoint, 1, |v| {
        v["dof"] = 6.into();
        v["chain"] = "T1-002".into();
    });
    let o = small_sweep(&out, &[]);
    assert_refused(
        &o,
        "other chain",
        &["checkpoint.jsonl line 1", "not one of this sweep's designs"],
    );
    assert!(!out.join("designs.jsonl").exists());
}

/// An edit of a row's JSON.
type Edit = Box<dyn Fn(&mut Value)>;

#[test]
fn merge_and_report_refuse_an_edited_row_with_its_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let whole = dir.path().join("whole");
    let o = small_sweep(&whole, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // The untouched results are accepted by the report.
    let o = kinsyn(&["sweep", "report", whole.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let rows = whole.join("designs.jsonl");
    // Each edit keeps the row well-formed JSON of the right types.
    let edits: Vec<(&str, Edit, &str)> = vec![
        (
            "dof 99",
            Box::new(|v| v["dof"] = 99.into()),
            "dof: 99 is more than 6",
        ),
        (
            "kinds",
            Box::new(|v| v["kinds"] = 7.into()),
            "kinds: 7 is not the number of group kinds",
        ),
        (
            "lock set",
            Box::new(|v| v["groups"][0]["lock_sets"][0] = "P9.1".into()),
            "\"P9.1\" is not '-' or labels of the inputs (P1.2 P2.2 P3.2)",
        ),
        (
            "pattern",
            Box::new(|v| v["groups"][0]["pattern"] = "Q(z)".into()),
            "\"Q(z)\" is not a pattern name",
        ),
        (
            "actuated",
            Box::new(|v| v["actuated"] = serde_json::json!([3])),
            "not one of this sweep's designs",
        ),
        (
            "subsets",
            Box::new(|v| v["groups"][0]["subsets"] = 5.into()),
            "not the 2^3 = 8 lock subsets",
        ),
        (
            "unknown field",
            Box::new(|v| v["colour"] = "red".into()),
            "unknown field `colour`",
        ),
    ];
    let original = std::fs::read_to_string(&rows).unwrap();
    for (what, edit, needle) in &edits {
        std::fs::write(&rows, &original).unwrap();
        edit_line(&rows, 2, edit);
        let o = kinsyn(&["sweep", "report", whole.to_str().unwrap()]);
        assert_refused(&o, what, &["designs.jsonl line 2", needle]);
    }
    // Shards: the second shard's rows edited; the merge refuses them and writes nothing.
    let shards: Vec<PathBuf> = (1..=2).map(|k| dir.path().join(format!("s{k}"))).collect();
    for (k, s) in shards.iter().enumerate() {
        let o = small_sweep(s, &["--shard", &format!("{}/2", k + 1)]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    edit_line(&shards[1].join("designs.jsonl"), 3, |v| {
        v["dof"] = 99.into();
    });
    let merged = dir.path().join("merged");
    let o = kinsyn(&[
        "sweep",
        "merge",
        shards[0].to_str().unwrap(),
        shards[1].to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]);
    assert_refused(&o, "merge", &["s2/designs.jsonl line 3", "dof: 99"]);
    assert!(!merged.join("designs.jsonl").exists());
    // A manifest edited to claim another count of designs.
    let manifest = shards[0].join("sweep.json");
    let mut m: Value = serde_json::from_str(&std::fs::read_to_string(&manifest).unwrap()).unwrap();
    m["sweep_designs"] = 7.into();
    write(&manifest, &serde_json::to_string_pretty(&m).unwrap());
    let o = kinsyn(&["sweep", "report", shards[0].to_str().unwrap()]);
    assert_refused(
        &o,
        "manifest",
        &[
            "sweep.json",
            "has 6 designs (3 in this directory) with this kinsyn's catalogue, not the 7 (3)",
        ],
    );
    m["sweep_designs"] = 6.into();
    m["rule"] = "every design".into();
    write(&manifest, &serde_json::to_string_pretty(&m).unwrap());
    let o = kinsyn(&["sweep", "report", shards[0].to_str().unwrap()]);
    assert_refused(
        &o,
        "manifest rule",
        &["sweep.json: a damaged sweep manifest: the rule"],
    );
}

/// A row over the UPS leg T4-034 (notation UPS, family PRRRRR, primitive word RRPRRR) with
/// its slider actuated: inputs P1.3 P2.3 P3.3, 8 lock subsets.
fn ups_row() -> DesignRow {
    let reached = |pattern: &str, dof: usize, subsets: usize, sets: &[&str]| Reached {
        pattern: pattern.into(),
        parameters: None,
        dof,
        subsets,
        lock_sets: sets.iter().map(|s| (*s).to_string()).collect(),
    };
    DesignRow {
        design: 7,
        chain: "T4-034".into(),
        notation: "UPS".into(),
        family: "PRRRRR".into(),
        legs: 3,
        actuated: vec![3],
        inputs: 3,
        dof: 6,
        subgroups: 2,
        group_kinds: vec!["E".into(), "D".into()],
        kinds: 2,
        groups: vec![
            reached("D", 6, 1, &["-"]),
            reached("E", 0, 1, &["P1.3 P2.3 P3.3"]),
        ],
        non_groups: vec![
            reached("1T3R", 4, 3, &["P1.3 P2.3", "P1.3 P3.3", "P2.3 P3.3"]),
            reached("2T3R", 5, 3, &["P1.3", "P2.3", "P3.3"]),
        ],
        unsampled: 0,
        singular: 0,
        singular_lock_sets: Vec::new(),
        error: None,
    }
}

#[test]
fn the_row_checker_is_one_public_function_of_the_library() {
    let catalogue = kinsyn::catalogue::Catalogue::committed().unwrap();
    let known = Known::catalogue(&catalogue);
    let line = |r: &DesignRow| serde_json::to_string(r).unwrap();
    let good = ups_row();
    assert_eq!(known.parse_rows(&line(&good)).unwrap(), vec![good.clone()]);
    // Each fault, on line 2 after a good row (blank lines are skipped, not counted out).
    let cases: Vec<(DesignRow, &str)> = vec![
        (
            DesignRow {
                dof: 99,
                ..ups_row()
            },
            "dof: 99 is more than 6",
        ),
        (
            DesignRow {
                inputs: 4,
                ..ups_row()
            },
            "inputs: 4 is not legs × actuated joints per leg (3 × 1)",
        ),
        (
            DesignRow {
                notation: "PPPS".into(),
                ..ups_row()
            },
            "is not a design of the catalogue: T4-034 is \"UPS\"",
        ),
        (
            DesignRow {
                chain: "T9-999".into(),
                ..ups_row()
            },
            "no verified catalogue chain has this id",
        ),
        (
            DesignRow {
                actuated: vec![3, 3],
                inputs: 6,
                ..ups_row()
            },
            "the actuated joints are not increasing joints 1 to 6",
        ),
        (
            DesignRow {
                legs: 7,
                inputs: 7,
                ..ups_row()
            },
            "a sweep builds 3 to 6 legs",
        ),
        (
            DesignRow {
                group_kinds: vec!["D".into(), "E".into()],
                ..ups_row()
            },
            "group_kinds: [\"D\", \"E\"] is not the kinds of the groups reached",
        ),
        (
            DesignRow {
                subgroups: 3,
                ..ups_row()
            },
            "subgroups: 3 is not the number of groups reached (2)",
        ),
        (
            DesignRow {
                singular: 1,
                ..ups_row()
            },
            "singular_lock_sets: 0 minimal lock sets for 1 singular subsets",
        ),
        (
            DesignRow {
                error: Some("no".into()),
                ..ups_row()
            },
            "dof: 6 in a row with an error",
        ),
    ];
    for (row, needle) in cases {
        let text = format!(
            "{}\n\n{}\n",
            line(&good),
            line(&DesignRow { design: 8, ..row })
        );
        let e = known.parse_rows(&text).unwrap_err();
        assert_eq!(e.line, 3, "{e}");
        assert!(e.to_string().contains(needle), "{needle:?} not in {e}");
    }
}

#[test]
fn the_row_checker_refuses_patterns_and_lock_sets_that_disagree() {
    let catalogue = kinsyn::catalogue::Catalogue::committed().unwrap();
    let known = Known::catalogue(&catalogue);
    let line = |r: &DesignRow| serde_json::to_string(r).unwrap();
    let good = ups_row();
    let mut wrong_dof = ups_row();
    wrong_dof.non_groups[0].dof = 3;
    let e = known.parse_rows(&line(&wrong_dof)).unwrap_err();
    assert!(
        e.to_string()
            .contains("non_groups[0].dof: 3 is not the dimension of 1T3R (4)"),
        "{e}"
    );
    let mut group_in_non_groups = ups_row();
    group_in_non_groups.non_groups[0].pattern = "X(z)".into();
    let e = known.parse_rows(&line(&group_in_non_groups)).unwrap_err();
    assert!(e.to_string().contains("\"X(z)\" is a group pattern"), "{e}");
    let mut not_canonical = ups_row();
    not_canonical.groups[0].pattern = " D ".into();
    let e = known.parse_rows(&line(&not_canonical)).unwrap_err();
    assert!(
        e.to_string()
            .contains("is not written as kinsyn writes it (D)"),
        "{e}"
    );
    let mut out_of_order = ups_row();
    out_of_order.groups[1].lock_sets = vec!["P2.3 P1.3 P3.3".into()];
    let e = known.parse_rows(&line(&out_of_order)).unwrap_err();
    assert!(
        e.to_string()
            .contains("groups[1].lock_sets[0]: \"P2.3 P1.3 P3.3\" is not '-' or labels of the inputs (P1.3 P2.3 P3.3) in that order"),
        "{e}"
    );
    let mut twice = ups_row();
    twice.non_groups[1].lock_sets[2] = "P1.3".into();
    let e = known.parse_rows(&line(&twice)).unwrap_err();
    assert!(
        e.to_string()
            .contains("non_groups[1].lock_sets[2]: \"P1.3\" is listed twice"),
        "{e}"
    );
    let mut parameters = ups_row();
    parameters.groups[1].parameters = Some("centre".into());
    let e = known.parse_rows(&line(&parameters)).unwrap_err();
    assert!(e.to_string().contains("E has no parameters"), "{e}");
    // The same design twice, and text that is not a row.
    let e = known
        .parse_rows(&format!("{}\n{}\n", line(&good), line(&good)))
        .unwrap_err();
    assert_eq!(
        e,
        RowError {
            line: 2,
            fault: RowFault::Repeated {
                design: 7,
                first: 1
            }
        }
    );
    let e = known.parse_rows("{\"design\": 1}").unwrap_err();
    assert!(matches!(e.fault, RowFault::NotARow(_)), "{e}");
}

#[test]
fn against_a_sweep_a_row_is_the_design_of_its_index() {
    let catalogue = kinsyn::catalogue::Catalogue::committed().unwrap();
    let line = |r: &DesignRow| serde_json::to_string(r).unwrap();
    let settings = kinsyn::sweep::SweepSettings {
        actuated_per_leg: vec![1],
        ..Default::default()
    };
    let mut ups_only = catalogue.clone();
    ups_only.entries.retain(|e| e.id == "T4-034");
    let designs = kinsyn::sweep::designs(&ups_only, &settings);
    assert_eq!(designs.len(), 6);
    let sweep = Known::sweep(&designs, 3);
    let at_2 = DesignRow {
        design: 2,
        ..ups_row()
    };
    sweep.parse_rows(&line(&at_2)).unwrap();
    let e = sweep.parse_rows(&line(&ups_row())).unwrap_err();
    assert!(
        e.to_string()
            .contains("no design of the sweep has this index"),
        "{e}"
    );
    let at_3 = DesignRow {
        design: 3,
        ..ups_row()
    };
    let e = sweep.parse_rows(&line(&at_3)).unwrap_err();
    assert!(e.to_string().contains("design 3 has actuated [4]"), "{e}");
}

// ---------------------------------------------------------------------------------------------
// 3. Text on a terminal.

#[test]
fn a_hostile_name_reaches_stdout_escaped_and_json_stays_json() {
    let dir = tempfile::tempdir().unwrap();
    let name = "a\u{1b}[31mb\u{0}\u{202e}c";
    let file = named_3ups(dir.path(), "hostile.json", name);
    let f = file.to_str().unwrap();
    for args in [
        vec!["analyze", f],
        vec!["modes", f],
        vec!["modes", f, "--lock", "P1.3"],
        vec!["analyze", f, "--all-assemblies"],
    ] {
        let o = kinsyn(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let text = stdout(&o);
        assert_terminal_safe(&text, &format!("{args:?}"));
        assert!(
            text.contains(r"a\u{1b}[31mb\0\u{202e}c"),
            "{args:?}: the name is not shown escaped in {text}"
        );
        // --json: the same value, escaped as JSON.
        let o = kinsyn(&[&args[..], &["--json"]].concat());
        assert_eq!(o.status.code(), Some(0), "{args:?} --json: {}", stderr(&o));
        let text = stdout(&o);
        assert_terminal_safe(&text, &format!("{args:?} --json"));
        assert!(text.contains(r"\u202e"), "{text}");
        let v: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(v["manipulator"], name, "{args:?}");
    }
}

#[test]
fn export_escapes_the_path_it_echoes_and_the_names_it_writes() {
    let dir = tempfile::tempdir().unwrap();
    let file = named_3ups(dir.path(), "hostile.json", HOSTILE);
    let out = dir.path().join("model\u{1b}[2J\u{202e}.xml");
    let o = kinsyn(&[
        "export",
        file.to_str().unwrap(),
        "--mjcf",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert_terminal_safe(&text, "export");
    assert!(
        text.starts_with("wrote ") && text.contains(r"model\u{1b}[2J\u{202e}.xml"),
        "{text}"
    );
    let xml = std::fs::read_to_string(&out).unwrap();
    assert_well_formed_xml(&xml);
    assert!(!xml.contains("<script") && !xml.contains("<img"), "{xml}");
    let model = xml.lines().next().unwrap();
    assert!(
        model.starts_with("<mujoco model=\"T1-001&quot;&gt;&lt;script&gt;"),
        "{model}"
    );
    assert!(model.contains(r"\u{1b}[31m\0\u{202e}!"), "{model}");
}

// ---------------------------------------------------------------------------------------------
// 4. Text in documents: Markdown, HTML, SVG, XML.

/// `line` without its Markdown code spans (`CommonMark`: a run of n backticks opens one, the
/// next run of exactly n closes it; an unclosed run is text).
fn outside_code_spans(line: &str) -> String {
    let mut out = String::new();
    let mut rest = line;
    while let Some(start) = rest.find('`') {
        out.push_str(&rest[..start]);
        let run = rest[start..].len() - rest[start..].trim_start_matches('`').len();
        let after = &rest[start + run..];
        let mut search = 0;
        let close = loop {
            let Some(i) = after[search..].find('`') else {
                break None;
            };
            let at = search + i;
            let n = after[at..].len() - after[at..].trim_start_matches('`').len();
            if n == run {
                break Some(at);
            }
            search = at + n;
        };
        if let Some(at) = close {
            rest = &after[at + run..];
        } else {
            out.push_str(&rest[start..start + run]);
            rest = after;
        }
    }
    out.push_str(rest);
    out
}

/// A failed design's row (T1-001, nothing counted) with `error` as its error.
fn failed_row(design: usize, actuated: usize, error: &str) -> DesignRow {
    DesignRow {
        design,
        chain: "T1-001".into(),
        notation: "PPPS".into(),
        family: "PPPRRR".into(),
        legs: 3,
        actuated: vec![actuated],
        inputs: 3,
        dof: 0,
        subgroups: 0,
        group_kinds: Vec::new(),
        kinds: 0,
        groups: Vec::new(),
        non_groups: Vec::new(),
        unsampled: 0,
        singular: 0,
        singular_lock_sets: Vec::new(),
        error: Some(error.into()),
    }
}

#[test]
fn the_report_has_no_markup_from_its_rows_or_file_name() {
    let dir = tempfile::tempdir().unwrap();
    // A folder name with Markdown, HTML, a terminal escape and a right-to-left override.
    let folder = dir.path().join("r`|<b>\u{1b}[1m\u{202e}");
    std::fs::create_dir_all(&folder).unwrap();
    // The free texts of a row: a failed design's error, and a group's parameters.
    let mut ups = ups_row();
    ups.groups[0].pattern = "S".into();
    ups.group_kinds = vec!["E".into(), "S".into()];
    ups.groups.swap(0, 1);
    ups.groups[1].dof = 3;
    ups.groups[1].parameters = Some("centre <img src=x onerror=alert(1)> | *m*".into());
    let rows = [
        failed_row(0, 1, HOSTILE),
        failed_row(1, 2, &format!("{HOSTILE}\nsecond line")),
        ups,
    ];
    let text: String = rows
        .iter()
        .map(|r| serde_json::to_string(r).unwrap() + "\n")
        .collect();
    write(&folder.join("designs.jsonl"), &text);
    let o = kinsyn(&["sweep", "report", folder.to_str().unwrap(), "--top", "1"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_terminal_safe(&stdout(&o), "report summary");
    let md = std::fs::read_to_string(folder.join("report").join("report.md")).unwrap();
    assert!(
        !md.chars().any(|c| markup::is_hidden(c) && c != '\n'),
        "a hidden character in report.md"
    );
    // Outside code spans (where nothing is markup), no markup from the rows or the path.
    for line in md.lines() {
        let text = outside_code_spans(line);
        for raw in ["<script", "<img", "<b>", "[l](j)", "*b*", "*m*", "`c`"] {
            assert!(!text.contains(raw), "{raw:?} raw in {line:?}");
        }
    }
    // Each table row of the failures keeps its four cells: no '|' from the text splits one.
    let failures: Vec<&str> = md
        .lines()
        .filter(|l| l.starts_with("| 0 | T1-001 |") || l.starts_with("| 1 | T1-001 |"))
        .collect();
    assert_eq!(failures.len(), 2, "{md}");
    for row in failures {
        let cells = row.replace("\\|", "").matches('|').count();
        assert_eq!(cells, 5, "{row}");
        assert!(row.contains("&lt;script&gt;"), "{row}");
    }
    // The failed designs' error in one line, its line break shown as \n.
    assert!(md.contains(r"\\nsecond line"), "{md}");
    // The S group with its parameters, in a code span whose '|' a table reads as text.
    assert!(
        md.contains(r"   | S | `S centre <img src=x onerror=alert(1)> \| *m*` | 3 | - |"),
        "{md}"
    );
    // The rows' file in a code span that the folder's backtick cannot close.
    let rows_line = md.lines().find(|l| l.starts_with("Rows: ")).unwrap();
    assert!(
        rows_line.contains("``") && rows_line.contains(r"r`\|<b>\u{1b}[1m\u{202e}"),
        "{rows_line}"
    );
    for name in ["capacity-by-family", "capacity-vs-inputs"] {
        let svg =
            std::fs::read_to_string(folder.join("report").join(format!("{name}.svg"))).unwrap();
        assert_well_formed_xml(&svg);
    }
}

#[test]
fn svg_drawn_by_plotters_needs_the_characters_made_visible() {
    use plotters::prelude::*;
    // The font the command registers for its figures' text (plotters lays captions out).
    let _ =
        plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular());
    let draw = |caption: &str| {
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (200, 100)).into_drawing_area();
            root.fill(&WHITE).unwrap();
            ChartBuilder::on(&root)
                .caption(caption, ("sans-serif", 12))
                .build_cartesian_2d(0.0..1.0, 0.0..1.0)
                .unwrap();
            root.present().unwrap();
        }
        svg
    };
    // plotters escapes the markup characters itself, not the characters XML cannot hold.
    let raw = draw(HOSTILE);
    assert!(raw.contains('\u{1b}') && raw.contains('\u{0}'));
    let shown = draw(&markup::visible(HOSTILE));
    assert_well_formed_xml(&shown);
    assert!(
        !shown.contains("<script") && !shown.contains("<img"),
        "{shown}"
    );
    assert!(shown.contains(r"\u{1b}[31m\0\u{202e}"), "{shown}");
}

#[test]
fn schematics_and_embedded_json_have_no_markup_from_their_text() {
    let chain: kinsyn::notation::Chain = "U(!,-)P!S".parse().unwrap();
    let word = kinsyn::synthesis::parse_word(&chain.primitive_word()).unwrap();
    let axes: Vec<kinsyn::notation::Axis> = "xyzxyz"
        .chars()
        .map(|c| kinsyn::notation::Axis::from_letter(c).unwrap())
        .collect();
    let svg = kinsyn::schematic::svg(&chain, &word, &axes, HOSTILE).unwrap();
    assert_well_formed_xml(&svg);
    assert!(!svg.contains("<script") && !svg.contains("<img"), "{svg}");
    // JSON in an HTML <script> element: no tag can be closed or opened from a string, and the
    // value reads back the same.
    let value = serde_json::json!({ "id": format!("</script><script>{HOSTILE}") });
    let embedded = markup::json_in_html(&serde_json::to_string(&value).unwrap());
    assert!(!embedded.contains('<') && !embedded.contains('>') && !embedded.contains('&'));
    assert!(!embedded.chars().any(markup::is_hidden), "{embedded}");
    let back: Value = serde_json::from_str(&embedded).unwrap();
    assert_eq!(back, value);
    // An HTML page's text: a catalogue site page escapes its facts with the same escaper.
    let page = format!("<p>{}</p>", markup::escape(HOSTILE));
    assert_well_formed_xml(&page);
}

#[test]
fn the_catalogue_site_embeds_its_data_as_json_for_html() {
    let dir = tempfile::tempdir().unwrap();
    let o = kinsyn(&["catalogue", "site", "--out", dir.path().to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let index = std::fs::read_to_string(dir.path().join("index.html")).unwrap();
    let open = r#"<script type="application/json" id="catalogue-data">"#;
    let start = index.find(open).unwrap() + open.len();
    let end = start + index[start..].find("</script>").unwrap();
    let data = &index[start..end];
    assert!(!data.contains('<') && !data.contains('&'));
    let v: Value = serde_json::from_str(data).unwrap();
    assert_eq!(v["entries"].as_array().unwrap().len(), 485);
    let page = std::fs::read_to_string(dir.path().join("entry").join("T1-001.html")).unwrap();
    let body = &page[page.find("<body>").unwrap()..page.find("</body>").unwrap() + 7];
    assert_well_formed_xml(body);
}
