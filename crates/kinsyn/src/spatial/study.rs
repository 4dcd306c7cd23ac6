//! Study parameters: Study's kinematic mapping of SE(3) onto the Study quadric in P⁷, the
//! algebraic coordinates of rigid displacements used for constraint polynomials (paper 004 §3,
//! eqs. 4–7, after Husty, Pfurner, Schröcker, Brunthaler, *Algebraic methods in mechanism
//! analysis and synthesis*, Robotica 25(6), 2007 — paper 004's reference 30).
//!
//! A displacement is the projective point `[x0 : x1 : x2 : x3 : y0 : y1 : y2 : y3]`, the dual
//! quaternion `x + ε y` with `x = x0 + x1 i + x2 j + x3 k` and `y = y0 + y1 i + y2 j + y3 k`,
//! defined up to a common non-zero factor. It represents a displacement exactly when (eq. 7)
//! - it lies on the **Study quadric** `x0 y0 + x1 y1 + x2 y2 + x3 y3 = 0` ([`quadric_residual`],
//!   paper 004's `g13`), and
//! - `x ≠ 0`: the points with `x0 = x1 = x2 = x3 = 0` (the exceptional generator) are no
//!   displacement.
//!
//! # Convention (paper 004 eqs. 4–5, checked in `tests/suite/spatial.rs`)
//! The matrix `M` of eq. 4 ([`matrix`]) acts on homogeneous points written `(1, x, y, z)ᵀ`, the
//! homogenising coordinate **first**, as the paper writes its points (eqs. 2, 3) and applies
//! `M` to them (eq. 9, `r⁰ = M r¹`):
//! `M = [[Δ, 0ᵀ], [M_T, M_R]]`, `Δ = x0² + x1² + x2² + x3²`, so `M (1; p) = (Δ; M_T + M_R p)`
//! and the displacement is `p ↦ R p + t` with `R = M_R / Δ`, `t = M_T / Δ`.
//! - `M_R / Δ` is the rotation of the unit quaternion `x / |x|` acting as `v ↦ x v x̄ / Δ`: a
//!   rotation by θ about the unit axis `u` has `x ∝ (cos θ/2, sin θ/2 · u)` (eq. 5's `M_R` for
//!   `x = (cos θ/2, 0, 0, sin θ/2)` is the right-handed rotation about z by θ).
//! - `M_T` of eq. 5 is `2 vec(x ȳ) = −2 vec(y x̄)` term by term, so `t = 2 x ȳ / Δ` (the scalar
//!   part of `x ȳ` is `x·y`, zero on the quadric), and conversely, for `|x| = 1`,
//!   **`y = −½ t x`** with `t` the pure quaternion `(0, t)`. This is Husty's sign; the common
//!   dual-quaternion convention `x + ε ½ t x` (e.g. Selig, *Geometric Fundamentals of
//!   Robotics*) has the opposite `y`. Paper 004's constraint equations (eqs. 11a, 12a) use this
//!   sign too: `tests/suite/spatial.rs` evaluates them at the parameters of known poses.
//!
//! # Normalisation
//! [`normalise`] divides by `|x|`, so that `x0² + x1² + x2² + x3² = 1` (paper 004's `g14`,
//! [`normalisation_residual`]), which leaves the sign: `x` and `−x` give the same displacement.
//! kinsyn's choice is **`x0 ≥ 0`**; when `x0 = 0` (a half turn) the first non-zero of
//! `x1, x2, x3` is made positive. [`from_displacement`] returns `x0 = cos(θ/2)` with θ in
//! `[0, π]` the angle of [`super::rotation_log`], so its parameters are normalised already.
//!
//! ```
//! use kinsyn::spatial::{exp, Twist, study};
//! use nalgebra::Vector3;
//! // A screw motion about z: a quarter turn and a rise of 2.
//! let g = exp(&Twist { w: Vector3::z() * std::f64::consts::FRAC_PI_2, v: Vector3::z() * 1.27 });
//! let s = study::from_displacement(&g);
//! assert!(study::quadric_residual(&s).abs() < 1e-15);
//! // Any multiple of the parameters gives the displacement back.
//! let scaled: Vec<f64> = s.iter().map(|c| -3.0 * c).collect();
//! let back = study::to_displacement(&scaled.try_into().unwrap(), study::QUADRIC_TOLERANCE).unwrap();
//! assert!((back.translation.vector - g.translation.vector).norm() < 1e-12);
//! assert!((back.rotation.matrix() - g.rotation.matrix()).amax() < 1e-12);
//! ```

use super::Displacement;
use nalgebra::{Matrix3, Matrix4, Rotation3, Vector3};

/// Study parameters `[x0, x1, x2, x3, y0, y1, y2, y3]`: the dual quaternion `x + ε y`, a point
/// of P⁷ (module documentation for the convention).
pub type StudyParameters = [f64; 8];

/// The default tolerance of [`to_displacement`] on the relative quadric residual
/// `|x·y| / (|x| |y|)`, the cosine of the angle between `x` and `y` in R⁴: free of the
/// projective scale and of the unit of length.
pub const QUADRIC_TOLERANCE: f64 = 1e-9;

/// The length of `y` (with `|x| = 1`) below which [`to_displacement`] judges the quadric
/// residual against this length rather than against `|y|`.
pub const NEGLIGIBLE_DUAL: f64 = 1e-6;

/// Why eight numbers are not the Study parameters of a displacement (paper 004 eq. 7).
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum StudyError {
    /// A parameter is NaN or infinite.
    #[error("the Study parameters are not all finite")]
    NotFinite,
    /// `x0 = x1 = x2 = x3 = 0`: the point lies on the exceptional generator of the Study
    /// quadric, which represents no displacement. Solutions of constraint equations meet it
    /// unless the normalisation `x0² + x1² + x2² + x3² = 1` is among the equations.
    #[error("x0 = x1 = x2 = x3 = 0: a point of the exceptional generator, not a displacement")]
    ExceptionalGenerator,
    /// `x0 y0 + x1 y1 + x2 y2 + x3 y3 ≠ 0`: the point is off the Study quadric. The residual
    /// is the relative one, `|x·y| / (|x| |y|)`; a solver's point this far off should be
    /// refined, or the tolerance raised if the data are known to be that rough.
    #[error("off the Study quadric: |x·y| / (|x| |y|) = {residual:.3e} exceeds {tolerance:e}")]
    OffQuadric {
        /// The relative residual `|x·y| / (|x| |y|)`.
        residual: f64,
        /// The tolerance it exceeds.
        tolerance: f64,
    },
}

/// The Study quadric `x0 y0 + x1 y1 + x2 y2 + x3 y3` (paper 004 eq. 7, `g13`): zero for the
/// parameters of every displacement. It scales with the square of the projective factor and
/// with the unit of length (`y` is a length); [`to_displacement`] checks a relative form.
#[must_use]
pub fn quadric_residual(s: &StudyParameters) -> f64 {
    s[0] * s[4] + s[1] * s[5] + s[2] * s[6] + s[3] * s[7]
}

/// The normalisation `x0² + x1² + x2² + x3² − 1` (paper 004 `g14`): zero for normalised
/// parameters, such as those of [`from_displacement`] and [`normalise`].
#[must_use]
pub fn normalisation_residual(s: &StudyParameters) -> f64 {
    s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[3] * s[3] - 1.0
}

/// The relative quadric residual `|x·y| / (|x| |y|)` (zero when `y = 0`), the cosine of the
/// angle between `x` and `y` in R⁴: free of the projective scale and of the unit of length, the
/// quantity [`to_displacement`] checks against its tolerance. `NaN` when `x = 0`.
#[must_use]
pub fn relative_quadric_residual(s: &StudyParameters) -> f64 {
    let x = s[..4].iter().map(|c| c * c).sum::<f64>().sqrt();
    let y = s[4..].iter().map(|c| c * c).sum::<f64>().sqrt();
    if y > 0.0 {
        quadric_residual(s).abs() / (x * y)
    } else {
        0.0
    }
}

/// The normalised Study parameters of a displacement `(R, t)`: `x = (cos θ/2, sin θ/2 · u)`
/// for the rotation by θ ∈ `[0, π]` about `u` ([`super::rotation_log`], accurate near the
/// identity and at a half turn), and `y = −½ t x` (module documentation). They satisfy the
/// quadric and the normalisation to round-off, with `x0 ≥ 0`.
#[must_use]
pub fn from_displacement(g: &Displacement) -> StudyParameters {
    let r = super::rotation_log(&g.rotation);
    let theta = r.norm();
    let half = theta / 2.0;
    // sin(θ/2)/θ, whose limit at θ = 0 is 1/2 (and r = 0 there anyway).
    let factor = if theta > 0.0 { half.sin() / theta } else { 0.5 };
    let x0 = half.cos();
    let xv = r * factor;
    let t = &g.translation.vector;
    // y = −½ (0, t)(x0, x⃗) = −½ (−t·x⃗, x0 t + t × x⃗).
    let y0 = 0.5 * t.dot(&xv);
    let yv = -0.5 * (t * x0 + t.cross(&xv));
    [x0, xv.x, xv.y, xv.z, y0, yv.x, yv.y, yv.z]
}

/// The matrix `M` of paper 004 eqs. 4–5 (Husty et al. 2007), for any eight numbers:
/// `[[Δ, 0ᵀ], [M_T, M_R]]` with `Δ = x0² + x1² + x2² + x3²`, acting on homogeneous points
/// `(1, p)` with the homogenising coordinate first. For Study parameters of a displacement
/// `(R, t)` it is `Δ [[1, 0ᵀ], [t, R]]`, so `M (1; p) = Δ (1; R p + t)`.
#[must_use]
pub fn matrix(s: &StudyParameters) -> Matrix4<f64> {
    let [x0, x1, x2, x3, y0, y1, y2, y3] = *s;
    let delta = x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3;
    let m_t = Vector3::new(
        2.0 * (-x0 * y1 + x1 * y0 - x2 * y3 + x3 * y2),
        2.0 * (-x0 * y2 + x1 * y3 + x2 * y0 - x3 * y1),
        2.0 * (-x0 * y3 - x1 * y2 + x2 * y1 + x3 * y0),
    );
    #[rustfmt::skip]
    let m_r = Matrix3::new(
        x0 * x0 + x1 * x1 - x2 * x2 - x3 * x3, 2.0 * (x1 * x2 - x0 * x3), 2.0 * (x1 * x3 + x0 * x2),
        2.0 * (x1 * x2 + x0 * x3), x0 * x0 - x1 * x1 + x2 * x2 - x3 * x3, 2.0 * (x2 * x3 - x0 * x1),
        2.0 * (x1 * x3 - x0 * x2), 2.0 * (x2 * x3 + x0 * x1), x0 * x0 - x1 * x1 - x2 * x2 + x3 * x3,
    );
    let mut m = Matrix4::zeros();
    m[(0, 0)] = delta;
    m.fixed_view_mut::<3, 1>(1, 0).copy_from(&m_t);
    m.fixed_view_mut::<3, 3>(1, 1).copy_from(&m_r);
    m
}

/// The Study parameters divided by `|x|` and signed so that `x0 ≥ 0` (the first non-zero of
/// `x1, x2, x3` positive when `x0 = 0`): the representative with `x0² + x1² + x2² + x3² = 1`
/// of the projective point. The quadric is not checked (see [`to_displacement`]).
///
/// # Errors
/// [`StudyError::NotFinite`] for a NaN or infinite parameter,
/// [`StudyError::ExceptionalGenerator`] when `x = 0`.
pub fn normalise(s: &StudyParameters) -> Result<StudyParameters, StudyError> {
    if !s.iter().all(|c| c.is_finite()) {
        return Err(StudyError::NotFinite);
    }
    // Scale by the largest magnitude first, so that |x|² neither underflows nor overflows.
    let largest = s.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    if largest == 0.0 {
        return Err(StudyError::ExceptionalGenerator);
    }
    let scaled = s.map(|c| c / largest);
    let norm = scaled[..4].iter().map(|c| c * c).sum::<f64>().sqrt();
    if norm == 0.0 {
        return Err(StudyError::ExceptionalGenerator);
    }
    let leading = scaled[..4]
        .iter()
        .copied()
        .find(|&c| c != 0.0)
        .unwrap_or(1.0);
    let factor = if leading < 0.0 { -norm } else { norm };
    Ok(scaled.map(|c| c / factor))
}

/// The displacement `(R, t)` of Study parameters given up to a non-zero factor: normalised by
/// [`normalise`], then read from [`matrix`] (`R = M_R / Δ`, `t = M_T / Δ`).
///
/// # Errors
/// [`StudyError::NotFinite`], [`StudyError::ExceptionalGenerator`] as [`normalise`], and
/// [`StudyError::OffQuadric`] when the relative residual `|x·y| / (|x| |y|)` exceeds
/// `tolerance` ([`QUADRIC_TOLERANCE`] by default). With `|x| = 1`, a `y` shorter than
/// [`NEGLIGIBLE_DUAL`] (a translation of the order of a numerical solver's noise at the
/// parameters' scale) has no meaningful direction: its residual is taken relative to that
/// length instead, so that a rotation about the origin computed with rounding errors in `y` is
/// read as the rotation.
pub fn to_displacement(s: &StudyParameters, tolerance: f64) -> Result<Displacement, StudyError> {
    let n = normalise(s)?;
    let y_norm = n[4..].iter().map(|c| c * c).sum::<f64>().sqrt();
    let residual = quadric_residual(&n).abs() / y_norm.max(NEGLIGIBLE_DUAL);
    if residual > tolerance {
        return Err(StudyError::OffQuadric {
            residual,
            tolerance,
        });
    }
    let m = matrix(&n);
    let delta = m[(0, 0)];
    let rotation = m.fixed_view::<3, 3>(1, 1) / delta;
    let translation = m.fixed_view::<3, 1>(1, 0) / delta;
    Ok(super::displacement(
        Rotation3::from_matrix_unchecked(rotation),
        translation.into_owned(),
    ))
}
