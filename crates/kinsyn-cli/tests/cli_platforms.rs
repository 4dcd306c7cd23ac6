//! The command line on descriptions with several moving bodies (`kinsyn-manipulator/2`,
//! issue 10, item 5); the library side is in crates/kinsyn/tests/platforms.rs.

mod common;

use common::{kinsyn, stderr, stdout};

/// The split 3-RPS of `mechanisms/multibody/` with `edit` applied to its JSON.
fn edited(edit: impl FnOnce(&mut serde_json::Value)) -> String {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../mechanisms/multibody/3-rps-split.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    edit(&mut v);
    serde_json::to_string_pretty(&v).unwrap()
}

#[test]
fn the_command_line_refuses_bad_v2_files_in_one_line_and_names_bodies() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("self-leg.json");
    std::fs::write(&bad, edited(|v| v["legs"][3]["to"] = "A".into())).unwrap();
    let o = kinsyn(&["analyze", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("legs[3].to: \"A\" again"), "{err}");
    let o = kinsyn(&[
        "analyze",
        "mechanisms/multibody/3-rps-split.json",
        "--body",
        "Q",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--body \"Q\": \"Q\" is not a moving body"));
    // Text names the end-effector and every body's dof; JSON lists the bodies.
    let o = kinsyn(&["analyze", "mechanisms/multibody/3-rps-3-rps.json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("coupler 3, end-effector 6"), "{out}");
    assert!(out.contains("J_D, J_I: not defined"), "{out}");
    let o = kinsyn(&["analyze", "mechanisms/multibody/3-rps-split.json", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["mobility"], 4);
    assert_eq!(v["end_effector"], "B");
    assert_eq!(v["bodies"][0]["name"], "A");
    assert_eq!(v["bodies"][0]["dof"], 4);
    assert_eq!(v["leg_wrench_jacobians"], false);
}
