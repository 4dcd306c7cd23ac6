//! `kinsyn plot workspace|indices`: paper 001's Figs. 3–4 written as SVG and PNG, the JSON
//! consistent with the library, bad input refused in one line.

use crate::common;
use common::kinsyn;
use kinsyn::manipulator::file::MultibodyDescription;
use kinsyn_papers::hexa::{Hexa, WorkspaceSettings};

/// Paper 001's HEXA as data (the plots read its dimensions from it).
const HEXA: &str = "mechanisms/6-ruu-hexa.json";

fn run_ok(args: &[&str]) -> String {
    let out = kinsyn(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn check_figure(dir: &std::path::Path, name: &str) {
    let png = std::fs::read(dir.join(format!("{name}.png"))).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"), "{name}.png");
    let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
    assert!(
        svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
        "{name}.svg"
    );
}

#[test]
fn the_workspace_figures_and_json_match_the_library() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().to_str().unwrap();
    let text = run_ok(&[
        "plot",
        "workspace",
        HEXA,
        "--out",
        d,
        "--step",
        "40",
        "--json",
    ]);
    check_figure(dir.path(), "hexa-workspace");
    check_figure(dir.path(), "hexa-four-bar");
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    // The library on the file's dimensions (read back to about 1e-14 mm: P2 samples binned to
    // the nearest cell can fall on a cell boundary, so paper001()'s exact 60s may bin a few
    // cells the other way).
    let text_file = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../mechanisms/6-ruu-hexa.json"
    ))
    .unwrap();
    let h = Hexa::from_description(&MultibodyDescription::from_json(&text_file).unwrap()).unwrap();
    let w = h
        .workspace(
            &WorkspaceSettings {
                step: 40.0,
                ..WorkspaceSettings::default()
            },
            &|_, _| {},
        )
        .unwrap();
    assert_eq!(v["end_effector1"]["cells"], w.points(0).len());
    assert_eq!(v["end_effector2"]["cells"], w.points(1).len());
    let c = w.regular_cylinder().unwrap();
    assert!((v["cylinder"]["radius"].as_f64().unwrap() - c.radius).abs() < 1e-9);
    assert!((v["cylinder"]["z_lo"].as_f64().unwrap() - c.z_lo).abs() < 1e-9);
}

#[test]
fn the_index_maps_are_written_at_45_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().to_str().unwrap();
    let text = run_ok(&[
        "plot",
        "indices",
        HEXA,
        "--out",
        d,
        "--phi1",
        "45",
        "--phi2",
        "-45",
        "--step",
        "30",
        "--workspace-step",
        "40",
        "--json",
    ]);
    check_figure(dir.path(), "hexa-indices");
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    for key in ["lambda_min", "sigma", "xi_min"] {
        let s = &v["all"][key];
        let (lo, hi) = (s["min"].as_f64().unwrap(), s["max"].as_f64().unwrap());
        assert!((0.0..=hi).contains(&lo) && hi <= 1.0, "{key}");
    }
    // §4: λ > 0.2 over the regular workspace.
    assert!(v["all"]["lambda_min"]["min"].as_f64().unwrap() > 0.2);
    assert_eq!(v["cells"], v["assemblable"]);
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    let file = tempfile::NamedTempFile::new().unwrap();
    let f = file.path().to_str().unwrap();
    for args in [
        vec!["plot", "workspace", HEXA, "--step", "0"],
        vec!["plot", "workspace", HEXA, "--step", "-5"],
        vec!["plot", "workspace", HEXA, "--step", "NaN"],
        vec!["plot", "workspace", HEXA, "--step", "0.5"],
        vec!["plot", "workspace", HEXA, "--phi1", "400"],
        vec!["plot", "indices", HEXA, "--phi2", "inf"],
        vec!["plot", "indices", HEXA, "--z", "100"],
        vec!["plot", "workspace", HEXA, "--step", "40", "--out", f],
        // Not a HEXA (docs/hexa.md: the dimensions are read from the file, which must be one).
        vec!["plot", "workspace", "mechanisms/3-rps.json"],
        vec!["plot", "indices", "mechanisms/missing.json"],
    ] {
        let out = kinsyn(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    }
}
