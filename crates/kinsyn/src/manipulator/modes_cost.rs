//! What sampling the motions of lock subsets costs, decided before any sampling.
//!
//! The unit is the **loop closure**: one Newton-corrected assembly of the mechanism
//! ([`crate::mechanism::SampledMotion::closures`]), the work that dominates a sampled motion
//! (each closure is a few damped Newton steps; the rank decisions at the samples come on top,
//! about one closure's worth per sample). A subset's count depends on what its locks leave at
//! the start:
//!
//! - **rigid** (no joint rate keeps the loops closed with those inputs held): every walk stops
//!   before its first step, so the motion is one closure, the start's;
//! - **free to move**: `1 + samples × steps` closures at a regular start (the start, then each
//!   walk's steps), and at most `1 + samples × WALK_ATTEMPTS × steps × STEP_TRIES` when walks
//!   end too near earlier samples and are walked again, and steps are halved until the loops
//!   close ([`crate::mechanism::WALK_ATTEMPTS`], [`crate::mechanism::STEP_TRIES`]). Starts where
//!   the locked mechanism is singular take more walks and more Newton steps per closure
//!   (Newton converges only linearly there); `docs/limits.md` gives the CPU measured per class.
//!
//! Whether a subset's locks leave the start rigid is decided from one null space: with `N` an
//! orthonormal basis of the joint rates that keep the loops closed when every joint is free (`M`
//! columns), the rates with the locked joints held are `N y` with `N_L y = 0` (`N_L` the rows of
//! the locked joints), so the start keeps `M − rank N_L` degrees of freedom. One SVD of the
//! closure Jacobian, then a rank of at most `inputs × M` entries per subset: far cheaper than a
//! loop closure.

use super::Manipulator;
use crate::linalg;
use crate::mechanism::{MOBILITY_TOLERANCE, STEP_TRIES, SampleSettings, WALK_ATTEMPTS};
use nalgebra::DMatrix;
use serde::Serialize;

/// The cost of sampling the motions of some lock subsets from one start, in loop closures,
/// decided before any sampling ([`Manipulator::modes_cost`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct ModesCost {
    /// The lock subsets.
    pub subsets: usize,
    /// Those whose locks leave the start rigid: one loop closure each.
    pub rigid: usize,
    /// The loop closures at regular starts: one per rigid subset,
    /// [`ModesCost::closures_per_motion`] per other.
    pub closures: u64,
    /// The most loop closures the sampling can run: one per rigid subset,
    /// [`ModesCost::most_closures_per_motion`] per other.
    pub most_closures: u64,
}

impl ModesCost {
    /// The loop closures of a motion sampled with `settings` from a regular start its locks
    /// leave free to move: the start's, then `steps` per walk, one walk per sample.
    #[must_use]
    pub fn closures_per_motion(settings: &SampleSettings) -> u64 {
        1 + (settings.samples.max(1) as u64) * (settings.steps as u64)
    }

    /// The most loop closures of a motion sampled with `settings`: every sample walked
    /// [`WALK_ATTEMPTS`] times, every step tried [`STEP_TRIES`] times.
    #[must_use]
    pub fn most_closures_per_motion(settings: &SampleSettings) -> u64 {
        1 + (settings.samples.max(1) as u64)
            * (WALK_ATTEMPTS as u64)
            * (settings.steps as u64)
            * (STEP_TRIES as u64)
    }
}

impl Manipulator {
    /// The cost of [`Manipulator::modes_from`] with the same `start`, `subsets` and
    /// `settings`, decided before any sampling: which subsets' locks leave the start rigid
    /// (module documentation), and the loop closures at regular starts and at most.
    ///
    /// The rigid decision is made on the start as given (the sampling first closes the loops
    /// there, which moves an assembled start by round-off only) at the rank tolerance of the
    /// sampling's ([`MOBILITY_TOLERANCE`]), on the null space of the closure equations rather
    /// than on the locked equations themselves: the two agree wherever the decision is not
    /// within round-off of the tolerance.
    ///
    /// # Complexity
    /// One SVD of the closure Jacobian, then per subset the rank of a `locks × M` matrix (`M`
    /// the degrees of freedom with every joint free).
    #[must_use]
    pub fn modes_cost(
        &self,
        start: &[f64],
        subsets: &[Vec<usize>],
        settings: &SampleSettings,
    ) -> ModesCost {
        // The compatible rates with every joint free, back in the dimensionless form in which
        // the sampling decides (prismatic rates over the length scale): orthonormal columns.
        let mut rates = self.mechanism.mobility(start, &[]).rates;
        for j in 0..rates.nrows() {
            rates.row_mut(j).unscale_mut(self.mechanism.unit(j));
        }
        let rigid = subsets
            .iter()
            .filter(|locked| Self::leaves_rigid(&rates, &self.locked_joints(locked)))
            .count();
        let moving = (subsets.len() - rigid) as u64;
        ModesCost {
            subsets: subsets.len(),
            rigid,
            closures: rigid as u64 + moving * ModesCost::closures_per_motion(settings),
            most_closures: rigid as u64 + moving * ModesCost::most_closures_per_motion(settings),
        }
    }

    /// The joints of a set of locked inputs (indices into the actuators), each once.
    fn locked_joints(&self, locked: &[usize]) -> Vec<usize> {
        let mask = self.lock_mask(locked);
        (0..mask.len()).filter(|&j| mask[j]).collect()
    }

    /// Whether holding the `joints` leaves no joint rate of the basis `rates` (orthonormal
    /// columns, one row per joint): the rows of the held joints have full column rank.
    fn leaves_rigid(rates: &DMatrix<f64>, joints: &[usize]) -> bool {
        let m = rates.ncols();
        if m == 0 {
            return true;
        }
        if joints.len() < m {
            return false;
        }
        let held = DMatrix::from_fn(joints.len(), m, |r, c| rates[(joints[r], c)]);
        // Orthonormal columns: a singular value of their rows is at most 1, so the scale is 1.
        linalg::svd(&held).rank(MOBILITY_TOLERANCE, Some(1.0)).rank == m
    }
}
