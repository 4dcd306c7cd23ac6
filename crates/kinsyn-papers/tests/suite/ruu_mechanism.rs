//! Paper 004's 4-RUU as a manipulator description (`mechanisms/4-ruu.json`) and the general
//! machinery on it: the polynomial layer's U–U legs (`Manipulator::constraint_system`, given
//! and free inputs) against the paper's `g1 … g8` as derived by `kinsyn_papers::ruu` (an independent
//! derivation), the leg equations against poses assembled with nalgebra, and the general
//! `modes`/`analyze` (sampled loop closure, Jacobians) at assemblies of the algebraic modes K1
//! and K2 found by homotopy on the paper's equations.

use kinsyn::geometry::Chart;
use kinsyn::homotopy::{SolveSettings, solve};
use kinsyn::manipulator::{InputValues, LegKind, Manipulator, PositionSystemError};
use kinsyn::mechanism::SampleSettings;
use kinsyn::poly::{C64, Poly, System};
use kinsyn::spatial::{Displacement, rotation_log, study};
use kinsyn_papers::ruu::{InputMode, Ruu};
use nalgebra::{Rotation3, Translation3, Unit, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI, SQRT_2};

/// The crank angles `θ1i` (absolute, paper 004 eq. 2) of the file's reference configuration:
/// `B_i = A_i + (cos θ1i, sin θ1i, 0)` = (2, −1, 0), (1, 2, 0), (−2, 1, 0), (1, −2, 0).
const REFERENCE_ANGLES: [f64; 4] = [-FRAC_PI_2, 0.0, FRAC_PI_2, 0.0];

fn root(path: &str) -> String {
    format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))
}

fn four_ruu() -> Manipulator {
    Manipulator::from_json(&std::fs::read_to_string(root("mechanisms/4-ruu.json")).unwrap())
        .unwrap()
}

/// A 4-RUU description (paper 004's design) assembled at the crank angles `theta` (absolute)
/// and the platform pose `g`: `B_i` from eq. 2, `C_i = g (b e_i)`, the inner U axes
/// `s_i = Z × (C_i − B_i)` (horizontal, normal to the link), the platform's last axis `g z`.
/// Loops close by construction; the coupler length is `|C_i − B_i|` (2 when `g` assembles).
fn description(name: &str, theta: [f64; 4], g: &Displacement) -> String {
    let ruu = Ruu::paper004();
    let n = g.rotation * Vector3::z();
    let legs: Vec<String> = (0..4)
        .map(|i| {
            let a = ruu.base_joint(i);
            let b = ruu.crank_joint(i, theta[i]);
            let c = g * nalgebra::Point3::from(ruu.platform_joint(i));
            let s = Vector3::z().cross(&(c.coords - b));
            let v = |v: Vector3<f64>| format!("[{:.17e}, {:.17e}, {:.17e}]", v.x, v.y, v.z);
            format!(
                r#"{{ "chain": "R!UU", "base": {}, "platform": {}, "points": [{}],
                   "axes": [[0, 0, 1], [0, 0, 1], {}, {}, {}] }}"#,
                v(a),
                v(ruu.platform_joint(i)),
                v(b),
                v(s),
                v(s),
                v(n)
            )
        })
        .collect();
    let r = rotation_log(&g.rotation) * (180.0 / PI);
    let t = g.translation.vector;
    format!(
        r#"{{ "format": "kinsyn-manipulator/1", "name": "{name}", "units": {{ "length": "m", "angle": "deg" }},
             "platform": {{ "position": [{:.17e}, {:.17e}, {:.17e}], "orientation": [{:.17e}, {:.17e}, {:.17e}] }},
             "legs": [{}] }}"#,
        t.x,
        t.y,
        t.z,
        r.x,
        r.y,
        r.z,
        legs.join(", ")
    )
}

fn pose(t: [f64; 3], axis: Vector3<f64>, angle: f64) -> Displacement {
    let rotation = if angle == 0.0 {
        Rotation3::identity()
    } else {
        Rotation3::from_axis_angle(&Unit::new_normalize(axis), angle)
    };
    Displacement::from_parts(Translation3::new(t[0], t[1], t[2]), rotation)
}

/// The 1st Schönflies mode's reference (test only): the platform turned by π about
/// (1, 1, 0)/√2 (z down, `C_i` at (0, 1), (1, 0), (0, −1), (−1, 0)), height √2, cranks at
/// 180°, −atan(3/4), 0°, 90°: `B_i` = (1, 0, 0), (0.8, 1.4, 0), (−1, 0, 0), (0, −1, 0), each
/// `|C_i − B_i|² = 2 + 2 = 4` by hand ((0.2, −1.4) for leg 2: 0.04 + 1.96).
fn k1_reference() -> ([f64; 4], Displacement) {
    (
        [PI, -(0.75f64).atan(), 0.0, FRAC_PI_2],
        pose([0.0, 0.0, SQRT_2], Vector3::new(1.0, 1.0, 0.0), PI),
    )
}

/// The equations of `system` restricted to its first `n` variables' ring after substituting
/// nothing: the ring is the same when `n` equals its variable count (a convenience to drop the
/// `t2i` of `Ruu::constraints`, which `g1 … g8` do not contain).
fn restricted(system: &System, keep: &[usize], n: usize) -> Vec<Poly> {
    keep.iter()
        .map(|k| {
            let p = &system.equations()[*k];
            assert!(
                p.terms().all(|(e, _)| e[n..].iter().all(|x| *x == 0)),
                "equation {k} uses a dropped variable"
            );
            Poly::from_terms(n, p.terms().map(|(e, c)| (e[..n].to_vec(), c)))
        })
        .collect()
}

fn cplx(rng: &mut ChaCha8Rng) -> C64 {
    C64::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0))
}

/// A random complex point of the Study quadric `x·y = 0` followed by `extra` random complex
/// coordinates.
fn quadric_point(rng: &mut ChaCha8Rng, extra: usize) -> Vec<C64> {
    let mut p: Vec<C64> = (0..8 + extra).map(|_| cplx(rng)).collect();
    let xx: C64 = (0..4).map(|k| p[k] * p[k]).sum();
    let xy: C64 = (0..4).map(|k| p[k] * p[4 + k]).sum();
    for k in 0..4 {
        let xk = p[k];
        p[4 + k] -= xk * (xy / xx);
    }
    p
}

/// Asserts that `a` and `b` agree up to a non-zero constant factor at the points: their ratio
/// is the same at every point (relative spread below 1e-9) and neither vanishes there.
fn assert_proportional(
    a: &Poly,
    b: &Poly,
    points: &[Vec<C64>],
    pb: &dyn Fn(&[C64]) -> Vec<C64>,
    what: &str,
) {
    let ratios: Vec<C64> = points
        .iter()
        .map(|p| {
            let (va, vb) = (a.eval(p), b.eval(&pb(p)));
            assert!(
                va.norm() > 1e-6 && vb.norm() > 1e-6,
                "{what}: vanishes at a random point"
            );
            va / vb
        })
        .collect();
    let spread = ratios
        .iter()
        .map(|r| (r - ratios[0]).norm() / ratios[0].norm())
        .fold(0.0, f64::max);
    assert!(spread < 1e-9, "{what}: ratios {ratios:?}");
}

/// The leg equations' index pairs: (this system's equation, paper's `g` index 0-based) — leg
/// `i` gives the distance (`g5+i`) then the coplanarity (`g1+i`).
fn paper_pairs() -> Vec<(usize, usize)> {
    (0..4)
        .flat_map(|i| [(2 * i, 4 + i), (2 * i + 1, i)])
        .collect()
}

#[test]
fn the_file_has_four_u_u_legs_at_its_reference() {
    let m = four_ruu();
    assert_eq!(m.name(), "4-RUU (paper 004)");
    let labels: Vec<String> = m
        .actuators()
        .iter()
        .map(kinsyn::manipulator::Actuator::label)
        .collect();
    assert_eq!(labels, ["R1.1", "R2.1", "R3.1", "R4.1"]);
    let ruu = Ruu::paper004();
    let frame = m.platform_frame(&m.reference());
    let ps = m
        .constraint_system(&InputValues::Given(&[]), &Chart::Unit)
        .unwrap_err();
    // No inputs given: the cranks are passive, the leg is R–U–U (not a U–U).
    assert!(
        matches!(ps, PositionSystemError::UnsupportedLeg { leg: 1, .. }),
        "{ps}"
    );
    let given: Vec<(usize, f64)> = (0..4).map(|k| (k, 0.0)).collect();
    let ps = m
        .constraint_system(&InputValues::Given(&given), &Chart::Unit)
        .unwrap();
    assert_eq!(ps.system().len(), 10);
    assert!(ps.inputs().is_empty());
    for (i, c) in ps.legs().iter().enumerate() {
        // Paper 004 eqs. 2–3 at the reference angles: B_i, C_i = b e_i, r = 2, u = Z, n = z.
        assert_eq!(c.kind, LegKind::CoplanarDistance);
        assert!((c.base - ruu.crank_joint(i, REFERENCE_ANGLES[i])).norm() < 1e-12);
        assert!((c.platform - ruu.platform_joint(i)).norm() < 1e-12);
        assert!((c.length - ruu.r).abs() < 1e-12, "leg {i}: {}", c.length);
        assert!((c.axis.unwrap().cross(&Vector3::z())).norm() < 1e-12);
        assert!((c.platform_axis.unwrap().cross(&Vector3::z())).norm() < 1e-12);
    }
    // The reference pose: C_i at b e_i + (0, 0, √2), so |C_i − B_i|² = 1 + 1 + 2 = 4.
    assert!((frame.translation.vector - Vector3::new(0.0, 0.0, SQRT_2)).norm() < 1e-12);
    for r in ps.leg_residuals(&frame) {
        assert!(
            r.distance.abs() < 1e-12 && r.plane.unwrap().abs() < 1e-12,
            "{r:?}"
        );
    }
    // Square only with six constraints: the 4-RUU's eight are refused by position_system.
    assert_eq!(
        m.position_system(&given, &Chart::Unit),
        Err(PositionSystemError::Overdetermined(8))
    );
}

#[test]
fn given_inputs_give_paper_004_g1_to_g8() {
    // Paper 004 eqs. 11–12 (g1–g8) as derived by kinsyn_papers::ruu at the absolute angles
    // θ1i = reference + δ_i, against this file's system at the inputs δ_i (displacements from
    // the reference), up to one constant factor per equation, modulo the Study quadric.
    let m = four_ruu();
    let delta = [0.3, -0.55, 0.8, 1.9];
    let given: Vec<(usize, f64)> = delta.iter().copied().enumerate().collect();
    let ours = m
        .constraint_system(&InputValues::Given(&given), &Chart::Unit)
        .unwrap();
    let theta: [f64; 4] = std::array::from_fn(|i| REFERENCE_ANGLES[i] + delta[i]);
    let paper = Ruu::paper004()
        .constraints(InputMode::Angles(theta))
        .unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(14);
    let points: Vec<Vec<C64>> = (0..6).map(|_| quadric_point(&mut rng, 0)).collect();
    let pad = |p: &[C64]| {
        let mut q = p.to_vec();
        q.extend([C64::new(0.0, 0.0); 4]);
        q
    };
    for (k, g) in paper_pairs() {
        assert_proportional(
            &ours.system().equations()[k],
            &paper.equations()[g],
            &points,
            &pad,
            &format!("equation {k} vs g{}", g + 1),
        );
    }
    // The quadric and the normalisation g13, g14 are the same polynomials.
    assert_eq!(
        ours.system().equations()[8],
        restricted(&paper, &[12], 8)[0].clone()
    );
}

#[test]
fn free_inputs_give_paper_004_g1_to_g8_with_the_tangents() {
    // A test-only 4-RUU whose reference has every crank at θ1i = 0 (B_i = A_i + (1, 0, 0)), the
    // platform translated by (1, 0, √3): C_i − B_i = −e_i + √3 Z, |C_i − B_i|² = 1 + 3 = 4 —
    // so that the inputs' tangents t_k (from the reference) are the paper's t1k: the free
    // system equals g1–g8 (InputMode::Free, with the same factor 1 + t1i²) up to a constant
    // per equation.
    let g = pose([1.0, 0.0, 3f64.sqrt()], Vector3::z(), 0.0);
    let text = description("4-RUU, cranks at 0", [0.0; 4], &g);
    let m = Manipulator::from_json(&text).unwrap();
    let ours = m
        .constraint_system(&InputValues::Free, &Chart::Unit)
        .unwrap();
    assert!(ours.legs().iter().all(|c| (c.length - 2.0).abs() < 1e-12));
    assert_eq!(ours.inputs(), [8, 9, 10, 11]);
    assert_eq!(&ours.system().variables()[8..], ["t1", "t2", "t3", "t4"]);
    assert_eq!(ours.system().len(), 10);
    let paper = Ruu::paper004().constraints(InputMode::Free).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(41);
    let points: Vec<Vec<C64>> = (0..6).map(|_| quadric_point(&mut rng, 4)).collect();
    let pad = |p: &[C64]| {
        let mut q = p.to_vec();
        q.extend([C64::new(0.0, 0.0); 4]);
        q
    };
    for (k, g) in paper_pairs() {
        let e = &ours.system().equations()[k];
        // Degree 2 in the Study parameters and 2 in the leg's own tangent, as the paper's.
        let leg = k / 2;
        assert_eq!(e.degree_in(&[8 + leg]), 2, "equation {k}");
        assert_eq!(e.degree_in(&[0, 1, 2, 3, 4, 5, 6, 7]), 2, "equation {k}");
        assert_proportional(
            e,
            &paper.equations()[g],
            &points,
            &pad,
            &format!("equation {k} vs g{}", g + 1),
        );
    }
}

#[test]
fn free_inputs_are_the_given_system_times_one_plus_t_squared() {
    // On the file (reference angles ≠ 0): the free system at t_k = tan(δ_k/2) is the system at
    // the given inputs δ_k (computed by another path: the leg's chain turned by the joint's
    // displacement) times w_k = 1 + t_k² for leg k's two equations, and the same quadric.
    let m = four_ruu();
    let delta: [f64; 4] = [-0.4, 0.25, 1.2, -2.2];
    let t: Vec<f64> = delta.iter().map(|d| (d / 2.0).tan()).collect();
    let given: Vec<(usize, f64)> = delta.iter().copied().enumerate().collect();
    let fixed = m
        .constraint_system(&InputValues::Given(&given), &Chart::Unit)
        .unwrap();
    let free = m
        .constraint_system(&InputValues::Free, &Chart::Unit)
        .unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for _ in 0..4 {
        let p = quadric_point(&mut rng, 0);
        let mut q = p.clone();
        q.extend(t.iter().map(|v| C64::new(*v, 0.0)));
        for k in 0..8 {
            let w = 1.0 + t[k / 2] * t[k / 2];
            let (a, b) = (
                free.system().equations()[k].eval(&q),
                fixed.system().equations()[k].eval(&p),
            );
            assert!(
                (a - b * w).norm() < 1e-9 * (1.0 + a.norm()),
                "equation {k}: {a} vs {w} × {b}"
            );
        }
    }
}

/// The crank angle closing leg `i` for the platform pose `g` (independent of the polynomial
/// layer: circle intersection in the base plane), the solution nearer `near`; `None` if the
/// leg cannot close. Valid for poses with the platform z axis vertical (K1, K2), where the
/// coplanarity holds for any crank.
fn close_leg(i: usize, g: &Displacement, near: f64) -> Option<f64> {
    let ruu = Ruu::paper004();
    let c = g * nalgebra::Point3::from(ruu.platform_joint(i));
    let a = ruu.base_joint(i);
    let rho2 = ruu.r * ruu.r - c.z * c.z;
    let d = Vector3::new(c.x - a.x, c.y - a.y, 0.0);
    let dn = d.norm();
    let x = (dn * dn + ruu.l * ruu.l - rho2) / (2.0 * dn);
    let h2 = ruu.l * ruu.l - x * x;
    if rho2 < 0.0 || h2 < 0.0 {
        return None;
    }
    let phi = d.y.atan2(d.x);
    let off = (h2.sqrt()).atan2(x);
    let wrap = |v: f64| (v - near + PI).rem_euclid(2.0 * PI) - PI + near;
    let (p, q) = (wrap(phi + off), wrap(phi - off));
    Some(if (p - near).abs() < (q - near).abs() {
        p
    } else {
        q
    })
}

#[test]
fn leg_equations_vanish_at_poses_assembled_independently() {
    let m = four_ruu();
    let chart = Chart::random_linear(3);
    let free = m.constraint_system(&InputValues::Free, &chart).unwrap();
    let (k1_theta, _) = k1_reference();
    // A K2 pose (z up, turned 0.2 rad about z, shifted) and a K1 pose (z down), each with the
    // cranks closing the legs by circle intersection.
    let cases = [
        (pose([0.15, -0.1, 1.3], Vector3::z(), 0.2), REFERENCE_ANGLES),
        (
            pose([0.05, 0.1, 1.35], Vector3::z(), 0.1)
                * pose([0.0; 3], Vector3::new(1.0, 1.0, 0.0), PI),
            k1_theta,
        ),
    ];
    for (g, near) in cases {
        let theta: [f64; 4] = std::array::from_fn(|i| close_leg(i, &g, near[i]).unwrap());
        let delta: Vec<(usize, f64)> = (0..4)
            .map(|i| (i, theta[i] - REFERENCE_ANGLES[i]))
            .collect();
        let ps = m
            .constraint_system(&InputValues::Given(&delta), &chart)
            .unwrap();
        for r in ps.leg_residuals(&g) {
            assert!(
                r.distance.abs() < 1e-9 && r.plane.unwrap().abs() < 1e-9,
                "{r:?}"
            );
        }
        let s = ps.solution_of(&g).unwrap();
        let mut z: Vec<C64> = s.iter().map(|v| C64::new(*v, 0.0)).collect();
        assert!(ps.system().evaluate(&z).iter().all(|r| r.norm() < 1e-9));
        z.extend(delta.iter().map(|(_, d)| C64::new((d / 2.0).tan(), 0.0)));
        assert!(free.system().evaluate(&z).iter().all(|r| r.norm() < 1e-9));
        // The same pose with leg 1's crank 0.1 rad off does not close leg 1.
        let mut off = delta.clone();
        off[0].1 += 0.1;
        let bad = m
            .constraint_system(&InputValues::Given(&off), &chart)
            .unwrap();
        assert!(bad.leg_residuals(&g)[0].distance.abs() > 1e-3);
        assert!(bad.system().evaluate(&z[..8])[0].norm() > 1e-3);
    }
}

#[test]
fn leg_equations_are_the_distance_and_the_triple_product_at_tilted_poses() {
    // At real poses in no mode (the platform tilted), with the unit chart (Δ = 1) the leg
    // equations equal |C − B|² − r² and (C − B)·(Z × R z) (paper 004 eq. 10) computed with
    // nalgebra, B turned by the free input's angle: that checks the coplanarity where it is
    // not trivially satisfied (in K1 and K2, Z ∥ R z).
    let m = four_ruu();
    let ruu = Ruu::paper004();
    let free = m
        .constraint_system(&InputValues::Free, &Chart::Unit)
        .unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    for _ in 0..5 {
        let axis = Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let g = pose(
            [
                rng.random_range(-0.5..0.5),
                rng.random_range(-0.5..0.5),
                rng.random_range(0.5..2.0),
            ],
            axis,
            rng.random_range(-2.0..2.0),
        );
        let delta: [f64; 4] = std::array::from_fn(|_| rng.random_range(-2.5..2.5));
        let s = study::from_displacement(&g);
        let n: f64 = s[..4].iter().map(|v| v * v).sum::<f64>().sqrt();
        let mut z: Vec<C64> = s.iter().map(|v| C64::new(v / n, 0.0)).collect();
        z.extend(delta.iter().map(|d| C64::new((d / 2.0).tan(), 0.0)));
        let values = free.system().evaluate(&z);
        for i in 0..4 {
            let w = 1.0 + (delta[i] / 2.0).tan().powi(2);
            let b = ruu.crank_joint(i, REFERENCE_ANGLES[i] + delta[i]);
            let c = (g * nalgebra::Point3::from(ruu.platform_joint(i))).coords;
            let distance = (c - b).norm_squared() - ruu.r * ruu.r;
            let triple = (c - b).dot(&Vector3::z().cross(&(g.rotation * Vector3::z())));
            assert!(
                (values[2 * i].re / w - distance).abs() < 1e-9,
                "leg {i}: {} vs {distance}",
                values[2 * i]
            );
            // The sign of the coplanarity polynomial is a convention: compare up to it.
            assert!(
                (values[2 * i + 1].re.abs() / w - triple.abs()).abs() < 1e-9,
                "leg {i}: {} vs {triple}",
                values[2 * i + 1]
            );
            assert!(
                triple.abs() > 1e-3,
                "a tilted pose has a non-zero triple product"
            );
        }
    }
}

#[test]
fn unsupported_free_inputs_and_u_u_legs_are_refused_in_one_line() {
    // Free inputs whose legs stay of a recognised kind are passive joints, eliminated with
    // the leg's motion: a UPS leg with its U's first revolute and its slider free is a U–P–S
    // chain of six dof, which constrains nothing. The system is the quadric and the chart in
    // the eight Study parameters alone: the platform's six dof.
    let ups =
        Manipulator::from_json(&std::fs::read_to_string(root("mechanisms/3-ups.json")).unwrap())
            .unwrap();
    let ps = ups
        .constraint_system(&InputValues::Free, &Chart::Unit)
        .unwrap();
    assert!(ps.legs().iter().all(|c| c.kind == LegKind::Free));
    assert_eq!((ps.system().len(), ps.system().nvars()), (2, 8));
    assert!(ps.inputs().is_empty() && ps.input_variable(0).is_none());
    // Inner axes not parallel: leg 1's platform U turned about the link.
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root("mechanisms/4-ruu.json")).unwrap())
            .unwrap();
    v["legs"][0]["axes"][3] = serde_json::json!([1, 1, 1]);
    let m = Manipulator::from_json(&v.to_string()).unwrap();
    let given: Vec<(usize, f64)> = (0..4).map(|k| (k, 0.0)).collect();
    let e = m
        .constraint_system(&InputValues::Given(&given), &Chart::Unit)
        .unwrap_err();
    let text = e.to_string();
    assert!(
        matches!(e, PositionSystemError::UnsupportedLeg { leg: 1, .. }),
        "{text}"
    );
    assert!(
        !text.contains('\n') && text.contains("not parallel"),
        "{text}"
    );
}

/// The square systems of a mode at inputs: g5–g8 (the distances), g13, g14 and the mode's two
/// linear equations (K1: x0 = x3 = 0; K2: x1 = x2 = 0) in the eight Study parameters.
fn mode_system(theta: [f64; 4], zero: [usize; 2]) -> (System, Vec<Poly>) {
    let paper = Ruu::paper004()
        .constraints(InputMode::Angles(theta))
        .unwrap();
    let mut eqs = restricted(&paper, &[4, 5, 6, 7, 12, 13], 8);
    eqs.extend(zero.map(|k| Poly::variable(8, k)));
    let coplanar = restricted(&paper, &[0, 1, 2, 3], 8);
    (
        System::new(paper.variables()[..8].to_vec(), eqs).unwrap(),
        coplanar,
    )
}

#[test]
fn general_modes_and_analyze_find_schoenflies_x_z_at_k1_and_k2_assemblies() {
    // Paper 004 §4.1–4.3: K1 (x0 = x3 = 0) and K2 (x1 = x2 = 0) are 4-dof Schönflies modes
    // X(z). Assemblies of each at fixed inputs are found by homotopy on the paper's equations
    // (kinsyn_papers::ruu); at each real one a description is built and the general, equation-free
    // machinery (sampled loop closure: `modes`; Jacobians: `analyze`) must find dof 4 and the
    // group X(z).
    let (k1_theta, _) = k1_reference();
    let inputs = [
        (
            std::array::from_fn(|i| REFERENCE_ANGLES[i] + [0.1, -0.2, 0.15, 0.05][i]),
            [1, 2],
            "K2",
        ),
        (
            std::array::from_fn(|i| k1_theta[i] + [-0.1, 0.1, 0.2, -0.05][i]),
            [0, 3],
            "K1",
        ),
    ];
    let settings = SampleSettings::default();
    for (theta, zero, mode) in inputs {
        let (system, coplanar) = mode_system(theta, zero);
        let report = solve(&system, &SolveSettings::default()).unwrap();
        // One pose per ± pair of the normalisation g14.
        let poses: Vec<Vec<f64>> = report
            .solutions
            .iter()
            .filter(|s| s.real && s.regular)
            .map(|s| s.x.iter().map(|c| c.re).collect::<Vec<f64>>())
            .filter(|x| x.iter().find(|v| v.abs() > 1e-9).is_some_and(|v| *v > 0.0))
            .collect();
        assert!(!poses.is_empty(), "{mode}: no real assembly at {theta:?}");
        for x in poses {
            let z: Vec<C64> = x.iter().map(|v| C64::new(*v, 0.0)).collect();
            // g1–g4 hold too: the coplanarity is implied in K1 and K2.
            assert!(coplanar.iter().all(|g| g.eval(&z).norm() < 1e-9), "{mode}");
            let s: [f64; 8] = x.clone().try_into().unwrap();
            let g = study::to_displacement(&s, 1e-9).unwrap();
            let up = (g.rotation * Vector3::z()).z;
            assert!(
                (up - if mode == "K2" { 1.0 } else { -1.0 }).abs() < 1e-9,
                "{mode}: z·Z = {up}"
            );
            let m = Manipulator::from_json(&description(mode, theta, &g)).unwrap();
            let lengths = m
                .constraint_system(
                    &InputValues::Given(&[(0, 0.0), (1, 0.0), (2, 0.0), (3, 0.0)]),
                    &Chart::Unit,
                )
                .unwrap();
            assert!(
                lengths.legs().iter().all(|c| (c.length - 2.0).abs() < 1e-9),
                "{mode}"
            );
            let mode_found = m.mode(&[], &settings);
            assert_eq!(mode_found.dof, 4, "{mode} at {x:?}");
            assert_eq!(mode_found.pattern_text(), "X(z)", "{mode} at {x:?}");
            let analysis = m.analyse(&m.reference(), &[], &settings).unwrap();
            assert_eq!(analysis.platform_dof, 4, "{mode} at {x:?}");
            assert_eq!(analysis.mobility, 4, "{mode} at {x:?}");
        }
    }
}
