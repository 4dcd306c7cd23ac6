//! Screws: twists, wrenches, Plücker lines, adjoint transforms, the reciprocal product and the
//! rank of screw systems.
//!
//! Conventions (DESIGN.md): a twist is `t = (ω; v)`, the angular velocity and the velocity of
//! the body point that coincides with the frame origin; a wrench is `w = (f; m)`, the force and
//! the moment about the origin. The reciprocal (virtual power) product is `w · t = f·v + m·ω`.
//! The joint screw of a revolute with unit axis `u` through `p` is `(u; p × u)`; of a prismatic
//! joint along `u`, `(0; u)`.
//!
//! ```
//! use kinsyn::screw::{Twist, Wrench, reciprocal_product};
//! use nalgebra::Vector3;
//! // A revolute about z through (1, 0, 0) and a pure force along z through the same point:
//! // the force does no work on the rotation (they intersect).
//! let r = Twist::revolute(Vector3::z(), Vector3::new(1.0, 0.0, 0.0));
//! let f = Wrench::force(Vector3::z(), Vector3::new(1.0, 0.0, 0.0));
//! assert!(reciprocal_product(&f, &r).abs() < 1e-12);
//! ```

pub use crate::spatial::{Twist, adjoint, skew, transform_twist};
use nalgebra::{DMatrix, Matrix6, Vector3, Vector6};

/// The default relative tolerance of ranks: singular values below this fraction of the largest
/// one count as zero (DESIGN.md).
pub const DEFAULT_RANK_TOLERANCE: f64 = 1e-9;

/// A wrench `(f; m)`: a force and its moment about the frame origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wrench {
    /// Force.
    pub f: Vector3<f64>,
    /// Moment about the origin.
    pub m: Vector3<f64>,
}

/// The joint screws of screw theory and the geometry of a twist (its pitch and axis); the
/// type and its coordinates are defined with the displacements in [`crate::spatial`].
impl Twist {
    /// The unit twist of a revolute joint: rotation about the line through `point` along the
    /// unit vector `axis`, `(u; p × u)`.
    #[must_use]
    pub fn revolute(axis: Vector3<f64>, point: Vector3<f64>) -> Self {
        Twist {
            w: axis,
            v: point.cross(&axis),
        }
    }

    /// The unit twist of a prismatic joint along `axis`, `(0; u)`.
    #[must_use]
    pub fn prismatic(axis: Vector3<f64>) -> Self {
        Twist {
            w: Vector3::zeros(),
            v: axis,
        }
    }

    /// A helical twist of pitch `pitch` about the line through `point` along `axis`.
    #[must_use]
    pub fn helical(axis: Vector3<f64>, point: Vector3<f64>, pitch: f64) -> Self {
        Twist {
            w: axis,
            v: point.cross(&axis) + axis * pitch,
        }
    }

    /// The velocity of the body point at `point`: `v + ω × p`.
    #[must_use]
    pub fn velocity_at(&self, point: &Vector3<f64>) -> Vector3<f64> {
        self.v + self.w.cross(point)
    }

    /// The same motion with its reference point moved to `point` (twist about a new origin at
    /// `point`, axes unchanged): `(ω; v + ω × p)`.
    #[must_use]
    pub fn at_point(&self, point: &Vector3<f64>) -> Self {
        Twist {
            w: self.w,
            v: self.velocity_at(point),
        }
    }

    /// The pitch `ω·v / ω·ω` of a twist with rotation; `None` for a pure translation.
    #[must_use]
    pub fn pitch(&self) -> Option<f64> {
        let ww = self.w.norm_squared();
        (ww > 0.0).then(|| self.w.dot(&self.v) / ww)
    }

    /// The screw axis of a twist with rotation: the point of the axis nearest the origin and
    /// the unit direction, `p = ω × v / |ω|²`.
    #[must_use]
    pub fn axis(&self) -> Option<(Vector3<f64>, Vector3<f64>)> {
        let ww = self.w.norm_squared();
        (ww > 0.0).then(|| (self.w.cross(&self.v) / ww, self.w / ww.sqrt()))
    }
}

impl Wrench {
    /// A pure force of unit direction `dir` along the line through `point`: `(f; p × f)`.
    #[must_use]
    pub fn force(dir: Vector3<f64>, point: Vector3<f64>) -> Self {
        Wrench {
            f: dir,
            m: point.cross(&dir),
        }
    }

    /// A pure couple (moment) `m`.
    #[must_use]
    pub fn couple(m: Vector3<f64>) -> Self {
        Wrench {
            f: Vector3::zeros(),
            m,
        }
    }

    /// The six coordinates `(f; m)`.
    #[must_use]
    pub fn to_vector(&self) -> Vector6<f64> {
        Vector6::new(self.f.x, self.f.y, self.f.z, self.m.x, self.m.y, self.m.z)
    }

    /// From six coordinates `(f; m)`.
    #[must_use]
    pub fn from_vector(x: &Vector6<f64>) -> Self {
        Wrench {
            f: Vector3::new(x[0], x[1], x[2]),
            m: Vector3::new(x[3], x[4], x[5]),
        }
    }
}

/// The virtual power of a wrench on a twist, `f·v + m·ω`: zero when the wrench is reciprocal
/// to (does no work on) the twist.
#[must_use]
pub fn reciprocal_product(w: &Wrench, t: &Twist) -> f64 {
    w.f.dot(&t.v) + w.m.dot(&t.w)
}

/// The Lie bracket of two twists, `[t1, t2] = (ω1 × ω2; ω1 × v2 − ω2 × v1)`: the motion that
/// the commutator of the two infinitesimal displacements produces. A set of twists is the Lie
/// algebra of a displacement subgroup exactly when its span is closed under this bracket.
#[must_use]
pub fn lie_bracket(a: &Twist, b: &Twist) -> Twist {
    Twist {
        w: a.w.cross(&b.w),
        v: a.w.cross(&b.v) - b.w.cross(&a.v),
    }
}

/// A Plücker line: unit direction and moment about the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// Unit direction.
    pub direction: Vector3<f64>,
    /// Moment `p × direction` for any point `p` of the line.
    pub moment: Vector3<f64>,
}

impl Line {
    /// The line through `point` along `direction` (normalised).
    #[must_use]
    pub fn through(point: Vector3<f64>, direction: Vector3<f64>) -> Self {
        let d = direction.normalize();
        Line {
            direction: d,
            moment: point.cross(&d),
        }
    }

    /// The point of the line nearest the origin.
    #[must_use]
    pub fn nearest_point(&self) -> Vector3<f64> {
        self.direction.cross(&self.moment)
    }

    /// The reciprocal product of two lines as screws (mutual moment): zero when they are
    /// coplanar (intersect or are parallel).
    #[must_use]
    pub fn mutual_moment(&self, other: &Line) -> f64 {
        self.direction.dot(&other.moment) + self.moment.dot(&other.direction)
    }
}

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

/// The SVD of `m`, checked: nalgebra's SVD (0.35) occasionally returns factors that do not
/// reconstruct the matrix (seen on chain Jacobians with two equal columns, error 2e-2). The
/// result is accepted only when `‖U Σ Vᵀ − m‖ ≤ 1e-12 ‖m‖` and the singular vectors are
/// orthonormal to 1e-12; otherwise the SVD of the matrix with
/// its columns reversed is tried, and last a one-sided Jacobi SVD. A matrix with a non-finite
/// entry goes straight to the Jacobi SVD (nalgebra's does not terminate on it).
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

/// The rank of the screws in the columns of `m`, by SVD with relative tolerance `tolerance`.
#[must_use]
pub fn rank(m: &DMatrix<f64>, tolerance: f64) -> Rank {
    let sv = svd(m).singular_values;
    let top = sv.first().copied().unwrap_or(0.0);
    let rank = sv
        .iter()
        .filter(|&&s| top > 0.0 && s > tolerance * top)
        .count();
    Rank {
        rank,
        singular_values: sv,
        tolerance,
        scale: top,
    }
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
/// computed (nalgebra's SVD) and counted. `tests/screw.rs` checks the two agree.
///
/// # Panics
/// If `m` does not have exactly six columns.
#[must_use]
pub fn rank6(m: &nalgebra::Matrix6xX<f64>, tolerance: f64) -> usize {
    assert_eq!(m.ncols(), 6, "six screws");
    let fixed = Matrix6::from_iterator(m.iter().copied());
    let r = fixed.col_piv_qr().unpack_r();
    let d: [f64; 6] = std::array::from_fn(|k| r[(k, k)].abs());
    if d[0] == 0.0 {
        return 0;
    }
    let k = d.iter().filter(|&&x| x > tolerance * d[0]).count();
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
        return (
            DMatrix::zeros(m.nrows(), 0),
            Rank {
                rank: 0,
                singular_values: Vec::new(),
                tolerance,
                scale: 0.0,
            },
        );
    }
    let d = svd(m);
    let top = scale.unwrap_or_else(|| d.singular_values.first().copied().unwrap_or(0.0));
    let r = d
        .singular_values
        .iter()
        .filter(|&&s| top > 0.0 && s > tolerance * top)
        .count();
    let basis = d.u.columns(0, r).into_owned();
    (
        basis,
        Rank {
            rank: r,
            singular_values: d.singular_values,
            tolerance,
            scale: top,
        },
    )
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
        return (
            DMatrix::zeros(0, 0),
            Rank {
                rank: 0,
                singular_values: Vec::new(),
                tolerance,
                scale: 0.0,
            },
        );
    }
    let d = svd(m);
    let top = scale.unwrap_or_else(|| d.singular_values.first().copied().unwrap_or(0.0));
    let r = d
        .singular_values
        .iter()
        .filter(|&&s| top > 0.0 && s > tolerance * top)
        .count();
    let basis = d.v.columns(r, cols - r).into_owned();
    (
        basis,
        Rank {
            rank: r,
            singular_values: d.singular_values,
            tolerance,
            scale: top,
        },
    )
}

/// The wrenches reciprocal to every twist in the columns of `twists`: the constraint wrench
/// system of a twist system (a basis, one wrench `(f; m)` per column).
///
/// A wrench `w` is reciprocal to `t` when `f·v + m·ω = 0`, i.e. `(Δ t)ᵀ w = 0` with `Δ` the
/// block swap; the result is the null space of `(Δ T)ᵀ`.
#[must_use]
pub fn reciprocal_complement(twists: &DMatrix<f64>, tolerance: f64) -> DMatrix<f64> {
    let n = twists.ncols();
    let mut swapped = DMatrix::zeros(n, 6);
    for j in 0..n {
        for k in 0..3 {
            swapped[(j, k)] = twists[(k + 3, j)];
            swapped[(j, k + 3)] = twists[(k, j)];
        }
    }
    if n == 0 {
        return DMatrix::identity(6, 6);
    }
    nullspace(&swapped, tolerance).0
}
