//! Loop closure: the bodies' displacements along the spanning tree, the current joint screws,
//! the loop-closure Jacobian (one 6-row block per chord) and its residual.

use super::{Mechanism, compose, inverse, log};
use crate::chain::Displacement;
use crate::screw::{Twist, transform_twist};
use nalgebra::{DMatrix, DVector};

impl Mechanism {
    /// The displacement of every body from its reference pose at joint values `q`.
    ///
    /// # Panics
    /// If `q` has fewer values than the mechanism has joints.
    #[must_use]
    pub fn poses(&self, q: &[f64]) -> Vec<Displacement> {
        assert!(q.len() >= self.joints.len(), "one value per joint");
        let mut poses = vec![crate::spatial::identity(); self.body_count()];
        for &(body, step) in &self.order {
            if let Some((joint, sign)) = step {
                let j = &self.joints[joint];
                let parent = if sign > 0.0 { j.from } else { j.to };
                poses[body] = compose(&poses[parent], &j.displacement(sign * q[joint]));
            }
        }
        poses
    }

    /// The current screw of every joint at `q` (in the ground frame): the reference screw
    /// carried by the displacement of the body it is fixed to.
    #[must_use]
    pub fn joint_screws(&self, q: &[f64]) -> Vec<Twist> {
        self.screws_at(&self.poses(q))
    }

    /// The current joint screws from the bodies' displacements.
    pub(super) fn screws_at(&self, poses: &[Displacement]) -> Vec<Twist> {
        self.joints
            .iter()
            .map(|j| {
                let g = &poses[j.from];
                transform_twist(&g.rotation, &g.translation.vector, &j.screw())
            })
            .collect()
    }

    /// The tree path from the ground to `body`: each joint with +1 when crossed from its
    /// `from` body to its `to` body.
    #[must_use]
    pub fn path(&self, body: usize) -> &[(usize, f64)] {
        &self.paths[body]
    }

    /// The spatial Jacobian of `body` along its tree path: its twist is `J q̇` (6 × joints,
    /// zero columns for joints off the path).
    #[must_use]
    pub fn body_jacobian(&self, body: usize, screws: &[Twist]) -> DMatrix<f64> {
        let mut j = DMatrix::zeros(6, self.joints.len());
        for &(joint, sign) in &self.paths[body] {
            j.column_mut(joint)
                .copy_from(&(screws[joint].to_vector() * sign));
        }
        j
    }

    /// The loop-closure Jacobian (6 rows per loop × joints): for the chord `a → b` of each loop,
    /// `V_b − V_a − ξ' q̇ = 0`.
    #[must_use]
    pub fn closure_jacobian(&self, screws: &[Twist]) -> DMatrix<f64> {
        let mut c = DMatrix::zeros(6 * self.chords.len(), self.joints.len());
        for (l, &chord) in self.chords.iter().enumerate() {
            let j = &self.joints[chord];
            // The body Jacobian of `to` minus that of `from`, column by column along their
            // tree paths, and the chord's own screw.
            let terms = self.paths[j.to]
                .iter()
                .map(|&(joint, sign)| (joint, sign))
                .chain(
                    self.paths[j.from]
                        .iter()
                        .map(|&(joint, sign)| (joint, -sign)),
                )
                .chain(std::iter::once((chord, -1.0)));
            for (joint, sign) in terms {
                let s = screws[joint].to_vector();
                for r in 0..6 {
                    c[(6 * l + r, joint)] += sign * s[r];
                }
            }
        }
        c
    }

    /// How far each loop is from closing at `q`: for the chord `a → b`, the screw `ε = log D`
    /// of `D = g_a exp(ξ q) g_b⁻¹` (6 entries per loop). Zero when assembled.
    #[must_use]
    pub fn closure_residual(&self, q: &[f64]) -> DVector<f64> {
        self.residual_at(q, &self.poses(q))
    }

    /// [`Mechanism::closure_residual`] with the bodies' displacements at `q` given.
    pub(super) fn residual_at(&self, q: &[f64], poses: &[Displacement]) -> DVector<f64> {
        let mut r = DVector::zeros(6 * self.chords.len());
        for (l, &chord) in self.chords.iter().enumerate() {
            let j = &self.joints[chord];
            let d = compose(
                &compose(&poses[j.from], &j.displacement(q[chord])),
                &inverse(&poses[j.to]),
            );
            r.rows_mut(6 * l, 6).copy_from(&log(&d).to_vector());
        }
        r
    }

    /// The dimensionless copy of a matrix of twists over joint rates (see
    /// [`Mechanism::unitless_twists`]), prismatic columns times the length scale so that every
    /// column is a unit screw.
    pub(super) fn dimensionless(&self, m: &DMatrix<f64>) -> DMatrix<f64> {
        let mut out = self.unitless_twists(m);
        for c in 0..out.ncols().min(self.joints.len()) {
            out.column_mut(c).scale_mut(self.unit(c));
        }
        out
    }
}
