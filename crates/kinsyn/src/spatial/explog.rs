//! The exponential and logarithm of SE(3) and SO(3), evaluated without cancellation near the
//! identity and exactly through a half turn.
//!
//! nalgebra's `Rotation3::angle` and `Rotation3::scaled_axis` read the angle from
//! `acos((tr R − 1)/2)`, which loses half the digits near the identity (nalgebra 0.35 returns 0
//! for every angle up to 1e-8 and is 5 % off at 2e-8, `tests/suite/spatial.rs`); [`rotation_log`]
//! reads `sin θ` from the skew part, and the axis of a half turn, where the skew part vanishes,
//! from the symmetric part instead.

use super::{Displacement, Twist, skew};
use nalgebra::{Matrix3, Rotation3, Vector3};

/// The screw `ε` (a spatial twist) with `exp(ε) = g`: the logarithm of a rigid displacement,
/// with the rotation angle `|ω|` in `[0, π]` (Murray–Li–Sastry §2.3: the exponential of
/// twists is onto SE(3); here in the `(ω; v)` order). At a half turn both senses of the axis are logarithms; the one of
/// [`rotation_log`] is returned.
#[must_use]
pub fn log(g: &Displacement) -> Twist {
    let w = rotation_log(&g.rotation);
    let v = translation_map(&w)
        .try_inverse()
        .map_or(g.translation.vector, |inverse| {
            inverse * g.translation.vector
        });
    Twist { w, v }
}

/// The map `V` that gives the translation `p = V v` of `exp((ω; v))` for a rotation `ω` of
/// angle θ: `V = I + (1 − cos θ)/θ² [ω] + (θ − sin θ)/θ³ [ω]²`. The coefficients are
/// evaluated without cancellation: `(1 − cos θ)/θ² = 2 sin²(θ/2)/θ²`, and `(θ − sin θ)/θ³` by
/// its Taylor series below 0.01 rad (the direct form loses every digit near θ = 1e-8).
fn translation_map(w: &Vector3<f64>) -> Matrix3<f64> {
    let theta = w.norm();
    let k = skew(w);
    let (a, b) = if theta < 1e-2 {
        let t2 = theta * theta;
        (
            0.5 - t2 / 24.0 + t2 * t2 / 720.0,
            1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0,
        )
    } else {
        let half = (theta / 2.0).sin() / theta;
        (
            2.0 * half * half,
            (theta - theta.sin()) / (theta * theta * theta),
        )
    };
    Matrix3::identity() + k * a + k * k * b
}

/// The rotation vector (axis × angle, angle in [0, π]) of a rotation, accurate for small angles:
/// the angle from `atan2(sin θ, cos θ)` with `sin θ` read from the skew part.
#[must_use]
pub fn rotation_log(r: &Rotation3<f64>) -> Vector3<f64> {
    let m = r.matrix();
    let skew = Vector3::new(
        m[(2, 1)] - m[(1, 2)],
        m[(0, 2)] - m[(2, 0)],
        m[(1, 0)] - m[(0, 1)],
    ) / 2.0;
    let sin = skew.norm();
    let cos = ((m.trace() - 1.0) / 2.0).clamp(-1.0, 1.0);
    let theta = sin.atan2(cos);
    if cos > -0.5 {
        // Away from a half turn the skew part carries the axis accurately.
        return if sin > 0.0 {
            skew * (theta / sin)
        } else {
            Vector3::zeros()
        };
    }
    // Near a half turn: (R + Rᵀ)/2 = cos θ I + (1 − cos θ) n nᵀ; read n from its largest
    // diagonal entry's column, and its sense from the skew part (sin θ · n).
    let sym = (m + m.transpose()) / 2.0 - Matrix3::identity() * cos;
    let k = (0..3)
        .max_by(|&a, &b| sym[(a, a)].total_cmp(&sym[(b, b)]))
        .unwrap_or(0);
    let mut n = Vector3::new(sym[(0, k)], sym[(1, k)], sym[(2, k)]);
    n /= n.norm().max(f64::MIN_POSITIVE);
    if n.dot(&skew) < 0.0 {
        n = -n;
    }
    n * theta
}

/// The rigid displacement `exp(ε)` of a twist held for unit time (the inverse of [`log`]):
/// `(exp [ω], V v)` with `V = I + (1 − cos θ)/θ² [ω] + (θ − sin θ)/θ³ [ω]²`, θ = |ω|:
/// Murray–Li–Sastry §2.3's exponential of a twist, written for an unnormalised `ω`.
#[must_use]
pub fn exp(t: &Twist) -> Displacement {
    super::displacement(
        Rotation3::from_scaled_axis(t.w),
        translation_map(&t.w) * t.v,
    )
}

/// The inverse of the left Jacobian of SO(3) at the rotation vector `r`: the map from the
/// spatial angular velocity to the rate of the rotation vector, `ṙ = J_l⁻¹(r) ω`, with
/// `J_l⁻¹ = I − [r]/2 + (1 − (θ/2) cot(θ/2))/θ² [r]²` (θ = |r| < π).
#[must_use]
pub fn inverse_left_jacobian(r: &Vector3<f64>) -> Matrix3<f64> {
    let theta = r.norm();
    let k = r.cross_matrix();
    // Coefficient of [r]²: (1 − θ/2 · cot(θ/2)) / θ², with its series at small θ.
    let c = if theta < 1e-4 {
        1.0 / 12.0 + theta * theta / 720.0
    } else {
        (1.0 - 0.5 * theta / (0.5 * theta).tan()) / (theta * theta)
    };
    Matrix3::identity() - 0.5 * k + c * k * k
}
