//! `kinsyn view`: the page loaded in headless Chromium (`common::browser`). It loads without
//! errors, draws (a screenshot that is not blank, the mechanism's bounding box on screen), and
//! the end-effector it shows — computed by the page's own forward kinematics, JavaScript's
//! product of exponentials over the joint values kinsyn wrote — is where kinsyn's
//! (`Manipulator::platform_frame`, Rust) puts it, to 1e-9 relative, along a mode's animation and
//! at every assembly. The assemblies are also compared with `kinsyn analyze --all-assemblies`,
//! whose poses come from the polynomial solve, not from joint values.

use crate::common;

use common::browser::{Screenshot, chromium, numbers, screenshot, url, view_states as states};
use common::{assert_refused, kinsyn, stdout};
use kinsyn::manipulator::Manipulator;
use serde_json::Value;
use std::path::Path;

const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// Writes the view of `file` (relative to the repository root) into `dir` with `extra`
/// options; returns the page's name and its data.
fn write_view(file: &str, dir: &Path, extra: &[&str]) -> (String, Value) {
    let name = format!(
        "{}.html",
        Path::new(file).file_stem().unwrap().to_str().unwrap()
    );
    let out = dir.join(&name);
    let mut args = vec!["view", file, "--out", out.to_str().unwrap()];
    args.extend_from_slice(extra);
    let o = kinsyn(&args);
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    assert!(stdout(&o).starts_with("wrote "), "{}", stdout(&o));
    let html = std::fs::read_to_string(&out).unwrap();
    let start = html
        .find("<script type=\"application/json\" id=\"kinsyn-data\">")
        .expect("the page's data");
    let rest = &html[start..];
    let json = &rest[rest.find('>').unwrap() + 1..rest.find("</script>").unwrap()];
    (name, serde_json::from_str(json).expect("the data is JSON"))
}

/// The page's end-effector frame equals kinsyn's at joint values `q`, to 1e-9 relative
/// (positions relative to the characteristic length).
fn assert_same_frame(m: &Manipulator, q: &[f64], state: &Value, what: &str) {
    let frame = m.platform_frame(q);
    let position = numbers(&state["end_effector_position"]);
    let rotation = numbers(&state["end_effector_rotation"]);
    let scale = m.mechanism().scale().max(frame.translation.vector.norm());
    for (i, p) in position.iter().enumerate() {
        let d = (p - frame.translation.vector[i]).abs();
        assert!(d <= 1e-9 * scale, "{what}: position {i} off by {d:e}");
    }
    let r = frame.rotation.matrix();
    for k in 0..9 {
        let d = (rotation[k] - r[(k / 3, k % 3)]).abs();
        assert!(d <= 1e-9, "{what}: rotation {k} off by {d:e}");
    }
}

fn joint_values(v: &Value) -> Vec<f64> {
    numbers(v)
}

fn manipulator(file: &str) -> Manipulator {
    Manipulator::from_json(&std::fs::read_to_string(format!("{ROOT}/{file}")).unwrap()).unwrap()
}

/// The share of the canvas (the page's left part) whose pixels differ from the background.
fn drawn_share(png: &Path) -> f64 {
    let image = Screenshot::read(png);
    image.drawn_share(0..image.width * 6 / 10, 0..image.height)
}

#[test]
fn the_view_of_the_3_ups_draws_it_and_animates_its_modes_where_kinsyn_puts_them() {
    let Some(chromium) = chromium("the view test") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let file = "mechanisms/3-ups.json";
    let (page, data) = write_view(file, dir.path(), &["--steps", "6"]);
    let m = manipulator(file);

    // Drawn: a screenshot that is not blank.
    let png = dir.path().join("shot.png");
    screenshot(&chromium, &url(dir.path(), &page), &png);
    let share = drawn_share(&png);
    assert!(share > 0.02, "the canvas is blank: {share}");

    let start = joint_values(&data["start"]);

    // A mode's animation: every frame closes the loops with the locked inputs held, the
    // end-effector moves, and the page shows it where kinsyn computes it.
    let modes = data["modes"].as_array().unwrap();
    let (k, mode) = modes
        .iter()
        .enumerate()
        .find(|(_, md)| md["dof"].as_u64() == Some(3) && md["locks"] != "-")
        .expect("a 3-dof mode with locks");
    let frames: Vec<Vec<f64>> = mode["joint_values"]
        .as_array()
        .unwrap()
        .iter()
        .map(joint_values)
        .collect();
    assert_eq!(frames.len(), 13, "6 steps to either side");
    let locked = m
        .parse_locks(&mode["locks"].as_str().unwrap().replace(' ', ","))
        .unwrap();
    for q in &frames {
        let residual = m.mechanism().closure_residual(q).amax();
        assert!(residual < 1e-9, "the loops are open: {residual:e}");
        for &a in &locked {
            let j = m.actuators()[a].joint;
            assert!((q[j] - start[j]).abs() < 1e-12, "a locked input moved");
        }
    }
    let (first, last) = (m.point(&frames[0]), m.point(&frames[12]));
    assert!(
        (first - last).norm() > 1e-2 * m.mechanism().scale(),
        "the mode does not move the end-effector"
    );

    // A sweep: the input takes the listed values, the others are held.
    let sweep = &data["sweeps"][1];
    let a = m.actuator_named(sweep["input"].as_str().unwrap()).unwrap();
    let swept = joint_values(&sweep["joint_values"][0]);
    assert!(
        (swept[m.actuators()[a].joint] - numbers(&sweep["values"])[0]).abs() < 1e-12,
        "a slider's value is the joint value in the length unit"
    );

    // What the page shows, where kinsyn puts it: the start, three frames of the mode, the
    // sweep's first configuration.
    let mut items = vec!["start:0".to_string()];
    items.extend([0, 4, 12].map(|f| format!("mode:{k}:{f}")));
    items.push("sweep:1:0".to_string());
    let shown = states(&chromium, dir.path(), &page, &items);
    assert_same_frame(&m, &start, &shown[0], "start");
    for (s, f) in shown[1..4].iter().zip([0, 4, 12]) {
        assert_eq!(s["frame"].as_u64(), Some(f as u64));
        assert_same_frame(&m, &frames[f], s, &format!("mode {k} frame {f}"));
    }
    assert_same_frame(&m, &swept, &shown[4], "sweep 1");
}

#[test]
fn the_view_shows_the_assemblies_of_the_polynomial_solve() {
    let Some(chromium) = chromium("the view test") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let file = "mechanisms/3-rps.json";
    let (page, data) = write_view(file, dir.path(), &["--steps", "2"]);
    let m = manipulator(file);
    let o = kinsyn(&["analyze", file, "--all-assemblies", "--json"]);
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    let report: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let solved: Vec<Vec<f64>> = report["real_assemblies"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| numbers(&a["position"]))
        .collect();
    let assemblies = data["assemblies"].as_array().unwrap();
    // As many as the polynomial solve reports, each at one of its poses.
    assert_eq!(assemblies.len(), solved.len());
    assert!(!solved.is_empty());
    let items: Vec<String> = (0..assemblies.len())
        .map(|k| format!("assembly:{k}"))
        .collect();
    let shown = states(&chromium, dir.path(), &page, &items);
    for (k, (a, s)) in assemblies.iter().zip(&shown).enumerate() {
        let q = joint_values(&a["joint_values"]);
        assert_same_frame(&m, &q, s, &format!("assembly {k}"));
        let shown = numbers(&s["end_effector_position"]);
        let nearest = solved
            .iter()
            .map(|p| {
                (0..3)
                    .map(|i| (p[i] - shown[i]).powi(2))
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(f64::INFINITY, f64::min);
        assert!(
            nearest < 1e-8 * m.mechanism().scale(),
            "assembly {k} is not one the solve found: {nearest:e}"
        );
    }
}

#[test]
fn view_refuses_bad_requests_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("v.html");
    let out = out.to_str().unwrap();
    for (args, needles) in [
        (
            vec![
                "view",
                "mechanisms/3-ups.json",
                "--out",
                out,
                "--steps",
                "0",
            ],
            vec!["--steps 0", "from 1 to 200"],
        ),
        (
            vec![
                "view",
                "mechanisms/3-ups.json",
                "--out",
                out,
                "--steps",
                "201",
            ],
            vec!["--steps 201"],
        ),
        (
            vec![
                "view",
                "mechanisms/3-ups.json",
                "--out",
                out,
                "--inputs",
                "Q9=1",
            ],
            vec!["--inputs"],
        ),
        (
            vec!["view", "mechanisms/none.json", "--out", out],
            vec!["none.json"],
        ),
        (
            vec![
                "view",
                "mechanisms/3-ups.json",
                "--out",
                "no/such/folder/v.html",
            ],
            vec!["--out"],
        ),
    ] {
        assert_refused(&kinsyn(&args), &args.join(" "), &needles);
        assert!(!Path::new(out).exists(), "{args:?} wrote the page");
    }
    // 18 inputs at 200 steps: their sweeps (18 × 401 configurations) and the walks of the
    // patterns reached pass the page's 8 192; refused before any walk.
    let ups = dir.path().join("ups18.json");
    let o = kinsyn(&[
        "build",
        "--legs",
        "6",
        "--chain",
        "U(!,!)P!S",
        "-o",
        ups.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    let args = [
        "view",
        ups.to_str().unwrap(),
        "--out",
        out,
        "--steps",
        "200",
        "--no-assemblies",
    ];
    assert_refused(
        &kinsyn(&args),
        "18 inputs at 200 steps",
        &["--steps 200", "8192", "fewer --steps"],
    );
    assert!(!Path::new(out).exists(), "the refused page was written");
    let o = kinsyn(&[
        "view",
        "mechanisms/3-rrr-planar.json",
        "--out",
        out,
        "--steps",
        "1",
    ]);
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    assert_refused(
        &kinsyn(&["view", "mechanisms/3-rrr-planar.json", "--out", out]),
        "an existing page",
        &["exists", "--force"],
    );
}

/// Every committed description: the page loads without errors, draws (a screenshot that is not
/// blank), and the mechanism is on screen at the start and along its first mode, where kinsyn
/// puts it. About 2 minutes (the HEXA's modes
/// and the 4-RRR's).
#[test]
#[ignore = "every committed description in Chromium: about 2 minutes"]
fn every_committed_description_has_a_view_that_loads_and_agrees_with_kinsyn() {
    let Some(chromium) = chromium("the view test") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let mut files: Vec<String> = Vec::new();
    for folder in ["mechanisms", "mechanisms/multibody"] {
        for entry in std::fs::read_dir(format!("{ROOT}/{folder}")).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "json") {
                files.push(format!(
                    "{folder}/{}",
                    path.file_name().unwrap().to_str().unwrap()
                ));
            }
        }
    }
    files.sort();
    assert!(files.len() >= 15, "{files:?}");
    for file in &files {
        let (page, data) = write_view(file, dir.path(), &["--steps", "3", "--no-assemblies"]);
        let m = manipulator(file);
        let start = joint_values(&data["start"]);
        let mode = &data["modes"][0];
        let last = mode["joint_values"].as_array().unwrap().len() - 1;
        let q = joint_values(&mode["joint_values"][last]);
        let shown = states(
            &chromium,
            dir.path(),
            &page,
            &["start:0".to_string(), format!("mode:0:{last}")],
        );
        assert_same_frame(&m, &start, &shown[0], file);
        assert_same_frame(&m, &q, &shown[1], &format!("{file} mode 0"));
        let png = dir.path().join(format!("{page}.png"));
        screenshot(&chromium, &url(dir.path(), &page), &png);
        let share = drawn_share(&png);
        assert!(share > 0.01, "{file}: the canvas is blank ({share})");
    }
}

#[test]
fn the_view_animates_the_self_motions_of_the_global_decomposition() {
    // Paper 004's 4-RUU at Fig. 13's inputs (absolute cranks 90°, 0°, 0°, 90°): its
    // decomposition (docs/operation-modes.md, `ruu_self_motions`) has a self-motion of the third
    // mode (1 dof, the platform turning) and two 1-dof translations in K2 with real points, and
    // complex curves in K1. The page animates each real one with every input held, and shows it
    // where kinsyn puts it.
    let dir = tempfile::tempdir().unwrap();
    let file = "mechanisms/4-ruu.json";
    let (page, data) = write_view(
        file,
        dir.path(),
        &[
            "--steps",
            "4",
            "--no-assemblies",
            "--components",
            "--inputs",
            "R1.1=180,R2.1=0,R3.1=-90,R4.1=90",
        ],
    );
    let m = manipulator(file);
    let inputs: Vec<usize> = m.actuators().iter().map(|a| a.joint).collect();
    let found: Vec<&Value> = data["modes"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|md| md["source"].as_str().unwrap().starts_with("components"))
        .collect();
    let mut patterns: Vec<&str> = found
        .iter()
        .map(|md| md["pattern"].as_str().unwrap())
        .collect();
    patterns.sort_unstable();
    assert_eq!(patterns, ["0T1R", "1T0R", "1T0R"], "{found:?}");
    let start = joint_values(&found[0]["joint_values"][0]);
    let mut items = Vec::new();
    let modes = data["modes"].as_array().unwrap();
    for md in &found {
        assert_eq!(md["locks"], "R1.1 R2.1 R3.1 R4.1");
        let frames: Vec<Vec<f64>> = md["joint_values"]
            .as_array()
            .unwrap()
            .iter()
            .map(joint_values)
            .collect();
        assert_eq!(frames.len(), 9);
        for q in &frames {
            assert!(m.mechanism().closure_residual(q).amax() < 1e-9);
            for &j in &inputs {
                assert!(
                    (q[j] - start[j]).abs() < 1e-9,
                    "an input moved on a self-motion"
                );
            }
        }
        assert!(
            (m.point(&frames[0]) - m.point(&frames[8])).norm() > 1e-3 * m.mechanism().scale()
                || (m
                    .platform_frame(&frames[0])
                    .rotation
                    .angle_to(&m.platform_frame(&frames[8]).rotation))
                    > 1e-3,
            "the self-motion does not move the platform"
        );
        let k = modes.iter().position(|x| std::ptr::eq(x, *md)).unwrap();
        items.push(format!("mode:{k}:8"));
    }
    let Some(chromium) = chromium("the view test") else {
        return;
    };
    let shown = states(&chromium, dir.path(), &page, &items);
    for (md, s) in found.iter().zip(&shown) {
        assert_same_frame(&m, &joint_values(&md["joint_values"][8]), s, "self-motion");
    }
}
