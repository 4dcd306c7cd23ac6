//! Position analysis (src/manipulator/position.rs): forward kinematics from input values and
//! platform poses given in part, checked against closed forms derived by hand from the geometry
//! of the description files (not from kinsyn's mechanism graph).

use kinsyn::manipulator::file::Description;
use kinsyn::manipulator::{Manipulator, PlatformGoal, PositionRequest};
use kinsyn::mechanism::{Coordinate, rotation_log};
use nalgebra::{Rotation3, Vector3};

fn load(name: &str) -> (Manipulator, Description) {
    let text = std::fs::read_to_string(format!("../../mechanisms/{name}.json")).unwrap();
    (
        Manipulator::from_json(&text).unwrap(),
        Description::from_json(&text).unwrap(),
    )
}

/// Leg `i`'s base attachment `A_i` and platform attachment `B_i` (platform frame), from the file.
fn attachments(d: &Description, i: usize) -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::from(d.legs[i].base),
        Vector3::from(d.legs[i].platform),
    )
}

/// The length of a UPS leg at the platform pose (R, p): |p + R `B_i` − `A_i`|, the distance
/// between the U and S centres, which the prismatic joint between them changes one for one.
fn leg_length(d: &Description, i: usize, r: &Rotation3<f64>, p: &Vector3<f64>) -> f64 {
    let (a, b) = attachments(d, i);
    (p + r * b - a).norm()
}

/// The change of leg `i`'s length from the file's reference pose to the pose (R, p): the
/// value of its slider, which the joint values measure from the reference.
fn leg_length_change(d: &Description, i: usize, r: &Rotation3<f64>, p: &Vector3<f64>) -> f64 {
    leg_length(d, i, r, p)
        - leg_length(
            d,
            i,
            &Rotation3::identity(),
            &Vector3::from(d.platform.position),
        )
}

fn frame(m: &Manipulator, q: &[f64]) -> (Vector3<f64>, Vector3<f64>) {
    let g_r = m.platform_frame(q);
    let (r, p) = (g_r.rotation, g_r.translation.vector);
    (p, rotation_log(&r))
}

/// The 6-UPS at a displaced pose: forward kinematics from the closed-form leg lengths of that
/// pose reaches it, and from there the reference's own leg lengths lead back to the reference.
#[test]
fn six_ups_forward_kinematics_reaches_the_pose_of_its_leg_lengths() {
    let (m, d) = load("6-ups");
    let reference_p = Vector3::from(d.platform.position);
    for (p, rv) in [
        (
            Vector3::new(0.05, 0.0, 1.1),
            Vector3::new(0.0, 5f64.to_radians(), 10f64.to_radians()),
        ),
        (Vector3::new(-0.1, 0.08, 0.9), Vector3::new(0.1, -0.05, 0.2)),
    ] {
        let r = Rotation3::from_scaled_axis(rv);
        // Input values are joint values from the reference: the change of each leg length.
        let inputs: Vec<(usize, f64)> = (0..6)
            .map(|i| {
                let a = m.actuator_named(&format!("P{}.3", i + 1)).unwrap();
                (a, leg_length_change(&d, i, &r, &p))
            })
            .collect();
        let request = PositionRequest {
            inputs: inputs.clone(),
            ..PositionRequest::default()
        };
        let reached = m.solve_position(&m.reference(), &request).unwrap();
        let (p_reached, rv_reached) = frame(&m, &reached.q);
        assert!((p_reached - p).norm() < 1e-9, "{p_reached} vs {p}");
        assert!((rv_reached - rv).norm() < 1e-9, "{rv_reached} vs {rv}");
        // Back: every leg at its reference length from the displaced configuration.
        let back = PositionRequest {
            inputs: inputs.iter().map(|&(a, _)| (a, 0.0)).collect(),
            ..PositionRequest::default()
        };
        let home = m.solve_position(&reached.q, &back).unwrap();
        let (p_home, rv_home) = frame(&m, &home.q);
        assert!((p_home - reference_p).norm() < 1e-9, "{p_home}");
        assert!(rv_home.norm() < 1e-9, "{rv_home}");
    }
}

/// The 3-RPS: each leg turns about its base revolute, so its spherical centre stays in the
/// plane through `A_i` normal to that axis `u_i`: (p + R `B_i` − `A_i)·u_i` = 0 (three equations,
/// the parasitic motion). Given z and the tilt (rx, ry), kinsyn solves x, y and rz; the
/// result must satisfy those planes, keep what was given, and have no torsion: rz = 0, since a
/// symmetric 3-RPS turns about horizontal axes only (Bonev, Zlatanov & Gosselin, "Advantages
/// of the modified Euler angles in the design and control of PKMs", 2002: zero torsion), and
/// a rotation about a horizontal axis has a rotation vector with no z component.
#[test]
fn three_rps_solves_its_parasitic_motion() {
    let (m, d) = load("3-rps");
    for (z, rx, ry) in [(1.1, 5.0, -3.0), (0.95, -8.0, 2.0), (1.2, 0.0, 10.0)] {
        let text = format!("z={z},rx={rx},ry={ry}");
        let goal = m.parse_pose(&text).unwrap();
        let request = PositionRequest {
            platform: Some(goal),
            ..PositionRequest::default()
        };
        let reached = m.solve_position(&m.reference(), &request).unwrap();
        let g_r = m.platform_frame(&reached.q);
        let (r, p) = (g_r.rotation, g_r.translation.vector);
        let rv = rotation_log(&r);
        assert!((p.z - z).abs() < 1e-9, "{text}: z {}", p.z);
        assert!(
            (rv.x - f64::to_radians(rx)).abs() < 1e-9,
            "{text}: rx {}",
            rv.x
        );
        assert!(
            (rv.y - f64::to_radians(ry)).abs() < 1e-9,
            "{text}: ry {}",
            rv.y
        );
        assert!(rv.z.abs() < 1e-9, "{text}: torsion {}", rv.z);
        for i in 0..3 {
            let (a, b) = attachments(&d, i);
            let u = Vector3::from(match d.legs[i].axes.as_ref().unwrap()[0] {
                kinsyn::manipulator::file::AxisSpec::Vector(ref v) => *v,
                kinsyn::manipulator::file::AxisSpec::Named(_) => {
                    panic!("the 3-RPS file gives vectors")
                }
            });
            let off_plane = (p + r * b - a).dot(&u);
            assert!(
                off_plane.abs() < 1e-9,
                "{text}: leg {} off its plane by {off_plane}",
                i + 1
            );
        }
        // The parasitic coordinates are not trivially zero away from the symmetric poses.
        if rx != 0.0 || ry != 0.0 {
            assert!(
                p.x.abs() + p.y.abs() > 1e-5,
                "{text}: no parasitic motion {p}"
            );
        }
    }
}

/// Too few values leave the platform free; the error says how many more are needed.
#[test]
fn a_partial_pose_that_does_not_determine_the_platform_is_refused() {
    let (m, _) = load("3-rps");
    let request = PositionRequest {
        platform: Some(PlatformGoal::Coordinates(vec![(Coordinate::Z, 1.1)])),
        ..PositionRequest::default()
    };
    let e = m.solve_position(&m.reference(), &request).unwrap_err();
    assert!(
        e.to_string()
            .contains("leave the platform 2 degrees of freedom"),
        "{e}"
    );
}

/// Leg lengths no pose has: the continuation stops and says how far it got.
#[test]
fn unreachable_inputs_say_so() {
    let (m, _) = load("6-ups");
    let mut inputs = vec![(m.actuator_named("P1.3").unwrap(), 10.0)];
    inputs.extend((2..=6).map(|i| (m.actuator_named(&format!("P{i}.3")).unwrap(), 0.0)));
    let request = PositionRequest {
        inputs,
        ..PositionRequest::default()
    };
    let e = m.solve_position(&m.reference(), &request).unwrap_err();
    assert!(e.to_string().contains("no assembly reached"), "{e}");
}

/// The input values kinsyn reports at a pose are the leg-length changes of the closed form.
#[test]
fn inputs_at_a_pose_are_the_closed_form_leg_length_changes() {
    let (m, d) = load("6-ups");
    let (p, rv) = (
        Vector3::new(0.02, -0.03, 1.05),
        Vector3::new(0.05, 0.02, -0.1),
    );
    let q = m.assemble_at(p, rv, &[]).unwrap();
    let r = Rotation3::from_scaled_axis(rv);
    for i in 0..6 {
        let a = &m.actuators()[m.actuator_named(&format!("P{}.3", i + 1)).unwrap()];
        let expected = leg_length_change(&d, i, &r, &p);
        assert!((q[a.joint] - expected).abs() < 1e-9, "leg {}", i + 1);
    }
}

/// A pose of the 3-RPS turned half a turn about the vertical exists (every leg turned over) but
/// no path of poses from the reference reaches it: turning about z is not one of the 3-RPS's
/// motions. It is reached by damped Newton steps from the start and flagged as not continuous
/// with it; the sliders are then the closed-form leg-length changes of that pose.
#[test]
fn a_pose_off_the_start_path_is_reached_and_flagged() {
    let (m, d) = load("3-rps");
    let request = PositionRequest {
        platform: Some(m.parse_pose("0,0,1,0,0,180").unwrap()),
        ..PositionRequest::default()
    };
    let reached = m.solve_position(&m.reference(), &request).unwrap();
    assert!(!reached.continuous);
    let r = Rotation3::from_scaled_axis(Vector3::z() * std::f64::consts::PI);
    let p = Vector3::new(0.0, 0.0, 1.0);
    for i in 0..3 {
        let a = &m.actuators()[m.actuator_named(&format!("P{}.2", i + 1)).unwrap()];
        let expected = leg_length_change(&d, i, &r, &p);
        assert!(
            (reached.q[a.joint] - expected).abs() < 1e-9,
            "leg {}",
            i + 1
        );
    }
    // Every pose of the earlier tests is reached by continuation.
    let near = PositionRequest {
        platform: Some(m.parse_pose("z=1.1,rx=5,ry=-3").unwrap()),
        ..PositionRequest::default()
    };
    assert!(m.solve_position(&m.reference(), &near).unwrap().continuous);
}

/// Found by fuzzing (target `position`, reproducers `fuzz/corpus/position/repro-far-*`):
/// `--pose rx=.05 --inputs P2.2=0980` on the 3-RPS (a slider extended by 980 m on a platform of
/// 0.5 m) took thousands of continuation steps of at most half a characteristic length each,
/// 22 s in the fuzz build. The continuation now gives up after a bounded number of steps and
/// says why.
#[test]
fn values_far_from_the_start_are_refused_after_bounded_steps() {
    let (m, _) = load("3-rps");
    let request = PositionRequest {
        platform: Some(m.parse_pose("rx=.05").unwrap()),
        inputs: m.parse_inputs("P2.2=0980").unwrap(),
        ..PositionRequest::default()
    };
    let e = m.solve_position(&m.reference(), &request).unwrap_err();
    assert!(e.to_string().contains("needs more than"), "{e}");
}
