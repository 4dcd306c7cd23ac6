//! Paper 001's 6-RUU by its closed forms (`kinsyn::hexa`): the inverse geometry of eq. 5
//! against the constraint it solves (eq. 4), the Jacobians of eqs. 9–11 against finite
//! differences of the inverse geometry, and the indices of eqs. 13, 15–16.

use kinsyn::hexa::{Hexa, forward_jacobian, output_index, rz};
use nalgebra::{DMatrix, DVector, Vector3};

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

#[test]
fn the_corrected_eq5_closes_every_limb_and_the_printed_one_does_not() {
    // Eq. 4: |c_i − b_i| = l. Both corrected roots close the limb to 1e-9 mm; the printed form
    // (−I ± √(I² + J² + K²))/(K − I) misses by millimetres (a documented deviation).
    let h = Hexa::paper001();
    let mut worst_printed: f64 = f64::INFINITY;
    for chi in POSES {
        let c = joints(&h, &chi, 0.5);
        for (i, ci) in c.iter().enumerate() {
            for theta in h.inverse_limb(i, ci).unwrap() {
                let s = h.limb(i, theta, ci);
                assert!(((ci - s.b).norm() - h.l).abs() < 1e-9, "limb {i}");
            }
            for theta in h.inverse_limb_as_printed(i, ci) {
                let s = h.limb(i, theta, ci);
                worst_printed = worst_printed.min(((ci - s.b).norm() - h.l).abs());
            }
        }
    }
    assert!(
        worst_printed > 1.0,
        "the printed eq. 5 misses by at least {worst_printed} mm"
    );
}

#[test]
fn a_chi_dot_equals_b_theta_dot_by_finite_differences() {
    // Eq. 9: A χ̇ = B θ̇, with θ̇ from central differences of the inverse geometry along a
    // pose velocity χ̇ — an independent check of A (the rows e_i, the s_i, the column order)
    // and of B = diag(h_i).
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
        // With θ in the sense that eq. 5's coefficients fix (v_i turning about −u_i), eq. 9
        // holds as A χ̇ = −B θ̇; with θ about +u_i, as printed, eq. 5's J_i changes sign
        // instead (docs/deviations.md). The printed sign is kept and shown to fail.
        assert!(
            (&lhs + &rhs).norm() < 1e-6 * (1.0 + lhs.norm()),
            "A χ̇ = {lhs:?}, −B θ̇ = {:?}",
            -&rhs
        );
        assert!(
            (&lhs - &rhs).norm() > 1e-3 * lhs.norm(),
            "eq. 9 with the printed sign"
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
fn eq15_against_the_determinant_of_a1() {
    // Eq. 15: |A1| = 2 r1 ((w1 × w6) × (w2 × w3))·s1 for the rows 1, 2, 3, 6 of A in the
    // columns x1, y1, z, φ1 (eq. 14), against the numerical determinant (Laplace's expansion
    // done by LU).
    let h = Hexa::paper001();
    for chi in POSES {
        let c = joints(&h, &chi, 0.5);
        let theta = angles(&h, &c);
        let w: [Vector3<f64>; 6] = std::array::from_fn(|i| h.limb(i, theta[i], &c[i]).w);
        let s1 = rz(chi[3]) * Vector3::y() * h.r[0];
        let rows = [(0, s1), (1, -s1), (2, -s1), (5, s1)];
        let a1 = DMatrix::from_fn(4, 4, |r, k| {
            let (i, s) = rows[r];
            if k < 3 { w[i][k] } else { w[i].dot(&s) }
        });
        let det = a1.determinant();
        // Eq. 15 holds with s1 the unit vector Q1 j (as in eq. 14, whose rows carry r1 w_iᵀ s_i);
        // with eq. 11's s1 = r1 Q1 j it would count r1 twice.
        let unit = rz(chi[3]) * Vector3::y();
        let printed = 2.0 * h.r[0] * w[0].cross(&w[5]).cross(&w[1].cross(&w[2])).dot(&unit);
        assert!(
            (det - printed).abs() < 1e-9 * printed.abs().max(1.0),
            "det A1 = {det}, eq. 15 = {printed}"
        );
        let with_eq11_s1 = printed * h.r[0];
        assert!((det - with_eq11_s1).abs() > 0.5 * det.abs());
    }
}
