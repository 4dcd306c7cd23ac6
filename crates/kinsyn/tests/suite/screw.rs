//! Screws (src/screw.rs): hand-derived reciprocal systems, the adjoint, the bracket and ranks.

use kinsyn::screw::{
    self, Line, Twist, Wrench, adjoint, lie_bracket, reciprocal_complement, reciprocal_product,
    transform_twist,
};
use nalgebra::{DMatrix, Rotation3, Vector3};

fn columns(twists: &[Twist]) -> DMatrix<f64> {
    DMatrix::from_fn(6, twists.len(), |r, c| twists[c].to_vector()[r])
}

#[test]
fn spherical_joint_is_constrained_by_three_forces_through_its_centre() {
    // Hand derivation: the twists of an S at N are (ω; N × ω); the wrenches reciprocal to all
    // of them are the forces through N (moment N × f), a 3-system.
    let n = Vector3::new(1.0, -2.0, 0.5);
    let s = columns(&[
        Twist::revolute(Vector3::x(), n),
        Twist::revolute(Vector3::y(), n),
        Twist::revolute(Vector3::z(), n),
    ]);
    let w = reciprocal_complement(&s, 1e-9);
    assert_eq!(w.ncols(), 3);
    for j in 0..3 {
        let wr = Wrench::from_vector(&w.column(j).fixed_rows::<6>(0).into_owned());
        assert!((wr.m - n.cross(&wr.f)).norm() < 1e-12, "a force through N");
    }
}

#[test]
fn translations_are_constrained_by_couples() {
    // PPP: reciprocal wrenches are the three pure couples (f = 0).
    let t = columns(&[
        Twist::prismatic(Vector3::x()),
        Twist::prismatic(Vector3::y()),
        Twist::prismatic(Vector3::z()),
    ]);
    let w = reciprocal_complement(&t, 1e-9);
    assert_eq!(w.ncols(), 3);
    assert!(w.rows(0, 3).norm() < 1e-12);
}

#[test]
fn reciprocal_product_and_lines() {
    // A force along a line does no work on a rotation about an intersecting or parallel line.
    let r = Twist::revolute(Vector3::z(), Vector3::new(1.0, 0.0, 0.0));
    assert!(
        reciprocal_product(
            &Wrench::force(Vector3::x(), Vector3::new(1.0, 0.0, 0.0)),
            &r
        )
        .abs()
            < 1e-15
    );
    assert!(
        reciprocal_product(
            &Wrench::force(Vector3::z(), Vector3::new(5.0, 3.0, 0.0)),
            &r
        )
        .abs()
            < 1e-15
    );
    // Skew lines at distance 2 at right angles: |mutual moment| = 2.
    let a = Line::through(Vector3::zeros(), Vector3::x());
    let b = Line::through(Vector3::new(0.0, 0.0, 2.0), Vector3::y());
    assert!((a.mutual_moment(&b).abs() - 2.0).abs() < 1e-12);
    assert!((b.nearest_point() - Vector3::new(0.0, 0.0, 2.0)).norm() < 1e-12);
    // Pitch and axis of a helical twist.
    let h = Twist::helical(Vector3::y(), Vector3::new(1.0, 0.0, 2.0), 0.25);
    assert!((h.pitch().unwrap() - 0.25).abs() < 1e-12);
    let (p, d) = h.axis().unwrap();
    assert!((p - Vector3::new(1.0, 0.0, 2.0)).norm() < 1e-12 && (d - Vector3::y()).norm() < 1e-12);
}

#[test]
fn adjoint_moves_twists_with_the_frame() {
    let rot = Rotation3::from_euler_angles(0.3, -1.1, 0.7);
    let p = Vector3::new(0.2, 1.0, -0.4);
    let t = Twist::revolute(Vector3::x(), Vector3::new(0.0, 1.0, 0.0));
    let by_matrix = Twist::from_vector(&(adjoint(&rot, &p) * t.to_vector()));
    let direct = transform_twist(&rot, &p, &t);
    assert!((by_matrix.to_vector() - direct.to_vector()).norm() < 1e-12);
    // A revolute moved by (R, p) is the revolute about the moved line.
    let moved = Twist::revolute(rot * Vector3::x(), rot * Vector3::new(0.0, 1.0, 0.0) + p);
    assert!((direct.to_vector() - moved.to_vector()).norm() < 1e-12);
    // The reciprocal product is invariant when wrenches move with the frame (dual adjoint).
    let w = Wrench::force(Vector3::y(), Vector3::new(0.5, 0.0, 0.0));
    let w_moved = Wrench::force(rot * Vector3::y(), rot * Vector3::new(0.5, 0.0, 0.0) + p);
    assert!((reciprocal_product(&w, &t) - reciprocal_product(&w_moved, &direct)).abs() < 1e-12);
}

#[test]
fn bracket_of_rotations_about_a_point_is_a_rotation_about_it() {
    let n = Vector3::new(1.0, 2.0, 3.0);
    let b = lie_bracket(
        &Twist::revolute(Vector3::x(), n),
        &Twist::revolute(Vector3::y(), n),
    );
    assert!((b.to_vector() - Twist::revolute(Vector3::z(), n).to_vector()).norm() < 1e-12);
    // Two translations commute.
    assert!(
        lie_bracket(
            &Twist::prismatic(Vector3::x()),
            &Twist::prismatic(Vector3::y())
        )
        .to_vector()
        .norm()
            == 0.0
    );
}

#[test]
fn rank_reports_the_gap() {
    let m = DMatrix::from_column_slice(3, 3, &[1.0, 0.0, 0.0, 0.0, 1e-3, 0.0, 1.0, 1e-3, 0.0]);
    let r = screw::rank(&m, 1e-9);
    assert_eq!(r.rank, 2);
    let (kept, dropped) = r.gap();
    assert!(kept > 1e-4 && dropped < 1e-12);
    let (null, _) = screw::nullspace(&m, 1e-9);
    assert_eq!(null.ncols(), 1);
    assert!((&m * &null).norm() < 1e-12);
    assert_eq!(screw::rank(&DMatrix::zeros(6, 0), 1e-9).rank, 0);
}

mod fast_rank {
    use kinsyn::screw::{self, rank6};
    use nalgebra::{DMatrix, Matrix6xX};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The certified pivoted-QR rank equals the SVD rank (second algorithm), on products of
        /// random 6×k and k×6 factors (rank k) with scales over many orders of magnitude.
        #[test]
        fn rank6_equals_svd_rank(k in 0usize..=6, seed in proptest::collection::vec(-1.0f64..1.0, 72), scale in -12i32..3) {
            let a = DMatrix::from_fn(6, k, |r, c| seed[r * 6 + c]);
            let b = DMatrix::from_fn(k, 6, |r, c| seed[36 + r * 6 + c] * 10f64.powi(scale * i32::try_from(c % 2).unwrap()));
            let m = &a * &b;
            let fixed = Matrix6xX::from_column_slice(m.as_slice());
            let svd_rank = screw::rank(&m, 1e-9).rank;
            prop_assert_eq!(rank6(&fixed, 1e-9), svd_rank);
        }
    }
}

mod checked_svd {
    use kinsyn::screw::svd;
    use nalgebra::DMatrix;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The SVD reconstructs the matrix and has orthonormal singular vectors, also with
        /// repeated columns (two guides along one direction), the case that broke nalgebra's.
        #[test]
        fn svd_reconstructs_with_repeated_columns(x in proptest::collection::vec(-1.0f64..1.0, 18), dup in 0usize..3) {
            let mut m = DMatrix::from_fn(6, 4, |r, c| if c < 3 { x[r * 3 + c] } else { 0.0 });
            let col = m.column(dup).into_owned();
            m.set_column(3, &col);
            let d = svd(&m);
            let mut sigma_vt = d.v.transpose();
            for (k, s) in d.singular_values.iter().enumerate() {
                sigma_vt.row_mut(k).scale_mut(*s);
            }
            prop_assert!((&d.u * sigma_vt - &m).norm() < 1e-12 * m.norm().max(1.0));
            prop_assert!((d.v.transpose() * &d.v - DMatrix::<f64>::identity(4, 4)).norm() < 1e-12);
            prop_assert!(d.singular_values[3] < 1e-12 * d.singular_values[0]);
        }
    }
}

#[test]
fn an_svd_of_a_non_finite_matrix_returns() {
    // Found by probing: nalgebra's SVD does not terminate on a matrix with an infinite entry
    // (a description with coordinates near 1e300 overflowed to one). The checked SVD must
    // return, with non-finite values that no rank decision will trust.
    let mut m = nalgebra::DMatrix::<f64>::identity(6, 6);
    m[(2, 3)] = f64::INFINITY;
    m[(4, 1)] = f64::NAN;
    let d = kinsyn::screw::svd(&m);
    assert_eq!(d.singular_values.len(), 6);
}
