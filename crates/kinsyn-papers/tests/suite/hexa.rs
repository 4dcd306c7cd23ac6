//! Paper 001's 6-RUU by its closed forms (`kinsyn_papers::hexa`): the inverse geometry of eq. 5
//! against the constraint it solves (eq. 4), the Jacobians of eqs. 9–11 against finite
//! differences of the inverse geometry, and the indices of eqs. 13, 15–16.

use kinsyn_papers::hexa::{Hexa, Pose, forward_jacobian, output_index, rz};
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

/// The platform joints `c_i` (eq. 6b) at the pose `χ = (x1, y1, z, φ1, x2, y2, φ2)`, with
/// `γ` (unstated in the paper) a parameter and `Q` of the fourth and fifth limbs read as `Q2`.
fn joints(h: &Hexa, chi: &[f64; 7], gamma: f64) -> [Vector3<f64>; 6] {
    let p1 = Vector3::new(chi[0], chi[1], chi[2]);
    let p2 = Vector3::new(chi[4], chi[5], chi[2]);
    let (q1, q2) = (rz(chi[3]), rz(chi[6]));
    let (r1, r2, r5) = (h.r[0], h.r[1], h.r[4]);
    std::array::from_fn(|k| {
        let i = k + 1; // the paper's 1-based index
        let sign = |e: usize| if e.is_multiple_of(2) { 1.0 } else { -1.0 };
        match i {
            1 | 2 => p1 + q1 * Vector3::x() * (sign(i + 1) * r1),
            3 | 6 => {
                p1 + q1 * Vector3::x() * (sign(i) * r1)
                    - Vector3::new(sign(i + 1) * gamma.cos(), gamma.sin(), 0.0) * r2
            }
            _ => p2 + q2 * Vector3::x() * (sign(i + 1) * r5),
        }
    })
}

const POSES: [[f64; 7]; 3] = [
    [10.0, -20.0, -600.0, 0.2, 15.0, 5.0, -0.1],
    [-40.0, 30.0, -650.0, -0.3, -20.0, 40.0, 0.25],
    [0.0, 0.0, -550.0, 0.0, 0.0, 0.0, 0.0],
];

/// The first root of eq. 5 (corrected) for every limb.
fn angles(h: &Hexa, c: &[Vector3<f64>; 6]) -> [f64; 6] {
    std::array::from_fn(|i| h.inverse_limb(i, &c[i]).expect("within reach")[0])
}

/// `R_z(μ_i) j`, the horizontal direction away from the base centre at limb `i`.
fn outward(i: usize) -> Vector3<f64> {
    rz(kinsyn_papers::hexa::mu(i)) * Vector3::y()
}

fn wrap(x: f64) -> f64 {
    (x + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
}

#[test]
fn eq5s_coefficients_are_those_of_eq4_with_theta_from_the_horizontal_about_plus_u() {
    // Eq. 5's I = −2b m_z, J = 2b(m_x sin μ − m_y cos μ), K = |m|² + b² − l², by hand:
    // |m − b v|² − l² = K − 2b m·v, and with v = cos θ R_z(μ) j + sin θ k,
    // −2b m·v = J cos θ + I sin θ. So eq. 4 reads J cos θ + I sin θ + K = 0 (kinsyn's
    // convention), and v turns about +u_i: dv/dθ = u × v.
    let h = Hexa::paper001();
    for chi in POSES {
        let c = joints(&h, &chi, 0.5);
        for (i, ci) in c.iter().enumerate() {
            let (ii, jj, kk) = h.coefficients(i, ci);
            for theta in [-1.3, -0.4, 0.2, 2.5] {
                let s = h.limb(i, theta, ci);
                let eq4 = (ci - s.b).norm_squared() - h.l * h.l;
                let eq5 = jj * theta.cos() + ii * theta.sin() + kk;
                assert!(
                    (eq4 - eq5).abs() < 1e-9 * h.l * h.l,
                    "limb {i}: {eq4} vs {eq5}"
                );
                let e = 1e-6;
                let dv =
                    (h.link_direction(i, theta + e) - h.link_direction(i, theta - e)) / (2.0 * e);
                assert!((dv - h.axis(i).cross(&s.v)).norm() < 1e-9);
            }
            assert!((h.link_direction(i, 0.0) - outward(i)).norm() < 1e-15);
        }
    }
}

#[test]
fn eq5s_printed_root_fails_under_every_convention_for_theta() {
    // Eq. 5 as printed: θ = 2 atan((−I ± √(I² + J² + K²))/(K − I)). Two independent arguments
    // that no convention for θ (from ±k or ±R_z(μ) j, about ±u_i, any fixed offset) makes it a
    // root of eq. 4.
    let h = Hexa::paper001();
    // 1. Whatever the convention, eq. 4 has real roots only where I² + J² ≥ K² (|m·v| ≤ |m|).
    //    Far below the reach (|m| > b + l) no active-link direction closes the limb, yet the
    //    printed square root is real and the printed "roots" are finite.
    let far = Vector3::new(0.0, 0.0, -2000.0);
    let (ii, jj, kk) = h.coefficients(0, &far);
    assert!((far - h.base_joint(0)).norm() > h.b + h.l);
    assert!(ii * ii + jj * jj < kk * kk && h.inverse_limb(0, &far).is_none());
    assert!(
        h.inverse_limb_as_printed(0, &far)
            .iter()
            .all(|t| t.is_finite())
    );
    // 2. Within reach: a convention is θ' = σ θ + δ (σ = ±1 the sense, δ the zero) relative to
    //    kinsyn's θ (σ, δ may even differ from limb to limb). For the printed roots to close a
    //    limb, one (σ, δ) must map each of them, at every pose, onto a true root: collect the δ
    //    each printed root needs and find none common to a limb's poses.
    let mut needed: Vec<(usize, [f64; 4])> = Vec::new();
    let mut worst_printed: f64 = f64::INFINITY;
    for chi in POSES {
        let c = joints(&h, &chi, 0.5);
        for (i, ci) in c.iter().enumerate() {
            let true_roots = h.inverse_limb(i, ci).unwrap();
            for theta in true_roots {
                let s = h.limb(i, theta, ci);
                assert!(((ci - s.b).norm() - h.l).abs() < 1e-9, "limb {i}");
            }
            for printed in h.inverse_limb_as_printed(i, ci) {
                let s = h.limb(i, printed, ci);
                worst_printed = worst_printed.min(((ci - s.b).norm() - h.l).abs());
                // δ for σ = +1 (two true roots), then for σ = −1.
                needed.push((
                    i,
                    [
                        wrap(true_roots[0] - printed),
                        wrap(true_roots[1] - printed),
                        wrap(true_roots[0] + printed),
                        wrap(true_roots[1] + printed),
                    ],
                ));
            }
        }
    }
    for limb in 0..6 {
        let mine: Vec<&[f64; 4]> = needed
            .iter()
            .filter(|(i, _)| *i == limb)
            .map(|(_, d)| d)
            .collect();
        for sense in 0..2 {
            for first in 0..2 {
                let delta = mine[0][2 * sense + first];
                let fits = mine
                    .iter()
                    .all(|d| (0..2).any(|k| wrap(d[2 * sense + k] - delta).abs() < 1e-6));
                assert!(!fits, "limb {limb}, sense {sense}, δ = {delta}");
            }
        }
    }
    assert!(
        worst_printed > 1.0,
        "the printed eq. 5 misses by at least {worst_printed} mm"
    );
}

#[test]
fn eq9_holds_as_printed_with_theta_about_plus_u_by_finite_differences() {
    // Eq. 9: A χ̇ = B θ̇, with θ̇ from central differences of the inverse geometry along a
    // pose velocity χ̇ — an independent check of A (the rows e_i, the s_i, the column order of
    // eq. 10a) and of B = diag(h_i) (eq. 11). With θ about +u_i (kinsyn's convention, the
    // one that also makes eq. 5's I, J, K the coefficients of eq. 4) it holds as printed; with
    // θ about −u_i (θ' = −θ, e.g. v = cos θ k + sin θ R_z(μ) j) it would need −B.
    let h = Hexa::paper001();
    let gamma = 0.5;
    for chi in POSES {
        let c = joints(&h, &chi, gamma);
        let theta = angles(&h, &c);
        let states: Vec<_> = (0..6).map(|i| h.limb(i, theta[i], &c[i])).collect();
        let w: [Vector3<f64>; 6] = std::array::from_fn(|i| states[i].w);
        let (q1, q2) = (rz(chi[3]), rz(chi[6]));
        let s1 = q1 * Vector3::y() * h.r[0];
        let s5 = q2 * Vector3::y() * h.r[4];
        let s = [s1, -s1, -s1, -s5, s5, s1];
        let a = forward_jacobian(&w, &s);
        let b = DMatrix::from_diagonal(&DVector::from_fn(6, |i, _| h.h(i, &states[i])));
        let chi_dot = [0.3, -0.7, 0.5, 0.002, 0.4, 0.9, -0.003];
        let eps = 1e-4;
        let shifted = |k: f64| -> [f64; 6] {
            let moved: [f64; 7] = std::array::from_fn(|j| chi[j] + k * eps * chi_dot[j]);
            let cm = joints(&h, &moved, gamma);
            std::array::from_fn(|i| {
                let roots = h.inverse_limb(i, &cm[i]).unwrap();
                // The branch continuous with θ_i.
                *roots
                    .iter()
                    .min_by(|x, y| (*x - theta[i]).abs().total_cmp(&(*y - theta[i]).abs()))
                    .unwrap()
            })
        };
        let (plus, minus) = (shifted(1.0), shifted(-1.0));
        let theta_dot = DVector::from_fn(6, |i, _| (plus[i] - minus[i]) / (2.0 * eps));
        let lhs = &a * DVector::from_column_slice(&chi_dot);
        let rhs = &b * &theta_dot;
        assert!(
            (&lhs - &rhs).norm() < 1e-6 * (1.0 + lhs.norm()),
            "A χ̇ = {lhs:?}, B θ̇ = {rhs:?}"
        );
        // About −u_i the rates change sign and the printed sign fails by the full size.
        assert!(
            (&lhs + &rhs).norm() > 1.0 * lhs.norm(),
            "eq. 9 with θ about −u_i"
        );
        // Eq. 13: the input indices lie in [0, 1].
        for (i, state) in states.iter().enumerate() {
            let lambda = h.input_index(i, state);
            assert!((0.0..=1.0).contains(&lambda), "λ_{} = {lambda}", i + 1);
        }
        // Eq. 16: σ ∈ [0, 1].
        let sigma = output_index(&w, &(q1 * Vector3::y()));
        assert!((0.0..=1.0).contains(&sigma));
    }
}

#[test]
fn eq10a_fifth_coordinate_is_x2_under_every_reading() {
    // Eq. 11's rows e_4, e_5 put w_ix in the fifth column of A. By finite differences of the
    // inverse geometry, the rate of θ_4 per unit ẋ2 is w_4x/h_4 (the column is ẋ2's), while
    // per unit rise of P2 alone (a separate ż2, the printed reading) it is w_4z/h_4 ≠ w_4x/h_4.
    // Since p2 = (x2, y2, z) (§3.1), χ must hold ẋ2 and its only candidate is the fifth entry.
    let h = Hexa::paper001();
    for chi in POSES {
        let c = joints(&h, &chi, 0.5);
        let theta = angles(&h, &c);
        let s4 = h.limb(3, theta[3], &c[3]);
        let eps = 1e-4;
        let rate = |dp: Vector3<f64>| {
            let at = |k: f64| {
                let roots = h.inverse_limb(3, &(c[3] + dp * k * eps)).unwrap();
                *roots
                    .iter()
                    .min_by(|x, y| (*x - theta[3]).abs().total_cmp(&(*y - theta[3]).abs()))
                    .unwrap()
            };
            (at(1.0) - at(-1.0)) / (2.0 * eps)
        };
        let h4 = h.h(3, &s4);
        assert!((rate(Vector3::x()) - s4.w.x / h4).abs() < 1e-8);
        assert!((rate(Vector3::z()) - s4.w.z / h4).abs() < 1e-8);
        assert!((s4.w.x - s4.w.z).abs() > 0.1);
    }
}

#[test]
fn eq15_is_the_determinant_of_eq14s_a1_as_printed() {
    // Eq. 15: |A1| = 2 r1 ((w1 × w6) × (w2 × w3))·s1 for eq. 14's A1, rows
    // [w_iᵀ, r1 w_iᵀ s_i] (i = 1, 2, 3, 6), against the numerical determinant (Laplace's
    // expansion done by LU). Eq. 14's rows are eq. 11's e_i when its s_i is the unit vector
    // (s1 = Q1 j), and with that s eq. 15 holds as printed; eq. 16's σ = |cos ω| ∈ [0, 1] needs
    // the unit s too. (With eq. 11's s_i = r1 Q1 j in both eq. 14 and eq. 15 the identity still
    // holds, but A1 is then not eq. 11's and σ exceeds 1.)
    let h = Hexa::paper001();
    for chi in POSES {
        let c = joints(&h, &chi, 0.5);
        let theta = angles(&h, &c);
        let w: [Vector3<f64>; 6] = std::array::from_fn(|i| h.limb(i, theta[i], &c[i]).w);
        // Eq. 14's A1 for a given s1 (s2 = s3 = −s1, s6 = s1).
        let a1 = |s1: Vector3<f64>| {
            let rows = [(0, s1), (1, -s1), (2, -s1), (5, s1)];
            DMatrix::from_fn(4, 4, |r, k| {
                let (i, s) = rows[r];
                if k < 3 {
                    w[i][k]
                } else {
                    h.r[0] * w[i].dot(&s)
                }
            })
        };
        let eq15 =
            |s1: Vector3<f64>| 2.0 * h.r[0] * w[0].cross(&w[5]).cross(&w[1].cross(&w[2])).dot(&s1);
        let unit = rz(chi[3]) * Vector3::y();
        let det = a1(unit).determinant();
        assert!(
            (det - eq15(unit)).abs() < 1e-9 * det.abs().max(1.0),
            "det A1 = {det}, eq. 15 = {}",
            eq15(unit)
        );
        // With the unit s, A1 is rows 1, 2, 3, 6 of eq. 11's A (s_i = r1 Q1 j there), the
        // Jacobian checked by finite differences above.
        let s = h.s_vectors(chi[3], chi[6]);
        let a = forward_jacobian(&w, &s);
        for (r, i) in [0, 1, 2, 5].into_iter().enumerate() {
            for k in 0..4 {
                assert!((a1(unit)[(r, k)] - a[(i, k)]).abs() < 1e-12);
            }
        }
        // Eq. 11's s in both: the identity holds (det scales by r1, eq. 15 too), σ does not.
        let det11 = a1(unit * h.r[0]).determinant();
        assert!((det11 - eq15(unit * h.r[0])).abs() < 1e-9 * det11.abs().max(1.0));
        let n = w[0].cross(&w[5]).cross(&w[1].cross(&w[2]));
        assert!(n.dot(&(unit * h.r[0])).abs() / n.norm() > 1.0);
    }
}

#[test]
fn the_library_platform_joints_are_eq_6b() {
    // Eq. 6b transcribed above (`joints`, with γ a parameter) against `Hexa::platform_joints`.
    let h = Hexa::paper001();
    for chi in POSES {
        let by_hand = joints(&h, &chi, h.gamma);
        let library = h.platform_joints(&Pose { chi });
        for i in 0..6 {
            assert!((by_hand[i] - library[i]).norm() < 1e-12, "c_{}", i + 1);
        }
    }
}

/// `R_η` as printed in eq. 8.
fn r_eta(eta: f64) -> Matrix3<f64> {
    Matrix3::new(
        eta.cos(),
        eta.sin(),
        0.0,
        eta.sin(),
        -eta.cos(),
        0.0,
        0.0,
        0.0,
        1.0,
    )
}

#[test]
fn eq7a_is_the_four_bar_and_eqs_7b_7c_place_p2_at_the_coupler_middle() {
    // For crank angles α over a turn, the β that eq. 7a pairs with α (Freudenstein's equation,
    // k1, k2 = k3 of eq. 8) must make the coupler D3D6 exactly 2 r4 long — the four-bar's
    // closure, an independent statement — and eqs. 7b–c as printed (with R_η of eq. 8) must
    // both give P2.
    let h = Hexa::paper001();
    let (r3, r4) = (h.r[2], h.r[3]);
    let (mut assembled, mut flipped_open) = (0, 0);
    for (p1, phi1) in [
        (Vector3::new(0.0, 0.0, -600.0), 0.0),
        (Vector3::new(40.0, -30.0, -650.0), 0.4),
        (Vector3::new(-20.0, 10.0, -550.0), -0.7),
    ] {
        let fb = h.four_bar(&p1, phi1);
        // Eq. 8's k1 against the Freudenstein constant (d² + a² + c² − b²)/(2ac), a = c = r3,
        // b = 2 r4, by hand.
        let (k1, k2) = h.freudenstein(fb.d);
        let hand = (fb.d * fb.d + 2.0 * r3 * r3 - 4.0 * r4 * r4) / (2.0 * r3 * r3);
        assert!((k1 - hand).abs() < 1e-12 && (k2 - fb.d / r3).abs() < 1e-12);
        for k in 0..72 {
            let alpha = f64::from(k) * 5f64.to_radians();
            let Some(betas) = h.rocker_angles(&fb, alpha) else {
                continue;
            };
            for beta in betas {
                assert!(h.eq7a(&fb, alpha, beta).abs() < 1e-12);
                let pose = h.four_bar_pose(&fb, alpha, beta);
                assert!(((pose.d6 - pose.d3).norm() - 2.0 * r4).abs() < 1e-9);
                let e = |t: f64| Vector3::new(t.cos(), t.sin(), 0.0);
                let eq7b = fb.c3 + r_eta(fb.eta) * (e(alpha) * r3 + e(pose.psi) * r4) - pose.p2;
                let eq7c = fb.c6 + r_eta(fb.eta) * (e(beta) * r3 - e(pose.psi) * r4) - pose.p2;
                assert!(eq7b.norm() < 1e-9 && eq7c.norm() < 1e-9, "α = {alpha}");
                // Reading: R_η a rotation R_z(η) (det +1). Eqs. 7b–c still agree, on the mirror
                // image of P2 across the ground line C3C6: the reflection only fixes the sense
                // of α, β, ψ (away from end-effector 1), so eqs. 7–8 hold either way.
                let by_rotation = |c: Vector3<f64>, crank: f64, sign: f64| {
                    c + rz(fb.eta) * (e(crank) * r3 + e(pose.psi) * (sign * r4))
                };
                let (b_rot, c_rot) = (
                    by_rotation(fb.c3, alpha, 1.0),
                    by_rotation(fb.c6, beta, -1.0),
                );
                assert!((b_rot - c_rot).norm() < 1e-9);
                let ground = (fb.c6 - fb.c3).normalize();
                let rel = pose.p2 - fb.c3;
                let mirror = fb.c3 + ground * (2.0 * rel.dot(&ground)) - rel;
                assert!((b_rot - mirror).norm() < 1e-9);
                // Reading: η the direction of C6 → C3 instead. Eqs. 7b–c then close only where
                // |r3 (e(α) − e(β)) + d i| = 2 r4, Freudenstein's equation with k2, k3 negated,
                // against eq. 8's k2 = k3 = d/r3 > 0: the α, β of eq. 7a miss it.
                let flipped = ((e(alpha) - e(beta)) * r3 + Vector3::x() * fb.d).norm() - 2.0 * r4;
                if flipped.abs() > 1e-6 {
                    flipped_open += 1;
                }
                assembled += 1;
            }
        }
    }
    assert!(assembled > 100, "{assembled} assemblies");
    assert!(
        10 * flipped_open > 9 * assembled,
        "{flipped_open} of {assembled}"
    );
}

#[test]
fn four_bar_through_inverts_four_bar_pose_and_refuses_points_off_the_curve() {
    let h = Hexa::paper001();
    let p1 = Vector3::new(25.0, -15.0, -620.0);
    let fb = h.four_bar(&p1, 0.3);
    let alpha = 0.45;
    let beta = h.rocker_angles(&fb, alpha).unwrap()[0];
    let pose = h.four_bar_pose(&fb, alpha, beta);
    let found = h.four_bar_through(&p1, 0.3, &pose.p2, 1e-9);
    assert!(
        found
            .iter()
            .any(|f| (f.d3 - pose.d3).norm() < 1e-7 && (f.d6 - pose.d6).norm() < 1e-7),
        "{found:?}"
    );
    // 5 mm across the curve is off it.
    let normal = (pose.d6 - pose.d3).normalize();
    assert!(
        h.four_bar_through(
            &p1,
            0.3,
            &(pose.p2 + normal.cross(&Vector3::z()) * 5.0),
            1e-6
        )
        .is_empty()
            || h.four_bar_through(
                &p1,
                0.3,
                &(pose.p2 - normal.cross(&Vector3::z()) * 5.0),
                1e-6
            )
            .is_empty()
    );
}

#[test]
fn the_nominal_four_bar_puts_p2_60_mm_below_p1() {
    // By hand at φ1 = 0: d = 2 r1 + 2 r2 cos γ and cos α = (d − 2 r4)/(2 r3) = cos γ when r1 = r4
    // and r2 = r3 (paper 001 §4: all 60), so α = γ = 30° and P2 = P1 − (r2 sin γ + r3 sin α) j
    // = P1 − 60 j.
    let h = Hexa::paper001();
    let p1 = Vector3::new(12.0, -7.0, -640.0);
    let nominal = h.nominal_four_bar(&p1, 0.0).unwrap();
    assert!((nominal.alpha - 30f64.to_radians()).abs() < 1e-12);
    assert!((nominal.p2 - (p1 - Vector3::y() * 60.0)).norm() < 1e-9);
}

/// End-effector 2 at the four-bar's crank angle `alpha` (the `beta` branch nearest `beta0`) with
/// end-effector 1 held at `(p1, φ1)`, turned so that limb `locked` keeps the angle `theta`:
/// `φ2` by the secant method on limb `locked`'s working-mode angle. Returns `c_driving`.
fn driven_joint(
    h: &Hexa,
    p1: &Vector3<f64>,
    phi1: f64,
    (alpha, beta0): (f64, f64),
    (locked, theta, phi2_start): (usize, f64, f64),
    driving: usize,
) -> Vector3<f64> {
    let fb = h.four_bar(p1, phi1);
    let beta = *h
        .rocker_angles(&fb, alpha)
        .unwrap()
        .iter()
        .min_by(|x, y| (*x - beta0).abs().total_cmp(&(*y - beta0).abs()))
        .unwrap();
    let p2 = h.four_bar_pose(&fb, alpha, beta).p2;
    let miss = |phi2: f64| {
        let c = h.platform_joints(&Pose::new(p1, phi1, &p2, phi2));
        h.working_root(locked, &c[locked]).unwrap() - theta
    };
    let (mut x0, mut x1) = (phi2_start, phi2_start + 1e-3);
    for _ in 0..50 {
        let (f0, f1) = (miss(x0), miss(x1));
        if f1 == 0.0 || (f1 - f0) == 0.0 {
            break;
        }
        let x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        (x0, x1) = (x1, x2);
        if (x1 - x0).abs() < 1e-15 {
            break;
        }
    }
    h.platform_joints(&Pose::new(p1, phi1, &p2, x1))[driving]
}

#[test]
fn xi_is_the_pressure_angle_found_by_moving_the_robot() {
    // ξ_k (eq. 17, as defined in `hexa::transmission`): an independent, position-level method.
    // Hold end-effector 1 and limb k's partner at its angle, move the four-bar a little either
    // way, re-solve φ2 so the partner's angle stays, and take the cosine between w_k and the
    // displacement of C_k. It must equal the library's velocity-level ξ_k.
    let h = Hexa::paper001();
    for (p1, phi1, alpha, phi2) in [
        (Vector3::new(30.0, -20.0, -600.0), 0.2, 0.6, -0.1),
        (Vector3::new(-45.0, 35.0, -650.0), -0.4, 0.35, 0.3),
        (Vector3::new(10.0, -60.0, -560.0), 0.7, 0.8, -0.6),
    ] {
        let fb = h.four_bar(&p1, phi1);
        let beta = h.rocker_angles(&fb, alpha).unwrap()[0];
        let p2 = h.four_bar_pose(&fb, alpha, beta).p2;
        let conf = h.inverse(&Pose::new(&p1, phi1, &p2, phi2)).unwrap();
        let xi = h.indices(&conf).xi;
        for (k, (driving, locked)) in [(3usize, 4usize), (4, 3)].into_iter().enumerate() {
            let eps = 1e-5;
            let moved = |s: f64| {
                driven_joint(
                    &h,
                    &p1,
                    phi1,
                    (alpha + s * eps, beta),
                    (locked, conf.limbs[locked].theta, phi2),
                    driving,
                )
            };
            let dc = moved(1.0) - moved(-1.0);
            let w = conf.limbs[driving].w;
            let cosine = (w.dot(&dc) / (w.norm() * dc.norm())).abs();
            assert!(
                (cosine - xi[k]).abs() < 1e-6,
                "ξ_{}: moved {cosine}, library {}",
                driving + 1,
                xi[k]
            );
        }
    }
}

#[test]
fn end_effector_2_is_singular_on_the_mirror_plane_and_the_printed_eq17_misses_it() {
    // By hand: at x1 = 0, φ1 = φ2 = 0 with the nominal (symmetric) four-bar, the robot is
    // mirror-symmetric about the plane x = 0; the coupler's middle moves along x (its velocity
    // is the mirror image of itself with the crank rates swapped), so rows 4 and 5 of
    // end-effector 2's Jacobian are [s w4x, −r5 w4y] and [−s w4x, r5 w4y]: opposite, det = 0,
    // ξ_4 = ξ_5 = 0. Off the plane (x1 = 40) it is regular.
    let h = Hexa::paper001();
    let at = |x1: f64| {
        let p1 = Vector3::new(x1, -20.0, -600.0);
        let p2 = h.nominal_four_bar(&p1, 0.0).unwrap().p2;
        h.inverse(&Pose::new(&p1, 0.0, &p2, 0.0)).unwrap()
    };
    let singular = at(0.0);
    let m = h.end_effector2_jacobian(&singular).unwrap();
    assert!(m.determinant().abs() < 1e-9 * m.norm_squared());
    assert!(h.indices(&singular).xi_min() < 1e-9);
    let regular = at(40.0);
    let m = h.end_effector2_jacobian(&regular).unwrap();
    assert!(m.determinant().abs() > 1e-3 * m.norm_squared());
    assert!(h.indices(&regular).xi_min() > 1e-3);
    // Eq. 17: ŝ_O ∘ ŝ_T, the reciprocal product ω_O · m_T + v_O · f_T, under each reading of
    // the printed screws ŝ_O = (k; r5 Q2 i), ŝ_T = (w_k; b v_k × w_k) (ŝ_T's moment is about
    // A_k). An index that is 0 at singular configurations (§3.2) needs a product that
    // vanishes at this singular pose; no normalisation turns a non-zero product into 0.
    // (a) as printed; (b) r5 Q2 j for r5 Q2 i (the velocity of C5 under φ̇2, eq. 11's s5);
    // (c) both referred to C_k: ŝ_T = (w_k; 0), ŝ_O = (k; s_k) (end-effector 2 turning about P2);
    // (d) ŝ_T referred to P2, ŝ_O as printed; (e) ŝ_T referred to P2 and ŝ_O = (k; r5 Q2 j) read
    // for each limb as (k; (c_k − p2) × k): the turn about C_k's own vertical, whose product
    // with a force through C_k is 0 at every pose.
    let (q2i, q2j) = (Vector3::x(), Vector3::y());
    let readings = |conf: &kinsyn_papers::hexa::Configuration, k: usize| {
        let s = conf.limbs[k];
        let s_k = if k == 3 { -q2j * h.r[4] } else { q2j * h.r[4] };
        let about_p2 = (conf.joints[k] - conf.pose.p2()).cross(&s.w);
        [
            Vector3::z().dot(&(s.v * h.b).cross(&s.w)) + h.r[4] * q2i.dot(&s.w),
            Vector3::z().dot(&(s.v * h.b).cross(&s.w)) + h.r[4] * q2j.dot(&s.w),
            s_k.dot(&s.w),
            Vector3::z().dot(&about_p2) + h.r[4] * q2i.dot(&s.w),
            Vector3::z().dot(&about_p2)
                + (conf.joints[k] - conf.pose.p2())
                    .cross(&Vector3::z())
                    .dot(&s.w),
        ]
    };
    for k in [3, 4] {
        let at_singular = readings(&singular, k);
        for (name, value) in ["a", "b", "c", "d"].iter().zip(at_singular) {
            assert!(
                value.abs() > 0.02 * (h.b + h.r[4]),
                "reading ({name}), limb {}: {value}",
                k + 1
            );
        }
        assert!(at_singular[4].abs() < 1e-9 && readings(&regular, k)[4].abs() < 1e-9);
    }
}

#[test]
fn at_the_coupler_curves_double_point_the_pose_leaves_the_four_bar_open() {
    // Fig. 3(a)'s curve is a figure-eight, symmetric about x = x1 at φ1 = 0 and under
    // (α, β) → (π − β, π − α) (the four-bar's own mirror), so it crosses itself on x = x1
    // halfway between its tips P1 and P1 − 60 j: at P1 − 30 j two assemblies pass, mirror
    // images of each other. `inverse` must keep the one nearest the nominal assembly, and the
    // choice matters: end-effector 2's Jacobian differs between them.
    let h = Hexa::paper001();
    let p1 = Vector3::new(20.0, -10.0, -600.0);
    let p2 = p1 - Vector3::y() * 30.0;
    let both = h.four_bar_through(&p1, 0.0, &p2, 1e-9 * h.l);
    assert_eq!(both.len(), 2, "{both:?}");
    let nominal = h.nominal_four_bar(&p1, 0.0).unwrap();
    let conf = h.inverse(&Pose::new(&p1, 0.0, &p2, 0.1)).unwrap();
    let kept = conf.four_bar.unwrap();
    let other = both
        .iter()
        .find(|f| (f.d3 - kept.d3).norm() > 1e-6)
        .unwrap();
    assert!((kept.d3 - nominal.d3).norm() < (other.d3 - nominal.d3).norm());
    let m_kept = h.end_effector2_jacobian(&conf).unwrap();
    let m_other = h
        .end_effector2_jacobian(&kinsyn_papers::hexa::Configuration {
            four_bar: Some(*other),
            ..conf
        })
        .unwrap();
    assert!((m_kept - m_other).norm() > 1e-3 * m_kept.norm());
}
