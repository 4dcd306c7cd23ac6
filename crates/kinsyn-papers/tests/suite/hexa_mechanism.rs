//! Paper 001's HEXA on the general mechanism graph:
//! `mechanisms/6-ruu-hexa.json` as `Hexa::description` writes it, read back into the paper's
//! dimensions; §2's displacement groups by the general machinery (mobility, motion patterns of
//! whole and cut-down mechanisms); the inverse geometry by the general assembly solver against
//! eq. 5; the loop-closure Jacobian's null space against eqs. 9–11 (`A χ̇ = B θ̇` as printed,
//! with `θ` about `+u_i`); and `ξ`
//! (eq. 17 as redefined in `hexa/transmission.rs`) by a locked mechanism's one motion.
//!
//! Regenerate the committed file with `KINSYN_BLESS=1 cargo test -p kinsyn-papers --test suite hexa_mechanism::`.

use kinsyn::manipulator::file::MultibodyDescription;
use kinsyn::manipulator::{Manipulator, parse_leg_list};
use kinsyn::mechanism::{Goal, SampleSettings};
use kinsyn::motion::{GroupKind, Pattern};
use kinsyn::spatial::{Displacement, displacement};
use kinsyn_papers::hexa::{Hexa, Pose, mu, rz};
use nalgebra::{DVector, Rotation3, Vector3};

const FILE: &str = "../../mechanisms/6-ruu-hexa.json";

/// The rods' half-width `h` (mm): a modelling choice; the parallelogram's motion does not
/// depend on it (any `h > 0`).
const HALF_WIDTH: f64 = 30.0;

/// A pose whose `P2` is on the four-bar: end-effector 1 at `(p1, φ1)`, the crank at `C3` turned
/// by `dα` (rad) from the nominal symmetric assembly, the rocker angle `β` of eq. 7a nearest the
/// nominal one, end-effector 2 turned by `φ2`. Angles in degrees but `dα`.
fn pose_on_four_bar(p1: [f64; 3], phi1_deg: f64, d_alpha: f64, phi2_deg: f64) -> Pose {
    let h = Hexa::paper001();
    let p1 = Vector3::from(p1);
    let phi1 = phi1_deg.to_radians();
    let fb = h.four_bar(&p1, phi1);
    let nominal = h.nominal_four_bar(&p1, phi1).unwrap();
    let alpha = nominal.alpha + d_alpha;
    let betas = h.rocker_angles(&fb, alpha).unwrap();
    let beta = if (betas[0] - nominal.beta).abs() <= (betas[1] - nominal.beta).abs() {
        betas[0]
    } else {
        betas[1]
    };
    let f = h.four_bar_pose(&fb, alpha, beta);
    Pose::new(&p1, phi1, &f.p2, phi2_deg.to_radians())
}

/// The file's reference: generic (the mirror-symmetric pose is a singularity of end-effector 2,
/// `ξ = 0`): P1 = (30, −20, −600) mm, φ1 = 10°, the crank 0.2 rad before the nominal assembly,
/// φ2 = −5°.
const REFERENCE: ([f64; 3], f64, f64, f64) = ([30.0, -20.0, -600.0], 10.0, -0.2, -5.0);

fn reference() -> Pose {
    let (p, a, d, b) = REFERENCE;
    pose_on_four_bar(p, a, d, b)
}

fn description() -> MultibodyDescription {
    MultibodyDescription::from_json(&std::fs::read_to_string(FILE).unwrap()).unwrap()
}

fn hexa_mechanism() -> Manipulator {
    Manipulator::from_bodies(&description()).unwrap()
}

fn body(m: &Manipulator, name: &str) -> usize {
    m.body_named(name).unwrap()
}

#[test]
fn the_committed_file_is_what_the_generator_writes() {
    let written = Hexa::paper001()
        .description(&reference(), HALF_WIDTH)
        .unwrap()
        .to_json();
    if std::env::var_os("KINSYN_BLESS").is_some() {
        std::fs::write(FILE, &written).unwrap();
    }
    let committed = std::fs::read_to_string(FILE).unwrap();
    assert!(
        committed == written,
        "{FILE} differs from Hexa::description; regenerate it with KINSYN_BLESS=1 cargo test -p kinsyn-papers --test suite hexa_mechanism::"
    );
}

#[test]
fn the_file_reads_back_into_paper_001s_dimensions() {
    let d = description();
    let file = Hexa::read_description(&d).unwrap();
    // §4: R = 200, a = 60, b = 260, l = 550, r1..r5 = 60 mm; γ = π/6 (Hexa::paper001's choice).
    let h = file.hexa;
    let expected = [200.0, 60.0, 260.0, 550.0, 60.0, 60.0, 60.0, 60.0, 60.0];
    let got = [
        h.big_r, h.a, h.b, h.l, h.r[0], h.r[1], h.r[2], h.r[3], h.r[4],
    ];
    for (g, e) in got.iter().zip(expected) {
        assert!((g - e).abs() < 1e-9, "{got:?}");
    }
    assert!((h.gamma - std::f64::consts::FRAC_PI_6).abs() < 1e-12);
    assert!((file.half_width - HALF_WIDTH).abs() < 1e-12);
    let reference = reference();
    for k in 0..7 {
        assert!(
            (file.reference.chi[k] - reference.chi[k]).abs() < 1e-9,
            "{:?}",
            file.reference
        );
    }
    assert_eq!(Hexa::from_description(&d).unwrap(), h);
    assert!(d.source.as_deref().unwrap().contains("paper 001"));

    // A moved point is named; another mechanism is refused; each error is one line.
    let mut moved = d.clone();
    moved.legs[13].first[1] += 0.5;
    let e = Hexa::from_description(&moved).unwrap_err().to_string();
    assert!(e.contains("legs[13].first[1]"), "{e}");
    // A HEXA with a longer parallelogram: the dimensions read from A_1, B_1, C_1 disagree with
    // the other limbs.
    let mut longer = d.clone();
    longer.bodies[1].position[2] -= 10.0;
    let e = Hexa::from_description(&longer).unwrap_err().to_string();
    assert!(e.starts_with("not a 6-RUU HEXA description"), "{e}");
    let split = MultibodyDescription::from_json(
        &std::fs::read_to_string("../../mechanisms/multibody/3-rps-split.json").unwrap(),
    )
    .unwrap();
    let e = Hexa::from_description(&split).unwrap_err().to_string();
    assert!(
        e.contains("2 moving bodies and 4 legs, where the HEXA has 21 and 33"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1);
    // A reference out of reach is an error, not a panic.
    let far = Pose::new(
        &Vector3::new(0.0, 0.0, -900.0),
        0.0,
        &Vector3::new(0.0, -60.0, -900.0),
        0.0,
    );
    assert!(Hexa::paper001().description(&far, HALF_WIDTH).is_err());
    assert!(Hexa::paper001().description(&reference, 0.0).is_err());
}

#[test]
fn the_limits_admit_the_hexa_and_refuse_beyond_24_bodies_48_legs_72_joints() {
    // The HEXA: 21 moving bodies, 33 legs, 6·7 + 9 = 51 primitive joints.
    let m = hexa_mechanism();
    assert_eq!((m.bodies().len(), m.legs().len()), (21, 33));
    assert_eq!(m.mechanism().joints().len(), 51);
    let split = || {
        MultibodyDescription::from_json(
            &std::fs::read_to_string("../../mechanisms/multibody/3-rps-split.json").unwrap(),
        )
        .unwrap()
    };
    // 25 moving bodies (each joined to the ground by an R).
    let mut d = split();
    for k in 0..23 {
        let mut b = d.bodies[0].clone();
        b.name = format!("extra{k}");
        d.bodies.push(b);
    }
    let e = Manipulator::from_bodies(&d).unwrap_err().to_string();
    assert_eq!(
        e, "bodies: 25 moving bodies: at most 24 (docs/limits.md)",
        "{e}"
    );
    // 49 legs.
    let mut d = split();
    while d.legs.len() < 49 {
        d.legs.push(d.legs[3].clone());
    }
    let e = Manipulator::from_bodies(&d).unwrap_err().to_string();
    assert_eq!(e, "legs: 49 legs: at most 48 (docs/limits.md)", "{e}");
    // 48 legs are accepted: 3 RPS legs (15 joints) and 45 revolutes = 60 joints.
    d.legs.pop();
    assert!(Manipulator::from_bodies(&d).is_ok());
    // 15 RPS legs: 75 primitive joints.
    let mut d = split();
    d.legs.truncate(3);
    while d.legs.len() < 15 {
        d.legs.push(d.legs[0].clone());
    }
    let e = Manipulator::from_bodies(&d).unwrap_err().to_string();
    assert!(
        e.starts_with("legs: 75 primitive joints in all: at most 72"),
        "{e}"
    );
}

/// The motion pattern of `name` in the sub-mechanism of the 1-based `legs`, at the reference,
/// every input free, and its dof.
fn pattern(legs: &str, name: &str) -> (usize, Pattern) {
    let d = description();
    let kept = d
        .with_legs(&parse_leg_list(legs, d.legs.len()).unwrap(), Some(name))
        .unwrap();
    let m = Manipulator::from_bodies(&kept).unwrap();
    let mode = m.mode(&[], &SampleSettings::default());
    assert!(mode.error.is_none(), "{legs} {name}: {:?}", mode.error);
    (mode.dof, mode.classification.unwrap().pattern)
}

/// Asserts a 4-dof Schönflies group `X(u)`.
fn assert_schoenflies(found: (usize, Pattern), u: &Vector3<f64>, what: &str) {
    let (dof, pattern) = found;
    let Pattern::Group(g) = pattern else {
        panic!("{what}: {pattern:?}, not X({u})")
    };
    assert_eq!((dof, g.kind), (4, GroupKind::X), "{what}");
    let direction = Vector3::from(g.direction.unwrap());
    assert!(
        direction.cross(u).norm() < 1e-6,
        "{what}: {direction} vs {u}"
    );
}

#[test]
fn section_2s_displacement_groups_by_the_general_machinery() {
    let m = hexa_mechanism();
    let q = m.reference();
    // Mobility by hand: the seven coordinates χ of eq. 10a less the four-bar's one equation
    // (eq. 7a: P2 on the coupler curve), with no idle freedom (every limb's four joints map
    // one-to-one onto X(u_i); the four-bar is fixed by its ground pivots and P2): 7 − 1 = 6.
    assert_eq!(m.mechanism().mobility(&q, &[]).dof, 6);
    // Eqs. 2–3: both end-effectors X(k), 4 dof, in the whole mechanism.
    let k = Vector3::z();
    for ee in ["ee1", "ee2"] {
        let m = m.with_end_effector(ee).unwrap();
        let mode = m.mode(&[], &SampleSettings::default());
        let Some(Pattern::Group(g)) = mode.classification.map(|c| c.pattern) else {
            panic!("{ee}: {:?}", mode.error)
        };
        assert_eq!((mode.dof, g.kind), (4, GroupKind::X), "{ee}");
        assert!(Vector3::from(g.direction.unwrap()).cross(&k).norm() < 1e-6);
    }
    // Eq. 1: each limb alone, L_i = R(A_i) R(B_i) T(n_i) R(C_i) = X(u_i), u_i = R_z(μ_i) i, is
    // the motion of the body after R(C_i): the sub-platform for limbs 1, 2, 3, 6. The lower
    // bar, before R(C_i), has R(A_i) R(B_i) T(n_i): three joints, one rotation (about u_i), so
    // 3 dof, two translations and one rotation, not a group (the circular translation T(n_i)
    // is not a subgroup). For limbs 4 and 5 the body after R(C_i) is the wrist.
    for i in 0..6 {
        let legs = format!("{}-{}", 4 * i + 1, 4 * i + 4);
        let u = rz(mu(i)) * Vector3::x();
        let what = format!("limb {}", i + 1);
        let (dof, lower) = pattern(&legs, &format!("lower{}", i + 1));
        assert_eq!(
            (dof, lower),
            (
                3,
                Pattern::NonGroup {
                    translations: 2,
                    rotations: 1
                }
            ),
            "{what}"
        );
        let platform = ["sub16", "sub23", "sub23", "wrist4", "wrist5", "sub16"][i];
        assert_schoenflies(pattern(&legs, platform), &u, &what);
    }
    // Eq. 2: limbs 1 and 6 with the revolute sub16 → ee1: X(u1) ∩ X(u6) = T3 for the
    // sub-platform, and T3 · R(N, k) = X(k) for end-effector 1.
    let (dof, sub16) = pattern("1-4,21-25", "sub16");
    assert!(matches!(sub16, Pattern::Group(g) if g.kind == GroupKind::T3) && dof == 3);
    assert_schoenflies(pattern("1-4,21-25", "ee1"), &k, "eq. 2");
    // Eq. 3 (L45 = T·S(N) printed): with limbs 4 and 5 alone, end-effector 2 is in
    // X(u4)·R(k) ∩ X(u5)·R(k); its rotations R_u4(a)R_k(b) = R_u5(c)R_k(d) near the identity
    // are the turns about k only (the tangent planes {u4, k} and {u5, k} meet along k, one
    // branch through the identity), so the loop A4–B4–C4–C5–B5–A5 gives X(k), 4 dof, not the
    // six of T·S(N).
    assert_schoenflies(pattern("13-20,32-33", "ee2"), &k, "eq. 3");
    // Eq. 3 read as printed: L45 is the bond of the closed loop A4–B4–C4–C5–B5–A5, the set of
    // displacements its chain, cut at A5, can make. The chain has F = 10 freedoms (per limb
    // R(A), R(B), the parallelogram's T, R(C) and the turn about k), and the loop's mobility is
    // M = F − dim L45 (Chebychev–Grübler–Kutzbach over the loop's bond). The general machinery
    // gives M = 4 (end-effector 2's X(k), no idle motion), so dim L45 = 6: the whole
    // displacement group D = T·S(N), as printed. The paper's intersection
    // X(k)·G(k) ∩ T·S(N) = X(k) then holds trivially.
    let d = description();
    let kept = d
        .with_legs(
            &parse_leg_list("13-20,32-33", d.legs.len()).unwrap(),
            Some("ee2"),
        )
        .unwrap();
    let loop45 = Manipulator::from_bodies(&kept).unwrap();
    let q45 = loop45.reference();
    assert_eq!(loop45.mechanism().mobility(&q45, &[]).dof, 4);
}

/// The frame of a body at a pose: origin and turn about `k`.
fn frame(origin: &Vector3<f64>, turn: f64) -> Displacement {
    displacement(
        Rotation3::from_axis_angle(&Vector3::z_axis(), turn),
        *origin,
    )
}

/// The mechanism assembled with both end-effectors at `pose` by the general solver, by
/// continuation from the reference in `steps` steps along the four-bar parameters.
fn assemble(m: &Manipulator, target: ([f64; 3], f64, f64, f64), steps: usize) -> (Vec<f64>, Pose) {
    let (ee1, ee2) = (body(m, "ee1"), body(m, "ee2"));
    let (p0, a0, d0, b0) = REFERENCE;
    let mut q = m.reference();
    let mut pose = reference();
    for s in 1..=steps {
        let t = s as f64 / steps as f64;
        let mix = |x: f64, y: f64| x + (y - x) * t;
        let p = [0, 1, 2].map(|k| mix(p0[k], target.0[k]));
        pose = pose_on_four_bar(p, mix(a0, target.1), mix(d0, target.2), mix(b0, target.3));
        let goal = |k: usize, origin: Vector3<f64>, turn: f64| Goal::Pose {
            body: m.bodies()[k].body,
            displacement: frame(&origin, turn) * m.bodies()[k].frame.inverse(),
        };
        let goal = Goal::All(vec![
            goal(ee1, pose.p1(), pose.phi1()),
            goal(ee2, pose.p2(), pose.phi2()),
        ]);
        q = m.mechanism().assemble_to(&q, &[], Some(&goal)).unwrap();
    }
    (q, pose)
}

/// Generic poses with P2 on the four-bar (reachable; checked not to be near a singularity of
/// end-effector 2).
const POSES: [([f64; 3], f64, f64, f64); 4] = [
    ([50.0, -40.0, -580.0], 15.0, -0.25, 0.0),
    ([10.0, 10.0, -620.0], 5.0, -0.15, -10.0),
    ([-20.0, 0.0, -590.0], 0.0, -0.3, 8.0),
    ([40.0, -30.0, -610.0], 20.0, 0.08, -12.0),
];

/// `θ_i` in the sense of [`Hexa::link_direction`] at joint values `q`: the reference angle
/// plus the actuated joint's value (its file axis is `+u_i`, and θ turns `v_i` about `+u_i`).
fn thetas(m: &Manipulator, q: &[f64]) -> [f64; 6] {
    let h = Hexa::paper001();
    let reference = h.inverse(&reference()).unwrap();
    std::array::from_fn(|i| reference.limbs[i].theta + q[m.actuators()[i].joint])
}

fn wrap(x: f64) -> f64 {
    (x + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
}

#[test]
fn the_general_solver_gives_eq_5s_working_mode() {
    let m = hexa_mechanism();
    let h = Hexa::paper001();
    // The actuated joints are the first joint of legs 1, 5, 9, …: limb i's R(A_i).
    let labels: Vec<String> = m
        .actuators()
        .iter()
        .map(kinsyn::manipulator::Actuator::label)
        .collect();
    assert_eq!(labels, ["R1.1", "R5.1", "R9.1", "R13.1", "R17.1", "R21.1"]);
    for target in POSES {
        let (q, pose) = assemble(&m, target, 4);
        let conf = h.inverse(&pose).unwrap();
        assert!(
            h.indices(&conf).xi_min() > 0.05,
            "{target:?}: near a singularity"
        );
        let theta = thetas(&m, &q);
        for (i, theta) in theta.iter().enumerate() {
            assert!(
                wrap(theta - conf.limbs[i].theta).abs() < 1e-8,
                "{target:?} limb {}: {} vs {}",
                i + 1,
                theta,
                conf.limbs[i].theta
            );
            // The limb closes (eq. 4) and its ends are eq. 6b's c_i and the b_i of θ_i.
            let b = m
                .body_frame(body(&m, &format!("upper{}", i + 1)), &q)
                .translation
                .vector;
            let c = m
                .body_frame(body(&m, &format!("lower{}", i + 1)), &q)
                .translation
                .vector;
            assert!(((c - b).norm() - h.l).abs() < 1e-9, "limb {}", i + 1);
            assert!((c - conf.joints[i]).norm() < 1e-8, "c_{}", i + 1);
            assert!((b - conf.limbs[i].b).norm() < 1e-8, "b_{}", i + 1);
        }
    }
}

/// The rates of every joint from a column of [`kinsyn::mechanism::Mobility::rates`] (free
/// joints only), the locked ones at zero.
fn all_rates(m: &Manipulator, locked: &[usize], free_rates: &DVector<f64>) -> DVector<f64> {
    let mask = m.lock_mask(locked);
    let mut out = DVector::zeros(mask.len());
    let mut k = 0;
    for (j, &held) in mask.iter().enumerate() {
        if !held {
            out[j] = free_rates[k];
            k += 1;
        }
    }
    out
}

/// The velocity of the point `p` of body `name` under the joint rates `rates`.
fn point_velocity(
    m: &Manipulator,
    q: &[f64],
    name: &str,
    p: &Vector3<f64>,
    rates: &DVector<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    let screws = m.mechanism().joint_screws(q);
    let twist = m
        .mechanism()
        .body_jacobian(m.bodies()[body(m, name)].body, &screws)
        * rates;
    let w = Vector3::new(twist[0], twist[1], twist[2]);
    let v = Vector3::new(twist[3], twist[4], twist[5]);
    (v + w.cross(p), w)
}

#[test]
fn the_closure_jacobians_null_space_satisfies_eqs_9_to_11() {
    let m = hexa_mechanism();
    let h = Hexa::paper001();
    for target in POSES {
        let (q, pose) = assemble(&m, target, 4);
        let conf = h.inverse(&pose).unwrap();
        let (a, b) = h.jacobians(&conf);
        let rates = m.mechanism().mobility(&q, &[]).rates;
        assert_eq!(rates.ncols(), 6);
        for k in 0..rates.ncols() {
            let r = rates.column(k).into_owned();
            let (p1_rate, w1) = point_velocity(&m, &q, "ee1", &pose.p1(), &r);
            let (p2_rate, w2) = point_velocity(&m, &q, "ee2", &pose.p2(), &r);
            // Both end-effectors keep z and turn about k only (eqs. 2–3).
            assert!(w1.xy().norm() < 1e-9 && w2.xy().norm() < 1e-9);
            assert!((p1_rate.z - p2_rate.z).abs() < 1e-9 * p1_rate.norm().max(1.0));
            let chi = DVector::from_vec(vec![
                p1_rate.x, p1_rate.y, p1_rate.z, w1.z, p2_rate.x, p2_rate.y, w2.z,
            ]);
            // θ̇ about +u_i (kinsyn_papers::hexa's convention, the file's actuated axis) is the joint
            // rate, and eq. 9 holds as printed: A χ̇ = B θ̇ (ḃ_i = b θ̇_i u_i × v_i).
            let theta = DVector::from_fn(6, |i, _| r[m.actuators()[i].joint]);
            let lhs = &a * &chi;
            let rhs = &b * &theta;
            let size = (a.norm() * chi.norm()).max(b.norm() * theta.norm());
            assert!(
                (&lhs - &rhs).norm() < 1e-8 * size,
                "{target:?}: {lhs} vs {rhs}"
            );
            // The other sign fails unless both sides vanish.
            if lhs.norm() > 1e-6 * size {
                assert!((&lhs + &rhs).norm() > 1e-3 * size);
            }
        }
    }
}

#[test]
fn xi_is_the_pressure_angle_of_the_locked_mechanisms_one_motion() {
    let m = hexa_mechanism();
    let h = Hexa::paper001();
    for target in POSES {
        let (q, pose) = assemble(&m, target, 4);
        let conf = h.inverse(&pose).unwrap();
        let xi = h.indices(&conf).xi;
        // Inputs 1, 2, 3, 6 hold end-effector 1; with input 5 (or 4) locked too, limb 4 (or 5)
        // drives end-effector 2 along one motion.
        for (k, other) in [(3usize, 4usize), (4, 3)] {
            let locked = [0, 1, 2, 5, other];
            let mobility = m.mechanism().mobility(&q, &m.lock_mask(&locked));
            assert_eq!(mobility.dof, 1, "{target:?}");
            let r = all_rates(&m, &locked, &mobility.rates.column(0).into_owned());
            let c = conf.joints[k];
            let (c_rate, _) = point_velocity(&m, &q, &format!("lower{}", k + 1), &c, &r);
            let w = conf.limbs[k].w;
            let cosine = w.dot(&c_rate).abs() / (w.norm() * c_rate.norm());
            assert!(
                (cosine - xi[k - 3]).abs() < 1e-8,
                "{target:?} ξ_{}: {cosine} vs {}",
                k + 1,
                xi[k - 3]
            );
        }
        // Generic: all six inputs locked leave nothing.
        let all: Vec<usize> = (0..6).collect();
        assert_eq!(m.mechanism().mobility(&q, &m.lock_mask(&all)).dof, 0);
    }
    // The mirror-symmetric pose (x1 = 0, φ1 = φ2 = 0, the nominal P2): end-effector 2 is
    // singular (ξ = 0, rows 4 and 5 of its Jacobian opposite), and the six locked inputs leave
    // it one motion.
    let (q, pose) = assemble(&m, ([0.0, 0.0, -600.0], 0.0, 0.0, 0.0), 4);
    let conf = h.inverse(&pose).unwrap();
    assert!(h.indices(&conf).xi_min() < 1e-9);
    let all: Vec<usize> = (0..6).collect();
    assert_eq!(m.mechanism().mobility(&q, &m.lock_mask(&all)).dof, 1);
    // The motion is end-effector 2's: end-effector 1 stays.
    let r = m.mechanism().mobility(&q, &m.lock_mask(&all)).rates;
    let r = all_rates(&m, &all, &r.column(0).into_owned());
    let (p1_rate, w1) = point_velocity(&m, &q, "ee1", &pose.p1(), &r);
    assert!(p1_rate.norm() < 1e-9 && w1.norm() < 1e-12);
}

#[test]
fn sub_mechanisms_keep_the_legs_listed_and_the_bodies_they_join() {
    let d = description();
    assert_eq!(parse_leg_list("1-4, 29", 31).unwrap(), [0, 1, 2, 3, 28]);
    assert_eq!(parse_leg_list("3,1-2,2", 31).unwrap(), [0, 1, 2]);
    for (text, message) in [
        ("0", "leg 0 does not exist: the mechanism has legs 1 to 31"),
        (
            "1-32",
            "leg 32 does not exist: the mechanism has legs 1 to 31",
        ),
        ("4-1", "the range 4-1 runs backwards"),
        (
            "x",
            "\"x\" is not a leg number or a range of them (e.g. 1-4,29)",
        ),
        (
            "1--3",
            "\"1--3\" is not a leg number or a range of them (e.g. 1-4,29)",
        ),
        (",", "no leg listed (e.g. 1-4,29)"),
    ] {
        assert_eq!(parse_leg_list(text, 31).unwrap_err().to_string(), message);
    }
    // Limb 1: its four legs, the bodies upper1, lower1 and sub16 (the last leg's platform).
    let limb = d.with_legs(&[0, 1, 2, 3], Some("lower1")).unwrap();
    let names: Vec<&str> = limb.bodies.iter().map(|b| b.name.as_str()).collect();
    assert_eq!(names, ["upper1", "lower1", "sub16"]);
    assert_eq!(limb.legs.len(), 4);
    assert_eq!(limb.end_effector.as_deref(), Some("lower1"));
    // A leg between bodies not joined to the ground goes with them; the end-effector dropped
    // is refused.
    let e = d
        .with_legs(&[0, 1, 2, 3, 26], None)
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "the end-effector \"ee1\" is not joined to the ground \"base\" by the legs kept (bodies kept: upper1, lower1, sub16)"
    );
    let cut = d.with_legs(&[0, 1, 2, 3, 26], Some("sub16")).unwrap();
    assert_eq!(cut.legs.len(), 4);
    let e = d.with_legs(&[4], Some("lower1")).unwrap_err().to_string();
    assert!(e.starts_with("the body \"lower1\" is not joined"), "{e}");
}

#[test]
fn where_sigma_vanishes_the_locked_mechanism_lets_end_effector_1_move() {
    // σ (eq. 16) is 0 where (w1 × w6) × (w2 × w3) ⟂ Q1 j (eq. 15: det A1 = 0). Found by bisection
    // in y (x1 = 30 mm, z = −420 mm, φ = 0, P2 nominal: σ falls from 0.8 at y = 0 through 0 near
    // y = 425 mm, beyond the regular workspace but inside the reachable one), that pose is a
    // parallel singularity of end-effector 1: the general machinery, with inputs 1, 2, 3, 6
    // locked, must give the mechanism one more freedom there (3: the four-bar, φ2 and a motion
    // of end-effector 1) than at a regular pose (2) — an independent check of σ's zero.
    let m = hexa_mechanism();
    let h = Hexa::paper001();
    let signed = |y: f64| {
        let pose = pose_on_four_bar([30.0, y, -420.0], 0.0, 0.0, 0.0);
        let conf = h.inverse(&pose).unwrap();
        let w: [Vector3<f64>; 6] = std::array::from_fn(|i| conf.limbs[i].w);
        w[0].cross(&w[5])
            .cross(&w[1].cross(&w[2]))
            .dot(&Vector3::y())
    };
    let (mut lo, mut hi) = (350.0, 450.0);
    assert!(signed(lo) * signed(hi) < 0.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if signed(lo) * signed(mid) <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let y0 = 0.5 * (lo + hi);
    let locked = [0, 1, 2, 5];
    for (y, sigma_zero) in [(y0, true), (150.0, false)] {
        let (q, pose) = assemble(&m, ([30.0, y, -420.0], 0.0, 0.0, 0.0), 8);
        let sigma = h.indices(&h.inverse(&pose).unwrap()).sigma;
        assert_eq!(sigma < 1e-9, sigma_zero, "σ = {sigma} at y = {y}");
        let mobility = m.mechanism().mobility(&q, &m.lock_mask(&locked));
        assert_eq!(
            mobility.dof,
            if sigma_zero { 3 } else { 2 },
            "y = {y}, σ = {sigma}"
        );
    }
}
