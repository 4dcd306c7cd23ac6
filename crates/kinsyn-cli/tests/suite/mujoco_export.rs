//! `kinsyn export --mjcf` checked in MuJoCo (tests/mujoco/check.py): the exported model, driven
//! to kinsyn's input values at a displaced pose, must reach that pose.
//!
//! The poses are chosen here, not computed by the export: kinsyn's inverse kinematics gives the
//! input values there (the 6-UPS: the whole pose; the 3-PRRR: a translation, its orientation
//! staying the identity; the 3-RPS: height and tilts, its parasitic x, y and rz solved), and
//! MuJoCo, from the reference with the inputs ramped to those values, simulates the platform to
//! where they put it. Needs python3 with `mujoco` and `numpy`; without them the test prints a
//! notice and passes, unless the environment variable `CI` is set.

use crate::common;

use kinsyn::manipulator::{Manipulator, PlatformGoal, PositionRequest};
use kinsyn::mechanism::Coordinate;
use kinsyn::mjcf::{ChordClosure, ExportTree};
use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use std::path::Path;
use std::process::Command;

/// Position error allowed, over the mechanism's characteristic length, and orientation error
/// (rad), after the model has settled: docs/export.md, "Accuracy". With no load the settled
/// state is the exact closure (a soft constraint at rest pulls with a force proportional to its
/// violation, and nothing pulls back), so what is left is the decay of the motion.
const LENGTH_TOLERANCE: f64 = 1e-9;
const ANGLE_TOLERANCE: f64 = 1e-9;

/// Whether MuJoCo can be used; panics when it cannot and `CI` is set.
fn mujoco_available() -> bool {
    let ok = Command::new("python3")
        .args(["-c", "import mujoco, numpy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set but `python3 -c 'import mujoco, numpy'` fails: install them (pip install mujoco numpy)"
        );
        eprintln!(
            "notice: python3 with mujoco and numpy not found; the MuJoCo export test is skipped"
        );
    }
    ok
}

fn repo() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// The primitive joint labels of a manipulator (`P1.3`: leg 1, third joint), by joint.
fn labels(m: &Manipulator) -> Vec<String> {
    let mut out = vec![String::new(); m.mechanism().joints().len()];
    for (l, leg) in m.legs().iter().enumerate() {
        for (k, j) in leg.joints.clone().enumerate() {
            out[j] = format!(
                "{}{}.{}",
                m.mechanism().joints()[j].kind.letter(),
                l + 1,
                k + 1
            );
        }
    }
    out
}

/// Exports `file`, solves kinsyn's inverse kinematics for `goal`, and checks in MuJoCo that the
/// inputs found put the end-effector where kinsyn says; `expect` checks kinsyn's pose against
/// the goal's own terms first. Returns MuJoCo's measurements.
fn check(
    file: &str,
    goal: PlatformGoal,
    expect: impl Fn(&nalgebra::IsometryMatrix3<f64>),
) -> serde_json::Value {
    let text = std::fs::read_to_string(repo().join(file)).unwrap();
    let m = Manipulator::from_json(&text).unwrap();
    let request = PositionRequest {
        platform: Some(goal),
        ..PositionRequest::default()
    };
    let reached = m.solve_position(&m.reference(), &request).unwrap();
    assert!(
        reached.continuous,
        "{file}: kinsyn left the reference's branch"
    );
    let q = reached.q;
    let frame = m.body_frame(m.end_effector(), &q);
    expect(&frame);

    let dir = tempfile::tempdir().unwrap();
    let xml = dir.path().join("model.xml");
    let o = common::kinsyn(&["export", file, "--mjcf", xml.to_str().unwrap()]);
    assert!(o.status.success(), "{file}: {}", common::stderr(&o));

    let labels = labels(&m);
    let connected: Vec<usize> = ExportTree::new(&m)
        .chords
        .iter()
        .filter(|(_, c)| *c == ChordClosure::Connect)
        .map(|&(j, _)| j)
        .collect();
    let joints: serde_json::Map<String, serde_json::Value> = (0..q.len())
        .filter(|j| !connected.contains(j))
        .map(|j| (labels[j].clone(), q[j].into()))
        .collect();
    let ctrl: serde_json::Map<String, serde_json::Value> = m
        .actuators()
        .iter()
        .map(|a| (a.label(), q[a.joint].into()))
        .collect();
    // With the inputs locked, no joint moves (no leg has an idle motion).
    let all_inputs: Vec<usize> = (0..m.actuators().len()).collect();
    let determined = m.mechanism().mobility(&q, &m.lock_mask(&all_inputs)).dof == 0;
    let rotation = UnitQuaternion::from_rotation_matrix(&frame.rotation);
    let p = frame.translation.vector;
    let expected = serde_json::json!({
        "body": m.bodies()[m.end_effector()].name,
        "ctrl": ctrl,
        "position": [p.x, p.y, p.z],
        "quaternion": [rotation.w, rotation.i, rotation.j, rotation.k],
        "joints": joints,
        "determined": determined,
        "scale": m.mechanism().scale(),
        "tolerance": {"length": LENGTH_TOLERANCE, "angle": ANGLE_TOLERANCE},
        "ramp": 1.0,
        "settle": 3.0,
    });
    let json = dir.path().join("expected.json");
    std::fs::write(&json, expected.to_string()).unwrap();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/mujoco/check.py");
    let o = Command::new("python3")
        .arg(&script)
        .arg(&xml)
        .arg(&json)
        .output()
        .unwrap();
    let out = common::stdout(&o);
    eprintln!("{file}: {out}");
    assert!(
        o.status.success(),
        "{file}: MuJoCo did not reach kinsyn's pose: {out} {}",
        common::stderr(&o)
    );
    serde_json::from_str(out.trim()).unwrap()
}

#[test]
fn six_ups_reaches_the_pose_its_inputs_give() {
    if !mujoco_available() {
        return;
    }
    // Raised 5 cm, shifted 3 cm, tilted 5° about an oblique axis.
    let position = Vector3::new(0.03, -0.02, 1.05);
    let tilt = Vector3::new(1.0, 2.0, 0.5).normalize() * 5f64.to_radians();
    let pose = kinsyn::spatial::displacement(Rotation3::from_scaled_axis(tilt), position);
    check("mechanisms/6-ups.json", PlatformGoal::Pose(pose), |g| {
        assert!((g.translation.vector - position).norm() < 1e-9);
        assert!((g.rotation.scaled_axis() - tilt).norm() < 1e-9);
    });
}

#[test]
fn three_prrr_translates_to_the_point_its_inputs_give() {
    if !mujoco_available() {
        return;
    }
    let goal = [
        (Coordinate::X, 0.04),
        (Coordinate::Y, -0.03),
        (Coordinate::Z, 1.05),
    ];
    check(
        "mechanisms/3-prrr.json",
        PlatformGoal::Coordinates(goal.to_vec()),
        |g| {
            // A translational manipulator: the platform keeps its orientation.
            assert!(g.rotation.angle() < 1e-9);
            assert!((g.translation.vector - Vector3::new(0.04, -0.03, 1.05)).norm() < 1e-9);
        },
    );
}

#[test]
fn three_rps_reaches_the_height_and_tilts_its_inputs_give() {
    if !mujoco_available() {
        return;
    }
    let (z, rx, ry) = (1.06, 4f64.to_radians(), -3f64.to_radians());
    let goal = [
        (Coordinate::Z, z),
        (Coordinate::Rx, rx),
        (Coordinate::Ry, ry),
    ];
    check(
        "mechanisms/3-rps.json",
        PlatformGoal::Coordinates(goal.to_vec()),
        |g| {
            assert!((g.translation.vector.z - z).abs() < 1e-9);
            let r = g.rotation.scaled_axis();
            assert!((r.x - rx).abs() < 1e-9 && (r.y - ry).abs() < 1e-9);
        },
    );
}

#[test]
fn a_loop_of_sliders_is_closed_by_a_welded_slider() {
    let file = "crates/kinsyn-cli/tests/mujoco/2-ppp.json";
    let m = Manipulator::from_json(&std::fs::read_to_string(repo().join(file)).unwrap()).unwrap();
    // Six sliders in one loop: the tree keeps the three inputs and two passive sliders, and
    // the last passive slider (leg 2's third, P2.3) closes the loop on a welded extra body.
    let tree = ExportTree::new(&m);
    assert_eq!(tree.chords, vec![(5, ChordClosure::Weld)]);
    if !mujoco_available() {
        return;
    }
    let goal = [
        (Coordinate::X, 0.04),
        (Coordinate::Y, -0.03),
        (Coordinate::Z, 1.05),
    ];
    check(file, PlatformGoal::Coordinates(goal.to_vec()), |g| {
        assert!(g.rotation.angle() < 1e-12);
        assert!((g.translation.vector - Vector3::new(0.04, -0.03, 1.05)).norm() < 1e-12);
    });
}

#[test]
fn revolute_chords_are_connected_on_their_axes() {
    // The 6-UPS: 36 joints, 32 bodies, so 5 loops; the six sliders (the inputs) are in the
    // tree and every loop is closed by a passive revolute, as two connects.
    let text = std::fs::read_to_string(repo().join("mechanisms/6-ups.json")).unwrap();
    let m = Manipulator::from_json(&text).unwrap();
    let tree = ExportTree::new(&m);
    assert_eq!(tree.chords.len(), 5);
    for &(j, closure) in &tree.chords {
        assert_eq!(closure, ChordClosure::Connect);
        assert!(m.actuators().iter().all(|a| a.joint != j));
    }
    let dir = tempfile::tempdir().unwrap();
    let xml = dir.path().join("6-ups.xml");
    let o = common::kinsyn(&[
        "export",
        "mechanisms/6-ups.json",
        "--mjcf",
        xml.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let text = std::fs::read_to_string(&xml).unwrap();
    assert_eq!(text.matches("<connect ").count(), 10);
    assert_eq!(text.matches("<joint ").count(), 31);
    assert_eq!(text.matches("<position ").count(), 6);
    assert!(text.contains("gravity=\"0 0 0\""));
}

#[test]
fn export_refuses_a_missing_file_and_an_unwritable_output() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.xml");
    let o = common::kinsyn(&["export", "no-such.json", "--mjcf", out.to_str().unwrap()]);
    common::assert_refused(&o, "missing file", &["no-such.json"]);
    let o = common::kinsyn(&["export", "mechanisms/3-rps.json"]);
    common::assert_refused(&o, "no --mjcf", &["--mjcf"]);
    // An output in a folder that does not exist: the path chosen (exit 2), the folder named.
    let bad = dir.path().join("missing-dir/out.xml");
    let o = common::kinsyn(&[
        "export",
        "mechanisms/3-rps.json",
        "--mjcf",
        bad.to_str().unwrap(),
    ]);
    common::assert_refused(&o, "missing folder", &["missing-dir does not exist"]);
    // A folder nobody may write (not even root can add a file to /proc/self): the environment
    // (exit 1), in one line naming the file.
    if cfg!(target_os = "linux") {
        let o = common::kinsyn(&[
            "export",
            "mechanisms/3-rps.json",
            "--mjcf",
            "/proc/self/out.xml",
        ]);
        assert_eq!(o.status.code(), Some(1), "{}", common::stderr(&o));
        assert_eq!(common::stderr(&o).lines().count(), 1);
        assert!(common::stderr(&o).contains("cannot write /proc/self/out.xml: "));
    }
}
