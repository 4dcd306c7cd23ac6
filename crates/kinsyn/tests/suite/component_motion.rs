//! The whole mechanism on a component of its constraint variety
//! ([`Manipulator::component_motion`]): a leg's inverse kinematics against its own forward
//! kinematics, and the inputs that move on each operation mode of a rhombus four-bar against
//! the crank angle read from the component's real points by hand.

use kinsyn::manipulator::{BlockModes, InputValues, Manipulator, OperationModeSettings};
use kinsyn::mechanism::SampleSettings;
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;

#[test]
fn a_legs_joint_values_carry_its_body_to_the_frame_they_were_taken_from() {
    // Forward kinematics at random joint values, then the inverse kinematics of each leg from
    // the bodies' frames: the joints found need not be the ones drawn (a U–P–S has one set
    // per branch), but they must put the platform at the same frame.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../mechanisms/3-ups.json"
    ))
    .unwrap();
    let m = Manipulator::from_json(&text).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..5 {
        let q: Vec<f64> = m
            .reference()
            .iter()
            .map(|v| v + rng.random_range(-0.2..0.2))
            .collect();
        for (i, leg) in m.legs().iter().enumerate() {
            // A leg alone: its last body is where its own joints put it.
            let mut own = m.reference();
            own[leg.joints.clone()].copy_from_slice(&q[leg.joints.clone()]);
            let to = m.body_frame(0, &own);
            let found = m
                .leg_joint_values(i, &kinsyn::spatial::identity(), &to, &[])
                .expect("the leg reaches a frame it was at");
            let mut back = m.reference();
            back[leg.joints.clone()].copy_from_slice(&found);
            let again = m.body_frame(0, &back);
            assert!(
                (again.to_homogeneous() - to.to_homogeneous()).amax() < 1e-9,
                "leg {}: {found:?}",
                i + 1
            );
        }
    }
}

/// A rhombus four-bar (every link of length 1) as a description: ground pivots `A = 0`,
/// `D = (1, 0)`, the coupler the platform from `B` (its frame's origin) to `C = B + (1, 0)`,
/// the crank `A–B` driven (`R!R`), the rocker `D–C` passive; at the reference a
/// parallelogram with the crank at 60°.
fn rhombus() -> Manipulator {
    let b = [0.5, 3.0_f64.sqrt() / 2.0, 0.0];
    let z = [0.0, 0.0, 1.0];
    let d = json!({
        "format": "kinsyn-manipulator/1",
        "name": "rhombus four-bar",
        "units": {"length": "m", "angle": "deg"},
        "platform": {"position": b, "orientation": [0.0, 0.0, 0.0], "point": [0.0, 0.0, 0.0]},
        "legs": [
            {"chain": "R!R", "base": [0.0, 0.0, 0.0], "platform": [0.0, 0.0, 0.0], "axes": [z, z]},
            {"chain": "RR", "base": [1.0, 0.0, 0.0], "platform": [1.0, 0.0, 0.0], "axes": [z, z]},
        ],
    });
    Manipulator::from_json(&d.to_string()).unwrap()
}

/// The crank's angle (radians) at a real point of the block: the direction from `A` to the
/// platform's origin `B`.
fn crank_angle(block: &BlockModes, point: &[f64]) -> f64 {
    let g = block.modes.system.displacement(point).unwrap();
    let b = g.translation.vector;
    b.y.atan2(b.x)
}

#[test]
fn on_the_rhombus_four_bars_folded_mode_the_crank_stays_still() {
    // A rhombus four-bar has, besides its parallelogram motion, two folded ones into which its
    // anti-parallelogram branch degenerates (Hunt, Kinematic Geometry of Mechanisms, 1978, §7;
    // the change points of a Grashof linkage with equal links): B on D, the coupler turning
    // about D with the crank held, and C on A, the crank turning with the coupler about A. The
    // input moves on every component but the first; read by hand from two real points of each
    // component, the crank angle changes on those and not on the first. The coupler's motion
    // classified on the polynomial constraints and on the whole mechanism agrees: a circular
    // translation (1T0R) on the parallelogram, a rotation R(z) on the folded modes.
    let m = rhombus();
    let blocks = m
        .block_operation_modes_with_progress(
            &InputValues::Free,
            &OperationModeSettings::default(),
            &mut |_| {},
        )
        .unwrap();
    let [block] = &blocks[..] else {
        panic!("one block")
    };
    let parts = [(block.parent, block.body, &block.modes.system)];
    let d = Vector3::new(1.0, 0.0, 0.0);
    let (mut folded, mut moving) = (0, 0);
    for c in &block.modes.components {
        assert_eq!(c.dimension, 1, "a four-bar moves with one dof");
        // Two real points of different poses (each pose is two points, ±(x, y)).
        let pose = |x: &Vec<f64>| block.modes.system.displacement(x).unwrap().to_homogeneous();
        let p = &c.real_points[0];
        let q = c
            .real_points
            .iter()
            .find(|q| (pose(q) - pose(p)).amax() > 1e-6)
            .expect("two real poses on every component");
        let b_on_d = (block
            .modes
            .system
            .displacement(p)
            .unwrap()
            .translation
            .vector
            - d)
            .norm()
            < 1e-8;
        let turned = (crank_angle(block, p) - crank_angle(block, q)).abs() > 1e-6;
        assert_eq!(
            turned, !b_on_d,
            "the crank turns exactly off the folded mode B = D"
        );
        let on = m
            .component_motion(&parts, &[Some(p)], &[], &SampleSettings::default())
            .unwrap();
        assert_eq!(
            on.moving,
            vec![turned],
            "the input moves where the crank turns"
        );
        assert_eq!(on.mode.dof, 1, "the coupler moves with one dof");
        let polynomial = c
            .real
            .as_ref()
            .expect("a real point")
            .motion
            .pattern
            .name()
            .to_string();
        let whole = on.mode.pattern.as_ref().expect("sampled").to_string();
        assert_eq!(
            polynomial, whole,
            "both methods classify the coupler's motion alike"
        );
        let circular = (crank_angle(block, p) - crank_angle(block, q)).abs() > 1e-6
            && (pose(p) - pose(q)).fixed_view::<3, 3>(0, 0).amax() < 1e-9;
        assert_eq!(whole, if circular { "1T0R" } else { "R(z)" });
        if b_on_d {
            folded += 1;
        } else {
            moving += 1;
        }
    }
    assert!(folded >= 1, "the folded mode B = D is found");
    assert!(
        moving >= 3,
        "the parallelogram, anti-parallelogram and C = A modes are found"
    );
}

#[test]
fn the_mechanism_is_placed_at_the_inputs_its_frames_were_found_at() {
    // Paper 004's 4-RUU: over one platform pose each RUU leg reaches with its crank in two
    // positions. The configuration continued from the reference to generic inputs gives the
    // platform's frame; placing the mechanism at that frame with those inputs must give back
    // those inputs (modulo a turn) and that frame; with every crank a radian away from its
    // value no leg reaches the frame (an RUU leg has five joints for six coordinates: with its
    // crank held elsewhere its other four cannot make up the difference).
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../mechanisms/4-ruu.json"
    ))
    .unwrap();
    let m = Manipulator::from_json(&text).unwrap();
    let inputs: Vec<(usize, f64)> = [0.35f64, -0.2, 0.15, -0.4]
        .into_iter()
        .enumerate()
        .collect();
    let request = kinsyn::manipulator::PositionRequest {
        inputs: inputs.clone(),
        ..Default::default()
    };
    let q0 = m.solve_position(&m.reference(), &request).unwrap().q;
    let frames: Vec<_> = (0..m.bodies().len())
        .map(|k| m.body_frame(k, &q0))
        .collect();
    let q = m.assemble_at_frames(&frames, &inputs).unwrap();
    for &(a, v) in &inputs {
        let d = (q[m.actuators()[a].joint] - v).rem_euclid(std::f64::consts::TAU);
        assert!(
            d.min(std::f64::consts::TAU - d) < 1e-7,
            "input {a}: {}",
            q[m.actuators()[a].joint]
        );
    }
    for (k, frame) in frames.iter().enumerate() {
        let d = (m.body_frame(k, &q).to_homogeneous() - frame.to_homogeneous()).amax();
        assert!(d < 1e-9, "body {k} off by {d:e}");
    }
    // Asked for other crank values, a placement either fails or holds them.
    let other: Vec<(usize, f64)> = inputs.iter().map(|&(a, v)| (a, v + 1.0)).collect();
    if let Ok(q) = m.assemble_at_frames(&frames, &other) {
        for &(a, v) in &other {
            assert!(
                (q[m.actuators()[a].joint] - v).abs() < 1e-7,
                "input {a} not held"
            );
        }
    }
}
