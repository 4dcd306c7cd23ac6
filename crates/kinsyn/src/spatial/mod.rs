//! Rigid displacements: the group SE(3), its Lie algebra se(3) of twists, and the maps between
//! them — composition, inverse, exponential and logarithm, the adjoint action on twists — and
//! the Study parameters (dual quaternions) of paper 004 in [`study`].
//!
//! This is the bottom layer of kinsyn: it knows nalgebra and nothing else of the crate. The
//! screw theory of [`crate::screw`] (joint screws, wrenches, lines, reciprocity, ranks), the serial
//! chains of [`crate::chain`] and the mechanism graph of [`crate::mechanism`] are built on it; their
//! old paths (`chain::compose`, `mechanism::exp`, `screw::adjoint`, …) re-export these items.
//!
//! # Conventions
//! - A rigid displacement `g = (R, p)` ([`Displacement`]) moves a body point at `x` (ground
//!   frame, before the motion) to `R x + p`: rotation about the origin, then translation. In
//!   homogeneous form `g = [R p; 0 1]` (Murray, Li, Sastry, *A Mathematical Introduction to
//!   Robotic Manipulation*, 1994, §2.2).
//! - `compose(a, b)` is the product `a · b`, `x ↦ R_a (R_b x + p_b) + p_a`: the displacement `b`
//!   followed by `a` in the ground frame, or `a` followed by `b` expressed in the frame `a`
//!   carries — the order of the product of exponentials `exp(ξ₁q₁) exp(ξ₂q₂) ···`.
//! - A twist `(ω; v)` ([`Twist`]) is an element of se(3) in the order of ARCHITECTURE.md's conventions: the angular
//!   velocity, then the velocity of the body point at the frame origin. (Murray–Li–Sastry write
//!   `(v; ω)`; their formulas are used here with the blocks swapped.)
//! - `exp(ξ)` is the displacement after moving with the twist `ξ` for unit time, `log` its
//!   inverse with a rotation angle in `[0, π]` ([`exp`], [`log`], [`rotation_log`]).
//! - The adjoint `Ad_g` maps twists to twists: `(ω; v) ↦ (R ω; R v + p × R ω)` ([`adjoint`],
//!   [`transform_twist`]), so that `Ad_{g h} = Ad_g Ad_h` and `exp(Ad_g ξ) = g exp(ξ) g⁻¹`.
//!
//! ```
//! use kinsyn::spatial::{Twist, compose, exp, inverse, log, rotation_log};
//! use nalgebra::Vector3;
//! // A quarter turn about the z axis through (1, 0, 0): the origin moves to (1, −1, 0).
//! let quarter = std::f64::consts::FRAC_PI_2;
//! let xi = Twist { w: Vector3::z() * quarter, v: Vector3::new(0.0, -quarter, 0.0) };
//! let g = exp(&xi);
//! assert!((g.translation.vector - Vector3::new(1.0, -1.0, 0.0)).norm() < 1e-12);
//! // The logarithm gives the twist back, and g · g⁻¹ is the identity.
//! assert!((log(&g).to_vector() - xi.to_vector()).norm() < 1e-12);
//! let e = compose(&g, &inverse(&g)); // also `g * g.inverse()`
//! assert!(e.translation.vector.norm() < 1e-12 && rotation_log(&e.rotation).norm() < 1e-12);
//! ```

mod explog;
pub mod study;

pub use explog::{exp, inverse_left_jacobian, log, rotation_log};

use nalgebra::{IsometryMatrix3, Matrix3, Matrix6, Rotation3, Translation3, Vector3, Vector6};

/// A twist `(ω; v)`: an element of se(3), the instantaneous motion of a rigid body — `ω` its
/// angular velocity, `v` the velocity of the body point at the frame origin (ARCHITECTURE.md, Conventions). The
/// joint screws, pitch and axis of a twist are screw theory and live in [`crate::screw`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Twist {
    /// Angular velocity.
    pub w: Vector3<f64>,
    /// Velocity of the body point at the origin.
    pub v: Vector3<f64>,
}

impl Twist {
    /// The six coordinates `(ω; v)`.
    #[must_use]
    pub fn to_vector(&self) -> Vector6<f64> {
        Vector6::new(self.w.x, self.w.y, self.w.z, self.v.x, self.v.y, self.v.z)
    }

    /// From six coordinates `(ω; v)`.
    #[must_use]
    pub fn from_vector(x: &Vector6<f64>) -> Self {
        Twist {
            w: Vector3::new(x[0], x[1], x[2]),
            v: Vector3::new(x[3], x[4], x[5]),
        }
    }
}

/// A rigid displacement `g = (R, p)`: rotation, then translation (`x ↦ R x + p`) — nalgebra's
/// isometry with a rotation *matrix* (`g.rotation`, `g.translation.vector`), so that products
/// and inverses are the plain matrix formulas (`a · b = (R_a R_b, R_a p_b + p_a)`,
/// `g⁻¹ = (Rᵀ, −Rᵀ p)`). `a * b` is [`compose`], `g.inverse()` is [`inverse`].
pub type Displacement = IsometryMatrix3<f64>;

/// The displacement `(R, p)` from its rotation and translation.
#[must_use]
pub fn displacement(rotation: Rotation3<f64>, translation: Vector3<f64>) -> Displacement {
    IsometryMatrix3::from_parts(Translation3::from(translation), rotation)
}

/// The identity displacement `(I, 0)`.
#[must_use]
pub fn identity() -> Displacement {
    IsometryMatrix3::identity()
}

/// `a` then `b`: the displacement `a · b`.
#[must_use]
pub fn compose(a: &Displacement, b: &Displacement) -> Displacement {
    a * b
}

/// The inverse displacement `g⁻¹ = (Rᵀ, −Rᵀ p)`.
#[must_use]
pub fn inverse(g: &Displacement) -> Displacement {
    g.inverse()
}

/// The skew-symmetric matrix of `x`: `[x] y = x × y`.
#[must_use]
pub fn skew(x: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -x.z, x.y, x.z, 0.0, -x.x, -x.y, x.x, 0.0)
}

/// The adjoint matrix of the rigid displacement `(R, p)` acting on twists `(ω; v)`:
/// `(ω; v) ↦ (R ω; R v + p × R ω)`, i.e. `[[R, 0], [[p] R, R]]` (Murray–Li–Sastry §2.4 with
/// the blocks in kinsyn's order). It carries a twist expressed in a moved frame back to the
/// fixed frame (change of frame and of reference point together).
#[must_use]
pub fn adjoint(rotation: &Rotation3<f64>, translation: &Vector3<f64>) -> Matrix6<f64> {
    let r = rotation.matrix();
    let mut m = Matrix6::zeros();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(r);
    m.fixed_view_mut::<3, 3>(3, 3).copy_from(r);
    m.fixed_view_mut::<3, 3>(3, 0)
        .copy_from(&(skew(translation) * r));
    m
}

/// Applies the rigid displacement `(R, p)` to a twist: the same motion seen after the body
/// frame has been displaced (see [`adjoint`]).
#[must_use]
pub fn transform_twist(rotation: &Rotation3<f64>, translation: &Vector3<f64>, t: &Twist) -> Twist {
    let w = rotation * t.w;
    Twist {
        w,
        v: rotation * t.v + translation.cross(&w),
    }
}
