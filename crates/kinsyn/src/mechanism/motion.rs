//! Finite motion of a body, sampled by position-level loop closure and classified among the 12
//! displacement groups or as `nTmR`; random assemblies of a mechanism.
//!
//! From an assembled configuration the mechanism is walked along random directions of its
//! compatible joint rates; after every step Newton's method closes the loops again, so the
//! samples are true (finite) configurations, not points of the tangent space. The twist spaces of
//! the body at the samples decide the pattern ([`crate::motion::classify`]): a group when they are
//! one Lie subalgebra at every sample.
//!
//! **Why a group claim can be trusted.** Each step has a continuous random length (uniform in
//! `[0.5, 1.5] × step`) and an isotropic random direction in the space of compatible rates, so a
//! walk's end has a continuous distribution over the configurations near the start. A motion
//! that is not a group has a twist space that varies analytically along the motion; the pairs of
//! configurations at which two such spaces coincide form a set of measure zero, which continuous
//! samples miss with probability one. Samples that (nearly) coincide would prove nothing, so a
//! walk whose body pose ends closer than [`MIN_SEPARATION`] to an earlier sample is walked again,
//! and the smallest pose distance between samples is reported: a group is claimed only when at
//! least two samples are that far apart, so that the samples could have shown otherwise
//! (`docs/verification.md`).

use super::{MOBILITY_TOLERANCE, Mechanism, MechanismError, compose, inverse, log};
use crate::chain::Displacement;
use crate::linalg;
use crate::motion::{self, Classification, MIN_SEPARATION, Pattern, SingularStart};
use nalgebra::{DMatrix, DVector, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;
use serde::{Deserialize, Serialize};

/// How a finite motion is sampled.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SampleSettings {
    /// Configurations sampled (each the end of its own random walk from the start).
    pub samples: usize,
    /// Newton-corrected steps per walk.
    pub steps: usize,
    /// Mean length of a step in joint space (radians; prismatic values over the length scale);
    /// each step's length is uniform in `[0.5, 1.5] × step`.
    pub step: f64,
    /// Seed of the walk directions and lengths.
    pub seed: u64,
}

impl Default for SampleSettings {
    fn default() -> Self {
        SampleSettings {
            samples: 3,
            steps: 3,
            step: 0.1,
            seed: 2026,
        }
    }
}

/// The continuation steps by which [`Mechanism::random_assemblies`] reaches each assembly.
pub const RANDOM_ASSEMBLY_STEPS: usize = 8;

/// Walks tried per sample before a sample too close to the others is accepted (and the group
/// claim refused).
pub const WALK_ATTEMPTS: usize = 16;

/// Loop closures tried per step of a walk: the step, then halved until the loops close again.
pub const STEP_TRIES: usize = 5;

/// One sampled configuration and the body's twist space there.
#[derive(Debug, Clone)]
pub struct MotionSample {
    /// Joint values (assembled).
    pub q: Vec<f64>,
    /// The body's displacement from its reference pose.
    pub pose: Displacement,
    /// Orthonormal basis of the body's spatial twists in the dimensionless form
    /// ([`Mechanism::unitless_twists`]: at the centre, translations over the length scale).
    pub twists: DMatrix<f64>,
    /// The rank decision behind it (relative to the norm of the body's dimensionless Jacobian).
    pub rank: crate::linalg::Rank,
    /// The mechanism's degrees of freedom here (closure nullity over the free joints).
    pub freedom: usize,
}

/// The sampled finite motion of a body.
#[derive(Debug, Clone)]
pub struct SampledMotion {
    /// The samples.
    pub samples: Vec<MotionSample>,
    /// The smallest distance between the body poses of two samples (dimensionless, see
    /// [`MIN_SEPARATION`]); infinite with fewer than two samples.
    pub min_separation: f64,
    /// The mechanism's degrees of freedom at the start (closure nullity over the free joints).
    pub start_dof: usize,
    /// The smallest of them at the samples: below `start_dof` when the start is singular
    /// ([`crate::motion::SingularStart`]). Near a regular start every sample has the start's
    /// degrees of freedom; a sample with fewer lies on a branch of which the start is not a
    /// regular point.
    pub motion_dof: usize,
    /// The loop closures (Newton-corrected assemblies) the sampling ran: the start's, then one
    /// per step tried on the walks (a halved step is another). The unit of its cost: at a
    /// regular start `1 + samples × steps`, at most `1 + samples × WALK_ATTEMPTS × steps ×
    /// STEP_TRIES` ([`crate::manipulator::ModesCost`]); one when the start has no degree of
    /// freedom, since then no walk can take a step.
    pub closures: usize,
}

/// The closure equations over the free joints at the start of the walks
/// ([`Mechanism::free_closure`]) and the basis of the rates that keep them
/// ([`super::mobility::rate_basis`]): every walk's first step is drawn from them, and their
/// dimension is the start's degrees of freedom, so they are found once per sampled motion.
struct StartClosure {
    /// The dimensionless closure Jacobian over the free joints.
    equations: DMatrix<f64>,
    /// An orthonormal basis of its null space.
    rates: DMatrix<f64>,
}

impl StartClosure {
    /// The closure equations of `mechanism` at `start` over the `free` joints.
    fn new(mechanism: &Mechanism, start: &[f64], free: &[usize]) -> Self {
        let equations = mechanism.free_closure(&mechanism.joint_screws(start), free);
        let rates = super::mobility::rate_basis(&equations);
        StartClosure { equations, rates }
    }
}

impl Mechanism {
    /// The distance between two displacements of a body: the size of the screw that carries
    /// one to the other, in the dimensionless form (radians; translation of the centre over the
    /// length scale).
    #[must_use]
    pub fn pose_distance(&self, a: &Displacement, b: &Displacement) -> f64 {
        let e = log(&compose(b, &inverse(a))).to_vector();
        let d = self.unitless_twists(&DMatrix::from_column_slice(6, 1, e.as_slice()));
        d.norm()
    }

    /// One random walk of `settings.steps` Newton-corrected steps from the assembled `start`,
    /// whose closure equations are `at_start`; every loop closure tried is counted in
    /// `closures`.
    fn walk(
        &self,
        (start, at_start): (&[f64], &StartClosure),
        locked: &[bool],
        free: &[usize],
        settings: &SampleSettings,
        rng: &mut ChaCha8Rng,
        closures: &mut usize,
    ) -> Result<Vec<f64>, MechanismError> {
        let mut q = start.to_vec();
        for step in 0..settings.steps {
            let direction = if step == 0 {
                Self::random_rates(&at_start.equations, Some(&at_start.rates), rng)
            } else {
                Self::random_rates(&self.free_closure(&self.joint_screws(&q), free), None, rng)
            };
            let Some(mut direction) = direction else {
                break;
            };
            let norm = direction.norm();
            if norm < 1e-15 {
                break;
            }
            direction /= norm;
            let mut h = settings.step * rng.random_range(0.5..1.5);
            // The step, halved until the loops close again (`STEP_TRIES` tries).
            let mut attempt = Err(MechanismError::NotAssembled {
                residual: f64::NAN,
                iterations: 0,
            });
            for _ in 0..STEP_TRIES {
                let mut trial = q.clone();
                for (k, &j) in free.iter().enumerate() {
                    trial[j] += h * direction[k] * self.unit(j);
                }
                *closures += 1;
                attempt = self.assemble(&trial, locked, None);
                if attempt.is_ok() {
                    break;
                }
                h /= 2.0;
            }
            q = attempt?;
        }
        Ok(q)
    }

    /// A random direction of the dimensionless rates of the free joints that keep every loop
    /// closed, isotropic in that space, from the closure equations over them `cf`
    /// ([`Mechanism::free_closure`]) and, when known, the basis of those rates `rates`
    /// ([`super::mobility::rate_basis`] of `cf`); `None` when there is none (no degree of
    /// freedom). The projection of a normal draw on the null space of the closure equations
    /// when their independence is certified ([`linalg::null_direction`]), otherwise normal
    /// coefficients of the basis: either way an isotropic normal direction.
    fn random_rates(
        cf: &DMatrix<f64>,
        rates: Option<&DMatrix<f64>>,
        rng: &mut ChaCha8Rng,
    ) -> Option<DVector<f64>> {
        if cf.nrows() > 0
            && cf.nrows() < cf.ncols()
            && let Some(direction) = linalg::null_direction(cf, MOBILITY_TOLERANCE, |_, _| {
                rng.sample::<f64, _>(StandardNormal)
            })
        {
            return Some(direction);
        }
        let computed;
        let rates = if let Some(r) = rates {
            r
        } else {
            computed = super::mobility::rate_basis(cf);
            &computed
        };
        if rates.ncols() == 0 {
            return None;
        }
        let coefficients =
            DVector::from_fn(rates.ncols(), |_, _| rng.sample::<f64, _>(StandardNormal));
        Some(rates * coefficients)
    }

    /// Samples the finite motion of `body` from the assembled configuration `start` with the
    /// `locked` joints held: `settings.samples` random walks, each walked again (up to
    /// [`WALK_ATTEMPTS`] times in all) while its body pose ends closer than [`MIN_SEPARATION`]
    /// to an earlier sample's and the body can move there.
    ///
    /// When the start has no degree of freedom (no joint rate keeps the loops closed), no walk
    /// can take a step: every sample is the start, observed once, and the walks are not taken
    /// (the samples and their separations are those the walks would give).
    ///
    /// # Errors
    /// When Newton's method cannot close the loops even after halving a step four times (the
    /// start is not assembled, or the walk met a singularity it cannot cross).
    pub fn sample_motion(
        &self,
        body: usize,
        start: &[f64],
        locked: &[bool],
        settings: &SampleSettings,
    ) -> Result<SampledMotion, MechanismError> {
        self.sample_observed(start, locked, settings, |q| {
            let poses = self.poses(q);
            let screws = self.screws_at(&poses);
            let (twists, rank, freedom) =
                self.unitless_span_and_freedom(&self.body_jacobian(body, &screws), &screws, locked);
            (poses[body], twists, rank, freedom)
        })
    }

    /// [`Mechanism::sample_motion`] of what `observe` sees at joint values `q`: a displacement
    /// (telling samples apart), a dimensionless twist space with its rank decision, and the
    /// mechanism's degrees of freedom there.
    pub(super) fn sample_observed(
        &self,
        start: &[f64],
        locked: &[bool],
        settings: &SampleSettings,
        observe: impl Fn(&[f64]) -> (Displacement, DMatrix<f64>, crate::linalg::Rank, usize),
    ) -> Result<SampledMotion, MechanismError> {
        let start = self.assemble(start, locked, None)?;
        let mut closures = 1;
        let free = self.free(locked);
        let at_start = StartClosure::new(self, &start, &free);
        let start_dof = at_start.rates.ncols();
        if start_dof == 0 {
            return Ok(Self::rigid_motion(&start, settings, observe, |a, b| {
                self.pose_distance(a, b)
            }));
        }
        let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
        let mut samples: Vec<MotionSample> = Vec::with_capacity(settings.samples);
        let mut min_separation = f64::INFINITY;
        for _ in 0..settings.samples.max(1) {
            let mut best: Option<(f64, MotionSample)> = None;
            for _ in 0..WALK_ATTEMPTS {
                let q = self.walk(
                    (&start, &at_start),
                    locked,
                    &free,
                    settings,
                    &mut rng,
                    &mut closures,
                )?;
                let (pose, twists, rank, freedom) = observe(&q);
                let nearest = samples
                    .iter()
                    .map(|s| self.pose_distance(&s.pose, &pose))
                    .fold(f64::INFINITY, f64::min);
                // A body that cannot move here has nothing to tell apart: no walk again.
                let done = nearest >= MIN_SEPARATION || rank.rank == 0;
                if best.as_ref().is_none_or(|(d, _)| nearest > *d) {
                    let sample = MotionSample {
                        q,
                        pose,
                        twists,
                        rank,
                        freedom,
                    };
                    best = Some((nearest, sample));
                }
                if done {
                    break;
                }
            }
            let Some((nearest, sample)) = best else {
                break;
            };
            min_separation = min_separation.min(nearest);
            samples.push(sample);
        }
        let motion_dof = samples.iter().map(|s| s.freedom).min().unwrap_or(0);
        Ok(SampledMotion {
            samples,
            min_separation,
            start_dof,
            motion_dof,
            closures,
        })
    }

    /// The sampled motion from an assembled `start` with no degree of freedom: every walk of
    /// [`Mechanism::sample_observed`] stops before its first step (no compatible rate) and ends
    /// at the start, so every sample is what `observe` sees there, the first with no earlier
    /// sample to be near, the others at the distance `distance` finds between that pose and
    /// itself (a walk again would end at the same place: the first kept). One loop closure,
    /// the start's.
    fn rigid_motion(
        start: &[f64],
        settings: &SampleSettings,
        observe: impl Fn(&[f64]) -> (Displacement, DMatrix<f64>, crate::linalg::Rank, usize),
        distance: impl Fn(&Displacement, &Displacement) -> f64,
    ) -> SampledMotion {
        let (pose, twists, rank, freedom) = observe(start);
        let count = settings.samples.max(1);
        let min_separation = if count > 1 {
            distance(&pose, &pose)
        } else {
            f64::INFINITY
        };
        let sample = MotionSample {
            q: start.to_vec(),
            pose,
            twists,
            rank,
            freedom,
        };
        SampledMotion {
            samples: vec![sample; count],
            min_separation,
            start_dof: 0,
            motion_dof: freedom,
            closures: 1,
        }
    }

    /// Assemblies of the mechanism scattered around `start`: the free joints moved by
    /// independent normal amounts of standard deviation `spread` (radians; prismatic values over
    /// the length scale), the loops closed by Newton's method along the way. Those that do not
    /// close are dropped. These are the generic configurations against which a configuration's
    /// ranks are judged: a singular set has measure zero, so random assemblies miss it.
    ///
    /// Each assembly is reached by continuation from `start`, in
    /// [`RANDOM_ASSEMBLY_STEPS`] equal parts of its displacement, each closed before the next,
    /// so that it stays on `start`'s component of the configuration space (its assembly mode).
    /// Closing the whole displacement at once can land on another component with other ranks:
    /// the HEXA of paper 001 (`mechanisms/6-ruu-hexa.json`), whose joints moved by 0.3 rad
    /// closed one parallelogram in about one draw in thirty as an anti-parallelogram, a
    /// component of mobility 5 instead of 6.
    #[must_use]
    pub fn random_assemblies(
        &self,
        start: &[f64],
        locked: &[bool],
        count: usize,
        spread: f64,
        seed: u64,
    ) -> Vec<Vec<f64>> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let free = self.free(locked);
        let parts = RANDOM_ASSEMBLY_STEPS as f64;
        (0..count)
            .filter_map(|_| {
                let step: Vec<f64> = free
                    .iter()
                    .map(|&j| spread * rng.sample::<f64, _>(StandardNormal) * self.unit(j) / parts)
                    .collect();
                let mut q = start.to_vec();
                for _ in 0..RANDOM_ASSEMBLY_STEPS {
                    for (&j, d) in free.iter().zip(&step) {
                        q[j] += d;
                    }
                    q = self.assemble(&q, locked, None).ok()?;
                }
                Some(q)
            })
            .collect()
    }

    /// The motion pattern of `body` with the `locked` joints held, from finite motion sampled
    /// from `start` ([`Mechanism::sample_motion`]). Points and pitches of the group are in the
    /// mechanism's length unit; the point of an axis is the one nearest the ground origin.
    ///
    /// # Errors
    /// As [`Mechanism::sample_motion`].
    pub fn motion_pattern(
        &self,
        body: usize,
        start: &[f64],
        locked: &[bool],
        settings: &SampleSettings,
    ) -> Result<Classification, MechanismError> {
        let motion = self.sample_motion(body, start, locked, settings)?;
        Ok(self.classify_motion(&motion))
    }

    /// The pattern of a sampled motion ([`crate::motion::classify`]), the group's point and
    /// pitch in the mechanism's length unit, the point of an axis the one nearest the origin.
    #[must_use]
    pub fn classify_motion(&self, motion: &SampledMotion) -> Classification {
        let spans: Vec<DMatrix<f64>> = motion.samples.iter().map(|s| s.twists.clone()).collect();
        // The rank decisions were made on the body's twists, not on these orthonormal bases.
        let mut c = motion::classify_quick(
            &spans,
            motion.min_separation,
            motion::SUBSPACE_TOLERANCE,
            motion::gap_over(motion.samples.iter().map(|s| &s.rank)),
        );
        if let Pattern::Group(g) = &mut c.pattern {
            // From the dimensionless form (about the centre, over the length scale) to the
            // mechanism's units, the axis point taken nearest the ground origin.
            g.point = g.point.map(|p| {
                let mut x = self.centre + Vector3::from(p) * self.scale;
                if let Some(d) = g.direction {
                    let d = Vector3::from(d);
                    x -= d * d.dot(&x);
                }
                x.into()
            });
            g.pitch = g.pitch.map(|p| p * self.scale);
        }
        c.singular_start = (motion.start_dof > motion.motion_dof).then_some(SingularStart {
            start_dof: motion.start_dof,
            motion_dof: motion.motion_dof,
        });
        c
    }
}
