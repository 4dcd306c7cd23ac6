//! The linear algebra under the screw theory (src/linalg.rs, re-exported from `kinsyn::screw`):
//! the ranks a QR certifies against the SVD's, the least-norm step and the null-space direction
//! against the SVD's pseudo-inverse and projector, and truncated least squares against hand
//! derivations and the normal equations.

use kinsyn::screw::{
    DEFAULT_RANK_TOLERANCE, full_row_rank, least_squares, min_norm_step, null_direction, nullspace,
    nullspace_scaled, rank, rank_quick, span_basis, span_basis_quick, span_basis_scaled, svd,
};
use nalgebra::{DMatrix, DVector};
use rand::{Rng, SeedableRng};

/// A random m × n matrix of rank `rank` (products of normal factors) with its singular
/// values spread by `spread` (the last kept one `spread` times the first), from `seed`.
fn with_rank(m: usize, n: usize, rank: usize, spread: f64, seed: u64) -> DMatrix<f64> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut normal =
        |r: usize, c: usize| DMatrix::from_fn(r, c, |_, _| rng.random_range(-1.0..1.0));
    let u = normal(m, rank).qr().q();
    let v = normal(n, rank).qr().q();
    #[expect(clippy::cast_precision_loss, reason = "small indices")]
    let sigma = DMatrix::from_fn(rank, rank, |i, j| {
        if i == j {
            spread.powf(i as f64 / (rank.max(2) - 1) as f64)
        } else {
            0.0
        }
    });
    u * sigma * v.transpose()
}

/// The certified ranks are the SVD's: on matrices of every rank, with singular values
/// spread from 1 to 1e-3, to within a factor 10 of the cut (1e-9 × 10) and to round-off
/// (1e-15), tall and wide, with the tolerance relative to the largest value and to a scale
/// of 1. Where a certificate cannot decide, the functions ask the SVD, so the answers must
/// agree everywhere; the test also checks that independent rows with singular values above
/// 1e-8 of the largest are certified, so that it cannot pass by always falling back.
#[test]
fn certified_ranks_are_the_svd_ranks() {
    let mut certified = 0;
    let mut cases = 0;
    for (m, n) in [(6, 3), (6, 6), (3, 6), (12, 18), (18, 12), (6, 2)] {
        for rank in 0..=m.min(n) {
            for spread in [1e-3, 1e-8, 1e-10, 1e-15] {
                for seed in 0..3 {
                    let a = if rank == 0 {
                        DMatrix::zeros(m, n)
                    } else {
                        with_rank(m, n, rank, spread, seed)
                    };
                    let svd_rank = svd(&a).rank(DEFAULT_RANK_TOLERANCE, None).rank;
                    assert_eq!(
                        rank_quick(&a, DEFAULT_RANK_TOLERANCE, None),
                        svd_rank,
                        "{m}×{n} rank {rank} spread {spread:e}"
                    );
                    let unit = svd(&a).rank(1e-7, Some(1.0)).rank;
                    assert_eq!(rank_quick(&a, 1e-7, Some(1.0)), unit);
                    let (basis, r) = span_basis_quick(&a, DEFAULT_RANK_TOLERANCE);
                    assert_eq!(r, svd_rank);
                    let (svd_basis, _) = span_basis(&a, DEFAULT_RANK_TOLERANCE);
                    // The same span: each basis projects the other onto itself, to the
                    // accuracy a span has with a smallest singular value `spread` (ε/σ).
                    if r == svd_rank && spread > 1e-9 {
                        let p = &basis * basis.transpose();
                        let e = (&p * &svd_basis - &svd_basis).norm();
                        assert!(e < 1e-14 / spread, "{m}×{n} rank {rank}: {e:e}");
                    }
                    let certificate = full_row_rank(&a, DEFAULT_RANK_TOLERANCE);
                    // Well-conditioned independent rows are certified.
                    assert!(
                        certificate.is_some() || svd_rank < m || spread < 1e-3,
                        "{m}×{n}: independent rows not certified"
                    );
                    if let Some(f) = certificate {
                        certified += 1;
                        assert_eq!(svd_rank, m, "{m}×{n} rank {rank}: certified wrongly");
                        let null = f.null_basis();
                        assert_eq!(null.ncols(), n - m);
                        assert!((&a * &null).norm() < 1e-12 * a.norm().max(1.0));
                        let gram = null.transpose() * &null;
                        assert!((gram - DMatrix::identity(n - m, n - m)).norm() < 1e-12);
                    }
                    cases += 1;
                }
            }
        }
    }
    // (6×6, 3×6 and 12×18 of full rank, with spread 1e-3 or 1e-8, three seeds.)
    assert_eq!(certified, 18, "certified {certified} of {cases}");
}

/// The least-norm Newton step equals the pseudo-inverse solution of the SVD (an
/// independent algorithm), for independent equations; dependent ones are refused.
#[test]
fn min_norm_step_is_the_pseudo_inverse_solution() {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
    for (m, n) in [(12, 18), (6, 6), (1, 4)] {
        let a = with_rank(m, n, m, 1e-2, 4);
        let b = DVector::from_fn(m, |_, _| rng.random_range(-1.0..1.0));
        let step = min_norm_step(&a, &b).expect("independent equations");
        let reference = least_squares(&a, &b, 1e-14).x;
        assert!((&step - &reference).norm() < 1e-10 * reference.norm());
    }
    assert!(min_norm_step(&with_rank(6, 8, 4, 1e-2, 1), &DVector::zeros(6)).is_none());
    // More equations than unknowns, independent columns: the least-squares step.
    let a = with_rank(30, 24, 24, 1e-2, 5);
    let b = DVector::from_fn(30, |_, _| rng.random_range(-1.0..1.0));
    let step = min_norm_step(&a, &b).expect("independent columns");
    let reference = least_squares(&a, &b, 1e-14).x;
    assert!((&step - &reference).norm() < 1e-10 * reference.norm());
}

/// The random direction lies in the null space, and it is isotropic there: the mean of
/// d dᵀ over 4000 draws is the orthogonal projector on the null space (the SVD's), to the
/// sampling error (entries within 0.06 for unit-variance draws).
#[test]
fn null_direction_is_isotropic_in_the_null_space() {
    let a = with_rank(4, 7, 4, 1e-1, 2);
    let (null, _) = nullspace(&a, DEFAULT_RANK_TOLERANCE);
    let projector = &null * null.transpose();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
    let mut moment = DMatrix::<f64>::zeros(7, 7);
    let draws = 4000;
    for _ in 0..draws {
        let d = null_direction(&a, DEFAULT_RANK_TOLERANCE, |_, _| {
            rng.sample::<f64, _>(rand_distr::StandardNormal)
        })
        .expect("independent rows");
        assert!((&a * &d).norm() < 1e-12 * d.norm());
        moment += &d * d.transpose();
    }
    moment /= f64::from(draws);
    assert!((moment - projector).amax() < 0.06);
    // Dependent rows are not certified.
    let dependent = with_rank(4, 7, 3, 1e-1, 2);
    assert!(null_direction(&dependent, DEFAULT_RANK_TOLERANCE, |_, _| 1.0).is_none());
}

/// The explicit scale of [`Svd::rank`]: singular values 1e-6 and 1e-12 are two
/// independent directions relative to their own largest value (1e-12 > 1e-9 × 1e-6), one
/// relative to the scale 1 of an orthonormal basis (1e-12 < 1e-9 × 1).
#[test]
#[expect(
    clippy::float_cmp,
    reason = "the scale is the largest singular value passed through unchanged: of a \
              diagonal matrix, its entry 1e-6 bit for bit"
)]
fn rank_is_relative_to_the_scale_given() {
    let m = DMatrix::from_diagonal(&DVector::from_vec(vec![1e-6, 1e-12]));
    let own = svd(&m).rank(1e-9, None);
    assert_eq!(own.rank, 2);
    assert_eq!(own.scale, 1e-6);
    let unit = svd(&m).rank(1e-9, Some(1.0));
    assert_eq!(unit.rank, 1);
    assert_eq!(unit.gap(), (1e-6, 1e-12));
    assert_eq!(rank(&m, 1e-9), own);
    assert_eq!(span_basis_scaled(&m, 1e-9, Some(1.0)).1, unit);
    assert_eq!(nullspace_scaled(&m, 1e-9, Some(1.0)).0.ncols(), 1);
}

/// A full-rank overdetermined system: the least-squares solution satisfies the normal
/// equations `aᵀ a x = aᵀ b`, solved independently by Cholesky, and nothing is dropped.
#[test]
fn least_squares_meets_the_normal_equations_at_full_rank() {
    let a = DMatrix::from_row_slice(
        6,
        3,
        &[
            1.0, 2.0, 0.5, //
            -1.0, 0.3, 2.0, //
            0.7, -1.5, 1.0, //
            2.0, 0.0, -0.4, //
            0.1, 1.1, 0.9, //
            -0.6, 0.8, -1.2,
        ],
    );
    let b = DVector::from_vec(vec![1.0, -2.0, 0.5, 3.0, -1.0, 0.25]);
    let ls = least_squares(&a, &b, 1e-12);
    assert_eq!(ls.dropped.ncols(), 0);
    let normal = (a.transpose() * &a)
        .cholesky()
        .expect("aᵀa is positive definite")
        .solve(&(a.transpose() * &b));
    assert!((&ls.x - &normal).norm() < 1e-12 * normal.norm());
    // And the residual is orthogonal to the columns of a (to round-off of their size).
    assert!((a.transpose() * (&a * &ls.x - &b)).norm() < 1e-12 * a.norm() * b.norm());
}

/// A rank-deficient system built by hand: columns e1, e1, e2 of R³ and b = (2, 3, 5). The
/// best fit makes x1 + x2 = 2 and x3 = 3 (residual 5 along e3, out of reach); of those
/// the smallest is x = (1, 1, 3), and (1, −1, 0)/√2 is the dropped direction.
#[test]
fn least_squares_is_the_minimum_norm_solution_when_rank_deficient() {
    let a = DMatrix::from_row_slice(3, 3, &[1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    let b = DVector::from_vec(vec![2.0, 3.0, 5.0]);
    let ls = least_squares(&a, &b, 1e-12);
    assert!((&ls.x - DVector::from_vec(vec![1.0, 1.0, 3.0])).norm() < 1e-12);
    assert_eq!(ls.dropped.ncols(), 1);
    let d = ls.dropped.column(0);
    let expected = DVector::from_vec(vec![1.0, -1.0, 0.0]) / 2f64.sqrt();
    assert!((d.dot(&expected).abs() - 1.0).abs() < 1e-12);
    assert!((&a * d).norm() < 1e-12);
}

/// The cut-off is absolute: a direction with singular value 1e-10 is dropped at cut-off
/// 1e-8 (its component of `x` is zero, not b/1e-10) and kept at 1e-12.
#[test]
fn least_squares_truncates_at_the_absolute_cut_off() {
    let a = DMatrix::from_diagonal(&DVector::from_vec(vec![1.0, 1e-10]));
    let b = DVector::from_vec(vec![1.0, 1.0]);
    let truncated = least_squares(&a, &b, 1e-8);
    assert!((&truncated.x - DVector::from_vec(vec![1.0, 0.0])).norm() < 1e-15);
    assert_eq!(truncated.dropped.ncols(), 1);
    assert!((truncated.dropped[(1, 0)].abs() - 1.0).abs() < 1e-15);
    let kept = least_squares(&a, &b, 1e-12);
    assert_eq!(kept.dropped.ncols(), 0);
    assert!((kept.x[1] - 1e10).abs() < 1e-2);
}

/// A rectangular wide system (fewer equations than unknowns): one equation x1 + x2 = 2 has
/// the minimum-norm solution (1, 1), and one dropped direction.
#[test]
fn least_squares_of_a_wide_system() {
    let a = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
    let b = DVector::from_vec(vec![2.0]);
    let ls = least_squares(&a, &b, 1e-12);
    assert!((&ls.x - DVector::from_vec(vec![1.0, 1.0])).norm() < 1e-12);
    assert_eq!(ls.dropped.ncols(), 1);
}
