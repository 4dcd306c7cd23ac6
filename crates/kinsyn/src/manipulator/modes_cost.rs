//! What sampling the motions of lock subsets costs, decided before any sampling.
//!
//! The unit is the **loop closure**: one Newton-corrected assembly of the mechanism
//! ([`crate::mechanism::SampledMotion::closures`]), the work of a sampled motion (the rank
//! decisions at the samples come on top, about one closure's worth per sample). What a subset
//! costs depends on what its locks leave at the start:
//!
//! - **rigid**: no joint rate keeps the loops closed with those inputs held. Every walk stops
//!   before its first step: one closure, the start's.
//! - **regular**: as many degrees of freedom at the start as at random assemblies nearby.
//!   `1 + samples × steps` closures (the start, then each walk's steps), each a few Newton
//!   steps (three on average for the files of `mechanisms/`); a walk that ends too near an
//!   earlier sample is walked again, which is rare.
//! - **singular**: more degrees of freedom at the start than at random assemblies nearby (a
//!   singular start, [`crate::motion::SingularStart`], or a start on a motion that is singular
//!   everywhere). The walks leave along directions that are free to first order only, so
//!   Newton's method converges linearly back to the constraint set (tens of damped steps per
//!   closure, an SVD each, up to [`crate::mechanism::ASSEMBLY_STEPS`]), walks end near each
//!   other and are walked again (up to [`crate::mechanism::WALK_ATTEMPTS`] per sample), and
//!   steps are halved ([`crate::mechanism::STEP_TRIES`] tries). Measured: three to a thousand
//!   times a regular subset's CPU (`docs/limits.md`, "Measured cost").
//!
//! Every subset runs at most `1 + samples × WALK_ATTEMPTS × steps × STEP_TRIES` closures
//! ([`ModesCost::most_closures_per_motion`]).
//!
//! **How a start is judged.** With `N` an orthonormal basis of the joint rates that keep the
//! loops closed when every joint is free (`M` columns), the rates with the locked joints held
//! are `N y` with `N_L y = 0` (`N_L` the rows of the locked joints), so the start keeps
//! `M − rank N_L` degrees of freedom. The same count at random assemblies around the start
//! (every joint free, as for [`Manipulator::analyse`]'s generic ranks) gives the generic
//! value, the least over them. One SVD of the closure Jacobian per configuration, then per
//! subset the rank of a `locks × M` matrix at each: far cheaper than one loop closure.

use super::Manipulator;
use super::singularity::{GENERIC_ASSEMBLIES, GENERIC_SPREAD};
use crate::linalg;
use crate::mechanism::{MOBILITY_TOLERANCE, STEP_TRIES, SampleSettings, WALK_ATTEMPTS};
use nalgebra::DMatrix;
use serde::Serialize;

/// The cost of sampling the motions of some lock subsets from one start, decided before any
/// sampling ([`Manipulator::modes_cost`]; the classes are the module documentation's).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct ModesCost {
    /// The lock subsets.
    pub subsets: usize,
    /// Those whose locks leave the start rigid: one loop closure each.
    pub rigid: usize,
    /// Those whose locks leave the start more degrees of freedom than at random assemblies
    /// nearby: the expensive ones.
    pub singular: usize,
    /// The loop closures at regular starts: one per rigid subset,
    /// [`ModesCost::closures_per_motion`] per other (a singular start's count is unknown
    /// beforehand: fewer when its walks stop early, more when they are walked again).
    pub closures: u64,
    /// The most loop closures the sampling can run: one per rigid subset,
    /// [`ModesCost::most_closures_per_motion`] per other.
    pub most_closures: u64,
}

impl ModesCost {
    /// The loop closures of a motion sampled with `settings` from a regular start: the start's,
    /// then `steps` per walk, one walk per sample.
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

/// What a subset's locks leave at the start (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum StartKind {
    Rigid,
    Regular,
    Singular,
}

impl Manipulator {
    /// The cost of [`Manipulator::modes_from`] with the same `start`, `subsets` and
    /// `settings`, decided before any sampling: how many subsets' locks leave the start rigid,
    /// how many leave it singular, and the loop closures at regular starts and at most (module
    /// documentation). The random assemblies are seeded by `settings.seed`.
    ///
    /// The degrees of freedom are counted on the start as given (the sampling first closes the
    /// loops there, which moves an assembled start by round-off only) at the sampling's rank
    /// tolerance ([`MOBILITY_TOLERANCE`]), on the null space of the closure equations rather
    /// than on the locked equations themselves: the two agree wherever the decision is not
    /// within round-off of the tolerance. When no random assembly closes, no start is called
    /// singular.
    ///
    /// # Complexity
    /// An SVD of the closure Jacobian at the start and at each of four random assemblies (each
    /// reached in eight closures), then per subset five ranks of `locks × M` matrices (`M` the
    /// degrees of freedom with every joint free).
    #[must_use]
    pub fn modes_cost(
        &self,
        start: &[f64],
        subsets: &[Vec<usize>],
        settings: &SampleSettings,
    ) -> ModesCost {
        let at_start = self.unitless_rates(start);
        let generic: Vec<DMatrix<f64>> = self
            .mechanism
            .random_assemblies(
                start,
                &vec![false; self.mechanism.joints().len()],
                GENERIC_ASSEMBLIES,
                GENERIC_SPREAD,
                settings.seed,
            )
            .iter()
            .map(|q| self.unitless_rates(q))
            .collect();
        let mut cost = ModesCost {
            subsets: subsets.len(),
            rigid: 0,
            singular: 0,
            closures: 0,
            most_closures: 0,
        };
        for locked in subsets {
            let kind = Self::start_kind(&at_start, &generic, &self.locked_joints(locked));
            match kind {
                StartKind::Rigid => cost.rigid += 1,
                StartKind::Singular => cost.singular += 1,
                StartKind::Regular => {}
            }
            let (closures, most) = match kind {
                StartKind::Rigid => (1, 1),
                _ => (
                    ModesCost::closures_per_motion(settings),
                    ModesCost::most_closures_per_motion(settings),
                ),
            };
            cost.closures += closures;
            cost.most_closures += most;
        }
        cost
    }

    /// An orthonormal basis of the dimensionless joint rates (prismatic rates over the length
    /// scale) that keep the loops closed at `q` with every joint free, one row per joint: the
    /// rates of [`crate::mechanism::Mechanism::mobility`] brought back to the form in which the
    /// sampling decides.
    fn unitless_rates(&self, q: &[f64]) -> DMatrix<f64> {
        let mut rates = self.mechanism.mobility(q, &[]).rates;
        for j in 0..rates.nrows() {
            rates.row_mut(j).unscale_mut(self.mechanism.unit(j));
        }
        rates
    }

    /// The joints of a set of locked inputs (indices into the actuators), each once.
    fn locked_joints(&self, locked: &[usize]) -> Vec<usize> {
        let mask = self.lock_mask(locked);
        (0..mask.len()).filter(|&j| mask[j]).collect()
    }

    /// What holding the `joints` leaves at the start, whose rates are `at_start`, against the
    /// rates at random assemblies nearby, `generic`.
    fn start_kind(
        at_start: &DMatrix<f64>,
        generic: &[DMatrix<f64>],
        joints: &[usize],
    ) -> StartKind {
        let freedom = Self::freedom(at_start, joints);
        if freedom == 0 {
            return StartKind::Rigid;
        }
        let least = generic
            .iter()
            .map(|rates| Self::freedom(rates, joints))
            .min();
        if least.is_some_and(|g| freedom > g) {
            StartKind::Singular
        } else {
            StartKind::Regular
        }
    }

    /// The degrees of freedom left by holding the `joints` still, of those of the orthonormal
    /// basis of rates `rates` (one row per joint): its columns less the rank of the held rows.
    fn freedom(rates: &DMatrix<f64>, joints: &[usize]) -> usize {
        let m = rates.ncols();
        if m == 0 || joints.is_empty() {
            return m;
        }
        let held = DMatrix::from_fn(joints.len(), m, |r, c| rates[(joints[r], c)]);
        // Orthonormal columns: a singular value of their rows is at most 1, so the scale is 1.
        m - linalg::svd(&held).rank(MOBILITY_TOLERANCE, Some(1.0)).rank
    }
}
