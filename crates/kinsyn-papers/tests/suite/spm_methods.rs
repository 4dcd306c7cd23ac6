//! Paper 002: three methods, one answer. At the reference and at random
//! assemblies of `mechanisms/multibody/3-rps-3-spr.json`, the general loop-closure machinery
//! (the mechanism graph: end-effector twist space, and the end-effector twist per unit rate of
//! each input with the other five held) is compared with the paper's Jacobian `J_S-PM` (eqs. 2–7,
//! `kinsyn_papers::series`) and the order of its twist system (eqs. 9–10), the modules' geometry read
//! off the assembled mechanism (`kinsyn_papers::series::stack`: frames, joint screws).

use kinsyn::manipulator::Manipulator;
use kinsyn::screw::{self, DEFAULT_RANK_TOLERANCE};
use nalgebra::{DMatrix, Vector3};

fn load(name: &str) -> Manipulator {
    let text = std::fs::read_to_string(format!("../../mechanisms/multibody/{name}.json")).unwrap();
    Manipulator::from_json(&text).unwrap()
}

/// The end-effector twist `(ω; v_{O_2})` in base axes per unit rate of each input with the
/// other inputs held, from the loop closure: the columns of the input–output Jacobian that
/// `J_S-PM` must equal (eq. 7).
fn closure_jacobian(m: &Manipulator, q: &[f64]) -> DMatrix<f64> {
    let effector = m.end_effector();
    let body = m.bodies()[effector].body;
    let mech = m.mechanism();
    let screws = mech.joint_screws(q);
    let origin = m.body_frame(effector, q).translation.vector;
    let inputs = m.actuators().len();
    let mut j = DMatrix::zeros(6, inputs);
    for (c, a) in m.actuators().iter().enumerate() {
        let locked: Vec<usize> = (0..inputs).filter(|&b| b != c).collect();
        let mask = m.lock_mask(&locked);
        let mobility = mech.mobility(q, &mask);
        assert_eq!(mobility.dof, 1, "one input free: one motion");
        let free: Vec<usize> = (0..mask.len()).filter(|&k| !mask[k]).collect();
        let mut rates = vec![0.0; mask.len()];
        for (row, &k) in free.iter().enumerate() {
            rates[k] = mobility.rates[(row, 0)];
        }
        let scale = rates[a.joint];
        let t = mech.body_jacobian(body, &screws) * nalgebra::DVector::from_vec(rates) / scale;
        let w = Vector3::new(t[0], t[1], t[2]);
        let v = Vector3::new(t[3], t[4], t[5]) + w.cross(&origin);
        for k in 0..3 {
            j[(k, c)] = w[k];
            j[(3 + k, c)] = v[k];
        }
    }
    j
}

/// Eq. 7 against the loop closure, and rank `J_S-PM` = order of `T_S-PM` (eq. 10) = the
/// end-effector dof of the mechanism graph = 6 at generic configurations (Table 1 rows 2–3;
/// paper 002 §4: "for general configurations … the mobility is found to be six").
#[test]
fn the_paper_jacobian_the_twist_system_and_the_loop_closure_agree() {
    agree("3-rps-3-spr");
}

/// Eq. 8 (n modules) against the loop closure for the 3-module stack 3-RPS-3-SPR-3-RPS: the 6 × 9
/// Jacobian equals the input–output Jacobian, and its rank is 6 at random configurations.
#[test]
fn the_n_module_jacobian_equals_the_loop_closure_for_three_modules() {
    agree("3-rps-3-spr-3-rps");
}

/// The three methods at the reference and four random assemblies of `name`.
fn agree(name: &str) {
    let m = load(name);
    let n = m.mechanism().joints().len();
    let mut configurations = vec![m.reference()];
    configurations.extend(m.mechanism().random_assemblies(
        &m.reference(),
        &vec![false; n],
        4,
        0.2,
        2017,
    ));
    assert!(
        configurations.len() >= 4,
        "random assemblies closed: {}",
        configurations.len()
    );
    let effector = m.body_named("end-effector").unwrap();
    for (k, q) in configurations.iter().enumerate() {
        let spm = kinsyn_papers::series::stack(&m, q).expect("a stack of two three-legged modules");
        let j = spm.jacobian().unwrap();
        let closure = closure_jacobian(&m, q);
        let scale = 1.0 + closure.amax();
        assert!(
            (&j - &closure).amax() < 1e-8 * scale,
            "{name}, configuration {k}: J_S-PM (eqs. 7–8) {j} against the loop closure {closure}"
        );
        let rank = screw::rank(&j, DEFAULT_RANK_TOLERANCE);
        let order = spm.twist_system(DEFAULT_RANK_TOLERANCE).order;
        let (_, dof) = m.body_twists(effector, q, &[]);
        assert_eq!(
            (rank.rank, order.rank, dof),
            (6, 6, 6),
            "{name}, configuration {k}"
        );
    }
}

/// Only stacks of three-legged RPS/SPR modules read as paper 002's S-PM: the 3-RPS-3-SPR and
/// the 3-module stack do (two and three modules), a single-platform 3-UPS (UPS legs) and the
/// split 3-RPS (two bodies side by side, joined by a revolute) do not.
#[test]
fn only_module_stacks_read_as_series_parallel() {
    let read = |path: &str| {
        let m = Manipulator::from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
        kinsyn_papers::series::stack(&m, &m.reference()).map(|s| s.modules().len())
    };
    assert_eq!(read("../../mechanisms/multibody/3-rps-3-spr.json"), Some(2));
    assert_eq!(
        read("../../mechanisms/multibody/3-rps-3-spr-3-rps.json"),
        Some(3)
    );
    assert_eq!(read("../../mechanisms/3-rps.json"), Some(1));
    assert_eq!(read("../../mechanisms/3-ups.json"), None);
    assert_eq!(read("../../mechanisms/multibody/3-rps-split.json"), None);
}

/// Each module alone is the 3-RPS of paper 000 §5 in form (paper 002 eq. 9): the coupler's twists
/// (the proximal module's, the distal legs leaving it free) are reciprocal to three independent
/// pure forces, one per leg, through the S centre along the R axis — as the platform twists of
/// `mechanisms/3-rps.json` are to its legs' forces. The forces are built from the joints of the
/// assembled mechanism; the twists come from the loop closure.
#[test]
fn each_module_has_the_constraint_forces_of_a_3_rps() {
    let check = |m: &Manipulator, body: usize, legs: std::ops::Range<usize>, what: &str| {
        let n = m.mechanism().joints().len();
        let mut qs = vec![m.reference()];
        qs.extend(
            m.mechanism()
                .random_assemblies(&m.reference(), &vec![false; n], 3, 0.2, 7),
        );
        for q in &qs {
            let (twists, dof) = m.body_twists(body, q, &[]);
            assert_eq!(
                dof, 3,
                "{what}: a 3-RPS platform has 3 dof (paper 000 §5.2)"
            );
            let screws = m.mechanism().joint_screws(q);
            let mut forces = DMatrix::zeros(6, 3);
            for (c, k) in legs.clone().enumerate() {
                let joints: Vec<usize> = m.legs()[k].joints.clone().collect();
                // R at the lower end, S (three revolutes meeting at its centre) at the upper.
                let r = screws[joints[0]].w.normalize();
                let (w, v) = (screws[joints[2]].w, screws[joints[2]].v);
                let (w2, v2) = (screws[joints[3]].w, screws[joints[3]].v);
                let (a1, a2) = (
                    w.cross(&v) / w.norm_squared(),
                    w2.cross(&v2) / w2.norm_squared(),
                );
                let normal = w.cross(&w2);
                let centre = a1 + w * ((a2 - a1).cross(&w2).dot(&normal) / normal.norm_squared());
                let moment = centre.cross(&r);
                for i in 0..3 {
                    forces[(i, c)] = r[i];
                    forces[(3 + i, c)] = moment[i];
                }
            }
            // Reciprocal product of a wrench (f; m_O) and a twist (ω; v_O): f·v + m·ω.
            let scale = forces.amax() * twists.amax();
            for t in twists.column_iter() {
                for f in forces.column_iter() {
                    let product = f[0] * t[3]
                        + f[1] * t[4]
                        + f[2] * t[5]
                        + f[3] * t[0]
                        + f[4] * t[1]
                        + f[5] * t[2];
                    assert!(
                        product.abs() < 1e-9 * scale,
                        "{what}: reciprocal product {product:e}"
                    );
                }
            }
            let rank = screw::rank(&forces, DEFAULT_RANK_TOLERANCE);
            assert_eq!(rank.rank, 3, "{what}: three independent constraint forces");
        }
    };
    let spm = load("3-rps-3-spr");
    check(
        &spm,
        spm.body_named("coupler").unwrap(),
        0..3,
        "3-RPS-3-SPR proximal module",
    );
    let rps =
        Manipulator::from_json(&std::fs::read_to_string("../../mechanisms/3-rps.json").unwrap())
            .unwrap();
    check(&rps, rps.end_effector(), 0..3, "mechanisms/3-rps.json");
}

/// Stacks made by `manipulator::stacking::stack` (a general way to stack n parallel modules): the
/// paper's 3-RPS-3-SPR (h = 2, 1, 2) and a 3-RPS-3-SPR-3-RPS. Hand (Grübler, as for the committed
/// files): mobility 6·(15 − 1) − 6·13 = 6 and 6·21 − 9·13 = 9; each module's platform 3 dof
/// relative to the one below, the end-effector 6 (eq. 8, generic). The methods agree on the made
/// files as on the committed ones.
#[test]
fn stacks_made_from_modules_have_the_hand_mobility() {
    use ModuleKind::{Rps, Spr};
    use kinsyn::manipulator::stacking::{ModuleKind, StackSpec, stack};
    for (modules, radii, heights, mobility) in [
        (vec![Rps, Spr], vec![2.0, 1.0, 2.0], vec![-1.5, -1.6], 6),
        (
            vec![Rps, Spr, Rps],
            vec![2.0, 1.0, 2.0, 1.0],
            vec![-1.5, -1.6, -1.4],
            9,
        ),
    ] {
        let d = stack(&StackSpec {
            modules: modules.clone(),
            radii,
            heights,
        })
        .unwrap();
        let m = Manipulator::from_bodies(&d).unwrap();
        let q = m.reference();
        let free = vec![false; m.mechanism().joints().len()];
        assert_eq!(
            m.mechanism().mobility(&q, &free).dof,
            mobility,
            "{}",
            d.name
        );
        let first = m.body_named("platform 1").unwrap();
        assert_eq!(
            m.body_twists(first, &q, &[]).1,
            3,
            "{}: a 3-RPS platform",
            d.name
        );
        assert_eq!(m.body_twists(m.end_effector(), &q, &[]).1, 6, "{}", d.name);
        let spm = kinsyn_papers::series::stack(&m, &q).expect("a module stack");
        assert_eq!(spm.modules().len(), modules.len());
        let j = spm.jacobian().unwrap();
        let closure = closure_jacobian(&m, &q);
        assert!(
            (&j - &closure).amax() < 1e-8 * (1.0 + closure.amax()),
            "{}",
            d.name
        );
    }
}
