//! Mobility: the joint rates compatible with loop closure (the null space of the closure
//! Jacobian over the free joints) and the twists they give a body.

use super::{MOBILITY_TOLERANCE, Mechanism};
use crate::linalg;
use crate::screw::Twist;
use nalgebra::DMatrix;

/// The result of a mobility analysis at one configuration.
#[derive(Debug, Clone)]
pub struct Mobility {
    /// Dimension of the joint-rate null space of the loop-closure Jacobian (free joints only).
    pub dof: usize,
    /// Rank report of the (dimensionless) loop-closure Jacobian.
    pub closure_rank: linalg::Rank,
    /// A basis of compatible rates of the free joints (columns, one entry per free joint, in
    /// joint order; prismatic rates in length units).
    pub rates: DMatrix<f64>,
}

impl Mechanism {
    /// The free joints of a lock mask.
    pub(super) fn free(&self, locked: &[bool]) -> Vec<usize> {
        (0..self.joints.len())
            .filter(|&j| !locked.get(j).copied().unwrap_or(false))
            .collect()
    }

    /// The mobility at `q` with the `locked` joints held: the dimension of the null space of the
    /// loop-closure Jacobian over the free joints.
    #[must_use]
    pub fn mobility(&self, q: &[f64], locked: &[bool]) -> Mobility {
        let screws = self.joint_screws(q);
        self.mobility_with(&screws, locked)
    }

    fn mobility_with(&self, screws: &[Twist], locked: &[bool]) -> Mobility {
        let free = self.free(locked);
        let (mut basis, rank) = self.unitless_rates(screws, &free);
        // Back to physical rates: prismatic rates in length units.
        for (k, &j) in free.iter().enumerate() {
            basis.row_mut(k).scale_mut(self.unit(j));
        }
        Mobility {
            dof: basis.ncols(),
            closure_rank: rank,
            rates: basis,
        }
    }

    /// An orthonormal basis of the dimensionless rates of the `free` joints (prismatic rates
    /// over the length scale) that keep every loop closed, with the rank decision of the
    /// dimensionless loop-closure Jacobian (unit-screw columns, so its largest singular value
    /// is not round-off).
    fn unitless_rates(&self, screws: &[Twist], free: &[usize]) -> (DMatrix<f64>, linalg::Rank) {
        let cf = self.free_closure(screws, free);
        if cf.nrows() == 0 {
            return (
                DMatrix::identity(free.len(), free.len()),
                linalg::Rank {
                    rank: 0,
                    singular_values: Vec::new(),
                    tolerance: MOBILITY_TOLERANCE,
                    scale: 0.0,
                },
            );
        }
        linalg::nullspace(&cf, MOBILITY_TOLERANCE)
    }

    /// An orthonormal basis of the dimensionless rates of the `free` joints that keep every loop
    /// closed: the null space of [`Mechanism::unitless_rates`], found by a certified QR when
    /// the closure equations are independent (the rank decision is then the SVD's, see
    /// [`linalg::FullRowRank`]) and by the SVD otherwise. Only the span is asked for here,
    /// not the singular values: the hot path of sampled motions.
    pub(super) fn unitless_rate_basis(&self, screws: &[Twist], free: &[usize]) -> DMatrix<f64> {
        rate_basis(&self.free_closure(screws, free))
    }

    /// The dimensionless loop-closure Jacobian over the `free` joints only (unit-screw
    /// columns): the equations every compatible rate of them meets.
    pub(super) fn free_closure(&self, screws: &[Twist], free: &[usize]) -> DMatrix<f64> {
        let c = self.dimensionless(&self.closure_jacobian(screws));
        DMatrix::from_fn(c.nrows(), free.len(), |r, k| c[(r, free[k])])
    }

    /// The twist space of `body` at `q` with the `locked` joints held: a basis (columns) of the
    /// spatial twists `(ω; v)` it can have, and the local degrees of freedom (its dimension).
    #[must_use]
    pub fn twist_space(&self, body: usize, q: &[f64], locked: &[bool]) -> (DMatrix<f64>, usize) {
        let screws = self.joint_screws(q);
        let (basis, rank) = self.unitless_twist_space(body, &screws, locked);
        (self.physical_twists(&basis), rank.rank)
    }

    /// The twist space of `body` in the dimensionless form ([`Mechanism::unitless_twists`]): an
    /// orthonormal basis and the rank decision. The body's twists are its dimensionless Jacobian
    /// over an orthonormal basis of the compatible (dimensionless) joint rates, so their size is
    /// judged against the norm of that Jacobian (unit screws), not against their own largest
    /// value, which is round-off when the body cannot move.
    pub(crate) fn unitless_twist_space(
        &self,
        body: usize,
        screws: &[Twist],
        locked: &[bool],
    ) -> (DMatrix<f64>, linalg::Rank) {
        self.unitless_span(&self.body_jacobian(body, screws), screws, locked)
    }

    /// The twists a Jacobian `jacobian` (6 × joints, physical spatial twists over joint rates)
    /// gives over the joint rates that keep every loop closed with the `locked` joints held, in
    /// the dimensionless form: an orthonormal basis and the rank decision (see
    /// [`Mechanism::unitless_twist_space`]).
    pub(crate) fn unitless_span(
        &self,
        jacobian: &DMatrix<f64>,
        screws: &[Twist],
        locked: &[bool],
    ) -> (DMatrix<f64>, linalg::Rank) {
        let (basis, rank, _) = self.unitless_span_and_freedom(jacobian, screws, locked);
        (basis, rank)
    }

    /// [`Mechanism::unitless_span`] and the mechanism's degrees of freedom with the `locked`
    /// joints held (the dimension of the rates that keep the loops closed, over which the span
    /// is taken).
    pub(crate) fn unitless_span_and_freedom(
        &self,
        jacobian: &DMatrix<f64>,
        screws: &[Twist],
        locked: &[bool],
    ) -> (DMatrix<f64>, linalg::Rank, usize) {
        let free = self.free(locked);
        let rates = self.unitless_rate_basis(screws, &free);
        let j = self.dimensionless(jacobian);
        let jf = DMatrix::from_fn(6, free.len(), |r, k| j[(r, free[k])]);
        let norm = jf.norm();
        let freedom = rates.ncols();
        let (basis, rank) =
            linalg::span_basis_scaled(&(jf * rates), MOBILITY_TOLERANCE, Some(norm.max(1.0)));
        (basis, rank, freedom)
    }
}

/// The two rank decisions behind the dimension of an image of the compatible joint rates
/// ([`Mechanism::twist_space_ranks`], [`Mechanism::joint_freedom_ranks_with_body_held`]): the
/// rank of the equations that the rates keep, and of those equations stacked on the rows of the
/// image. The dimension is their difference.
///
/// Each is the rank of a matrix of fixed shape that depends analytically on the configuration,
/// so it can only drop at special configurations, never rise: its value at generic
/// configurations is the largest over random assemblies. The difference can move either way
/// at a special configuration (a drop of either rank), so a generic dimension is the
/// difference of the two generic ranks, not the extreme of the differences.
#[derive(Debug, Clone, PartialEq)]
pub struct ImageRanks {
    /// The rank of the equations the rates keep (dimensionless loop closure over the free
    /// joints, with any held rows).
    pub equations: linalg::Rank,
    /// The rank of the equations stacked on the image's rows.
    pub stacked: linalg::Rank,
}

impl ImageRanks {
    /// The dimension of the image: `stacked − equations`.
    #[must_use]
    pub fn dimension(&self) -> usize {
        self.stacked.rank.saturating_sub(self.equations.rank)
    }
}

impl Mechanism {
    /// How many independent rates the `joints` can have at `q` with the `locked` joints held and
    /// `body` held still: the dimension of their rates over the joint rates that keep every
    /// loop closed and give `body` no twist ([`Mechanism::joint_freedom_ranks_with_body_held`]).
    /// For a manipulator's inputs and its end-effector, more than at generic configurations is
    /// an inverse (serial) singularity: inputs that move while the end-effector stays.
    #[must_use]
    pub fn joint_freedom_with_body_held(
        &self,
        body: usize,
        q: &[f64],
        locked: &[bool],
        joints: &[usize],
    ) -> usize {
        self.joint_freedom_ranks_with_body_held(body, q, locked, joints)
            .dimension()
    }

    /// The rank decisions behind [`Mechanism::joint_freedom_with_body_held`]: with `C` the
    /// dimensionless loop-closure Jacobian over the free joints, `B` the body's dimensionless
    /// Jacobian and `E` the rows that pick the `joints`' rates, the rates of `joints` over
    /// `null [C; B]` span `rank [C; B; E] − rank [C; B]` dimensions ([`MOBILITY_TOLERANCE`]).
    #[must_use]
    pub fn joint_freedom_ranks_with_body_held(
        &self,
        body: usize,
        q: &[f64],
        locked: &[bool],
        joints: &[usize],
    ) -> ImageRanks {
        let screws = self.joint_screws(q);
        let free = self.free(locked);
        let c = self.dimensionless(&self.closure_jacobian(&screws));
        let b = self.dimensionless(&self.body_jacobian(body, &screws));
        let equations = DMatrix::from_fn(c.nrows() + 6, free.len(), |r, k| {
            if r < c.nrows() {
                c[(r, free[k])]
            } else {
                b[(r - c.nrows(), free[k])]
            }
        });
        let picked: Vec<usize> = joints
            .iter()
            .filter_map(|j| free.iter().position(|f| f == j))
            .collect();
        let pick = DMatrix::from_fn(picked.len(), free.len(), |r, k| {
            if picked[r] == k { 1.0 } else { 0.0 }
        });
        stacked_ranks(&equations, &pick)
    }

    /// The rank decisions behind the dimension of `body`'s twist space at `q` with the
    /// `locked` joints held ([`Mechanism::twist_space`]): `rank [C; B] − rank C`, with `C` the
    /// dimensionless loop-closure Jacobian over the free joints and `B` the body's
    /// dimensionless Jacobian ([`MOBILITY_TOLERANCE`]).
    #[must_use]
    pub fn twist_space_ranks(&self, body: usize, q: &[f64], locked: &[bool]) -> ImageRanks {
        let screws = self.joint_screws(q);
        let free = self.free(locked);
        let c = self.free_closure(&screws, &free);
        let b = self.dimensionless(&self.body_jacobian(body, &screws));
        let bf = DMatrix::from_fn(6, free.len(), |r, k| b[(r, free[k])]);
        stacked_ranks(&c, &bf)
    }
}

/// `rank a` and `rank [a; image]` at [`MOBILITY_TOLERANCE`] of each matrix's largest singular
/// value.
fn stacked_ranks(a: &DMatrix<f64>, image: &DMatrix<f64>) -> ImageRanks {
    let stacked = DMatrix::from_fn(a.nrows() + image.nrows(), a.ncols(), |r, k| {
        if r < a.nrows() {
            a[(r, k)]
        } else {
            image[(r - a.nrows(), k)]
        }
    });
    ImageRanks {
        equations: linalg::rank(a, MOBILITY_TOLERANCE),
        stacked: linalg::rank(&stacked, MOBILITY_TOLERANCE),
    }
}

/// An orthonormal basis of the null space of the dimensionless closure equations `cf` (rows)
/// over the free joints (columns), at [`MOBILITY_TOLERANCE`]: empty when the columns are
/// certified independent, from a certified QR when the rows are, by the SVD otherwise
/// ([`linalg::independent_rows`], [`linalg::full_row_rank`]).
pub(super) fn rate_basis(cf: &DMatrix<f64>) -> DMatrix<f64> {
    let n = cf.ncols();
    if cf.nrows() == 0 {
        return DMatrix::identity(n, n);
    }
    // As many equations as free joints or more, certified independent columns: no rate.
    if cf.nrows() >= n && linalg::independent_rows(&cf.transpose(), MOBILITY_TOLERANCE).is_some() {
        return DMatrix::zeros(n, 0);
    }
    match linalg::full_row_rank(cf, MOBILITY_TOLERANCE) {
        Some(f) => f.null_basis(),
        None => linalg::nullspace(cf, MOBILITY_TOLERANCE).0,
    }
}
