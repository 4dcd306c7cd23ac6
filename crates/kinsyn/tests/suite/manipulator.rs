//! Parallel manipulators (src/manipulator): the Jacobians of paper 000 §4–5 (eqs. 11, 12–19,
//! 20–22) checked element by element against the paper's formulas evaluated from the geometry,
//! against finite differences of the inverse kinematics, and against the loop-closure mechanism
//! (a second algorithm); motion patterns checked on manipulators whose pattern follows from first
//! principles.

use kinsyn::manipulator::{Manipulator, RowKind};
use kinsyn::mechanism::SampleSettings;
use kinsyn::motion::{GroupKind, Pattern};
use nalgebra::{DMatrix, DVector, Rotation3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn load(name: &str) -> Manipulator {
    let text = std::fs::read_to_string(format!("../../mechanisms/{name}.json")).unwrap();
    Manipulator::from_json(&text).unwrap()
}

fn description(name: &str) -> kinsyn::manipulator::file::Description {
    let text = std::fs::read_to_string(format!("../../mechanisms/{name}.json")).unwrap();
    kinsyn::manipulator::file::Description::from_json(&text).unwrap()
}

/// A random platform pose near the file's reference pose: the frame origin moved by up to
/// `reach` in each coordinate, and turned by up to `turn` radians about a random axis.
fn random_pose(
    d: &kinsyn::manipulator::file::Description,
    rng: &mut ChaCha8Rng,
    reach: f64,
    turn: f64,
) -> (Vector3<f64>, Vector3<f64>) {
    let p = Vector3::from(d.platform.position)
        + Vector3::from_fn(|_, _| rng.random_range(-reach..reach));
    let axis = Vector3::from_fn(|_, _| rng.random_range(-1.0..1.0)).normalize();
    (p, axis * rng.random_range(-turn..turn))
}

/// Leg `i`'s base point `A_i` and platform attachment `G_i` at the pose `(p, r)`, from the file.
fn attachment(
    d: &kinsyn::manipulator::file::Description,
    i: usize,
    p: &Vector3<f64>,
    r: &Rotation3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::from(d.legs[i].base),
        r * Vector3::from(d.legs[i].platform) + p,
    )
}

fn row(j: &DMatrix<f64>, r: usize) -> Vec<f64> {
    (0..j.ncols()).map(|c| j[(r, c)]).collect()
}

fn paper_row(u: &Vector3<f64>, gp: &Vector3<f64>) -> Vec<f64> {
    let m = u.cross(gp);
    vec![u.x, u.y, u.z, m.x, m.y, m.z]
}

fn assert_close(a: &[f64], b: &[f64], tol: f64, what: &str) {
    let err = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(err < tol, "{what}: {a:?} vs {b:?} (error {err:e})");
}

/// Equal up to a common sign (a row and its `J_I` entry can both be negated).
fn assert_close_up_to_sign(a: &[f64], b: &[f64], tol: f64, what: &str) {
    let neg: Vec<f64> = b.iter().map(|x| -x).collect();
    let plus = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    let minus = a
        .iter()
        .zip(&neg)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(
        plus.min(minus) < tol,
        "{what}: {a:?} vs ±{b:?} (error {:e})",
        plus.min(minus)
    );
}

#[test]
fn six_ups_direct_jacobian_is_eq_11_element_by_element_at_random_poses() {
    // Paper 000 eq. 11: row i of J_D is ((u_ci)ᵀ, (u_ci × G_iP)ᵀ) and J_I = I, with u_ci the
    // unit vector from the U centre A_i to the S centre G_i and G_iP = P − G_i. The expected
    // values come from the file's geometry and the pose, not from the mechanism.
    let d = description("6-ups");
    let m = load("6-ups");
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..5 {
        let (p, rv) = random_pose(&d, &mut rng, 0.1, 0.15);
        let q = m.assemble_at(p, rv, &[]).unwrap();
        let r = Rotation3::from_scaled_axis(rv);
        let point = r * Vector3::from(d.platform.point) + p;
        let j = m.jacobians(&q, &[]);
        assert_eq!((j.jd.nrows(), j.ji.ncols()), (6, 6));
        assert_close(
            j.ji.as_slice(),
            DMatrix::<f64>::identity(6, 6).as_slice(),
            1e-12,
            "J_I = I",
        );
        for i in 0..6 {
            let (a, g) = attachment(&d, i, &p, &r);
            let u = (g - a).normalize();
            assert_close(
                &row(&j.jd, i),
                &paper_row(&u, &(point - g)),
                1e-9,
                "eq. 11 row",
            );
        }
    }
}

#[test]
fn six_ups_input_rates_are_the_derivatives_of_the_leg_lengths() {
    // Independent method: the inverse kinematics of the Gough–Stewart platform, leg lengths
    // L_i = |R b_i + p − A_i|, differentiated by central differences along each unit platform
    // twist (v_P; ω) (P translated by t v_P, the platform turned by exp(t ω) about P). Then
    // ċ = J_I⁻¹ J_D (v_P; ω) (paper 000 eq. 11) column by column.
    let d = description("6-ups");
    let m = load("6-ups");
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let (p, rv) = random_pose(&d, &mut rng, 0.1, 0.15);
    let q = m.assemble_at(p, rv, &[]).unwrap();
    let r = Rotation3::from_scaled_axis(rv);
    let point = r * Vector3::from(d.platform.point) + p;
    let j = m.jacobians(&q, &[]);
    let rates = j.ji.clone().lu().solve(&j.jd).unwrap(); // J_I⁻¹ J_D
    let lengths = |t: f64, k: usize| -> Vec<f64> {
        let mut e = [0.0; 6];
        e[k] = t;
        let (v, w) = (
            Vector3::new(e[0], e[1], e[2]),
            Vector3::new(e[3], e[4], e[5]),
        );
        let turn = Rotation3::from_scaled_axis(w);
        (0..6)
            .map(|i| {
                let g = r * Vector3::from(d.legs[i].platform) + p;
                let moved = point + v + turn * (g - point);
                (moved - Vector3::from(d.legs[i].base)).norm()
            })
            .collect()
    };
    let h = 1e-6;
    for k in 0..6 {
        let (plus, minus) = (lengths(h, k), lengths(-h, k));
        for i in 0..6 {
            let fd = (plus[i] - minus[i]) / (2.0 * h);
            assert!(
                (rates[(i, k)] - fd).abs() < 1e-7,
                "leg {i}, twist direction {k}: J_I⁻¹J_D {} vs finite difference {fd}",
                rates[(i, k)]
            );
        }
    }
}

/// The 3-UPS geometry at a pose: for leg i, (`A_i`, `G_i`, `u_α`, `u_β`, `u_c`, c). The U's first axis `u_α`
/// is fixed to the base (the file's axis); `u_β` is perpendicular to `u_α` (a U) and to `u_c` (the
/// generic chain keeps consecutive joints perpendicular, §3), so `u_β` = ±`u_α` × `u_c` / |·|.
fn ups_leg(
    d: &kinsyn::manipulator::file::Description,
    i: usize,
    p: &Vector3<f64>,
    r: &Rotation3<f64>,
) -> [Vector3<f64>; 5] {
    let (a, g) = attachment(d, i, p, r);
    let alpha = match &d.legs[i].axes.as_ref().unwrap()[0] {
        kinsyn::manipulator::file::AxisSpec::Vector(v) => Vector3::from(*v).normalize(),
        other @ kinsyn::manipulator::file::AxisSpec::Named(_) => panic!("{other:?}"),
    };
    let uc = (g - a).normalize();
    let beta = alpha.cross(&uc).normalize();
    [g, alpha, beta, uc, Vector3::new((g - a).norm(), 0.0, 0.0)]
}

#[test]
fn three_ups_jacobians_are_eqs_12_to_19() {
    // Paper 000 eqs. 12 and 17–19: for each leg, the row of the prismatic input c is
    // (u_c, u_c × GP) with J_I entry 1, and the row of the U's first revolute α is
    // (u_β, u_β × GP) with J_I entry c (u_β × u_α)·u_c (up to a common sign: u_β's sense is
    // arbitrary). Evaluated at random poses from the geometry alone.
    let d = description("3-ups");
    let m = load("3-ups");
    let labels: Vec<String> = m
        .actuators()
        .iter()
        .map(kinsyn::manipulator::Actuator::label)
        .collect();
    assert_eq!(labels, ["R1.1", "P1.3", "R2.1", "P2.3", "R3.1", "P3.3"]);
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    for _ in 0..5 {
        let (p, rv) = random_pose(&d, &mut rng, 0.1, 0.2);
        let q = m.assemble_at(p, rv, &[]).unwrap();
        let r = Rotation3::from_scaled_axis(rv);
        let point = r * Vector3::from(d.platform.point) + p;
        let j = m.jacobians(&q, &[]);
        assert_eq!((j.jd.nrows(), j.ji.ncols()), (6, 6));
        for i in 0..3 {
            let [g, ua, ub, uc, c] = ups_leg(&d, i, &p, &r);
            let gp = point - g;
            // Rows follow the inputs: leg i's α is row 2i, its c row 2i + 1.
            let mut expected_c = paper_row(&uc, &gp);
            expected_c.push(1.0);
            let mut got_c = row(&j.jd, 2 * i + 1);
            got_c.push(j.ji[(2 * i + 1, 2 * i + 1)]);
            assert_close(&got_c, &expected_c, 1e-9, "eq. 12 row and J_I = 1");
            let mut expected_a = paper_row(&ub, &gp);
            expected_a.push(c.x * ub.cross(&ua).dot(&uc));
            let mut got_a = row(&j.jd, 2 * i);
            got_a.push(j.ji[(2 * i, 2 * i)]);
            assert_close_up_to_sign(&got_a, &expected_a, 1e-9, "eq. 17 row and eq. 19 entry");
            // The other entries of J_I in these rows vanish (eq. 19 is diagonal).
            for col in 0..6 {
                if col != 2 * i && col != 2 * i + 1 {
                    assert!(
                        j.ji[(2 * i, col)].abs() < 1e-12 && j.ji[(2 * i + 1, col)].abs() < 1e-12
                    );
                }
            }
        }
    }
}

#[test]
fn three_ups_has_six_dof_with_every_input_free() {
    // Paper 000 §5.1: "The 3-UPS is a 6 dof parallel manipulator". Three UPS legs of six joints
    // each: mobility 3·6 − 6·2 = 6 by loop closure, and no constraint wrench.
    let m = load("3-ups");
    let q = m.reference();
    let a = m.analyse(&q, &[], &SampleSettings::default()).unwrap();
    assert_eq!((a.mobility, a.platform_dof), (6, 6));
    // Second method: the twist space of the platform by loop closure.
    assert_eq!(m.mechanism().twist_space(m.platform(), &q, &[]).1, 6);
    let mode = m.mode(&[], &SampleSettings::default());
    assert_eq!(mode.pattern_text(), "D");
}

#[test]
fn locking_every_alpha_gives_three_dof_1t2r_and_the_constraints_of_eq_22() {
    // Paper 000 §5.2: blocking α_i turns the 3-UPS into the 3-RPS, of three dof; its platform
    // motion is the well-known 1T2R with parasitic motion, not a group (two rotations and one
    // translation independent; the other three coupled). The locked rows of J_D are the
    // constraint equations (eq. 22): u_βi·v_P + (u_βi × G_iP)·ω = 0, with zero rows in J_I
    // (eq. 21). Checked at configurations reached by the finite motion.
    let d = description("3-ups");
    let m = load("3-ups");
    let alphas = m.parse_locks("R1.1,R2.1,R3.1").unwrap();
    let settings = SampleSettings::default();
    let mode = m.mode(&alphas, &settings);
    assert_eq!(mode.dof, 3);
    assert_eq!(mode.pattern_text(), "1T2R");
    assert!(!mode.group);
    let mask = m.lock_mask(&alphas);
    let samples = m
        .mechanism()
        .sample_motion(m.platform(), &m.reference(), &mask, &settings)
        .unwrap()
        .samples;
    for s in &samples {
        let j = m.jacobians(&s.q, &alphas);
        let g = m.platform_frame(&s.q);
        let (r, p) = (g.rotation, g.translation.vector);
        let point = m.point(&s.q);
        assert_eq!(j.ji.ncols(), 3);
        for i in 0..3 {
            let [g, _, ub, _, _] = ups_leg(&d, i, &p, &r);
            let k = j
                .rows
                .iter()
                .position(|w| w.kind == RowKind::Locked { actuator: 2 * i })
                .unwrap();
            assert_close_up_to_sign(
                &row(&j.jd, k),
                &paper_row(&ub, &(point - g)),
                1e-9,
                "eq. 22",
            );
            assert!(
                j.ji.row(k).amax() == 0.0,
                "eq. 21: the J_I row of a locked input is zero"
            );
        }
    }
}

#[test]
fn three_rps_built_directly_equals_three_ups_with_alpha_locked() {
    // Paper 000 §5: "if the aim would be analysing only the low-mobility manipulator ... this
    // can be perfectly done by directly particularizing the generic chain into the RPS chain".
    // The 3-RPS file has the 3-UPS's geometry with the U's second axis as its R; at the same
    // platform poses the Jacobians agree row by row (c rows, then constraints) — eq. 21.
    let rps = load("3-rps");
    let ups = load("3-ups");
    let alphas = ups.parse_locks("R1.1,R2.1,R3.1").unwrap();
    let samples = rps
        .mechanism()
        .sample_motion(
            rps.platform(),
            &rps.reference(),
            &[],
            &SampleSettings::default(),
        )
        .unwrap()
        .samples;
    for q_rps in std::iter::once(rps.reference()).chain(samples.into_iter().map(|s| s.q)) {
        let g = rps.platform_frame(&q_rps);
        let (r, p) = (g.rotation, g.translation.vector);
        let q_ups = ups.assemble_at(p, r.scaled_axis(), &alphas).unwrap();
        let a = rps.jacobians(&q_rps, &[]);
        let b = ups.jacobians(&q_ups, &alphas);
        assert_eq!(a.jd.shape(), b.jd.shape());
        for k in 0..6 {
            let what = format!("row {k}");
            if k < 3 {
                assert_close(&row(&a.jd, k), &row(&b.jd, k), 1e-9, &what);
            } else {
                assert_close_up_to_sign(&row(&a.jd, k), &row(&b.jd, k), 1e-9, &what);
            }
        }
        assert_close(a.ji.as_slice(), b.ji.as_slice(), 1e-9, "J_I");
    }
}

#[test]
fn jacobians_agree_with_the_loop_closure_of_every_mechanism() {
    // Second algorithm: every joint-rate vector compatible with the loop closure (null space of
    // the closure Jacobian) gives a platform twist t at P and input rates q̇_a; the reciprocal
    // screws must satisfy J_D t = J_I q̇_a. And the platform dof from loop closure equals six
    // minus the rank of the constraint wrenches.
    for name in [
        "3-ups",
        "3-rps",
        "6-ups",
        "3-prrr",
        "3-rrr-spherical",
        "3-rrr-planar",
    ] {
        let m = load(name);
        let settings = SampleSettings::default();
        let samples = m
            .mechanism()
            .sample_motion(m.platform(), &m.reference(), &[], &settings)
            .unwrap()
            .samples;
        for s in &samples {
            let j = m.jacobians(&s.q, &[]);
            let mob = m.mechanism().mobility(&s.q, &[]);
            let screws = m.mechanism().joint_screws(&s.q);
            let body = m.mechanism().body_jacobian(m.platform(), &screws);
            let point = m.point(&s.q);
            for c in 0..mob.rates.ncols() {
                let qdot = DVector::from_fn(m.mechanism().joints().len(), |k, _| mob.rates[(k, c)]);
                let twist = &body * &qdot;
                let w = Vector3::new(twist[0], twist[1], twist[2]);
                let vp = Vector3::new(twist[3], twist[4], twist[5]) + w.cross(&point);
                let t = DVector::from_vec(vec![vp.x, vp.y, vp.z, w.x, w.y, w.z]);
                let inputs =
                    DVector::from_fn(j.free.len(), |k, _| qdot[m.actuators()[j.free[k]].joint]);
                let residual = (&j.jd * &t - &j.ji * &inputs).amax();
                assert!(
                    residual < 1e-9 * (1.0 + t.amax()),
                    "{name}: J_D t − J_I q̇ = {residual:e}"
                );
            }
            let a = m.analyse(&s.q, &[], &settings).unwrap();
            // The dof from the wrenches equals the twist space by loop closure (second method).
            let (_, by_closure) = m.mechanism().twist_space(m.platform(), &s.q, &[]);
            assert_eq!(a.platform_dof, by_closure, "{name}");
        }
    }
}

fn group(name: &str, locked: &str) -> (Pattern, usize) {
    let m = load(name);
    let locks = m.parse_locks(locked).unwrap();
    let mode = m.mode(&locks, &SampleSettings::default());
    let c = mode.classification.expect("sampled");
    (c.pattern, c.dof)
}

#[test]
fn first_principles_patterns_are_recognised() {
    // 3-PRRR with each leg's slider parallel to its three revolutes (Kong & Gosselin's
    // translational 3-PRRR): each leg allows X(u_i), the intersection of three with independent
    // u_i is T3. Locking leg 1's slider leaves translations perpendicular to u_1: T2.
    let (t3, dof) = group("3-prrr", "-");
    assert_eq!((t3.to_string().as_str(), dof), ("T3", 3));
    let (t2, _) = group("3-prrr", "P1.1");
    let Pattern::Group(g) = t2 else {
        panic!("{t2}")
    };
    assert_eq!(g.kind, GroupKind::T2);
    let d = description("3-prrr");
    let kinsyn::manipulator::file::AxisSpec::Vector(u1) = &d.legs[0].axes.as_ref().unwrap()[1]
    else {
        panic!()
    };
    let n = Vector3::from(g.direction.unwrap());
    assert!(
        n.cross(&Vector3::from(*u1).normalize()).norm() < 1e-6,
        "T2 normal {n} along u_1"
    );
    // Spherical 3-RRR: every axis through N = (0, 0, 0.5) (the file's source): S(N), 3 dof.
    let (s, dof) = group("3-rrr-spherical", "-");
    let Pattern::Group(g) = s else { panic!("{s}") };
    assert_eq!((g.kind, dof), (GroupKind::S, 3));
    assert!((Vector3::from(g.point.unwrap()) - Vector3::new(0.0, 0.0, 0.5)).norm() < 1e-6);
    // Planar 3-RRR: every axis along z: G(xy), 3 dof.
    let (planar, dof) = group("3-rrr-planar", "-");
    assert_eq!((planar.to_string().as_str(), dof), ("G(xy)", 3));
    // Gough–Stewart: D with the inputs free, E (a structure) with all locked.
    assert_eq!(group("6-ups", "-").0.to_string(), "D");
    assert_eq!(
        group("6-ups", "P1.3,P2.3,P3.3,P4.3,P5.3,P6.3")
            .0
            .to_string(),
        "E"
    );
    // 3-UPS with legs 2 and 3 fully locked and leg 1's α locked: the S centres G_2, G_3 can
    // stay put, and G_1 (free along leg 1's vertical plane, which is perpendicular to G_2G_3)
    // turns about the line G_2G_3, along y: R(y).
    assert_eq!(
        group("3-ups", "R1.1,R2.1,P2.3,R3.1,P3.3").0.to_string(),
        "R(y)"
    );
}

#[test]
fn a_similar_hexagon_gough_stewart_platform_is_singular_everywhere() {
    // Ma & Angeles (1991), architecture singularities: a Gough–Stewart platform whose base and
    // platform points form similar regular hexagons (here radii 1 and 0.5, legs in radial
    // planes) has J_D rank-deficient at every pose. kinsyn reports a direct singularity.
    let d = kinsyn::manipulator::build::build(&kinsyn::manipulator::build::BuildSpec {
        legs: 6,
        chain: "UP!S".into(),
        ..Default::default()
    })
    .unwrap();
    let m = Manipulator::new(&d).unwrap();
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert!(a.generic.jd < 6, "generic rank {}", a.generic.jd);
    assert!(
        a.singularities
            .iter()
            .any(|s| s.kind == kinsyn::manipulator::SingularityKind::Direct),
        "{:?}",
        a.singularities
    );
    // The paired layout of mechanisms/6-ups.json is not.
    let good = load("6-ups");
    let a = good
        .analyse(&good.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert!(
        a.singularities.is_empty() && a.jd_rank.rank == 6,
        "{:?}",
        a.singularities
    );
}

#[test]
fn modes_of_the_three_ups_cover_all_64_lock_subsets() {
    // `kinsyn modes` on the 3-UPS enumerates 2^6 lock subsets; the dof with k inputs locked is
    // 6 − k near the reference (each locked input removes one, the legs being non-singular there),
    // and 1T2R is reached exactly by locking the three α (§5.2).
    let m = load("3-ups");
    let modes = m.modes(&SampleSettings::default()).unwrap();
    assert_eq!(modes.modes.len(), 64);
    for mode in &modes.modes {
        assert_eq!(mode.dof, 6 - mode.locked.len(), "{}", mode.lock_text);
    }
    let rps = modes
        .non_groups
        .iter()
        .find(|p| p.pattern == "1T2R")
        .unwrap();
    assert_eq!(rps.lock_sets, ["R1.1 R2.1 R3.1"]);
    assert!(modes.groups.iter().any(|g| g.pattern == "D"));
    assert!(modes.groups.iter().any(|g| g.pattern == "E"));
}

#[test]
fn the_committed_manipulator_files_are_what_kinsyn_build_writes() {
    // mechanisms/*.json of the paper's manipulators are generated (their `source` names the
    // command): rebuilding them gives the same bytes, so the files and the builder agree.
    use kinsyn::manipulator::build::{BuildSpec, build};
    let cases = [
        ("3-ups", "U(!,-)P!S", None, 0.0, false),
        ("3-rps", "RP!S", Some("yzxyz"), 0.0, false),
        ("6-ups", "UP!S", None, 20.0, true),
        ("3-prrr", "P!RaRaRa", Some("xxxx"), 0.0, false),
    ];
    for (file, chain, axes, twist, alternate) in cases {
        let d = build(&BuildSpec {
            legs: if file == "6-ups" { 6 } else { 3 },
            chain: chain.into(),
            axes: axes.map(Into::into),
            twist,
            alternate,
            name: Some(file.to_uppercase()),
            ..Default::default()
        })
        .unwrap();
        let committed = std::fs::read_to_string(format!("../../mechanisms/{file}.json")).unwrap();
        assert_eq!(d.to_json(), committed, "../../mechanisms/{file}.json");
    }
}

#[test]
fn a_three_rps_with_radial_revolutes_is_constraint_singular_at_the_horizontal_pose() {
    // Hand derivation: with vertical legs (base and platform radii equal) the R axis may be
    // radial and horizontal while staying perpendicular to the slider (paper 000 §3). A leg's
    // constraint wrench is then the force through its S centre G_i parallel to its R axis
    // (reciprocal to R, P and S). With the platform horizontal the three radial forces are
    // coplanar and meet on the vertical axis, so they span only the two forces of that plane
    // through that point: rank 2 instead of 3, and the platform gains a dof (4 instead of 3).
    // Tilted nearby, the three lines are no longer coplanar and the rank is 3.
    use kinsyn::manipulator::build::{BuildSpec, build};
    let spec = |axes: &str| BuildSpec {
        chain: "RP!S".into(),
        axes: Some(axes.into()),
        platform_radius: 1.0,
        ..Default::default()
    };
    let m = Manipulator::new(&build(&spec("xzxyz")).unwrap()).unwrap();
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!((a.constraint_rank.rank, a.generic.constraint), (2, 3));
    assert_eq!(a.platform_dof, 4);
    assert_eq!(
        m.mechanism()
            .twist_space(m.platform(), &m.reference(), &[])
            .1,
        4
    );
    let constraint = a
        .singularities
        .iter()
        .find(|s| s.kind == kinsyn::manipulator::SingularityKind::Constraint)
        .expect("a constraint singularity");
    assert!(
        constraint
            .detail()
            .contains("rank 2 here, 3 at generic configurations"),
        "{}",
        constraint.detail()
    );
    // Tangential R axes give three lines that bound a triangle: independent, no singularity.
    let m = Manipulator::new(&build(&spec("yzxyz")).unwrap()).unwrap();
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!((a.constraint_rank.rank, a.platform_dof), (3, 3));
    assert!(a.singularities.is_empty(), "{:?}", a.singularities);
}

#[test]
fn every_verified_catalogue_chain_builds_a_six_dof_manipulator() {
    // `kinsyn build` must give a geometry in which any catalogue chain can be tried as a leg. A
    // 3T3R leg (rank 6) allows every platform twist, so three of them leave the platform its six
    // dof (the intersection of three full twist systems) — unless the built geometry is special.
    // Checked for all 446 verified chains at the reference configuration.
    use kinsyn::catalogue::Catalogue;
    use kinsyn::manipulator::build::{BuildSpec, build};
    let cat = Catalogue::generate(
        &kinsyn::synthesis::Options::default(),
        &kinsyn::published::PrintedTables::default(),
    );

    for e in cat.verified() {
        let d = build(&BuildSpec {
            chain: e.notation.clone(),
            axes: Some(e.axes.to_string()),
            actuated: Some(vec![1]),
            ..Default::default()
        })
        .unwrap();
        let m = Manipulator::new(&d).unwrap();
        let (_, dof) = m.mechanism().twist_space(m.platform(), &m.reference(), &[]);
        assert_eq!(dof, 6, "{} {}: {:?}", e.id, e.notation, d.source);
    }
}

#[test]
fn the_three_prrr_sliders_drive_the_platform() {
    // Fixed with the trustworthy manipulator analysis: each PRRR leg's constraints are two couples
    // (perpendicular to its axis direction u_i), and the old wrench selection took one of them as
    // the slider's actuation wrench (J_I = 0, false inverse and architecture singularities). Hand
    // derivation: a force along u_i is reciprocal to the three revolutes (parallel lines) and does
    // work 1 on the slider (f·u_i = 1), so J_I = 1 and the row's force is u_i (up to the row's
    // sign).
    let d = description("3-prrr");
    let m = load("3-prrr");
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert!(a.singularities.is_empty(), "{:?}", a.singularities);
    assert_eq!((a.platform_dof, a.jd_rank.rank), (3, 6));
    for (i, leg) in d.legs.iter().enumerate() {
        let kinsyn::manipulator::file::AxisSpec::Vector(u) = leg.axes.as_ref().unwrap()[0] else {
            panic!()
        };
        let u = Vector3::from(u).normalize();
        let k = a
            .jacobians
            .rows
            .iter()
            .position(|r| r.kind == RowKind::Actuation { actuator: i })
            .unwrap();
        let row = &a.jacobians.rows[k];
        assert!(
            (row.input - 1.0).abs() < 1e-12,
            "leg {i}: J_I {}",
            row.input
        );
        let f = Vector3::new(row.wrench[0], row.wrench[1], row.wrench[2]);
        assert!(
            f.cross(&u).norm() < 1e-12 && (f.norm() - 1.0).abs() < 1e-12,
            "{f} vs {u}"
        );
    }
    // Locking a slider removes a dof, as the J_I entry says (modes agreed all along).
    let locked = m.mode(&[1], &SampleSettings::default());
    assert_eq!(locked.dof, 2);
}

#[test]
fn extreme_units_give_the_answers_of_the_metre() {
    // Fixed with the trustworthy manipulator analysis: the 3-PRRR with lengths ×1e±3 gave other
    // ranks and singularities, and the 3-UPS ×1e-9 "platform dof 5" with every input without
    // effect. A unit is a choice: the answers at ×1e-9 and ×1e9 must be those of the file
    // (tests/suite/invariance.rs checks every file and exponent; these are the reported cases).
    for name in ["3-prrr", "3-ups"] {
        let summary = |m: &Manipulator| {
            let a = m
                .analyse(&m.reference(), &[], &SampleSettings::default())
                .unwrap();
            (
                a.platform_dof,
                a.jd_rank.rank,
                a.constraint_rank.rank,
                a.singularities.len(),
                a.jacobians.without_wrench.len(),
            )
        };
        let want = summary(&load(name));
        assert_eq!(want.3 + want.4, 0, "{name}: no singularity in metres");
        for k in [1e-9, 1e-3, 1e3, 1e9] {
            let m = edited(name, |v| scaled(v, k, [0.0; 3])).unwrap();
            assert_eq!(summary(&m), want, "{name} × {k:e}");
        }
    }
}

#[test]
fn a_leg_singular_reference_has_one_dof_and_is_flagged() {
    // Fixed with the trustworthy manipulator analysis: the planar 3-RRR with its `points` removed
    // puts each leg's middle joint on the line from base to platform. Hand derivation: three
    // parallel revolutes through collinear points span only two twists (the leg cannot move along
    // its line), each revolute depends on the other two, and three such legs meeting the platform
    // at points whose lines are not concurrent leave it no instantaneous motion: platform dof 0
    // (not 3), while the joint rates keep 3 internal motions. The old code printed "platform dof 3
    // (twist space) = 0 (wrenches)" and no singularity.
    use kinsyn::manipulator::SingularityKind::{Inverse, Leg};
    let mut d = description("3-rrr-planar");
    for leg in &mut d.legs {
        leg.points = None;
    }
    let m = Manipulator::new(&d).unwrap();
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!((a.mobility, a.platform_dof), (3, 0));
    // One answer: the loop-closure twist space (second method) agrees.
    assert_eq!(
        m.mechanism()
            .twist_space(m.platform(), &m.reference(), &[])
            .1,
        0
    );
    for kind in [Inverse, Leg] {
        assert_eq!(
            a.singularities.iter().filter(|s| s.kind == kind).count(),
            3,
            "{kind:?}: {:?}",
            a.singularities
        );
    }
    assert_eq!(a.generic.legs, vec![3, 3, 3]);
    assert!(a.leg_ranks.iter().all(|r| r.rank == 2));
}

#[test]
fn the_three_ppps_reaches_no_helical_motion() {
    // Fixed with the trustworthy manipulator analysis: a 3-PPPS built from T1-001 (three sliders
    // and a spherical joint per leg) reported "5 of the 12 kinds (E R H S D)" for some seeds; H was
    // a one-dof walk whose samples coincided. First principles: every joint axis of the legs is
    // fixed in direction (three sliders) or passes through one point of the platform (the S), so a
    // one-dof motion with legs locked is a rotation about a line through S centres, never a screw
    // motion of non-zero pitch. Over 20 seeds the kinds reached are the same and never include H.
    use kinsyn::manipulator::build::{BuildSpec, build};
    let d = build(&BuildSpec {
        chain: "T1-001".into(),
        actuated: Some(vec![1, 2, 3]),
        ..Default::default()
    })
    .unwrap();
    let m = Manipulator::new(&d).unwrap();
    let kinds: std::collections::BTreeSet<Vec<String>> = (0..20)
        .map(|seed| {
            m.modes(&SampleSettings {
                seed,
                ..SampleSettings::default()
            })
            .unwrap()
            .group_kinds
        })
        .collect();
    assert_eq!(kinds.len(), 1, "{kinds:?}");
    assert!(
        !kinds.iter().next().unwrap().contains(&"H".to_string()),
        "{kinds:?}"
    );
}

// ---- Leg checks and parallel marks ----

/// The committed file `name` as JSON with `edit` applied, built into a manipulator.
fn edited(
    name: &str,
    edit: impl FnOnce(&mut serde_json::Value),
) -> Result<Manipulator, kinsyn::manipulator::ManipulatorError> {
    let text = std::fs::read_to_string(format!("../../mechanisms/{name}.json")).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    edit(&mut v);
    Manipulator::from_json(&v.to_string())
}

/// Every length of a description multiplied by `s` and moved by `shift` (in the new unit).
fn scaled(v: &mut serde_json::Value, s: f64, shift: [f64; 3]) {
    let scale = |p: &mut serde_json::Value, shift: [f64; 3]| {
        for (i, x) in p.as_array_mut().unwrap().iter_mut().enumerate() {
            *x = serde_json::json!(x.as_f64().unwrap() * s + shift[i]);
        }
    };
    scale(&mut v["platform"]["position"], shift);
    scale(&mut v["platform"]["point"], [0.0; 3]);
    for leg in v["legs"].as_array_mut().unwrap() {
        scale(&mut leg["base"], shift);
        scale(&mut leg["platform"], [0.0; 3]);
        if let Some(points) = leg.get_mut("points").and_then(|p| p.as_array_mut()) {
            for p in points {
                scale(p, shift);
            }
        }
    }
}

/// The planar 3-RRR with leg 1's middle joint moved to the midpoint of its base and platform
/// points: its three joint points collinear.
fn collinear_planar(v: &mut serde_json::Value) {
    let leg = &mut v["legs"][0];
    let (b, p) = (leg["base"].clone(), leg["platform"].clone());
    let mid: Vec<f64> = (0..3)
        .map(|i| f64::midpoint(b[i].as_f64().unwrap(), p[i].as_f64().unwrap()))
        .collect();
    leg["points"] = serde_json::json!([mid]);
}

/// The 3-UPS with leg 1's U's second axis along the leg (base to platform point).
fn ups_with_spinning_leg(v: &mut serde_json::Value) {
    v["legs"][0]["axes"][1] = "leg".into();
}

#[test]
fn committed_files_have_generic_legs() {
    // The files of mechanisms/ are meant to be generic. Hand ranks of their legs: a UPS leg's
    // six twists span all six (U and S centres distinct, the slider joining them); an RPS leg's
    // five are independent (the R's axis misses the S centre); a PRRR leg with three revolutes
    // parallel to its slider spans ω along them, the two translations across them (three axis
    // points not collinear across the axes) and the slider: 4; three revolutes through one point
    // (spherical) or parallel through non-collinear points (planar): 3. Each equals the number
    // of joints, at the reference and generically.
    let expected = [
        ("3-ups", 6),
        ("3-rps", 5),
        ("6-ups", 6),
        ("3-prrr", 4),
        ("3-rrr-spherical", 3),
        ("3-rrr-planar", 3),
    ];
    for (name, joints) in expected {
        let m = load(name);
        assert!(
            m.leg_warnings().is_empty(),
            "{name}: {:?}",
            m.leg_warnings()
        );
        for c in m.leg_checks() {
            assert_eq!(
                (c.joints, c.reference.rank, c.generic.rank),
                (joints, joints, joints),
                "{name} leg {}",
                c.leg + 1
            );
            // The decision has a clear gap: nothing near the relative tolerance 1e-9.
            assert!(c.reference.gap().0 > 1e-4, "{name}: {:?}", c.reference);
        }
    }
}

#[test]
fn a_planar_rrr_leg_with_collinear_joint_points_is_singular_at_the_reference() {
    // Hand-written files got no leg check before the trustworthy manipulator analysis. Three
    // revolutes along z through p1, p2 = (p1 + p3)/2, p3 have twists (z; p_i × z), linear in p_i:
    // column 2 is the mean of columns 1 and 3, rank 2, all three joints in the dependency. Turned
    // by any angle at the middle joint, p3 leaves the line and the rank is 3 (= joints: no
    // dependency everywhere).
    let m = edited("3-rrr-planar", collinear_planar).unwrap();
    let checks = m.leg_checks();
    assert_eq!(
        (
            checks[0].reference.rank,
            checks[0].generic.rank,
            checks[0].joints
        ),
        (2, 3, 3)
    );
    assert_eq!(checks[0].dependent_at_reference, vec![1, 2, 3]);
    let warnings: Vec<String> = m.leg_warnings().iter().map(ToString::to_string).collect();
    assert_eq!(
        warnings,
        vec![
            "leg 1 (RaRaRa) is singular at the reference configuration: its 3 joint twists have rank 2 there, 3 at generic joint values; joints 1, 2 and 3 dependent"
        ]
    );
}

#[test]
fn a_ups_leg_whose_u_turns_about_the_leg_has_dependent_joints_everywhere() {
    // Hand derivation: the U's second axis along the leg is the line through the U centre B and
    // the S centre G. Whatever the joint values, the first revolute carries that line, the slider
    // along it and G together, so the line still passes through G, and a rotation about a line
    // through G is a combination of the S's three revolutes: joints 2, 4, 5, 6 are dependent at
    // every configuration (the leg spins about itself), rank 5 of 6 both at the reference and
    // generically, so no singularity of the reference is claimed.
    let m = edited("3-ups", ups_with_spinning_leg).unwrap();
    let c = &m.leg_checks()[0];
    assert_eq!((c.reference.rank, c.generic.rank, c.joints), (5, 5, 6));
    let warnings: Vec<String> = m.leg_warnings().iter().map(ToString::to_string).collect();
    assert_eq!(
        warnings,
        vec![
            "leg 1 (UPS) has joints dependent at every configuration: its 6 joint twists have rank 5 at generic joint values; joints 2, 4, 5 and 6 dependent"
        ]
    );
}

#[test]
fn leg_checks_do_not_depend_on_the_length_unit_or_the_origin() {
    // Ranks are unit-free: the twists are made dimensionless with the leg's characteristic length,
    // so scaling every length by 10^k and moving the origin changes no rank and no warning.
    type Edit = fn(&mut serde_json::Value);
    let files: Vec<(&str, Edit)> = vec![
        ("3-rrr-planar", |_| {}),
        ("3-prrr", |_| {}),
        ("6-ups", |_| {}),
        ("3-rrr-spherical", |_| {}),
        ("3-rrr-planar", collinear_planar),
        ("3-ups", ups_with_spinning_leg),
    ];
    for (name, edit) in files {
        let base = edited(name, edit).unwrap();
        let summary = |m: &Manipulator| {
            let ranks: Vec<(usize, usize, usize)> = m
                .leg_checks()
                .iter()
                .map(|c| (c.reference.rank, c.generic.rank, c.joints))
                .collect();
            (ranks, m.leg_warnings())
        };
        let expected = summary(&base);
        for k in [-9, -5, -1, 2, 6, 9] {
            let s = 10f64.powi(k);
            let m = edited(name, |v| {
                edit(v);
                scaled(v, s, [3.0 * s, -7.0 * s, 0.5 * s]);
            })
            .unwrap();
            assert_eq!(summary(&m), expected, "{name} ×1e{k}");
        }
    }
}

#[test]
fn parallel_marks_are_checked_against_the_axes() {
    // `RaRaRa` says the three revolutes are parallel (docs/notation.md). Leg 1 of the planar 3-RRR
    // with its second axis along x instead of z contradicts it (90° apart).
    let e = edited("3-rrr-planar", |v| {
        v["legs"][0]["axes"][1] = serde_json::json!([1.0, 0.0, 0.0]);
    })
    .unwrap_err()
    .to_string();
    assert_eq!(
        e,
        "legs[0].axes[1]: marked 'a' in RaRaRa like axes[0], so the two must be parallel (a parallel group, docs/notation.md), but they are 90.000° apart"
    );
    // The third axis tilted by 1° about x: sin 1° = 0.017 ≫ 1e-6, named with its angle.
    let t = 1f64.to_radians();
    let e = edited("3-rrr-planar", |v| {
        v["legs"][2]["axes"][2] = serde_json::json!([0.0, -t.sin(), t.cos()]);
    })
    .unwrap_err()
    .to_string();
    assert!(
        e.starts_with("legs[2].axes[2]: marked 'a' in RaRaRa like axes[0]")
            && e.contains("1.000° apart"),
        "{e}"
    );
    // Opposite directions are parallel axes; unmarked revolutes may be parallel or not (the
    // notation asserts nothing about them: the committed 3-UPS has its U's first axis parallel
    // to its S's first, unmarked).
    edited("3-rrr-planar", |v| {
        v["legs"][0]["axes"][1] = serde_json::json!([0.0, 0.0, -1.0]);
    })
    .unwrap();
    let m = load("3-ups");
    let axis = |k: usize| m.mechanism().joints()[k].axis;
    assert!(axis(0).cross(&axis(3)).norm() < 1e-9);
    // Positions count primitive joints: in `PRaRaRa` the group starts at axes[1].
    let e = edited("3-prrr", |v| {
        v["legs"][1]["axes"][3] = serde_json::json!([0.0, 1.0, 0.0]);
    })
    .unwrap_err()
    .to_string();
    assert!(
        e.starts_with("legs[1].axes[3]: marked 'a' in PRaRaRa like axes[1]"),
        "{e}"
    );
}

#[test]
fn build_refuses_a_singular_leg_instead_of_claiming_turned_axes() {
    // Before the trustworthy manipulator analysis, `build --chain CRR --axes zzzz --actuated 1`
    // wrote "axes turned" with the axes unchanged. Hand derivation: z is the leg line, from the
    // base point (the C) to the platform point (the last R), so the C's revolute and the last
    // revolute are the same line: equal twists, joints 2 and 4 dependent, rank 3 of 4 at the
    // reference. At generic values the middle revolute moves the last axis off the C's (three
    // parallel revolutes through non-collinear points give ω_z and two translations, the slider the
    // third): rank 4. Turning revolutes about z axes leaves z axes z, so no turn can help: `build`
    // fails.
    use kinsyn::manipulator::build::{BuildSpec, build};
    let spec = |chain: &str, axes: &str| BuildSpec {
        chain: chain.into(),
        axes: Some(axes.into()),
        actuated: Some(vec![1]),
        ..Default::default()
    };
    // The library's typed error, worded with the CLI's option names (flag names are the front
    // end's, `BuildError::describe`).
    let cli = |e: kinsyn::manipulator::build::BuildError| {
        e.describe(|f| format!("--{}", f.name().replace('_', "-")))
    };
    let e = cli(build(&spec("CRR", "zzzz")).unwrap_err());
    assert_eq!(
        e,
        "--chain \"CRR\" --axes zzzz: leg 1 (CRR) is singular at the reference configuration: its 4 joint twists have rank 3 there, 4 at generic joint values; joints 2 and 4 dependent; turning its revolutes leaves these axis directions unchanged, so no file is written"
    );
    // Four parallel revolutes span at most ω_z and two translations: dependent everywhere.
    let e = cli(build(&spec("RRRR", "zzzz")).unwrap_err());
    assert!(
        e.contains("leg 1 (RRRR) has joints dependent at every configuration: its 4 joint twists have rank 3 at generic joint values; joints 1, 2, 3 and 4 dependent"),
        "{e}"
    );
    // Parallel marks are checked on the letters too.
    let e = cli(build(&spec("RaRaRa", "xyx")).unwrap_err());
    assert_eq!(
        e,
        "--axes \"xyx\": joints 1 and 2 of RaRaRa are in parallel group 'a' but get 'x' and 'y': the axes of a parallel group must be parallel"
    );
    // When turning does help, the claim is true. Catalogue PPRCR with axes xyxyyz: joints 2 and
    // 4 are both guides along y, twists (0; y), rank 5 at the reference; the R along x between
    // them turns the second guide away at generic values (rank 6). The turned file has that
    // guide no longer parallel to the first, and its legs are generic.
    let d = build(&spec("PPRCR", "xyxyyz")).unwrap();
    let source = d.source.clone().unwrap();
    assert!(
        source.contains("axes turned: with the directions of --axes the leg is singular at the reference (rank 5 there, 6 at generic joint values; joints 2 and 4 dependent)"),
        "{source}"
    );
    let m = Manipulator::new(&d).unwrap();
    assert!(m.leg_warnings().is_empty(), "{:?}", m.leg_warnings());
    for leg in m.legs() {
        let joints = &m.mechanism().joints()[leg.joints.clone()];
        assert!(joints[1].axis.cross(&joints[3].axis).norm() > 1e-3);
    }
    // A build that needs no turn says nothing about turning.
    let d = build(&spec("P!RaRaRa", "xxxx")).unwrap();
    assert!(!d.source.unwrap().contains("turned"));
}

#[test]
fn the_platform_twists_from_the_wrenches_are_those_of_the_loop_closure() {
    // One dof, one answer: the platform's twists are computed once, as the twists reciprocal to the
    // constraint rows of J_D. Second method: the platform's twists over the joint rates that close
    // every loop (the intersection of the legs' twist systems). The two spans must be the same
    // subspace, for every file of mechanisms/ and tests/library/, at the reference and along the
    // finite motion.
    let mut paths: Vec<std::path::PathBuf> = ["../../mechanisms", "tests/library"]
        .iter()
        .flat_map(|d| std::fs::read_dir(d).unwrap().map(|e| e.unwrap().path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    for path in paths {
        let m = Manipulator::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let settings = SampleSettings::default();
        let walked = m
            .mechanism()
            .sample_motion(m.platform(), &m.reference(), &[], &settings)
            .unwrap()
            .samples;
        for q in std::iter::once(m.reference()).chain(walked.into_iter().map(|s| s.q)) {
            let (from_wrenches, _) = m.platform_twists(&q, &[]);
            let (by_closure, dof) = m.mechanism().twist_space(m.platform(), &q, &[]);
            assert_eq!(from_wrenches.ncols(), dof, "{}", path.display());
            // (ω; v at the origin) to (v_P; ω), dimensionless with the mechanism's length.
            let p = m.point(&q);
            let l = m.mechanism().scale();
            let to_p = |t: &DMatrix<f64>| {
                DMatrix::from_fn(6, t.ncols(), |r, c| {
                    let w = Vector3::new(t[(0, c)], t[(1, c)], t[(2, c)]);
                    let v = Vector3::new(t[(3, c)], t[(4, c)], t[(5, c)]) + w.cross(&p);
                    [v.x / l, v.y / l, v.z / l, w.x, w.y, w.z][r]
                })
            };
            let a = kinsyn::screw::span_basis(&to_p(&by_closure), 1e-9).0;
            let mut b = from_wrenches.clone();
            for r in 0..3 {
                b.row_mut(r).scale_mut(1.0 / l);
            }
            let b = kinsyn::screw::span_basis(&b, 1e-9).0;
            assert!(
                kinsyn::motion::same_span(&a, &b, 1e-7),
                "{}: twist spaces differ",
                path.display()
            );
        }
    }
}

// ---- Modes from any start, of chosen lock subsets, with progress ----

#[test]
fn lock_subsets_are_the_binomial_sums_in_order() {
    // Σ_{k≤K} C(6, k) for the six inputs of the 3-UPS: 1, 7, 22, 42, 57, 63, 64; K ≥ n is all
    // 2^6 subsets.
    let m = load("3-ups");
    let sums = [1, 7, 22, 42, 57, 63, 64];
    for (k, &sum) in sums.iter().enumerate() {
        assert_eq!(m.lock_subset_count(k), sum, "k = {k}");
        let subsets = m.lock_subsets(k);
        assert_eq!(subsets.len() as u128, sum, "k = {k}");
        // By number of locks, then lexicographically; each sorted, all distinct.
        for pair in subsets.windows(2) {
            assert!(
                (pair[0].len(), &pair[0]) < (pair[1].len(), &pair[1]),
                "{pair:?}"
            );
        }
        assert!(subsets.iter().all(|s| s.windows(2).all(|w| w[0] < w[1])));
    }
    assert_eq!(m.lock_subset_count(100), 64);
}

#[test]
fn modes_from_the_reference_agree_with_modes_subset_by_subset() {
    // The subsets of at most one lock, sampled on their own, give exactly the modes of the full
    // run (each subset's seed comes from the subset alone), and progress is told once per subset.
    use std::sync::atomic::{AtomicUsize, Ordering};
    let m = load("3-ups");
    let settings = SampleSettings::default();
    let full = m.modes(&settings).unwrap();
    let finished = AtomicUsize::new(0);
    let short = m.modes_from(&m.reference(), &m.lock_subsets(1), &settings, &|| {
        finished.fetch_add(1, Ordering::Relaxed);
    });
    assert_eq!(finished.into_inner(), 7);
    assert_eq!(short.modes.len(), 7);
    for mode in &short.modes {
        let same = full.modes.iter().find(|f| f.locked == mode.locked).unwrap();
        assert_eq!(mode, same);
    }
    // The patterns among them: D by no lock, 2T3R by any one lock (6 subsets, all minimal).
    assert_eq!(short.groups.len(), 1);
    assert_eq!(
        (
            short.groups[0].pattern.to_string().as_str(),
            short.groups[0].subsets
        ),
        ("D", 1)
    );
    assert_eq!(short.non_groups.len(), 1);
    let one = &short.non_groups[0];
    assert_eq!(
        (one.pattern.to_string().as_str(), one.dof, one.subsets),
        ("2T3R", 5, 6)
    );
    assert_eq!(one.lock_sets.len(), 6);
}

#[test]
fn modes_from_a_displaced_pose_hold_the_locks_at_their_values_there() {
    // The 6-UPS with its platform frame at (0.1, 0.05, 1.1) m, turned by (5°, −3°, 10°): every
    // slider has another length than at the reference. Locking all six there leaves no motion
    // (E), locking none the whole of D, locking one a 5-dof motion; and the sampled
    // configurations keep each locked slider at its value at that pose, not at the reference.
    let m = load("6-ups");
    let position = Vector3::new(0.1, 0.05, 1.1);
    let orientation = Vector3::new(5.0_f64, -3.0, 10.0).map(f64::to_radians);
    let start = m.assemble_at(position, orientation, &[]).unwrap();
    let all: Vec<usize> = (0..6).collect();
    let settings = SampleSettings::default();
    let modes = m.modes_from(&start, &[vec![], vec![0], all.clone()], &settings, &|| {});
    let summary: Vec<(usize, String)> = modes
        .modes
        .iter()
        .map(|md| (md.dof, md.pattern_text()))
        .collect();
    let summary: Vec<(usize, &str)> = summary.iter().map(|(d, p)| (*d, p.as_str())).collect();
    assert_eq!(summary, [(6, "D"), (5, "2T3R"), (0, "E")]);
    for (got, want) in modes.start_position.iter().zip(position.iter()) {
        assert!((got - want).abs() < 1e-9, "{:?}", modes.start_position);
    }
    for (got, want) in modes
        .start_rotation_vector_rad
        .iter()
        .zip(orientation.iter())
    {
        assert!((got - want).abs() < 1e-9);
    }
    let slider = m.actuators()[0].joint;
    assert!((start[slider] - m.reference()[slider]).abs() > 1e-3);
    let samples = m
        .mechanism()
        .sample_motion(m.platform(), &start, &m.lock_mask(&[0]), &settings)
        .unwrap()
        .samples;
    for s in &samples {
        assert!((s.q[slider] - start[slider]).abs() < 1e-12);
    }
}

/// Found by fuzzing (fuzz target `description`, reproducer
/// `fuzz/corpus/description/repro-float-roundtrip.json`): a point written
/// `-0.103333355607461616` was read one unit in the last place away from the nearest double
/// (`serde_json`'s default, best-effort float parsing), and so was the shortest text of some
/// doubles (`-0.10333333333333336`): a description written by `Description::to_json` did not
/// read back to itself. Numbers must be read correctly rounded.
#[test]
#[expect(
    clippy::float_cmp,
    reason = "the point of the test: a number is read bit for bit as Rust parses it"
)]
fn a_description_reads_its_numbers_exactly_and_its_own_json_back() {
    use kinsyn::manipulator::file::Description;
    let committed = std::fs::read_to_string("../../mechanisms/3-rps.json").unwrap();
    for text in [
        "-0.103333355607461616",
        "-0.10333333333333336",
        "1.2345678901234567e-300",
    ] {
        let edited = committed.replacen(
            "\"point\": [0.0, 0.0, 0.0]",
            &format!("\"point\": [{text}, 0.0, 0.0]"),
            1,
        );
        assert_ne!(edited, committed);
        let d = Description::from_json(&edited).unwrap();
        assert_eq!(d.platform.point[0], text.parse::<f64>().unwrap(), "{text}");
        let again = Description::from_json(&d.to_json()).unwrap();
        assert_eq!(again, d, "{text}");
        assert_eq!(again.to_json(), d.to_json(), "{text}");
    }
}

// ---- Catalogue ids resolved through a lookup, not by synthesis ----

#[test]
fn the_committed_lookup_gives_every_synthesised_entry() {
    // Manipulator::new resolves ids in the compiled-in catalogue (CommittedChains) instead of
    // generating it; both must give, for every entry's id and notation, the same entry,
    // notation and axis word as Catalogue::generate with the default options (verified: the
    // axis word is the reading verification kept, which for T1-055 and others is not the
    // first one enumerated).
    use kinsyn::catalogue::Catalogue;
    use kinsyn::manipulator::{ChainLookup, CommittedChains};
    use kinsyn::published::PrintedTables;
    use kinsyn::synthesis::Options;
    let synthesised = Catalogue::generate(&Options::default(), &PrintedTables::default());
    let committed = CommittedChains::get();
    assert!(!synthesised.entries.is_empty());
    for e in &synthesised.entries {
        for query in [e.id.as_str(), &e.id.to_lowercase(), &e.notation] {
            assert_eq!(committed.chain(query), synthesised.chain(query), "{query}");
        }
        let found = committed.chain(&e.id).unwrap();
        assert_eq!(
            (found.notation, found.axes),
            (e.notation.as_str(), e.axes.as_str())
        );
    }
    assert_eq!(committed.chain("T9-999"), None);
    assert_eq!(committed.chain("not a chain"), None);
}

#[test]
fn a_catalogue_id_builds_the_same_manipulator_as_the_synthesised_catalogue() {
    // A 3-leg description whose legs are catalogue ids with the catalogue's axes (docs/
    // mechanism-format.md: `chain` may be an id, `axes` left out): Manipulator::new (committed
    // lookup) and Manipulator::new_with the synthesised catalogue give the same legs, joints
    // (kind, axis, point, bodies) and inputs.
    use kinsyn::catalogue::Catalogue;
    use kinsyn::manipulator::file::Description;
    use kinsyn::published::PrintedTables;
    use kinsyn::synthesis::Options;
    let text = r#"{
      "format": "kinsyn-manipulator/1",
      "name": "3-T4-034",
      "units": {"length": "m", "angle": "deg"},
      "platform": {"position": [0.0, 0.0, 1.0], "orientation": [0.0, 0.0, 0.0], "point": [0.0, 0.0, 0.0]},
      "legs": [
        {"chain": "T4-034", "base": [1.0, 0.0, 0.0], "platform": [0.5, 0.0, 0.0], "actuated": [1]},
        {"chain": "t4-034", "base": [-0.5, 0.866, 0.0], "platform": [-0.25, 0.433, 0.0], "actuated": [1]},
        {"chain": "T1-001", "base": [-0.5, -0.866, 0.0], "platform": [-0.25, -0.433, 0.0], "actuated": [1]}
      ]
    }"#;
    let d = Description::from_json(text).unwrap();
    let by_default = Manipulator::new(&d).unwrap();
    let synthesised = Catalogue::synthesise(&Options::default(), &PrintedTables::default());
    let by_synthesis = Manipulator::new_with(&d, &synthesised).unwrap();
    assert_eq!(by_default.legs(), by_synthesis.legs());
    assert_eq!(by_default.actuators(), by_synthesis.actuators());
    assert_eq!(
        by_default.mechanism().joints(),
        by_synthesis.mechanism().joints()
    );
    assert_eq!(
        by_default.legs()[0].chain.to_string(),
        synthesised.find("T4-034").unwrap().notation
    );
    // An unknown id is refused the same way by both.
    let bad = Description::from_json(&text.replace("T1-001", "T9-999")).unwrap();
    let (a, b) = (
        Manipulator::new(&bad).unwrap_err().to_string(),
        Manipulator::new_with(&bad, &synthesised)
            .unwrap_err()
            .to_string(),
    );
    assert_eq!(a, b);
    assert!(a.contains("legs[2].chain") && a.contains("T9-999"), "{a}");
}

/// The library's build errors name the spec's fields (`base_radius`), never the CLI's options
/// (`--base-radius`); the CLI words them with its options through `BuildError::describe`
/// (`tests/suite/cli_manipulator.rs` checks those texts).
#[test]
fn build_errors_name_spec_fields_not_cli_options() {
    use kinsyn::manipulator::build::{BuildField, BuildSpec, build};
    let good = || BuildSpec {
        chain: "RP!S".into(),
        axes: Some("yxxyz".into()),
        ..Default::default()
    };
    let cases: Vec<(BuildSpec, Vec<BuildField>)> = vec![
        (BuildSpec { legs: 2, ..good() }, vec![BuildField::Legs]),
        (
            BuildSpec {
                base_radius: -1.0,
                ..good()
            },
            vec![BuildField::BaseRadius],
        ),
        (
            BuildSpec {
                height: 1e-300,
                ..good()
            },
            vec![BuildField::Height],
        ),
        (
            BuildSpec {
                platform_radius: 1e9,
                ..good()
            },
            vec![
                BuildField::BaseRadius,
                BuildField::PlatformRadius,
                BuildField::Height,
            ],
        ),
        (
            BuildSpec {
                twist: 400.0,
                ..good()
            },
            vec![BuildField::Twist],
        ),
        (
            BuildSpec {
                chain: "RPX".into(),
                ..good()
            },
            vec![BuildField::Chain],
        ),
        (
            BuildSpec {
                axes: None,
                ..good()
            },
            vec![BuildField::Axes],
        ),
        (
            BuildSpec {
                axes: Some("xy".into()),
                ..good()
            },
            vec![BuildField::Axes],
        ),
        (
            BuildSpec {
                actuated: Some(vec![9]),
                ..good()
            },
            vec![BuildField::Actuated],
        ),
        (
            BuildSpec {
                chain: "RPS".into(),
                ..good()
            },
            vec![BuildField::Actuated],
        ),
    ];
    for (spec, fields) in cases {
        let e = build(&spec).expect_err("a bad spec");
        let text = e.to_string();
        assert!(!text.contains("--"), "{text}");
        assert_eq!(e.fields(), fields, "{text}");
        for f in &fields {
            assert!(
                text.contains(f.name()) || matches!(f, BuildField::Chain),
                "{text} names {}",
                f.name()
            );
        }
    }
}
