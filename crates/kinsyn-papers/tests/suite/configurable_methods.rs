//! Paper 003's velocities, three methods and one answer at the Table 2 configuration: the
//! screw theory of §4 (eqs. 16–29, `configurable::velocity`), the loop-closure
//! Jacobian of the general mechanism graph built from `mechanisms/4-rrr-configurable.json`, and
//! (in `tests/suite/configurable_velocity.rs`) finite differences of the forward position.

use kinsyn::manipulator::Manipulator;
use kinsyn_papers::configurable::trajectory::{assemble, paper_input_rates};
use kinsyn_papers::configurable::velocity::{Configuration, velocities};
use kinsyn_papers::configurable::{Configurable, CornerPose};
use nalgebra::{DVector, Vector2, Vector3, Vector4};

#[test]
fn screw_theory_equals_the_loop_closure_of_the_mechanism_graph() {
    let text = std::fs::read_to_string("../../mechanisms/4-rrr-configurable.json").unwrap();
    let m = Manipulator::from_json(&text).unwrap();
    let q = m.reference();
    let mechanism = m.mechanism();
    let screws = mechanism.joint_screws(&q);
    let closure = mechanism.closure_jacobian(&screws);
    // The inputs R1.1 … R4.1 at the rates of §5 at t = 0 and at two other rate vectors.
    let inputs: Vec<usize> = m.actuators().iter().map(|a| a.joint).collect();
    assert_eq!(inputs.len(), 4);
    let qs: [f64; 4] = std::array::from_fn(|i| q[inputs[i]]);
    // The same configuration for the paper's method: the corners of the file's reference
    // (each link's frame origin is its corner C_i, docs/mechanism-format.md).
    let frame = |name: &str| {
        m.bodies()[m.body_named(name).unwrap()]
            .frame
            .translation
            .vector
    };
    let corners: [Vector2<f64>; 4] = ["m1", "m2", "m3", "m4"].map(|n| {
        let p = frame(n);
        Vector2::new(p.x, p.y)
    });
    let paper = Configurable::paper003();
    // The joint angles of the file are measured from its reference; the paper's q_i are
    // absolute: the reference of the file is Table 2's q (the file's `source`).
    let q_paper = [141.956f64, 203.366, 337.773, 305.499].map(f64::to_radians);
    let pose = assemble(
        &paper,
        &q_paper,
        &CornerPose {
            c4: corners[3],
            theta: (corners[0] - corners[3])
                .y
                .atan2((corners[0] - corners[3]).x),
            phi: (corners[2] - corners[3])
                .y
                .atan2((corners[2] - corners[3]).x),
        },
    )
    .unwrap();
    for (k, c) in pose.corners(paper.c).iter().enumerate() {
        assert!(
            (c - corners[k]).norm() < 1e-6,
            "the file's C{} is the paper's",
            k + 1
        );
    }
    assert!(
        qs.iter().all(|v| v.abs() < 1e-12),
        "the file's reference is its zero"
    );
    let configuration = Configuration::new(&paper, q_paper, &pose);
    for rates in [
        paper_input_rates(0.0),
        [1.0, 0.0, 0.0, 0.0],
        [0.3, -0.7, 0.2, 0.9],
    ] {
        // Loop closure: C q̇ = 0 with the inputs' rates given; passive rates by least squares.
        let passive: Vec<usize> = (0..closure.ncols())
            .filter(|j| !inputs.contains(j))
            .collect();
        let cp = closure.select_columns(&passive);
        let mut rhs = DVector::zeros(closure.nrows());
        for (i, j) in inputs.iter().enumerate() {
            rhs -= closure.column(*j) * rates[i];
        }
        let solved = cp.svd(true, true).solve(&rhs, 1e-12).unwrap();
        let mut all = DVector::zeros(closure.ncols());
        for (k, j) in passive.iter().enumerate() {
            all[*j] = solved[k];
        }
        for (i, j) in inputs.iter().enumerate() {
            all[*j] = rates[i];
        }
        assert!(
            (&closure * &all).amax() < 1e-9,
            "the loops close at first order"
        );
        let screw = velocities(&configuration, &Vector4::from(rates)).unwrap();
        for (k, name) in ["m1", "m2", "m3", "m4"].iter().enumerate() {
            let body = m.bodies()[m.body_named(name).unwrap()].body;
            let twist = mechanism.body_jacobian(body, &screws) * &all;
            let (w, v) = (
                Vector3::new(twist[0], twist[1], twist[2]),
                Vector3::new(twist[3], twist[4], twist[5]),
            );
            // C_k is on m_k (and on m_{k−1}): its velocity from m_k's twist.
            let p = Vector3::new(corners[k].x, corners[k].y, 0.0);
            let velocity = v + w.cross(&p);
            let expected = screw.corners[k];
            assert!(
                (Vector2::new(velocity.x, velocity.y) - expected).norm()
                    < 1e-6 * (1.0 + expected.norm()),
                "C{}: loop closure {velocity:?}, screw theory {expected:?}",
                k + 1
            );
        }
        // Links m1 and m3 turn alike (eq. 27): the graph's angular velocities agree.
        let wz = |name: &str| {
            (mechanism.body_jacobian(m.bodies()[m.body_named(name).unwrap()].body, &screws) * &all)
                [2]
        };
        assert!((wz("m1") - wz("m3")).abs() < 1e-9 && (wz("m1") - screw.m1.w.z).abs() < 1e-9);
    }
}
