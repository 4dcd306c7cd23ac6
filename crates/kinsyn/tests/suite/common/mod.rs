//! Helpers shared by the integration tests: an independent Jacobian by finite differences, and
//! Singular, the exact check of some tests ([`singular`]).

pub mod singular;

use kinsyn::chain::SerialChain;
use kinsyn::screw::Twist;
use nalgebra::{DMatrix, Matrix3, Vector3};

/// The spatial twist of the motion q(t) = q + `t·e_i` by central differences of g(q), step h:
/// ω from (dR/dt) Rᵀ, v = dp/dt − ω × p.
#[must_use]
pub fn finite_difference_column(c: &SerialChain, q: &[f64], i: usize, h: f64) -> Twist {
    let mut qp = q.to_vec();
    let mut qm = q.to_vec();
    qp[i] += h;
    qm[i] -= h;
    let gp = c.forward(&qp);
    let (rp, pp) = (gp.rotation, gp.translation.vector);
    let gm = c.forward(&qm);
    let (rm, pm) = (gm.rotation, gm.translation.vector);
    let g0 = c.forward(q);
    let (r0, p0) = (g0.rotation, g0.translation.vector);
    let dr: Matrix3<f64> = (rp.matrix() - rm.matrix()) / (2.0 * h);
    let w_hat = dr * r0.matrix().transpose();
    let w = Vector3::new(w_hat[(2, 1)], w_hat[(0, 2)], w_hat[(1, 0)]);
    let dp = (pp - pm) / (2.0 * h);
    Twist {
        w,
        v: dp - w.cross(&p0),
    }
}

/// The whole Jacobian by finite differences (6 × n, twists `(ω; v)` in the columns).
#[allow(dead_code)]
#[must_use]
pub fn finite_difference_jacobian(c: &SerialChain, q: &[f64], h: f64) -> DMatrix<f64> {
    let mut j = DMatrix::zeros(6, c.len());
    for i in 0..c.len() {
        j.column_mut(i)
            .copy_from_slice(finite_difference_column(c, q, i, h).to_vector().as_slice());
    }
    j
}
