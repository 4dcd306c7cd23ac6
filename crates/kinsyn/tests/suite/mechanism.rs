//! The mechanism graph (src/mechanism): loops from a cycle basis, the loop-closure Jacobian
//! against finite differences of the position-level closure, mobility against hand counts,
//! Newton assembly against the analytic inverse kinematics of the Gough–Stewart platform.

use kinsyn::manipulator::Manipulator;
use kinsyn::mechanism::{self, JointSpec, Mechanism, MechanismError};
use kinsyn::notation::Primitive::{P, R};
use kinsyn::screw::Twist;
use nalgebra::{Rotation3, Vector3};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};

fn four_bar() -> Mechanism {
    let z = Vector3::z();
    let p = |x: f64, y: f64| Vector3::new(x, y, 0.0);
    Mechanism::new(
        &["ground", "crank", "coupler", "rocker"],
        0,
        vec![
            JointSpec::new(R, z, p(0.0, 0.0), 0, 1),
            JointSpec::new(R, z, p(0.0, 1.0), 1, 2),
            JointSpec::new(R, z, p(2.0, 1.5), 2, 3),
            JointSpec::new(R, z, p(2.5, 0.0), 3, 0),
        ],
    )
    .unwrap()
}

#[test]
fn a_planar_four_bar_has_one_loop_and_one_dof() {
    // Hand count: one independent loop (4 joints − 4 bodies + 1); Grübler in the plane
    // 3(4 − 1) − 2·4 = 1. The loop-closure null space has dimension 1 at any assembled
    // configuration, and the coupler then has one local dof.
    let m = four_bar();
    assert_eq!(m.loop_count(), 1);
    let q = vec![0.0; 4];
    let mob = m.mobility(&q, &[false; 4]);
    assert_eq!(mob.dof, 1);
    assert_eq!(m.twist_space(2, &q, &[false; 4]).1, 1);
    // Locking the crank leaves a structure.
    assert_eq!(m.mobility(&q, &[true, false, false, false]).dof, 0);
    // Driving the crank by 0.3 rad and closing the loop keeps one dof and zero residual.
    let mut moved = q.clone();
    moved[0] = 0.3;
    let closed = m
        .assemble(&moved, &[true, false, false, false], None)
        .unwrap();
    assert!(m.closure_residual(&closed).amax() < 1e-10);
    assert!(
        (closed[0] - 0.3).abs() < 1e-15,
        "a locked joint is not moved by assembly"
    );
    assert_eq!(m.mobility(&closed, &[false; 4]).dof, 1);
}

#[test]
fn a_spatial_four_bar_with_parallel_axes_is_overconstrained_but_mobile() {
    // The same four-bar is a spatial mechanism whose Kutzbach count is 6(4 − 1) − 5·4 = −2; the
    // null space of the closure Jacobian still gives 1 (the planar motion): mobility is not
    // counted but computed.
    let m = four_bar();
    let bodies = i64::try_from(m.body_count()).unwrap();
    let joints = i64::try_from(m.joints().len()).unwrap();
    let spatial = 6 * (bodies - 1) - 5 * joints;
    assert_eq!(spatial, -2);
    assert_eq!(m.mobility(&[0.0; 4], &[false; 4]).dof, 1);
}

#[test]
fn the_closure_jacobian_is_minus_the_derivative_of_the_loop_residual() {
    // Independent method: central differences of the position-level residual log(g_a e^{ξq}
    // g_b⁻¹) of each loop of the 3-UPS (two loops, 18 joints), at a random assembled
    // configuration: d(residual)/dq = −C (the closure Jacobian of twists).
    let text = std::fs::read_to_string("../../mechanisms/3-ups.json").unwrap();
    let man = Manipulator::from_json(&text).unwrap();
    let m = man.mechanism();
    assert_eq!(m.loop_count(), 2);
    let q = man
        .assemble_at(
            Vector3::new(0.03, -0.02, 1.05),
            Vector3::new(0.1, 0.05, -0.08),
            &[],
        )
        .unwrap();
    let c = m.closure_jacobian(&m.joint_screws(&q));
    let h = 1e-6;
    for k in 0..q.len() {
        let (mut a, mut b) = (q.clone(), q.clone());
        a[k] += h;
        b[k] -= h;
        let fd = (m.closure_residual(&a) - m.closure_residual(&b)) / (2.0 * h);
        let err = (fd + c.column(k)).amax();
        assert!(err < 1e-7, "joint {k}: error {err:e}");
    }
}

#[test]
fn a_body_jacobian_matches_finite_differences_of_its_pose() {
    // Independent method: the spatial twist of the platform from central differences of its
    // displacement along each joint (ω from Ṙ Rᵀ, v = ṗ − ω × p) equals the tree-path Jacobian.
    let text = std::fs::read_to_string("../../mechanisms/3-ups.json").unwrap();
    let man = Manipulator::from_json(&text).unwrap();
    let m = man.mechanism();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    let q: Vec<f64> = (0..m.joints().len())
        .map(|_| rng.random_range(-0.5..0.5))
        .collect();
    let j = m.body_jacobian(man.platform(), &m.joint_screws(&q));
    let h = 1e-6;
    for k in 0..q.len() {
        let (mut a, mut b) = (q.clone(), q.clone());
        a[k] += h;
        b[k] -= h;
        let g_ra = m.poses(&a)[man.platform()];
        let (ra, pa) = (g_ra.rotation, g_ra.translation.vector);
        let g_rb = m.poses(&b)[man.platform()];
        let (rb, pb) = (g_rb.rotation, g_rb.translation.vector);
        let g_r0 = m.poses(&q)[man.platform()];
        let (r0, p0) = (g_r0.rotation, g_r0.translation.vector);
        let dr = (ra.matrix() - rb.matrix()) / (2.0 * h);
        let w_hat = dr * r0.matrix().transpose();
        let w = Vector3::new(w_hat[(2, 1)], w_hat[(0, 2)], w_hat[(1, 0)]);
        let v = (pa - pb) / (2.0 * h) - w.cross(&p0);
        let fd = Twist { w, v }.to_vector();
        for r in 0..6 {
            assert!((fd[r] - j[(r, k)]).abs() < 1e-7, "joint {k} row {r}");
        }
    }
}

#[test]
fn assembly_at_a_pose_gives_the_gough_stewart_leg_lengths() {
    // Independent method: the inverse kinematics of the 6-UPS is closed-form, L_i = |R b_i + p −
    // A_i|. Newton assembly to the pose must change each slider by L_i − L_i(reference).
    let text = std::fs::read_to_string("../../mechanisms/6-ups.json").unwrap();
    let d = kinsyn::manipulator::file::Description::from_json(&text).unwrap();
    let man = Manipulator::new(&d).unwrap();
    let (p, rv) = (
        Vector3::new(0.05, -0.04, 1.08),
        Vector3::new(0.12, -0.07, 0.2),
    );
    let q = man.assemble_at(p, rv, &[]).unwrap();
    let r = Rotation3::from_scaled_axis(rv);
    let p0 = Vector3::from(d.platform.position);
    for (i, leg) in d.legs.iter().enumerate() {
        let a = Vector3::from(leg.base);
        let length = (r * Vector3::from(leg.platform) + p - a).norm();
        let reference = (Vector3::from(leg.platform) + p0 - a).norm();
        let slider = man.actuators()[i].joint;
        assert!(
            (q[slider] - (length - reference)).abs() < 1e-9,
            "leg {i}: slider {} vs {}",
            q[slider],
            length - reference
        );
    }
    // Sliders have no limits here, so a tall pose is still reachable (z = 25: every leg longer).
    assert!(
        man.assemble_at(Vector3::new(0.0, 0.0, 25.0), Vector3::zeros(), &[])
            .is_ok()
    );
    // The 3-RPS has three dof: a general pose (a turn about the vertical with a sideways shift)
    // is out of reach, and assembly says so instead of returning the nearest configuration.
    let text = std::fs::read_to_string("../../mechanisms/3-rps.json").unwrap();
    let rps = Manipulator::from_json(&text).unwrap();
    let e = rps
        .assemble_at(
            Vector3::new(0.2, 0.1, 1.0),
            Vector3::new(0.0, 0.0, 0.3),
            &[],
        )
        .unwrap_err();
    assert!(e.to_string().contains("no assembly reached"), "{e}");
}

#[test]
fn bad_graphs_are_rejected_with_their_reason() {
    let z = Vector3::z();
    let o = Vector3::zeros();
    let e = Mechanism::new(&["g", "a", "b"], 0, vec![JointSpec::new(R, z, o, 0, 1)]).unwrap_err();
    assert_eq!(e, MechanismError::Disconnected("b".into()));
    let e = Mechanism::new(&["g", "a"], 0, vec![JointSpec::new(R, z, o, 1, 1)]).unwrap_err();
    assert!(matches!(e, MechanismError::SelfJoint { joint: 1, .. }));
    let e = Mechanism::new(&["g", "a"], 0, vec![JointSpec::new(P, o, o, 0, 1)]).unwrap_err();
    assert!(e.to_string().contains("no length"), "{e}");
    let e = Mechanism::new(&["g", "a"], 0, vec![JointSpec::new(R, z, o, 0, 7)]).unwrap_err();
    assert!(matches!(e, MechanismError::UnknownBody { body: 7, .. }));
}

proptest! {
    #[test]
    fn log_inverts_exp(w in prop::array::uniform3(-1.5f64..1.5), v in prop::array::uniform3(-2.0f64..2.0)) {
        // The screw of a displacement: exp(log g) = g and log(exp ε) = ε for rotations below π.
        let t = Twist { w: Vector3::from(w), v: Vector3::from(v) };
        let g = mechanism::exp(&t);
        let back = mechanism::log(&g);
        prop_assert!((back.w - t.w).norm() < 1e-9 && (back.v - t.v).norm() < 1e-9);
        let small = Twist { w: t.w * 1e-7, v: t.v * 1e-7 };
        let back = mechanism::log(&mechanism::exp(&small));
        prop_assert!((back.w - small.w).norm() < 1e-15 + 1e-9 * small.w.norm());
    }
}

proptest! {
    #[test]
    fn rotation_log_is_exact_up_to_a_half_turn(
        axis in prop::array::uniform3(-1.0f64..1.0),
        gap in prop::sample::select(vec![0.0, 1e-12, 1e-8, 1e-4, 0.5, 2.0]),
    ) {
        // Near a half turn the skew part of R vanishes and gives no axis; the rotation vector
        // must still reproduce R (checked by rebuilding R from it), also at exactly π.
        let n = Vector3::from(axis);
        prop_assume!(n.norm() > 0.1);
        let r = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(n), std::f64::consts::PI - gap);
        let back = Rotation3::from_scaled_axis(mechanism::rotation_log(&r));
        prop_assert!((back.matrix() - r.matrix()).amax() < 1e-9, "{:?}", mechanism::rotation_log(&r));
    }
}

proptest! {
    #[test]
    fn exp_is_the_matrix_exponential_at_every_angle(
        w in prop::array::uniform3(-1.0f64..1.0),
        v in prop::array::uniform3(-2.0f64..2.0),
        angle in prop::sample::select(vec![1e-12, 1e-9, 1e-8, 1e-6, 1e-3, 0.009, 0.011, 0.5, 2.5]),
    ) {
        // Independent method: the 4×4 matrix exponential (nalgebra's Padé approximant with
        // scaling and squaring) of the twist's matrix [[ω]× v; 0 0]. The closed form must agree
        // to round-off at every angle, including the small ones where (1 − cos θ)/θ² and
        // (θ − sin θ)/θ³ cancel catastrophically when evaluated directly (a loss of precision
        // fixed with the trustworthy manipulator analysis).
        let w = Vector3::from(w);
        prop_assume!(w.norm() > 0.1);
        let w = w.normalize() * angle;
        let v = Vector3::from(v);
        let mut m = nalgebra::Matrix4::zeros();
        m.fixed_view_mut::<3, 3>(0, 0).copy_from(&kinsyn::screw::skew(&w));
        m.fixed_view_mut::<3, 1>(0, 3).copy_from(&v);
        let e = m.exp();
        let g_r = mechanism::exp(&Twist { w, v });
        let (r, p) = (g_r.rotation, g_r.translation.vector);
        let p_ref = Vector3::new(e[(0, 3)], e[(1, 3)], e[(2, 3)]);
        prop_assert!((p - p_ref).norm() <= 1e-14 * (1.0 + v.norm()), "{p} vs {p_ref}");
        prop_assert!((r.matrix() - e.fixed_view::<3, 3>(0, 0)).amax() < 1e-14);
        // And log undoes it to the same accuracy, relative to the twist.
        let back = mechanism::log(&g_r);
        prop_assert!((back.v - v).norm() <= 1e-13 * (1.0 + v.norm()), "{:?} vs {v}", back.v);
    }
}

/// The pattern of `body` of a mechanism over 50 seeds, as the set of distinct answers.
fn patterns_over_seeds(m: &Mechanism, body: usize) -> std::collections::BTreeSet<String> {
    (0..50)
        .map(|seed| {
            let settings = mechanism::SampleSettings {
                seed,
                ..Default::default()
            };
            let q = vec![0.0; m.joints().len()];
            let locked = vec![false; m.joints().len()];
            m.motion_pattern(body, &q, &locked, &settings)
                .unwrap()
                .pattern
                .to_string()
        })
        .collect()
}

#[test]
fn one_dof_motions_are_never_mistaken_for_groups() {
    // Fixed with the trustworthy manipulator analysis: one-dof walks of ±0.1 made the samples
    // coincide for about one seed in eight, and any motion then "agreed" with itself. First
    // principles: a planar four-bar's crank turns about its fixed pivot, R(z) through (0, 0); its
    // coupler turns about a moving instantaneous centre, one rotation and no fixed axis: 0T1R, not
    // a group, for every seed.
    let m = four_bar();
    let crank = patterns_over_seeds(&m, 1);
    assert_eq!(crank.into_iter().collect::<Vec<_>>(), ["R(z)"]);
    let coupler = patterns_over_seeds(&m, 2);
    assert_eq!(coupler.into_iter().collect::<Vec<_>>(), ["0T1R"]);
    // A parallelogram (cranks of equal length, coupler equal to the ground link): the coupler
    // translates on a circle — a curvilinear translation whose direction turns, 1T0R, never
    // T(u).
    let z = Vector3::z();
    let p = |x: f64, y: f64| Vector3::new(x, y, 0.0);
    let parallelogram = Mechanism::new(
        &["ground", "crank", "coupler", "rocker"],
        0,
        vec![
            JointSpec::new(R, z, p(0.0, 0.0), 0, 1),
            JointSpec::new(R, z, p(0.3, 1.0), 1, 2),
            JointSpec::new(R, z, p(2.3, 1.0), 2, 3),
            JointSpec::new(R, z, p(2.0, 0.0), 3, 0),
        ],
    )
    .unwrap();
    let coupler = patterns_over_seeds(&parallelogram, 2);
    assert_eq!(coupler.into_iter().collect::<Vec<_>>(), ["1T0R"]);
}

#[test]
fn a_sampled_motion_reports_how_far_apart_its_samples_are() {
    // The samples of a one-dof motion are walked again while they fall closer than
    // MIN_SEPARATION to each other, and the smallest distance is reported: it must be at least
    // that, and it must be the distance between two of the returned poses (recomputed here).
    let m = four_bar();
    for seed in 0..20 {
        let settings = mechanism::SampleSettings {
            seed,
            ..Default::default()
        };
        let motion = m
            .sample_motion(2, &[0.0; 4], &[false; 4], &settings)
            .unwrap();
        assert!(motion.min_separation >= kinsyn::motion::MIN_SEPARATION);
        let mut nearest = f64::INFINITY;
        for (i, a) in motion.samples.iter().enumerate() {
            for b in &motion.samples[i + 1..] {
                nearest = nearest.min(m.pose_distance(&a.pose, &b.pose));
            }
        }
        assert!((nearest - motion.min_separation).abs() < 1e-12);
    }
}

#[test]
fn a_classification_reports_the_gap_of_its_rank_decisions() {
    // The four-bar's coupler has one dof at every sample: one kept singular value, none
    // dropped (its twists over a one-dimensional space of rates), and the kept one well away
    // from the tolerance — a generic configuration. With the crank locked the coupler cannot
    // move: nothing kept, and what is dropped is round-off relative to its unit screws.
    let m = four_bar();
    let settings = mechanism::SampleSettings::default();
    let free = m
        .motion_pattern(2, &[0.0; 4], &[false; 4], &settings)
        .unwrap();
    assert_eq!(free.dof, 1);
    assert!(
        free.rank_gap.smallest_kept.unwrap() > 1e-3,
        "{:?}",
        free.rank_gap
    );
    assert!(free.rank_gap.largest_dropped == 0.0, "{:?}", free.rank_gap);
    let locked = m
        .motion_pattern(2, &[0.0; 4], &[true, false, false, false], &settings)
        .unwrap();
    assert_eq!(locked.dof, 0);
    assert_eq!(locked.rank_gap.smallest_kept, None);
    assert!(
        locked.rank_gap.largest_dropped < 1e-12,
        "{:?}",
        locked.rank_gap
    );
}

#[test]
fn assembly_settings_default_to_the_assembly_constants() {
    // The assembly's tolerance and step counts are named settings. The default is what assemble_to
    // has always used (1e-10, 100 steps, 2 polishing steps), and assembling with it gives bit for
    // bit what assemble_to gives; a looser tolerance with no polishing stops once the residual is
    // below it, and no step at all refuses an open loop.
    use kinsyn::mechanism::{ASSEMBLY_STEPS, ASSEMBLY_TOLERANCE, AssemblySettings};
    let d = AssemblySettings::default();
    assert_eq!(
        (d.tolerance, d.max_steps, d.polishing_steps),
        (1e-10, 100, 2)
    );
    assert_eq!((ASSEMBLY_TOLERANCE, ASSEMBLY_STEPS), (1e-10, 100));
    let m = four_bar();
    let locked = [true, false, false, false];
    let mut moved = vec![0.0; 4];
    moved[0] = 0.3;
    let by_default = m.assemble_to(&moved, &locked, None).unwrap();
    assert_eq!(
        m.assemble_with(&moved, &locked, None, &d).unwrap(),
        by_default
    );
    let loose = AssemblySettings {
        tolerance: 1e-3,
        polishing_steps: 0,
        ..d
    };
    let rough = m.assemble_with(&moved, &locked, None, &loose).unwrap();
    assert!(m.closure_residual(&rough).amax() < 1e-3);
    let none = AssemblySettings { max_steps: 0, ..d };
    assert!(matches!(
        m.assemble_with(&moved, &locked, None, &none),
        Err(MechanismError::NotAssembled { iterations: 0, .. })
    ));
}
