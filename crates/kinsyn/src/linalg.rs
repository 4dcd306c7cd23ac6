//! The linear algebra under the screw theory: the checked singular value decomposition, ranks
//! with their gaps, span and null-space bases, and truncated least squares.
//!
//! This is a bottom layer beside [`crate::spatial`]: it knows nalgebra and nothing else of the
//! crate. It is private; what users call is re-exported from [`crate::screw`]
//! (`screw::svd`, `screw::rank`, `screw::Rank`, `screw::rank6`, `screw::span_basis`,
//! `screw::nullspace`, `screw::rank_quick`, `screw::least_squares`,
//! `screw::DEFAULT_RANK_TOLERANCE`, …), and every SVD of the crate goes
//! through [`svd`], because nalgebra's alone is not always right (docs/verification.md).
//!
//! Tolerances are explicit: a rank is decided by a *relative* tolerance, relative to the
//! largest singular value or to a scale the caller gives (for a block of an orthonormal basis,
//! whose own largest value may be round-off); least squares truncates at an *absolute*
//! cut-off.

use nalgebra::{DMatrix, DVector, Matrix6, Matrix6xX};

/// The default relative tolerance of ranks: singular values below this fraction of the largest
/// one count as zero (ARCHITECTURE.md, Conventions).
pub const DEFAULT_RANK_TOLERANCE: f64 = 1e-9;

/// The rank of a set of screws (the columns of `m`) with the singular values that decide it.
#[derive(Debug, Clone, PartialEq)]
pub struct Rank {
    /// Number of singular values above `tolerance × scale`.
    pub rank: usize,
    /// All singular values, largest first.
    pub singular_values: Vec<f64>,
    /// The relative tolerance used.
    pub tolerance: f64,
    /// The value the tolerance is relative to: the largest singular value, or a scale that
    /// cannot be round-off when one was given ([`span_basis_scaled`]).
    pub scale: f64,
}

impl Rank {
    /// The rank of nothing (no columns, or no rows) at relative tolerance `tolerance`.
    fn empty(tolerance: f64) -> Self {
        Rank {
            rank: 0,
            singular_values: Vec::new(),
            tolerance,
            scale: 0.0,
        }
    }

    /// The last singular value kept (zero when the rank is zero).
    #[must_use]
    pub fn smallest_kept(&self) -> f64 {
        if self.rank == 0 {
            0.0
        } else {
            self.singular_values[self.rank - 1]
        }
    }

    /// The first singular value dropped (zero when none is dropped).
    #[must_use]
    pub fn largest_dropped(&self) -> f64 {
        self.singular_values.get(self.rank).copied().unwrap_or(0.0)
    }

    /// The gap at the cut relative to the scale the rank was judged against (the largest
    /// singular value unless another was given): the smallest kept value over it (how far the
    /// rank is from dropping) and the largest dropped value over it (how far it is from
    /// rising). Near-singular cases show as a small first number.
    #[must_use]
    pub fn gap(&self) -> (f64, f64) {
        if self.scale <= 0.0 {
            return (0.0, 0.0);
        }
        (
            self.smallest_kept() / self.scale,
            self.largest_dropped() / self.scale,
        )
    }
}

/// A singular value decomposition `m = U Σ Vᵀ` with the values sorted, largest first: `u` is
/// rows × cols, `v` cols × cols (all right singular vectors, for null spaces).
#[derive(Debug, Clone)]
pub struct Svd {
    /// Left singular vectors (columns), one per singular value.
    pub u: DMatrix<f64>,
    /// Singular values, largest first (as many as `m` has columns).
    pub singular_values: Vec<f64>,
    /// Right singular vectors (columns).
    pub v: DMatrix<f64>,
}

impl Svd {
    /// The rank these singular values give at relative tolerance `tolerance`: the number above
    /// `tolerance × scale`, where `scale` is the largest singular value unless one is given (a
    /// value that cannot be round-off, such as 1 for a block of an orthonormal basis). Nothing
    /// is kept when the scale is zero.
    #[must_use]
    pub fn rank(&self, tolerance: f64, scale: Option<f64>) -> Rank {
        let top = scale.unwrap_or_else(|| self.singular_values.first().copied().unwrap_or(0.0));
        let rank = self
            .singular_values
            .iter()
            .filter(|&&s| top > 0.0 && s > tolerance * top)
            .count();
        Rank {
            rank,
            singular_values: self.singular_values.clone(),
            tolerance,
            scale: top,
        }
    }
}

/// The SVD of `m`, checked: nalgebra's SVD (0.35) occasionally returns factors that do not
/// reconstruct the matrix (seen on chain Jacobians with two equal columns, error 2e-2). The
/// result is accepted only when `‖U Σ Vᵀ − m‖ ≤ 1e-12 ‖m‖` and the singular vectors are
/// orthonormal to 1e-12; otherwise the SVD of the matrix with
/// its columns reversed is tried, and last a one-sided Jacobi SVD. A matrix with a non-finite
/// entry goes straight to the Jacobi SVD (nalgebra's does not terminate on it).
///
/// # Panics
/// Never: nalgebra's SVD is asked for both U and V, and returns both.
#[must_use]
pub fn svd(m: &DMatrix<f64>) -> Svd {
    let (rows, cols) = m.shape();
    if cols == 0 {
        return Svd {
            u: DMatrix::zeros(rows, 0),
            singular_values: Vec::new(),
            v: DMatrix::zeros(0, 0),
        };
    }
    // Pad to at least as many rows as columns so that every right singular vector is returned.
    let mut a = DMatrix::zeros(rows.max(cols), cols);
    a.view_mut((0, 0), (rows, cols)).copy_from(m);
    let scale = a.norm();
    if !scale.is_finite() {
        // nalgebra's SVD does not return on non-finite input; the Jacobi sweeps are bounded.
        return jacobi_svd(&a);
    }
    let reconstructs = |d: &Svd| {
        let mut sigma_vt = d.v.transpose();
        for (k, s) in d.singular_values.iter().enumerate() {
            sigma_vt.row_mut(k).scale_mut(*s);
        }
        let top = d.singular_values.first().copied().unwrap_or(0.0);
        let kept = d
            .singular_values
            .iter()
            .filter(|&&s| s > 1e-14 * top)
            .count();
        let u = d.u.columns(0, kept);
        (&d.u * sigma_vt - &a).norm() <= 1e-12 * scale.max(f64::MIN_POSITIVE)
            && (d.v.transpose() * &d.v - DMatrix::<f64>::identity(cols, cols)).norm() <= 1e-12
            && (u.transpose() * u - DMatrix::<f64>::identity(kept, kept)).norm() <= 1e-12
    };
    let nalgebra_svd = |a: &DMatrix<f64>, reversed: bool| {
        let s = a.clone().svd(true, true);
        let (u, v_t) = (s.u.expect("requested U"), s.v_t.expect("requested V"));
        let mut order: Vec<usize> = (0..cols).collect();
        order.sort_by(|&x, &y| s.singular_values[y].total_cmp(&s.singular_values[x]));
        let mut v = DMatrix::from_columns(
            &order
                .iter()
                .map(|&i| v_t.row(i).transpose())
                .collect::<Vec<_>>(),
        );
        if reversed {
            let flipped = DMatrix::from_fn(cols, cols, |r, c| v[(cols - 1 - r, c)]);
            v = flipped;
        }
        Svd {
            u: DMatrix::from_columns(
                &order
                    .iter()
                    .map(|&i| u.column(i).into_owned())
                    .collect::<Vec<_>>(),
            ),
            singular_values: order.iter().map(|&i| s.singular_values[i]).collect(),
            v,
        }
    };
    let reversed_a = DMatrix::from_fn(a.nrows(), cols, |r, c| a[(r, cols - 1 - c)]);
    let mut d = nalgebra_svd(&a, false);
    if !reconstructs(&d) {
        d = nalgebra_svd(&reversed_a, true);
    }
    if !reconstructs(&d) {
        d = jacobi_svd(&a);
    }
    d.u = d.u.rows(0, rows).into_owned();
    d
}

/// The SVD by one-sided (Hestenes) Jacobi rotations: the fallback of [`svd`]. Slower than
/// nalgebra's bidiagonal method but robust, and accurate for small singular values.
fn jacobi_svd(a: &DMatrix<f64>) -> Svd {
    let cols = a.ncols();
    let mut w = a.clone();
    let mut v = DMatrix::<f64>::identity(cols, cols);
    for _sweep in 0..60 {
        let mut rotated = false;
        for i in 0..cols {
            for j in i + 1..cols {
                let alpha = w.column(i).norm_squared();
                let beta = w.column(j).norm_squared();
                let gamma = w.column(i).dot(&w.column(j));
                if gamma == 0.0 || gamma.abs() <= f64::EPSILON * (alpha * beta).sqrt() {
                    continue;
                }
                rotated = true;
                let zeta = (beta - alpha) / (2.0 * gamma);
                let t = zeta.signum() / (zeta.abs() + (1.0 + zeta * zeta).sqrt());
                let c = 1.0 / (1.0 + t * t).sqrt();
                let sn = c * t;
                for m in [&mut w, &mut v] {
                    for r in 0..m.nrows() {
                        let (x, y) = (m[(r, i)], m[(r, j)]);
                        m[(r, i)] = c * x - sn * y;
                        m[(r, j)] = sn * x + c * y;
                    }
                }
            }
        }
        if !rotated {
            break;
        }
    }
    let norms: Vec<f64> = (0..cols).map(|k| w.column(k).norm()).collect();
    let mut order: Vec<usize> = (0..cols).collect();
    order.sort_by(|&x, &y| norms[y].total_cmp(&norms[x]));
    let top = norms.iter().copied().fold(0.0, f64::max);
    let mut u = DMatrix::zeros(a.nrows(), cols);
    for (k, &i) in order.iter().enumerate() {
        if top > 0.0 && norms[i] > 0.0 {
            u.column_mut(k).copy_from(&(w.column(i) / norms[i]));
        }
    }
    Svd {
        u,
        singular_values: order.iter().map(|&i| norms[i]).collect(),
        v: DMatrix::from_columns(
            &order
                .iter()
                .map(|&i| v.column(i).into_owned())
                .collect::<Vec<_>>(),
        ),
    }
}

/// The rank of the screws in the columns of `m`, by SVD with relative tolerance `tolerance`
/// (relative to the largest singular value; [`Svd::rank`] takes another scale).
#[must_use]
pub fn rank(m: &DMatrix<f64>, tolerance: f64) -> Rank {
    svd(m).rank(tolerance, None)
}

/// The rank of six screws (the columns of a 6×6 `m`, e.g. a 6-joint chain Jacobian) with
/// relative tolerance `tolerance`: the same number as [`rank`] (SVD), found faster.
///
/// A QR factorisation with column pivoting, `m P = Q R`, bounds the singular values: with
/// `r_kk` the diagonal of `R` and `σ` those of `m`, `σ_1 ∈ [|r_11|, √6 |r_11|]`,
/// `σ_k ≥ 3 |r_kk| / √(4^k + 6k − 1)` (Faddeev–Kublanovskaya–Faddeeva; Higham, *Accuracy and
/// Stability of Numerical Algorithms*, §20.1) and `σ_(k+1) ≤ √(6−k) |r_(k+1,k+1)|` (the
/// pivot is the largest remaining column). When these bounds put `σ_k / σ_1` above the tolerance
/// and `σ_(k+1) / σ_1` below it, the rank is `k` for certain; otherwise the singular values are
/// computed ([`svd`]) and counted. `tests/suite/screw.rs` checks the two agree.
///
/// # Panics
/// If `m` does not have exactly six columns.
#[must_use]
pub fn rank6(m: &Matrix6xX<f64>, tolerance: f64) -> usize {
    assert_eq!(m.ncols(), 6, "six screws");
    let fixed = Matrix6::from_iterator(m.iter().copied());
    let r = fixed.col_piv_qr().unpack_r();
    let d: [f64; 6] = std::array::from_fn(|k| r[(k, k)].abs());
    if d[0] == 0.0 {
        return 0;
    }
    let k = d.iter().filter(|&&x| x > tolerance * d[0]).count();
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_possible_wrap,
        reason = "k counts pivots of a six-column matrix, 1 to 6"
    )]
    let lower = |k: usize| {
        let kk = k as f64;
        3.0 * d[k - 1] / (4f64.powi(k as i32) + 6.0 * kk - 1.0).sqrt() / (6f64.sqrt() * d[0])
    };
    let upper = |k: usize| {
        if k == 6 {
            0.0
        } else {
            ((6 - k) as f64).sqrt() * d[k] / d[0]
        }
    };
    if k >= 1 && lower(k) > tolerance && upper(k) <= tolerance {
        return k;
    }
    rank(&DMatrix::from_column_slice(6, 6, m.as_slice()), tolerance).rank
}

/// An orthonormal basis (columns) of the span of the columns of `m`, and its rank report
/// (singular values below `tolerance ×` the largest are dropped).
#[must_use]
pub fn span_basis(m: &DMatrix<f64>, tolerance: f64) -> (DMatrix<f64>, Rank) {
    span_basis_scaled(m, tolerance, None)
}

/// [`span_basis`] with the tolerance relative to `scale` instead of the largest singular value
/// (for a block of an orthonormal basis, whose own largest value may be mere round-off).
#[must_use]
pub fn span_basis_scaled(
    m: &DMatrix<f64>,
    tolerance: f64,
    scale: Option<f64>,
) -> (DMatrix<f64>, Rank) {
    if m.ncols() == 0 || m.nrows() == 0 {
        return (DMatrix::zeros(m.nrows(), 0), Rank::empty(tolerance));
    }
    let d = svd(m);
    let rank = d.rank(tolerance, scale);
    (d.u.columns(0, rank.rank).into_owned(), rank)
}

/// An orthonormal basis of the null space of `m` (vectors `x` with `m x = 0`), with the rank
/// report of `m`.
#[must_use]
pub fn nullspace(m: &DMatrix<f64>, tolerance: f64) -> (DMatrix<f64>, Rank) {
    nullspace_scaled(m, tolerance, None)
}

/// [`nullspace`] with the tolerance relative to `scale` (see [`span_basis_scaled`]).
#[must_use]
pub fn nullspace_scaled(
    m: &DMatrix<f64>,
    tolerance: f64,
    scale: Option<f64>,
) -> (DMatrix<f64>, Rank) {
    let cols = m.ncols();
    if cols == 0 {
        return (DMatrix::zeros(0, 0), Rank::empty(tolerance));
    }
    let d = svd(m);
    let rank = d.rank(tolerance, scale);
    (d.v.columns(rank.rank, cols - rank.rank).into_owned(), rank)
}

/// A wide matrix `A` (m × n, m ≤ n) whose full row rank is certified without an SVD, factored
/// as `Aᵀ = Q₁ R` (Householder QR, `R` m × m upper triangular) with `Q = [Q₁ Q₂]` orthogonal:
/// `Q₁` spans the row space of `A`, `Q₂` its null space (the rates that keep its equations).
///
/// **The certificate.** The decision is the SVD's: rank m when `σ_m > tolerance · σ_1`. The
/// factors bound both values, `σ_1 ≤ ‖A‖_F` and `σ_m = 1/‖R⁻¹‖₂ ≥ 1/‖R⁻¹‖_F`, so
/// `1/‖R⁻¹‖_F > tolerance · ‖A‖_F` proves the rank m; the bounds lose at most a factor √m
/// each, so a matrix whose smallest singular value is within that factor of the cut, or
/// below it, is not certified and the caller takes the SVD ([`full_row_rank`] returns `None`).
/// Householder QR is backward stable, so the round-off in these bounds is of the order of
/// `ε ‖A‖`, far below any tolerance used here (1e-9 and up).
#[derive(Debug, Clone)]
pub struct FullRowRank {
    /// The orthogonal factor, n × n: the first m columns span the row space, the others the
    /// null space.
    q: DMatrix<f64>,
    /// The rows m of the matrix.
    rows: usize,
}

/// The certified factorisation of `a` when its rank is its number of rows at relative tolerance
/// `tolerance` (relative to its largest singular value), `None` when that cannot be certified
/// (more rows than columns, a rank below the rows, or a smallest singular value too near the
/// cut for the bounds of [`FullRowRank`]): then ask [`svd`].
#[must_use]
pub fn full_row_rank(a: &DMatrix<f64>, tolerance: f64) -> Option<FullRowRank> {
    let (m, n) = a.shape();
    let qr = certified_independent_columns(&a.transpose(), tolerance)?;
    let mut qt = DMatrix::<f64>::identity(n, n);
    qr.q_tr_mul(&mut qt);
    Some(FullRowRank {
        q: qt.transpose(),
        rows: m,
    })
}

/// The Householder QR of `m` when its columns are certified independent at relative tolerance
/// `tolerance` (every singular value above `tolerance ×` the largest, by the bounds of
/// [`FullRowRank`]); `None` when that cannot be certified.
fn certified_independent_columns(
    m: &DMatrix<f64>,
    tolerance: f64,
) -> Option<nalgebra::linalg::QR<f64, nalgebra::Dyn, nalgebra::Dyn>> {
    let (rows, cols) = m.shape();
    if cols > rows || cols == 0 {
        return None;
    }
    let norm = m.norm();
    if !norm.is_finite() || norm == 0.0 {
        return None;
    }
    let qr = m.clone().qr();
    // ‖R⁻¹‖_F from the triangular inverse (columns of R⁻¹ solve R x = e_k).
    let mut inverse = DMatrix::<f64>::identity(cols, cols);
    if !qr.r().solve_upper_triangular_mut(&mut inverse) {
        return None;
    }
    let inverse_norm = inverse.norm();
    (inverse_norm.is_finite() && inverse_norm * tolerance * norm < 1.0).then_some(qr)
}

/// The rank of `m` as [`Svd::rank`] decides it (singular values above `tolerance ×` the scale:
/// `scale`, or the largest singular value when `None`), certified from a QR with column
/// pivoting `m P = Q [R₁₁ R₁₂; 0 R₂₂]` (`R₁₁` r × r) where it can be, by the SVD otherwise.
///
/// **The certificate** holds for any pivoting: removing rows or columns does not raise singular
/// values, so `σ_r(m) ≥ σ_min(R₁₁) ≥ 1/‖R₁₁⁻¹‖_F`; and `[R₁₁ R₁₂; 0 0]` has rank r, so
/// `σ_(r+1)(m) ≤ ‖R₂₂‖₂ ≤ ‖R₂₂‖_F` (Eckart–Young). With the largest singular value between
/// `‖m‖_F/√k` and `‖m‖_F` (k columns), the rank is r for certain when the first bound is above
/// the cut and the second below it. The r tried is the number of diagonal entries of `R` above
/// the cut; where the bounds leave it open, the singular values are computed.
#[must_use]
pub fn rank_quick(m: &DMatrix<f64>, tolerance: f64, scale: Option<f64>) -> usize {
    let (rows, cols) = m.shape();
    let norm = m.norm();
    if rows == 0 || cols == 0 || norm == 0.0 {
        return 0;
    }
    if !norm.is_finite() {
        return svd(m).rank(tolerance, scale).rank;
    }
    // The cut, for certain above (keep) and for certain below (drop).
    let (keep_above, drop_below) = match scale {
        Some(s) => (tolerance * s, tolerance * s),
        #[expect(clippy::cast_precision_loss, reason = "a column count")]
        None => (tolerance * norm, tolerance * norm / (cols as f64).sqrt()),
    };
    let qr = m.clone().col_piv_qr();
    let r_full = qr.r();
    let k = rows.min(cols);
    let r = (0..k)
        .filter(|&i| r_full[(i, i)].abs() > keep_above)
        .count();
    let lower_ok = r == 0 || {
        let mut inverse = DMatrix::<f64>::identity(r, r);
        let r11 = r_full.view((0, 0), (r, r)).into_owned();
        r11.solve_upper_triangular_mut(&mut inverse) && inverse.norm() * keep_above < 1.0
    };
    let upper_ok = r_full.view((r, r), (k - r, cols - r)).norm() <= drop_below;
    if lower_ok && upper_ok {
        return r;
    }
    svd(m).rank(tolerance, scale).rank
}

/// An orthonormal basis of the span of the columns of `m` and its dimension, the rank decided
/// as [`span_basis`] decides it (relative tolerance `tolerance` of the largest singular value):
/// by a certified QR when the columns are independent ([`FullRowRank`]'s bounds), by the SVD
/// otherwise. For deciding patterns, where the singular values themselves are not reported.
#[must_use]
pub fn span_basis_quick(m: &DMatrix<f64>, tolerance: f64) -> (DMatrix<f64>, usize) {
    if let Some(qr) = certified_independent_columns(m, tolerance) {
        return (qr.q(), m.ncols());
    }
    let (basis, rank) = span_basis(m, tolerance);
    (basis, rank.rank)
}

impl FullRowRank {
    /// The rows m of the matrix factored (its rank).
    #[must_use]
    pub fn rank(&self) -> usize {
        self.rows
    }

    /// An orthonormal basis (columns) of the null space of the matrix: n − m vectors.
    #[must_use]
    pub fn null_basis(&self) -> DMatrix<f64> {
        let m = self.rank();
        self.q.columns(m, self.q.ncols() - m).into_owned()
    }
}

/// The Gauss–Newton step of least norm for the equations `a x = b`, the pseudo-inverse
/// solution `a⁺ b` when `a` has full rank: with m ≤ n unknowns `x = aᵀ (a aᵀ)⁻¹ b`, by the
/// Cholesky factor of the Gram matrix `a aᵀ`; with more equations than unknowns the
/// least-squares step `(aᵀ a)⁻¹ aᵀ b`. `None` when the Gram matrix is not numerically positive
/// definite (rank deficient or nearly so: take the damped steps of an SVD instead). No rank is
/// decided here: the caller keeps the step only if it reduces the residual.
#[must_use]
pub fn min_norm_step(a: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    let (m, n) = a.shape();
    if m == 0 || n == 0 || b.len() != m {
        return None;
    }
    let x = if m <= n {
        a.tr_mul(&(a * a.transpose()).cholesky()?.solve(b))
    } else {
        a.tr_mul(a).cholesky()?.solve(&a.tr_mul(b))
    };
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// A random direction, isotropic in the null space of the wide matrix `a` (the rates that keep
/// its equations): `g` minus its projection on the row space, `g − aᵀ (a aᵀ)⁻¹ a g`, for `g`
/// drawn by `draw` with one entry per column. `None` unless the rows of `a` are certified
/// independent at relative tolerance `tolerance` (the SVD's decision, `σ_m > tolerance ·
/// σ_1`): the Gram matrix's Cholesky factor `L` bounds `σ_m² ≥ 1/‖L⁻¹‖_F²`, which must clear
/// the cut and the round-off of forming `a aᵀ` (`m ε ‖a‖_F²`, with a factor 100 to spare).
/// With the certificate, the null space has dimension n − m.
#[must_use]
pub fn null_direction(
    a: &DMatrix<f64>,
    tolerance: f64,
    draw: impl FnMut(usize, usize) -> f64,
) -> Option<DVector<f64>> {
    let cholesky = independent_rows(a, tolerance)?;
    let g = DVector::from_fn(a.ncols(), draw);
    let z = cholesky.solve(&(a * &g));
    Some(g - a.tr_mul(&z))
}

/// The Cholesky factor of the Gram matrix `a aᵀ` when the rows of `a` are certified independent
/// at relative tolerance `tolerance` (the bound of [`null_direction`]), `None` otherwise.
#[must_use]
pub fn independent_rows(
    a: &DMatrix<f64>,
    tolerance: f64,
) -> Option<nalgebra::Cholesky<f64, nalgebra::Dyn>> {
    let (m, n) = a.shape();
    if m > n || m == 0 {
        return None;
    }
    let norm2 = a.norm_squared();
    if !norm2.is_finite() || norm2 == 0.0 {
        return None;
    }
    let cholesky = (a * a.transpose()).cholesky()?;
    let mut inverse = DMatrix::<f64>::identity(m, m);
    // Only the lower triangle of `l_dirty` is the factor; the solve reads only that.
    if !cholesky.l_dirty().solve_lower_triangular_mut(&mut inverse) {
        return None;
    }
    #[expect(clippy::cast_precision_loss, reason = "a row count")]
    let round_off = 100.0 * m as f64 * f64::EPSILON;
    let lower = 1.0 / inverse.norm_squared();
    // A NaN bound certifies nothing.
    if lower.is_nan() || lower <= (tolerance * tolerance + round_off) * norm2 {
        return None;
    }
    Some(cholesky)
}

/// The truncated least-squares solution of `a x ≈ b` ([`least_squares`]).
#[derive(Debug, Clone, PartialEq)]
pub struct LeastSquares {
    /// The solution over the kept directions: among the `x` that minimise `‖a x − b‖` once the
    /// dropped singular values are taken as zero, the one of smallest norm (`x = A⁺ b` with the
    /// truncated pseudo-inverse).
    pub x: DVector<f64>,
    /// The dropped directions (orthonormal columns, right singular vectors): those along which
    /// `a` is below the cut-off, so that adding any combination of them to `x` changes `a x`
    /// by round-off only. No columns when `a` has full column rank at the cut-off.
    pub dropped: DMatrix<f64>,
}

/// The minimum-norm least-squares solution of `a x ≈ b`, truncated at the absolute cut-off
/// `cutoff`: singular values of `a` at or below it count as zero, their directions are left out
/// of `x` and returned as [`LeastSquares::dropped`].
///
/// The cut-off is absolute, not relative: the callers solve with blocks of orthonormal bases
/// (whose singular values are at most 1, so a tiny one is round-off whatever the largest is)
/// or with matrices of unit-size entries.
///
/// # Panics
/// If `b` does not have as many rows as `a`.
#[must_use]
pub fn least_squares(a: &DMatrix<f64>, b: &DVector<f64>, cutoff: f64) -> LeastSquares {
    assert_eq!(a.nrows(), b.nrows(), "one right-hand side per row");
    let d = svd(a);
    let mut x = DVector::zeros(a.ncols());
    let mut dropped = Vec::new();
    for (k, &sigma) in d.singular_values.iter().enumerate() {
        if sigma > cutoff && k < d.u.ncols() {
            x += d.v.column(k) * (d.u.column(k).dot(b) / sigma);
        } else {
            dropped.push(d.v.column(k).into_owned());
        }
    }
    let dropped = if dropped.is_empty() {
        DMatrix::zeros(a.ncols(), 0)
    } else {
        DMatrix::from_columns(&dropped)
    };
    LeastSquares { x, dropped }
}
