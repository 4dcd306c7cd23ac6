//! `kinsyn sweep report`: the report and figures written from design rows, and the refusals of
//! bad input (one line, exit 2).

use crate::common;
use common::{assert_refused, kinsyn, stdout};
use kinsyn::sweep::{DesignRow, Reached};

/// A row that reads back (`kinsyn::sweep::rows`): design `design` over catalogue chain
/// `chain` (T1-001 `PPPS` of family PPPRRR, or T8-008 `RaU(a,b)RbU` of family RRRRRR, both
/// with prismatic or revolute joints only in the positions used here) with one or two actuated
/// joints per leg (3 or 6 inputs), reaching the last `kinds` of T3, X(z), D, each by one
/// lock subset, and 1T3R by all the others.
fn row(design: usize, inputs: usize, kinds: usize, family: &str) -> DesignRow {
    let (chain, notation, letter) = if family == "PPPRRR" {
        ("T1-001", "PPPS", 'P')
    } else {
        ("T8-008", "RaU(a,b)RbU", 'R')
    };
    // Distinct designs of one chain: actuated joint 1 + design % 2 (then the next one).
    let first = 1 + design % 2;
    let actuated: Vec<usize> = if inputs == 3 {
        vec![first]
    } else {
        vec![first, first + 2]
    };
    let labels: Vec<String> = (1..=3)
        .flat_map(|leg| actuated.iter().map(move |j| format!("{letter}{leg}.{j}")))
        .collect();
    let group_kinds: Vec<String> = ["T3", "X", "D"][3 - kinds.min(3)..]
        .iter()
        .map(|s| (*s).to_string())
        .collect();
    let groups: Vec<Reached> = group_kinds
        .iter()
        .map(|k| Reached {
            pattern: if k == "X" { "X(z)".into() } else { k.clone() },
            parameters: None,
            dof: match k.as_str() {
                "T3" => 3,
                "X" => 4,
                _ => 6,
            },
            subsets: 1,
            lock_sets: vec![match k.as_str() {
                "D" => "-".into(),
                "X" => labels[0].clone(),
                _ => labels[..2].join(" "),
            }],
        })
        .collect();
    DesignRow {
        design,
        chain: chain.into(),
        notation: notation.into(),
        family: family.into(),
        legs: 3,
        inputs,
        dof: 6,
        subgroups: kinds,
        non_groups: vec![Reached {
            pattern: "1T3R".into(),
            parameters: None,
            dof: 4,
            subsets: (1 << inputs) - groups.len(),
            lock_sets: vec![labels.join(" ")],
        }],
        groups,
        kinds,
        group_kinds,
        actuated,
        unsampled: 0,
        singular: 0,
        singular_lock_sets: Vec::new(),
        error: None,
    }
}

/// A well-formedness check of XML: every element closed in order, attributes quoted.
fn assert_well_formed_xml(text: &str) {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = text;
    while let Some(start) = rest.find('<') {
        let after = &rest[start + 1..];
        let end = after.find('>').expect("an unclosed tag");
        let tag = &after[..end];
        rest = &after[end + 1..];
        if tag.starts_with('?') || tag.starts_with('!') {
            continue;
        }
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name.trim()), "closing {name}");
            continue;
        }
        let name = tag.split_whitespace().next().unwrap().trim_end_matches('/');
        assert_eq!(
            tag.matches('"').count() % 2,
            0,
            "attribute quotes in <{tag}>"
        );
        if !tag.ends_with('/') {
            stack.push(name.to_string());
        }
    }
    assert!(stack.is_empty(), "unclosed elements {stack:?}");
}

#[test]
fn report_writes_markdown_and_figures() {
    let dir = tempfile::tempdir().unwrap();
    // d0 (3 inputs, 1 kind), d1 (3 inputs, 2 kinds), d2 (6 inputs, 2 kinds: dominated by d1),
    // d3 (6 inputs, 3 kinds): the front is d1, d3.
    let rows = [
        row(0, 3, 1, "PPPRRR"),
        row(1, 3, 2, "PPPRRR"),
        row(2, 6, 2, "RRRRRR"),
        row(3, 6, 3, "RRRRRR"),
    ];
    let text: String = rows
        .iter()
        .map(|r| serde_json::to_string(r).unwrap() + "\n")
        .collect();
    std::fs::write(dir.path().join("designs.jsonl"), text).unwrap();
    let results = dir.path().to_str().unwrap();
    let o = kinsyn(&["sweep", "report", results, "--top", "1"]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    assert!(stdout(&o).contains("4 designs, 4 built"), "{}", stdout(&o));
    let out = dir.path().join("report");
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(md.contains("| design | chain | notation |"), "{md}");
    // The front's points and rows: d1 with 3 inputs and 2 kinds, d3 with 6 inputs and 3 kinds,
    // each the only design at its point.
    assert!(
        md.contains("**3 inputs: 2 kinds, 2 subgroups**, reached by 1 design:"),
        "{md}"
    );
    assert!(md.contains("| 1 | T1-001 | `PPPS` | 2 | 6 | X D |"), "{md}");
    assert!(
        md.contains("**6 inputs: 3 kinds, 3 subgroups**, reached by 1 design:"),
        "{md}"
    );
    assert!(
        md.contains("| 3 | T8-008 | `RaU(a,b)RbU` | 2,4 | 6 | T3 X D |"),
        "{md}"
    );
    assert!(!md.contains("| 2 | T8-008 |"), "{md}");
    // The best design's lock sets: X(z) by the first input locked, T3 by the first two.
    assert!(md.contains("   | X | `X(z)` | 4 | R1.2 |"), "{md}");
    assert!(md.contains("   | T3 | `T3` | 3 | R1.2 R1.4 |"), "{md}");
    assert!(md.contains("![capacity per family](capacity-by-family.png)"));
    for name in ["capacity-by-family", "capacity-vs-inputs"] {
        let png = std::fs::read(out.join(format!("{name}.png"))).unwrap();
        assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"), "{name}.png");
        let svg = std::fs::read_to_string(out.join(format!("{name}.svg"))).unwrap();
        assert!(svg.starts_with("<svg"), "{name}.svg");
        assert_well_formed_xml(&svg);
    }
    // --json: the ranking, the front by design index.
    let o = kinsyn(&[
        "sweep",
        "report",
        results,
        "--json",
        "--out",
        dir.path().join("j").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let front: Vec<u64> = v["ranking"]["front"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["design"].as_u64().unwrap())
        .collect();
    assert_eq!(front, vec![1, 3]);
}

#[test]
fn bad_results_are_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nothing.jsonl");
    let o = kinsyn(&["sweep", "report", missing.to_str().unwrap()]);
    assert_refused(&o, "missing file", &["nothing.jsonl"]);
    let o = kinsyn(&["sweep", "report", dir.path().to_str().unwrap()]);
    assert_refused(&o, "folder without rows", &["designs.jsonl"]);
    let empty = dir.path().join("empty.jsonl");
    std::fs::write(&empty, "\n").unwrap();
    let o = kinsyn(&["sweep", "report", empty.to_str().unwrap()]);
    assert_refused(&o, "empty file", &["no design rows"]);
    let bad = dir.path().join("bad.jsonl");
    let good = serde_json::to_string(&row(0, 3, 1, "PPPRRR")).unwrap();
    std::fs::write(&bad, format!("{good}\n{{\"design\": 1}}\n")).unwrap();
    let o = kinsyn(&["sweep", "report", bad.to_str().unwrap()]);
    assert_refused(&o, "not a row", &["line 2", "not a design row"]);
    let twice = dir.path().join("twice.jsonl");
    std::fs::write(&twice, format!("{good}\n{good}\n")).unwrap();
    let o = kinsyn(&["sweep", "report", twice.to_str().unwrap()]);
    assert_refused(&o, "design twice", &["line 2", "design 0", "line 1"]);
}
