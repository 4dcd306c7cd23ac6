//! `kinsyn export --mjcf` and `--urdf` read by Pinocchio (tests/pinocchio/check.py): every
//! committed description's spanning tree, whole, with forward kinematics equal to kinsyn's.
//!
//! For each description in `mechanisms/` (and `mechanisms/multibody/`), kinsyn assembles a
//! configuration away from the reference (every input moved, the other joints solved by
//! continuation) and computes every body's displacement and the end-effector frame there by its
//! own product of exponentials. Pinocchio reads the export, takes kinsyn's joint values, and
//! must put every body and the end-effector at kinsyn's poses: an independent second
//! implementation of the tree's kinematics. Pinocchio holds the tree only (it ignores MJCF
//! equality constraints, URDF has none), so its joints are the tree's: one per body but the
//! ground, plus, in the MJCF, the joint of each welded chord's extra body. Needs python3 with
//! `pinocchio` (`pip install pin`) and `numpy`; without them the test prints a notice and
//! passes, unless the environment variable `CI` is set.

use crate::common;

use kinsyn::manipulator::{Manipulator, PlatformGoal, PositionRequest};
use kinsyn::mechanism::Coordinate;
use kinsyn::mjcf::{ChordClosure, ExportTree};
use kinsyn::notation::Primitive;
use kinsyn::spatial::Displacement;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Position error allowed over the characteristic length, and angle error (rad).
const TOLERANCE: f64 = 1e-9;

/// Whether Pinocchio can be used; panics when it cannot and `CI` is set.
fn pinocchio_available() -> bool {
    let ok = Command::new("python3")
        .args(["-c", "import pinocchio, numpy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set but `python3 -c 'import pinocchio, numpy'` fails: install them (pip install pin numpy)"
        );
        eprintln!(
            "notice: python3 with pinocchio and numpy not found; the Pinocchio export test is skipped"
        );
    }
    ok
}

fn repo() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// The committed descriptions: `mechanisms/*.json` and `mechanisms/multibody/*.json`.
fn descriptions() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for dir in ["mechanisms", "mechanisms/multibody"] {
        for entry in std::fs::read_dir(repo().join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "json") {
                files.push(path);
            }
        }
    }
    files.sort();
    assert!(
        files.len() >= 9,
        "the committed descriptions were not found"
    );
    files
}

/// The primitive joint labels of a manipulator (`P1.3`: leg 1, third joint), by joint.
fn labels(m: &Manipulator) -> Vec<String> {
    let mech = m.mechanism();
    let mut out: Vec<String> = (0..mech.joints().len())
        .map(|j| format!("joint {}", j + 1))
        .collect();
    for (l, leg) in m.legs().iter().enumerate() {
        for (k, j) in leg.joints.clone().enumerate() {
            out[j] = format!("{}{}.{}", mech.joints()[j].kind.letter(), l + 1, k + 1);
        }
    }
    out
}

/// An assembled configuration away from the reference: every input moved (sliders by a few
/// hundredths of the characteristic length, revolutes by a few hundredths of a radian,
/// differently per input; halved until kinsyn's continuation from the reference reaches it
/// without leaving the reference's branch), the other joints solved. Where the inputs leave
/// the end-effector free (a split platform), one of its coordinates is moved as well.
fn displaced(m: &Manipulator, file: &Path) -> Vec<f64> {
    let scale = m.mechanism().scale();
    let start = m.body_frame(m.end_effector(), &m.reference());
    let (p, r) = (start.translation.vector, start.rotation.scaled_axis());
    let coordinates = [
        None,
        Some((Coordinate::Rz, r.z)),
        Some((Coordinate::Z, p.z)),
        Some((Coordinate::X, p.x)),
        Some((Coordinate::Rx, r.x)),
    ];
    for extra in coordinates {
        let mut size = 1.0;
        for _ in 0..5 {
            #[allow(clippy::cast_precision_loss, reason = "a few inputs")]
            let inputs = m
                .actuators()
                .iter()
                .enumerate()
                .map(|(a, act)| {
                    let step = size * (0.02 + 0.01 * (a % 3) as f64);
                    let sign = if a % 2 == 0 { 1.0 } else { -1.0 };
                    let value = match m.mechanism().joints()[act.joint].kind {
                        Primitive::P => sign * step * scale,
                        Primitive::R => sign * step,
                    };
                    (a, value)
                })
                .collect();
            let platform = extra.map(|(c, at)| {
                let step = if matches!(c, Coordinate::X | Coordinate::Z) {
                    0.01 * scale
                } else {
                    0.01
                };
                PlatformGoal::Coordinates(vec![(c, at + size * step)])
            });
            let request = PositionRequest {
                inputs,
                platform,
                ..PositionRequest::default()
            };
            if let Ok(reached) = m.solve_position(&m.reference(), &request)
                && reached.continuous
            {
                assert!(reached.q.iter().any(|v| v.abs() > 1e-4));
                return reached.q;
            }
            size /= 2.0;
        }
    }
    panic!("{}: no displaced configuration reached", file.display());
}

fn matrix(d: &Displacement) -> serde_json::Value {
    let h = d.to_homogeneous();
    (0..4)
        .map(|r| (0..4).map(|c| h[(r, c)]).collect::<Vec<f64>>())
        .collect::<Vec<_>>()
        .into()
}

/// Exports `file` as `format` and checks it in Pinocchio at kinsyn's displaced configuration.
fn check(file: &Path, format: &str) -> serde_json::Value {
    let shown = file.display();
    let m = Manipulator::from_json(&std::fs::read_to_string(file).unwrap()).unwrap();
    let mech = m.mechanism();
    let q = displaced(&m, file);
    let labels = labels(&m);

    // The tree has one joint per body but the ground; the MJCF adds one per welded chord.
    let tree = ExportTree::new(&m);
    let in_tree: Vec<usize> = tree.parent.iter().flatten().map(|&(_, j)| j).collect();
    assert_eq!(in_tree.len(), mech.body_count() - 1, "{shown}");
    let mut model_joints = in_tree.clone();
    if format == "mjcf" {
        model_joints.extend(
            tree.chords
                .iter()
                .filter(|(_, c)| *c == ChordClosure::Weld)
                .map(|&(j, _)| j),
        );
    }
    // Every joint of both files is bounded (hinge, slide; URDF revolute, prismatic): one
    // coordinate each.
    let nv = model_joints.len();
    let nq = nv;

    let poses = mech.poses(&q);
    let mut names: Vec<String> = (0..mech.body_count())
        .map(|b| mech.body_name(b).to_string())
        .collect();
    names.dedup();
    assert_eq!(names.len(), mech.body_count(), "{shown}: body names repeat");
    let bodies: serde_json::Map<String, serde_json::Value> = (0..mech.body_count())
        .map(|b| (names[b].clone(), matrix(&poses[b])))
        .collect();
    let end = m.end_effector();
    let expected = serde_json::json!({
        "format": format,
        "nq": nq,
        "nv": nv,
        "joints": (0..q.len()).map(|j| (labels[j].clone(), q[j].into()))
            .collect::<serde_json::Map<String, serde_json::Value>>(),
        "model_joints": model_joints.iter().map(|&j| labels[j].clone()).collect::<Vec<_>>(),
        "bodies": bodies,
        "end_effector": {"name": m.bodies()[end].name, "frame": matrix(&m.body_frame(end, &q))},
        "scale": mech.scale(),
        "tolerance": {"length": TOLERANCE, "angle": TOLERANCE},
    });

    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join(format!("model.{format}"));
    let o = common::kinsyn(&[
        "export",
        file.to_str().unwrap(),
        &format!("--{format}"),
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{shown}: {}", common::stderr(&o));
    let json = dir.path().join("expected.json");
    std::fs::write(&json, expected.to_string()).unwrap();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/pinocchio/check.py");
    let o = Command::new("python3")
        .arg(&script)
        .arg(&out)
        .arg(&json)
        .output()
        .unwrap();
    let report = common::stdout(&o);
    eprintln!("{shown} ({format}): {report}");
    assert!(
        o.status.success(),
        "{shown} ({format}): Pinocchio's tree is not kinsyn's: {report} {}",
        common::stderr(&o)
    );
    serde_json::from_str(report.trim()).unwrap()
}

#[test]
fn pinocchio_reads_every_leg_of_the_mjcf_export() {
    if !pinocchio_available() {
        return;
    }
    for file in descriptions() {
        check(&file, "mjcf");
    }
}

#[test]
fn pinocchio_reads_the_urdf_export() {
    if !pinocchio_available() {
        return;
    }
    for file in descriptions() {
        check(&file, "urdf");
    }
}

#[test]
fn the_urdf_lists_the_loop_closing_joints() {
    // The 6-UPS: five loops, each closed by a passive revolute at the platform (R2.6 to
    // R6.6), none of them a URDF joint. The platform's frame is off the axis of R1.6, the tree
    // joint that reaches it: R1.6 reaches the extra link `platform (R1.6)`, fixed to
    // `platform`.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("6-ups.urdf");
    let o = common::kinsyn(&[
        "export",
        "mechanisms/6-ups.json",
        "--urdf",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(text.matches("<joint ").count(), 32);
    assert_eq!(text.matches("type=\"revolute\"").count(), 25);
    assert_eq!(text.matches("<limit ").count(), 31);
    assert_eq!(text.matches("type=\"prismatic\"").count(), 6);
    assert_eq!(text.matches("type=\"fixed\"").count(), 1);
    assert_eq!(text.matches("<link ").count(), 33);
    assert!(text.contains("<child link=\"platform (R1.6)\"/>"));
    for leg in 2..=6 {
        let label = format!("R{leg}.6");
        assert!(!text.contains(&format!("<joint name=\"{label}\"")));
        assert!(text.contains(&format!(
            "{label} (revolute) from link 'leg {leg} link 5' to link 'platform'"
        )));
    }
}

#[test]
fn urdf_output_follows_the_output_file_rules() {
    let dir = tempfile::tempdir().unwrap();
    let urdf = dir.path().join("out.urdf");
    let xml = dir.path().join("out.xml");
    let (urdf_s, xml_s) = (urdf.to_str().unwrap(), xml.to_str().unwrap());
    // Both at once.
    let o = common::kinsyn(&[
        "export",
        "mechanisms/3-rps.json",
        "--mjcf",
        xml_s,
        "--urdf",
        urdf_s,
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    assert!(common::stdout(&o).contains("out.urdf"));
    assert!(std::fs::read_to_string(&urdf).unwrap().starts_with("<?xml"));
    // An existing file is refused, and nothing is written: the MJCF beside it is left alone.
    std::fs::write(&xml, "old").unwrap();
    let o = common::kinsyn(&[
        "export",
        "mechanisms/3-rps.json",
        "--mjcf",
        xml_s,
        "--urdf",
        urdf_s,
    ]);
    common::assert_refused(&o, "existing URDF", &["--mjcf", "--force"]);
    assert_eq!(std::fs::read_to_string(&xml).unwrap(), "old");
    let o = common::kinsyn(&["export", "mechanisms/3-rps.json", "--urdf", urdf_s]);
    common::assert_refused(&o, "existing URDF", &["--urdf", "exists", "--force"]);
    let o = common::kinsyn(&[
        "export",
        "mechanisms/3-rps.json",
        "--urdf",
        urdf_s,
        "--force",
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    // The same file for both.
    let o = common::kinsyn(&[
        "export",
        "mechanisms/3-rps.json",
        "--mjcf",
        urdf_s,
        "--urdf",
        urdf_s,
        "--force",
    ]);
    common::assert_refused(&o, "same file", &["give two files"]);
    let o = common::kinsyn(&["export", "--help"]);
    assert!(common::stdout(&o).contains("--urdf 6-ups.urdf"));
}
