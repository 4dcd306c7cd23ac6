//! The motion of one body relative to another: the displacement `h = g_a⁻¹ g_b` of body `b`
//! seen from body `a` (both displacements from their reference poses), its twists and its
//! finite motion pattern.
//!
//! The twist of `h` is `ḣ h⁻¹ = Ad(g_a⁻¹) (V_b − V_a)`: the difference of the two spatial twists,
//! carried into the frame of `a` (the ground frame where `a` is at its reference pose). The
//! relative displacements form a group exactly when these twists span one Lie subalgebra at every
//! configuration, as for a body relative to the ground ([`crate::motion::classify`]). Two links
//! that always turn together (opposite sides of a parallelogram, paper 003 §2.1, option 2) have
//! `ω_b = ω_a`: every relative twist is a translation.

use super::motion::SampledMotion;
use super::{Mechanism, MechanismError, SampleSettings, compose, inverse};
use crate::chain::Displacement;
use crate::motion::Classification;
use crate::spatial::adjoint;
use nalgebra::{DMatrix, Matrix6};

impl Mechanism {
    /// The displacement of `body` relative to `base` at joint values `q`, `g_base⁻¹ g_body`
    /// (each the body's displacement from its reference pose): the identity at the reference.
    ///
    /// # Panics
    /// If `q` has fewer values than the mechanism has joints, or a body index is out of range.
    #[must_use]
    pub fn relative_pose(&self, body: usize, base: usize, q: &[f64]) -> Displacement {
        let poses = self.poses(q);
        compose(&inverse(&poses[base]), &poses[body])
    }

    /// The Jacobian of the motion of `body` relative to `base` at joint values `q`: its twist
    /// `(ω; v)` (v the velocity of the point at the origin of `base`'s frame carried from the
    /// ground frame at the reference) is this 6 × joints matrix times the joint rates,
    /// `Ad(g_base⁻¹) (J_body − J_base)`.
    ///
    /// # Panics
    /// As [`Mechanism::relative_pose`].
    #[must_use]
    pub fn relative_jacobian(&self, body: usize, base: usize, q: &[f64]) -> DMatrix<f64> {
        let screws = self.joint_screws(q);
        self.relative_jacobian_with(body, base, &self.poses(q), &screws)
    }

    fn relative_jacobian_with(
        &self,
        body: usize,
        base: usize,
        poses: &[Displacement],
        screws: &[crate::screw::Twist],
    ) -> DMatrix<f64> {
        let back = inverse(&poses[base]);
        let ad: Matrix6<f64> = adjoint(&back.rotation, &back.translation.vector);
        let ad = DMatrix::from_fn(6, 6, |r, c| ad[(r, c)]);
        ad * (self.body_jacobian(body, screws) - self.body_jacobian(base, screws))
    }

    /// The twist space of `body` relative to `base` at `q` with the `locked` joints held: a basis
    /// (columns) of the relative twists `(ω; v)` of [`Mechanism::relative_jacobian`] over the
    /// joint rates that keep every loop closed, and its dimension (the relative degrees of
    /// freedom).
    ///
    /// # Panics
    /// As [`Mechanism::relative_pose`].
    #[must_use]
    pub fn relative_twist_space(
        &self,
        body: usize,
        base: usize,
        q: &[f64],
        locked: &[bool],
    ) -> (DMatrix<f64>, usize) {
        let poses = self.poses(q);
        let screws = self.screws_at(&poses);
        let j = self.relative_jacobian_with(body, base, &poses, &screws);
        let (basis, rank) = self.unitless_span(&j, &screws, locked);
        (self.physical_twists(&basis), rank.rank)
    }

    /// The finite motion of `body` relative to `base`, sampled as in
    /// [`Mechanism::sample_motion`] (the same walks; the relative displacement and twists at
    /// each sample).
    ///
    /// # Errors
    /// As [`Mechanism::sample_motion`].
    pub fn sample_relative_motion(
        &self,
        body: usize,
        base: usize,
        start: &[f64],
        locked: &[bool],
        settings: &SampleSettings,
    ) -> Result<SampledMotion, MechanismError> {
        self.sample_observed(start, locked, settings, |q| {
            let poses = self.poses(q);
            let screws = self.screws_at(&poses);
            let j = self.relative_jacobian_with(body, base, &poses, &screws);
            let (twists, rank, freedom) = self.unitless_span_and_freedom(&j, &screws, locked);
            (
                compose(&inverse(&poses[base]), &poses[body]),
                twists,
                rank,
                freedom,
            )
        })
    }

    /// The motion pattern of `body` relative to `base` with the `locked` joints held, from finite
    /// motion sampled from `start` ([`Mechanism::sample_relative_motion`]): a displacement group
    /// when the relative displacements form one. Directions, points and pitches are in the frame
    /// of `base` (the ground frame where `base` is at its reference pose), in the mechanism's
    /// length unit.
    ///
    /// # Errors
    /// As [`Mechanism::sample_motion`].
    pub fn relative_motion_pattern(
        &self,
        body: usize,
        base: usize,
        start: &[f64],
        locked: &[bool],
        settings: &SampleSettings,
    ) -> Result<Classification, MechanismError> {
        let motion = self.sample_relative_motion(body, base, start, locked, settings)?;
        Ok(self.classify_motion(&motion))
    }
}
