//! Finite motion of a body, sampled by position-level loop closure and classified among the 12
//! displacement groups or as `nTmR`.
//!
//! From an assembled configuration the mechanism is walked along random directions of its
//! compatible joint rates; after every step Newton's method closes the loops again, so the
//! samples are true (finite) configurations, not points of the tangent space. The twist spaces of
//! the body at the samples decide the pattern ([`crate::motion::classify`]): a group when they are
//! one Lie subalgebra at every sample.

use super::{Mechanism, MechanismError};
use crate::motion::{self, Classification, Pattern};
use nalgebra::DMatrix;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;

/// How a finite motion is sampled.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SampleSettings {
    /// Configurations sampled (each the end of its own random walk from the start).
    pub samples: usize,
    /// Newton-corrected steps per walk.
    pub steps: usize,
    /// Length of a step in joint space (radians; prismatic values over the length scale).
    pub step: f64,
    /// Seed of the walk directions.
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

/// One sampled configuration and the body's twist space there.
#[derive(Debug, Clone)]
pub struct MotionSample {
    /// Joint values (assembled).
    pub q: Vec<f64>,
    /// Orthonormal basis of the body's spatial twists, in the dimensionless form (translational
    /// rows over the length scale).
    pub twists: DMatrix<f64>,
}

impl Mechanism {
    /// Samples the finite motion of `body` from the assembled configuration `start` with the
    /// `locked` joints held.
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
    ) -> Result<Vec<MotionSample>, MechanismError> {
        let start = self.assemble(start, locked, None)?;
        let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
        let mut samples = Vec::with_capacity(settings.samples);
        for _ in 0..settings.samples.max(1) {
            let mut q = start.clone();
            for _ in 0..settings.steps {
                let m = self.mobility(&q, locked);
                if m.dof == 0 {
                    break;
                }
                let coefficients =
                    nalgebra::DVector::from_fn(m.dof, |_, _| rng.random_range(-1.0..1.0));
                let free: Vec<usize> = (0..self.joints.len())
                    .filter(|&j| !locked.get(j).copied().unwrap_or(false))
                    .collect();
                // The direction in dimensionless joint units, normalised.
                let mut direction = &m.rates * coefficients;
                for (k, &j) in free.iter().enumerate() {
                    direction[k] /= self.unit(j);
                }
                let norm = direction.norm();
                if norm < 1e-15 {
                    break;
                }
                direction /= norm;
                // The step, halved until the loops close again (five tries).
                let mut h = settings.step;
                let mut attempt = Err(MechanismError::NotAssembled {
                    residual: f64::NAN,
                    iterations: 0,
                });
                for _ in 0..5 {
                    let mut trial = q.clone();
                    for (k, &j) in free.iter().enumerate() {
                        trial[j] += h * direction[k] * self.unit(j);
                    }
                    attempt = self.assemble(&trial, locked, None);
                    if attempt.is_ok() {
                        break;
                    }
                    h /= 2.0;
                }
                q = attempt?;
            }
            let (twists, _) = self.twist_space(body, &q, locked);
            samples.push(MotionSample {
                twists: self.dimensionless_twists(&twists),
                q,
            });
        }
        Ok(samples)
    }

    /// Twists with their translational rows over the length scale.
    fn dimensionless_twists(&self, twists: &DMatrix<f64>) -> DMatrix<f64> {
        let mut out = twists.clone();
        for r in 3..6 {
            out.row_mut(r).scale_mut(1.0 / self.scale);
        }
        out
    }

    /// The motion pattern of `body` with the `locked` joints held, from finite motion sampled
    /// from `start` ([`Mechanism::sample_motion`]). Points and pitches of the group are in the
    /// mechanism's length unit.
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
        let samples = self.sample_motion(body, start, locked, settings)?;
        let spans: Vec<DMatrix<f64>> = samples.into_iter().map(|s| s.twists).collect();
        let mut c = motion::classify(&spans, motion::SUBSPACE_TOLERANCE);
        if let Pattern::Group(g) = &mut c.pattern {
            g.point = g.point.map(|p| p.map(|x| x * self.scale));
            g.pitch = g.pitch.map(|p| p * self.scale);
        }
        Ok(c)
    }
}
