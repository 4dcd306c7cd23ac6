//! Constraint polynomials from geometry (`kinsyn::geometry`) and manipulators as
//! polynomial systems (`Manipulator::position_system`), each checked against an independent
//! numeric computation: the displacement of `spatial::study::to_displacement` applied to points
//! with nalgebra, distances and dot products computed from that displacement, finite
//! differences, and the loop closure of `Manipulator::solve_position`.

use kinsyn::geometry::{self, Chart, StudyVariables};
use kinsyn::poly::{C64, Poly};
use kinsyn::spatial::{self, Displacement, study};
use nalgebra::{Point3, Rotation3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn eval(p: &Poly, s: &[f64]) -> f64 {
    let z: Vec<C64> = s.iter().map(|r| C64::new(*r, 0.0)).collect();
    let v = p.eval(&z);
    assert!(
        v.im.abs() <= 1e-12 * (1.0 + v.re.abs()),
        "a real polynomial"
    );
    v.re
}

fn vec3(rng: &mut ChaCha8Rng, r: f64) -> Vector3<f64> {
    Vector3::new(
        rng.random_range(-r..r),
        rng.random_range(-r..r),
        rng.random_range(-r..r),
    )
}

fn unit(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    loop {
        let v = vec3(rng, 1.0);
        if v.norm() > 0.2 {
            return v.normalize();
        }
    }
}

/// A random pose (rotation up to π about a random axis, translation in [−2, 2]³) and its Study
/// parameters times a random non-zero factor (the parameters are projective).
fn random_pose(rng: &mut ChaCha8Rng) -> (Displacement, [f64; 8]) {
    let r = unit(rng) * rng.random_range(0.0..std::f64::consts::PI);
    let g = spatial::displacement(Rotation3::from_scaled_axis(r), vec3(rng, 2.0));
    let lambda = rng.random_range(0.3..3.0) * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
    (g, study::from_displacement(&g).map(|c| c * lambda))
}

fn delta(s: &[f64; 8]) -> f64 {
    s[..4].iter().map(|c| c * c).sum()
}

fn moved(g: &Displacement, p: &Vector3<f64>) -> Vector3<f64> {
    g.transform_point(&Point3::from(*p)).coords
}

#[test]
fn study_points_and_vectors_match_the_displacement() {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let sv = StudyVariables::leading(8);
    for _ in 0..20 {
        let (g, s) = random_pose(&mut rng);
        // The independent transform: to_displacement of the (scaled) parameters.
        let back = study::to_displacement(&s, study::QUADRIC_TOLERANCE).unwrap();
        assert!((back.translation.vector - g.translation.vector).norm() < 1e-12);
        let p = vec3(&mut rng, 1.5);
        let v = vec3(&mut rng, 1.0);
        let d = delta(&s);
        let point = geometry::evaluate_vector(&sv.point(&p), &s) / d;
        let vector = geometry::evaluate_vector(&sv.vector(&v), &s) / d;
        assert!((point - moved(&back, &p)).norm() < 1e-12, "Δ(R p + t) / Δ");
        assert!((vector - back.rotation * v).norm() < 1e-12, "Δ R v / Δ");
        assert!((eval(&sv.delta(), &s) - d).abs() < 1e-12);
        // Quadric and normalisation at the parameters of a displacement.
        assert!(eval(&sv.quadric(), &s).abs() < 1e-12);
        let unit_rep = Chart::Unit.representative(&s).unwrap();
        assert!(eval(&sv.unit_normalisation(), &unit_rep).abs() < 1e-12);
        assert!((eval(&sv.unit_normalisation(), &s) - (d - 1.0)).abs() < 1e-12);
        let chart = Chart::random_linear(9);
        let lin = chart.representative(&s).unwrap();
        assert!(eval(&sv.chart(&chart), &lin).abs() < 1e-12);
        assert!(unit_rep[0] >= 0.0, "x0 ≥ 0 on the unit chart");
    }
}

#[test]
fn study_variables_may_sit_anywhere_in_a_ring() {
    // The same conditions with the parameters as variables 3..11 of a ring of 12 (other
    // unknowns around them, given arbitrary values) take the same values.
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    let (_, s) = random_pose(&mut rng);
    let indices = [11, 3, 7, 5, 0, 9, 2, 8];
    let sv = StudyVariables::new(12, indices);
    let mut x = vec![0.37; 12];
    for (k, i) in indices.iter().enumerate() {
        x[*i] = s[k];
    }
    let lead = StudyVariables::leading(8);
    let a = Vector3::new(0.3, -0.2, 0.9);
    let b = Vector3::new(-0.5, 0.1, 0.4);
    assert!(
        (eval(&sv.distance(&a, &b, 1.3), &x) - eval(&lead.distance(&a, &b, 1.3), &s)).abs() < 1e-12
    );
    assert!((eval(&sv.quadric(), &x) - eval(&lead.quadric(), &s)).abs() < 1e-12);
}

#[test]
fn husty_distance_quadric_is_delta_times_the_squared_distance_condition() {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let sv = StudyVariables::leading(8);
    for _ in 0..30 {
        let (g, s) = random_pose(&mut rng);
        let a = vec3(&mut rng, 2.0);
        let b = vec3(&mut rng, 1.0);
        let d = (moved(&g, &b) - a).norm();
        // At the true distance it vanishes (relative to the size of its terms, Δ d²).
        let at = eval(&sv.distance(&a, &b, d), &s);
        assert!(at.abs() < 1e-11 * delta(&s) * (1.0 + d * d), "{at}");
        // At another length l it is Δ (d² − l²): not zero, and the right number.
        let l = d * rng.random_range(0.5..0.95);
        let off = eval(&sv.distance(&a, &b, l), &s);
        assert!((off - delta(&s) * (d * d - l * l)).abs() < 1e-10 * delta(&s) * (1.0 + d * d));
        assert_eq!(sv.distance(&a, &b, l).total_degree(), 2);
        // Homogeneous of degree 2: any scale of the parameters.
        let scaled = s.map(|c| 2.5 * c);
        assert!(
            (eval(&sv.distance(&a, &b, l), &scaled) - 6.25 * off).abs() < 1e-9 * off.abs().max(1.0)
        );
    }
}

#[test]
fn husty_distance_quadric_off_the_study_quadric_differs_by_the_quadric_term() {
    // For eight numbers off the quadric the polynomial is Δ(|R b + t − a|² − l²) + 4 (x·y)²/Δ
    // (module documentation), R and t read from M by the definitions R = M_R/Δ, t = M_T/Δ.
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let sv = StudyVariables::leading(8);
    for _ in 0..10 {
        let s: [f64; 8] = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
        let m = study::matrix(&s);
        let d = m[(0, 0)];
        let a = vec3(&mut rng, 2.0);
        let b = vec3(&mut rng, 1.0);
        let rb_t = (m.fixed_view::<3, 3>(1, 1) * b + m.fixed_view::<3, 1>(1, 0)) / d;
        let l = 0.7;
        let q = study::quadric_residual(&s);
        let expected = d * ((rb_t - a).norm_squared() - l * l) + 4.0 * q * q / d;
        assert!(
            (eval(&sv.distance(&a, &b, l), &s) - expected).abs() < 1e-10 * (1.0 + expected.abs())
        );
    }
}

#[test]
fn plane_and_orthogonality_conditions_match_the_displacement() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let sv = StudyVariables::leading(8);
    for _ in 0..30 {
        let (g, s) = random_pose(&mut rng);
        let d = delta(&s);
        let b = vec3(&mut rng, 1.0);
        let a = vec3(&mut rng, 2.0);
        let n = unit(&mut rng);
        let m = unit(&mut rng);
        let v = unit(&mut rng);
        // Moving point on a fixed plane: Δ n·(R b + t − a).
        let p = sv.moving_point_on_fixed_plane(&b, &a, &n);
        assert_eq!(p.total_degree(), 2);
        let expected = d * n.dot(&(moved(&g, &b) - a));
        assert!((eval(&p, &s) - expected).abs() < 1e-11 * d);
        // ... vanishing when a is moved into the plane of the moving point.
        let a_in = moved(&g, &b) + n.cross(&v) * 0.8;
        assert!(eval(&sv.moving_point_on_fixed_plane(&b, &a_in, &n), &s).abs() < 1e-11 * d);
        // Fixed point on a moving plane: Δ (R m)·(a − R b − t).
        let f = sv.fixed_point_on_moving_plane(&a, &b, &m);
        assert_eq!(f.total_degree(), 2);
        let expected = d * (g.rotation * m).dot(&(a - moved(&g, &b)));
        assert!((eval(&f, &s) - expected).abs() < 1e-11 * d * 4.0);
        let rm = g.rotation * m;
        let a_on = moved(&g, &b) + rm.cross(&v) * 1.1;
        assert!(eval(&sv.fixed_point_on_moving_plane(&a_on, &b, &m), &s).abs() < 1e-11 * d * 4.0);
        // Moving vector ⟂ fixed vector: Δ n·(R v).
        let o = sv.moving_vector_orthogonal(&v, &n);
        assert_eq!((o.total_degree(), o.degree_in(&[4, 5, 6, 7])), (2, 0));
        assert!((eval(&o, &s) - d * n.dot(&(g.rotation * v))).abs() < 1e-12 * d);
        let n_perp = (g.rotation * v).cross(&a).normalize();
        assert!(eval(&sv.moving_vector_orthogonal(&v, &n_perp), &s).abs() < 1e-12 * d);
        // Coincidence: Δ (R b + t − a).
        let c = sv.moving_point_at(&b, &a);
        let cv = geometry::evaluate_vector(&c, &s);
        assert!((cv - (moved(&g, &b) - a) * d).norm() < 1e-11 * d);
        assert!(
            geometry::evaluate_vector(&sv.moving_point_at(&b, &moved(&g, &b)), &s).norm()
                < 1e-11 * d
        );
    }
}

#[test]
fn coplanar_lines_condition_is_delta_times_the_triple_product_on_the_quadric() {
    // Paper 004 eq. 10: (r_C − r_B)·(u × n) with n the moving direction.
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    let sv = StudyVariables::leading(8);
    for _ in 0..30 {
        let (g, s) = random_pose(&mut rng);
        let d = delta(&s);
        let a = vec3(&mut rng, 2.0);
        let u = unit(&mut rng);
        let b = vec3(&mut rng, 1.0);
        let m = unit(&mut rng);
        let c = sv.lines_coplanar(&a, &u, &b, &m);
        assert_eq!(c.total_degree(), 2);
        let rm = g.rotation * m;
        let expected = d * (moved(&g, &b) - a).dot(&u.cross(&rm));
        assert!(
            (eval(&c, &s) - expected).abs() < 1e-10 * d,
            "{} {}",
            eval(&c, &s),
            expected
        );
        // Two lines that meet: the fixed line through a point of the moving line.
        let meet = moved(&g, &b) + rm * 0.6;
        let a2 = meet - u * 1.7;
        assert!(eval(&sv.lines_coplanar(&a2, &u, &b, &m), &s).abs() < 1e-10 * d);
    }
}

#[test]
fn constraint_gradients_match_finite_differences() {
    // The derivative of the distance quadric along the pose's own parameters, against a
    // central difference of Δ(|R b + t − a|² − l²) + 4 (x·y)²/Δ computed from study::matrix.
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let sv = StudyVariables::leading(8);
    let (_, s) = random_pose(&mut rng);
    let a = vec3(&mut rng, 2.0);
    let b = vec3(&mut rng, 1.0);
    let p = sv.distance(&a, &b, 0.9);
    let numeric = |s: &[f64; 8]| {
        let m = study::matrix(s);
        let d = m[(0, 0)];
        let rb_t = (m.fixed_view::<3, 3>(1, 1) * b + m.fixed_view::<3, 1>(1, 0)) / d;
        let q = study::quadric_residual(s);
        d * ((rb_t - a).norm_squared() - 0.81) + 4.0 * q * q / d
    };
    for i in 0..8 {
        let h = 1e-6;
        let mut up = s;
        let mut down = s;
        up[i] += h;
        down[i] -= h;
        let fd = (numeric(&up) - numeric(&down)) / (2.0 * h);
        let exact = eval(&p.derivative(i), &s);
        assert!(
            (fd - exact).abs() < 1e-6 * (1.0 + exact.abs()),
            "∂/∂s{i}: {fd} vs {exact}"
        );
    }
}

#[test]
fn plain_distance_unit_vector_and_sine_cosine() {
    // Two planar points with unknown coordinates (u, v) and (w, z): paper 003's link condition.
    let p = geometry::variable_vector(4, [0, 1, 2]);
    let q = [
        Poly::variable(4, 3),
        Poly::real(4, 1.0),
        Poly::real(4, -2.0),
    ];
    let cond = geometry::distance_condition(&p, &q, 3.0);
    let x = [1.0, 2.0, 0.5, -1.0];
    let expected = (1.0f64 + 1.0).powi(2) + (2.0f64 - 1.0).powi(2) + (0.5f64 + 2.0).powi(2) - 9.0;
    assert!((eval(&cond, &x) - expected).abs() < 1e-14);
    assert_eq!(cond.total_degree(), 2);
    let u = geometry::variable_vector(4, [0, 1, 2]);
    let w = Vector3::new(0.36, 0.48, 0.8);
    assert!(eval(&geometry::unit_vector(&u), &[w.x, w.y, w.z, 5.0]).abs() < 1e-15);
    assert!((eval(&geometry::unit_vector(&u), &[1.0, 1.0, 0.0, 5.0]) - 1.0).abs() < 1e-15);
    let (s, c) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let sc = geometry::sin_cos(&s, &c);
    let t = 0.731_f64;
    assert!(eval(&sc, &[t.sin(), t.cos()]).abs() < 1e-15);
    assert!((eval(&sc, &[0.5, 0.5]) + 0.5).abs() < 1e-15);
    let k = geometry::constant_vector(4, &w);
    assert!(
        (eval(&geometry::dot(&u, &k), &[1.0, 2.0, 3.0, 0.0]) - (0.36 + 0.96 + 2.4)).abs() < 1e-14
    );
    let cr = geometry::evaluate_vector(&geometry::cross(&u, &k), &[1.0, 2.0, 3.0, 0.0]);
    assert!((cr - Vector3::new(1.0, 2.0, 3.0).cross(&w)).norm() < 1e-14);
}

/// A general Gough–Stewart platform: base points on a circle of radius ~1 with random
/// perturbations, platform points on one of radius ~0.5, and the leg lengths of a random pose.
type GoughStewart = ([Vector3<f64>; 6], [Vector3<f64>; 6], Displacement, [f64; 6]);

fn random_gough_stewart(rng: &mut ChaCha8Rng) -> GoughStewart {
    let base: [Vector3<f64>; 6] = std::array::from_fn(|_| vec3(rng, 1.0));
    let platform: [Vector3<f64>; 6] = std::array::from_fn(|_| vec3(rng, 0.5));
    let g = spatial::displacement(
        Rotation3::from_scaled_axis(vec3(rng, 0.6)),
        Vector3::new(0.1, -0.2, 1.0) + vec3(rng, 0.2),
    );
    let lengths = std::array::from_fn(|i| (moved(&g, &platform[i]) - base[i]).norm());
    (base, platform, g, lengths)
}

#[test]
fn gough_stewart_system_vanishes_at_the_pose_of_its_leg_lengths() {
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    for chart in [Chart::random_linear(11), Chart::Unit] {
        let (base, platform, g, lengths) = random_gough_stewart(&mut rng);
        let system = geometry::gough_stewart(&base, &platform, &lengths, &chart);
        assert!(system.is_square() && system.is_real());
        assert_eq!(
            system.variables(),
            ["x0", "x1", "x2", "x3", "y0", "y1", "y2", "y3"]
        );
        let expected_degrees = match chart {
            Chart::Linear(_) => vec![2, 2, 2, 2, 2, 2, 2, 1],
            Chart::Unit => vec![2; 8],
        };
        assert_eq!(system.degrees(), expected_degrees);
        let s = chart.representative(&study::from_displacement(&g)).unwrap();
        let z: Vec<C64> = s.iter().map(|r| C64::new(*r, 0.0)).collect();
        let residual = system.evaluate(&z);
        assert!(residual.iter().all(|r| r.norm() < 1e-10), "{residual:?}");
        // Another pose: the leg equations do not vanish.
        let other = spatial::displacement(
            g.rotation,
            g.translation.vector + Vector3::new(0.0, 0.0, 0.05),
        );
        let s = chart
            .representative(&study::from_displacement(&other))
            .unwrap();
        let z: Vec<C64> = s.iter().map(|r| C64::new(*r, 0.0)).collect();
        let residual = system.evaluate(&z);
        assert!(
            residual[..6].iter().all(|r| r.norm() > 1e-4),
            "{residual:?}"
        );
    }
    let (base, platform, _, lengths) = random_gough_stewart(&mut rng);
    assert_eq!(
        geometry::gough_stewart(&base, &platform, &lengths, &Chart::random_linear(1))
            .bezout_number(),
        128
    );
}

// ---- Manipulator::position_system ----

use kinsyn::manipulator::{
    InputValues, LegKind, Manipulator, PlatformGoal, PositionRequest, PositionSystem,
    PositionSystemError,
};

fn manipulator(path: &str) -> Manipulator {
    let file = format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"));
    Manipulator::from_json(&std::fs::read_to_string(file).unwrap()).unwrap()
}

fn residual_at(ps: &PositionSystem, pose: &Displacement) -> f64 {
    let s = ps.solution_of(pose).unwrap();
    let z: Vec<C64> = s.iter().map(|r| C64::new(*r, 0.0)).collect();
    ps.system()
        .evaluate(&z)
        .iter()
        .map(|r| r.norm())
        .fold(0.0, f64::max)
}

/// Every actuator given the value it has in configuration `q` (joint values from the
/// reference, as `parse_inputs` returns them).
fn inputs_at(m: &Manipulator, q: &[f64]) -> Vec<(usize, f64)> {
    m.actuators()
        .iter()
        .enumerate()
        .map(|(a, act)| (a, q[act.joint]))
        .collect()
}

/// Forward kinematics by the numeric loop closure: the configuration reached from the
/// reference with every actuator moved to `values`.
fn forward(m: &Manipulator, values: &[f64]) -> Vec<f64> {
    let request = PositionRequest {
        inputs: values.iter().copied().enumerate().collect(),
        ..PositionRequest::default()
    };
    m.solve_position(&m.reference(), &request).unwrap().q
}

fn check_assembly(m: &Manipulator, q: &[f64], kinds: &[LegKind]) {
    let chart = Chart::random_linear(5);
    let ps = m.position_system(&inputs_at(m, q), &chart).unwrap();
    assert!(ps.system().is_square() && ps.system().is_real());
    assert_eq!(ps.legs().iter().map(|l| l.kind).collect::<Vec<_>>(), kinds);
    let pose = m.platform_frame(q);
    assert!(
        residual_at(&ps, &pose) < 1e-9,
        "{}",
        residual_at(&ps, &pose)
    );
    for r in ps.leg_residuals(&pose) {
        assert!(
            r.distance.abs() < 1e-9 && r.plane.unwrap_or(0.0).abs() < 1e-9,
            "{r:?}"
        );
    }
    // The solution vector gives the pose back.
    let back = ps.displacement(&ps.solution_of(&pose).unwrap()).unwrap();
    assert!((back.translation.vector - pose.translation.vector).norm() < 1e-12);
    // Not elsewhere: the reference pose at these (non-reference) inputs, or a shifted pose.
    let shifted = spatial::displacement(
        pose.rotation,
        pose.translation.vector + Vector3::new(0.01, -0.02, 0.03),
    );
    assert!(residual_at(&ps, &shifted) > 1e-4);
    assert!(
        ps.leg_residuals(&shifted)
            .iter()
            .any(|r| r.distance.abs() > 1e-3)
    );
}

#[test]
fn six_ups_system_vanishes_at_the_reference_pose_and_at_a_forward_kinematics_pose() {
    let m = manipulator("mechanisms/6-ups.json");
    let kinds = [LegKind::Distance; 6];
    check_assembly(&m, &m.reference(), &kinds);
    let q = forward(&m, &[0.05, -0.03, 0.02, 0.04, -0.01, 0.03]);
    check_assembly(&m, &q, &kinds);
    let ps = m
        .position_system(&inputs_at(&m, &q), &Chart::random_linear(5))
        .unwrap();
    assert!(residual_at(&ps, &m.platform_frame(&m.reference())) > 1e-4);
    assert_eq!(ps.system().bezout_number(), 128);
}

#[test]
fn six_ups_inputs_are_slider_displacements_from_the_reference() {
    // Inverse kinematics by hand (solve_position's doc example): the platform raised to
    // z = 1.1 without turning, leg 1 from A = (1, 0, 0) to B = (0.469846, 0.171010, 0) in the
    // platform frame, so P1.3 = |p′ + B − A| − |p + B − A|, the others alike.
    let m = manipulator("mechanisms/6-ups.json");
    let raised = spatial::displacement(Rotation3::identity(), Vector3::new(0.0, 0.0, 1.1));
    let request = PositionRequest {
        platform: Some(PlatformGoal::Pose(raised)),
        ..PositionRequest::default()
    };
    let q = m.solve_position(&m.reference(), &request).unwrap().q;
    let a = Vector3::new(1.0, 0.0, 0.0);
    let b = Vector3::new(0.469_846_310_393, 0.171_010_071_663, 0.0);
    let len = |z: f64| (Vector3::new(0.0, 0.0, z) + b - a).norm();
    let p1 = m.actuator_named("P1.3").unwrap();
    let ps = m
        .position_system(
            &[(p1, len(1.1) - len(1.0))]
                .iter()
                .copied()
                .chain(inputs_at(&m, &q).into_iter().filter(|(k, _)| *k != p1))
                .collect::<Vec<_>>(),
            &Chart::Unit,
        )
        .unwrap();
    assert!(
        (ps.legs()[0].length - len(1.1)).abs() < 1e-9,
        "the leg length is reference + input"
    );
    assert!(residual_at(&ps, &raised) < 1e-9);
}

#[test]
fn three_rps_system_has_distance_and_plane_per_leg() {
    let m = manipulator("mechanisms/3-rps.json");
    let kinds = [LegKind::RevoluteSpherical; 3];
    check_assembly(&m, &m.reference(), &kinds);
    let q = forward(&m, &[0.06, -0.04, 0.02]);
    check_assembly(&m, &q, &kinds);
    // The base axis is the leg's R axis (0, −1, 0) of the description, A the foot of B on it.
    let ps = m.position_system(&inputs_at(&m, &q), &Chart::Unit).unwrap();
    let n = ps.legs()[0].axis.unwrap();
    assert!((n.cross(&Vector3::y())).norm() < 1e-12);
    assert!((ps.legs()[0].base - Vector3::new(1.0, 0.0, 0.0)).norm() < 1e-9);
}

#[test]
fn three_ups_with_every_input_is_revolute_spherical() {
    // Locking α (R1.1 …) and the slider leaves β of the U and the S: the 3-RPS geometry.
    let m = manipulator("mechanisms/3-ups.json");
    let q = forward(&m, &[0.05, 0.04, -0.03, 0.02, 0.01, -0.05]);
    check_assembly(&m, &q, &[LegKind::RevoluteSpherical; 3]);
}

/// A 3-SPR: spherical joints on a base circle of radius 1, revolutes tangent to a platform
/// circle of radius 0.5 one unit above, sliders along the legs.
fn three_spr() -> Manipulator {
    let mut legs = Vec::new();
    for k in 0..3 {
        let t = f64::from(k) * 2.0 * std::f64::consts::PI / 3.0;
        let a = Vector3::new(t.cos(), t.sin(), 0.0);
        let b = Vector3::new(0.5 * t.cos(), 0.5 * t.sin(), 1.0);
        let leg = (b - a).normalize();
        let tangent = Vector3::new(-t.sin(), t.cos(), 0.0);
        let mid = (a + b) / 2.0;
        legs.push(format!(
            r#"{{"chain": "SPR", "base": [{}, {}, 0.0], "platform": [{}, {}, 0.0], "points": [[{}, {}, {}]],
               "axes": [[1,0,0],[0,1,0],[0,0,1],[{}, {}, {}],[{}, {}, 0.0]], "actuated": [4]}}"#,
            a.x, a.y, b.x, b.y, mid.x, mid.y, mid.z, leg.x, leg.y, leg.z, tangent.x, tangent.y
        ));
    }
    let text = format!(
        r#"{{"format": "kinsyn-manipulator/1", "name": "3-SPR", "units": {{"length": "m", "angle": "deg"}},
           "platform": {{"position": [0.0, 0.0, 1.0], "orientation": [0.0, 0.0, 0.0], "point": [0.0, 0.0, 0.0]}},
           "legs": [{}]}}"#,
        legs.join(",")
    );
    Manipulator::from_json(&text).unwrap()
}

#[test]
fn three_spr_system_has_distance_and_moving_plane_per_leg() {
    let m = three_spr();
    let kinds = [LegKind::SphericalRevolute; 3];
    check_assembly(&m, &m.reference(), &kinds);
    let q = forward(&m, &[0.05, -0.02, 0.03]);
    check_assembly(&m, &q, &kinds);
}

fn one_line(e: &PositionSystemError) -> String {
    let text = e.to_string();
    assert!(!text.contains('\n'), "{text}");
    text
}

#[test]
fn unsupported_manipulators_get_one_clear_line() {
    // The planar 3-RRR with the last axis of leg 1 tilted: its two passive revolutes are
    // neither parallel nor concurrent (a skew RR dyad).
    let file = format!(
        "{}/../../mechanisms/3-rrr-planar.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
    v["legs"][0]["chain"] = serde_json::json!("RRR");
    v["legs"][0]["axes"][2] = serde_json::json!([0.0, 0.6, 0.8]);
    let skew = Manipulator::from_json(&v.to_string()).unwrap();
    let e = skew
        .constraint_system(
            &InputValues::Given(&inputs_at(&skew, &skew.reference())),
            &Chart::Unit,
        )
        .unwrap_err();
    assert!(
        matches!(e, PositionSystemError::UnsupportedLeg { leg: 1, .. }),
        "{e}"
    );
    let text = one_line(&e);
    assert!(
        text.starts_with("leg 1 (RRR): ")
            && text.contains("one revolute at the base and one revolute at the platform")
            && text.contains("supported"),
        "{text}"
    );

    // Planar legs give more equations than the platform's six dof: the square position
    // system is refused, the constraint system is the over-constrained one.
    let planar = manipulator("mechanisms/3-rrr-planar.json");
    let e = planar
        .position_system(&inputs_at(&planar, &planar.reference()), &Chart::Unit)
        .unwrap_err();
    assert_eq!(e, PositionSystemError::Overdetermined(12));
    one_line(&e);

    let multi = manipulator("mechanisms/multibody/3-rps-3-spr.json");
    let e = multi
        .position_system(&inputs_at(&multi, &multi.reference()), &Chart::Unit)
        .unwrap_err();
    assert!(matches!(e, PositionSystemError::Multibody { .. }), "{e}");
    assert!(one_line(&e).contains("one block per body"));
}

#[test]
fn missing_inputs_leave_degrees_of_freedom() {
    // The 3-UPS with only its sliders given: three distances, three dof left.
    let m = manipulator("mechanisms/3-ups.json");
    let sliders: Vec<(usize, f64)> = ["P1.3", "P2.3", "P3.3"]
        .iter()
        .map(|l| (m.actuator_named(l).unwrap(), 0.0))
        .collect();
    let e = m.position_system(&sliders, &Chart::Unit).unwrap_err();
    assert_eq!(
        e,
        PositionSystemError::Underdetermined {
            constraints: 3,
            missing: vec!["R1.1".into(), "R2.1".into(), "R3.1".into()]
        }
    );
    let text = one_line(&e);
    assert!(
        text.contains("3 dof left") && text.contains("R1.1 R2.1 R3.1"),
        "{text}"
    );
    // Only the U's first revolutes given: the sliders are passive, each leg an R–P–S (the
    // U's second revolute, the slider across it, the S) that keeps the S centre in a plane —
    // one constraint per leg, three dof left.
    let alphas: Vec<(usize, f64)> = ["R1.1", "R2.1", "R3.1"]
        .iter()
        .map(|l| (m.actuator_named(l).unwrap(), 0.0))
        .collect();
    let e = m.position_system(&alphas, &Chart::Unit).unwrap_err();
    assert_eq!(
        e,
        PositionSystemError::Underdetermined {
            constraints: 3,
            missing: vec!["P1.3".into(), "P2.3".into(), "P3.3".into()]
        }
    );
    // Bad inputs.
    assert!(matches!(
        m.position_system(&[(99, 0.0)], &Chart::Unit),
        Err(PositionSystemError::UnknownInput { index: 99, .. })
    ));
    assert!(matches!(
        m.position_system(&[(0, 0.0), (0, 1.0)], &Chart::Unit),
        Err(PositionSystemError::InputTwice(_))
    ));
    assert!(matches!(
        m.position_system(&[(0, f64::NAN)], &Chart::Unit),
        Err(PositionSystemError::NotFinite { .. })
    ));
}
