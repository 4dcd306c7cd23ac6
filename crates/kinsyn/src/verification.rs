//! Numerical verification of a leg chain: the rank of its Jacobian at random configurations,
//! its idle joints, and the motion pattern left by every subset of locked joints (paper 000's
//! "multioperation capacity" of a leg).
//!
//! Geometry: the chain's axes have the catalogue directions at the reference configuration;
//! joints of one C, U or S share a point, other consecutive joints are offset by generic
//! non-zero vectors ([`SerialChain::from_layout`]), all drawn from a seeded generator. Locked
//! joints are held at their reference values, where the catalogue's directions hold; free joints
//! are sampled at random (revolutes in [−π, π), prismatics in [−1, 1)).
//!
//! ```
//! use kinsyn::verification::{verify, Settings};
//! use kinsyn::chain::SerialChain;
//! use kinsyn::notation::Axis::{X, Y, Z};
//! use kinsyn::notation::Primitive::{P, R};
//! use rand::SeedableRng;
//! // PPPS: three perpendicular guides and a spherical wrist (Table 1 row 1).
//! let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
//! let chain = SerialChain::from_layout(&[P, P, P, R, R, R], &[X, Y, Z, X, Y, Z], &[1, 1, 1, 3], &mut rng).unwrap();
//! let v = verify(&chain, &Settings::default(), 7);
//! let name = |text: &str| text.parse::<kinsyn::motion::PatternName>().unwrap();
//! assert!(v.is_3t3r);
//! assert_eq!(v.patterns[&name("T3")], vec!["456"]); // lock the S: spatial translation
//! assert_eq!(v.patterns[&name("S")], vec!["123"]);  // lock the guides: spherical motion
//! ```

use crate::chain::SerialChain;
/// Moved to [`crate::chain`]; re-exported here for earlier callers.
pub use crate::chain::random_configuration;
use crate::linalg::{self, DEFAULT_RANK_TOLERANCE};
pub use crate::lockset::{LockSet, LockSetError};
use crate::motion::{self, Classification, PatternName};
use crate::notation::Primitive;
use nalgebra::DMatrix;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// How a chain is verified.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Settings {
    /// Random configurations sampled.
    pub samples: usize,
    /// Relative rank tolerance (of the largest singular value).
    pub rank_tolerance: f64,
    /// Relative tolerance for comparing twist spaces and brackets.
    pub subspace_tolerance: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            samples: 3,
            rank_tolerance: DEFAULT_RANK_TOLERANCE,
            subspace_tolerance: motion::SUBSPACE_TOLERANCE,
        }
    }
}

/// What the numerical check found for one chain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Verification {
    /// The seed of the random configurations (the geometry's seed is the caller's).
    pub seed: u64,
    /// Generic rank of the chain Jacobian (the largest over the samples).
    pub rank: usize,
    /// Singular values at the sample where the smallest kept one is smallest (rounded to 6
    /// significant digits).
    pub singular_values: Vec<f64>,
    /// The smallest kept singular value over the largest, at that sample: how far the rank is
    /// from dropping.
    pub gap: f64,
    /// The largest dropped singular value over the largest, over all samples: how far the rank
    /// is from rising. Ratios below 1e-12 are round-off and written as 0.
    pub dropped: f64,
    /// Joints (1-based) whose removal does not lower the rank at any sample.
    pub idle_joints: Vec<usize>,
    /// Rank 6 at every sample and no idle joint.
    pub is_3t3r: bool,
    /// Every pattern the chain gives with some joints locked, by name, with its minimal lock
    /// sets: the sets of locked joints that leave this motion and hold no smaller such set, in
    /// increasing order of their bit masks. In files, the names and sets are their text
    /// (`"T3": ["456"]`).
    pub patterns: BTreeMap<PatternName, Vec<LockSet>>,
}

impl Verification {
    /// The check in words: the rank at every sample, the gap to a rank drop, the idle joints.
    #[must_use]
    pub fn summary(&self) -> String {
        format!(
            "rank {} at every sample, smallest kept singular value {:.3e} of the largest{}",
            self.rank,
            self.gap,
            if self.idle_joints.is_empty() {
                String::new()
            } else {
                format!("; idle joints {:?}", self.idle_joints)
            }
        )
    }
}

/// Rounds to `digits` significant digits, so that files do not carry floating-point noise.
#[must_use]
pub fn round_significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    #[expect(
        clippy::cast_possible_truncation,
        reason = "the decimal exponent of a finite non-zero f64 is within ±324"
    )]
    let exponent = x.abs().log10().floor() as i32;
    let scale = 10f64.powi(digits - 1 - exponent);
    (x * scale).round() / scale
}

/// A ratio of singular values rounded to 3 digits, and 0 below 1e-12 (round-off).
fn round_off_to_zero(x: f64) -> f64 {
    if x < 1e-12 {
        0.0
    } else {
        round_significant(x, 3)
    }
}

/// The motion left when the joints in `mask` are locked at their reference values, classified
/// from the twist spaces at the given configurations of the free joints.
#[must_use]
pub fn locked_motion(
    chain: &SerialChain,
    mask: u32,
    configurations: &[Vec<f64>],
    settings: &Settings,
) -> Classification {
    let (samples, separation) = locked_samples(chain, mask, configurations);
    motion::classify(&samples, separation, settings.subspace_tolerance)
}

/// The pattern of [`locked_motion`], its ranks decided by certified QR where the free joints'
/// twists are independent ([`motion::classify_quick`]): the same decisions without the
/// singular values, for the 2^n subsets of [`verify`].
fn locked_pattern(
    chain: &SerialChain,
    mask: u32,
    configurations: &[Vec<f64>],
    settings: &Settings,
) -> PatternName {
    let (samples, separation) = locked_samples(chain, mask, configurations);
    let unreported = motion::RankGap {
        smallest_kept: None,
        largest_dropped: 0.0,
    };
    motion::classify_quick(
        &samples,
        separation,
        settings.subspace_tolerance,
        unreported,
    )
    .pattern
    .name()
}

/// The twists of the free joints at each configuration (locked joints at their reference
/// values) and the smallest distance between two configurations over the free joints (radians;
/// the offsets are of unit size): the evidence of [`locked_motion`].
fn locked_samples(
    chain: &SerialChain,
    mask: u32,
    configurations: &[Vec<f64>],
) -> (Vec<DMatrix<f64>>, f64) {
    let n = chain.len();
    let free: Vec<usize> = (0..n).filter(|i| mask & (1 << i) == 0).collect();
    let samples: Vec<DMatrix<f64>> = configurations
        .iter()
        .map(|q| {
            let q: Vec<f64> = (0..n)
                .map(|i| if mask & (1 << i) == 0 { q[i] } else { 0.0 })
                .collect();
            let j = chain.jacobian(&q);
            DMatrix::from_fn(6, free.len(), |r, c| j[(r, free[c])])
        })
        .collect();
    let mut separation = f64::INFINITY;
    for (a, qa) in configurations.iter().enumerate() {
        for qb in &configurations[a + 1..] {
            let d = free
                .iter()
                .map(|&i| joint_distance(chain, i, qa[i], qb[i]).powi(2))
                .sum::<f64>()
                .sqrt();
            separation = separation.min(d);
        }
    }
    (samples, separation)
}

/// How far apart two values of joint `i` are: radians for a revolute (the shorter way round),
/// guide units for a prismatic joint.
fn joint_distance(chain: &SerialChain, i: usize, a: f64, b: f64) -> f64 {
    let d = (a - b).abs();
    match chain.joints()[i].kind {
        Primitive::R => d.min(std::f64::consts::TAU - d),
        Primitive::P => d,
    }
}

/// The smallest difference, joint by joint, between two sampled configurations: every joint of
/// every pair differs by at least this much, so that whatever joints a lock set leaves free,
/// the samples are distinct ([`crate::motion::MIN_SEPARATION`]).
const SAMPLE_APART: f64 = 1e-2;

/// Draws per sample before one that is not apart is taken anyway (with many samples the joint
/// ranges run out of room; the classification then refuses group claims it cannot prove).
const DRAWS_PER_SAMPLE: usize = 1000;

/// The sampled configurations [`verify`] uses for `seed`: independent uniform draws, a draw
/// taken again (up to `DRAWS_PER_SAMPLE` times) while one of its joint values is within
/// `SAMPLE_APART` of an earlier sample's.
#[must_use]
pub fn configurations(chain: &SerialChain, settings: &Settings, seed: u64) -> Vec<Vec<f64>> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out: Vec<Vec<f64>> = Vec::with_capacity(settings.samples.max(1));
    while out.len() < settings.samples.max(1) {
        let mut q = random_configuration(chain, &mut rng);
        for _ in 1..DRAWS_PER_SAMPLE {
            let apart = out.iter().all(|p| {
                (0..chain.len()).all(|i| joint_distance(chain, i, p[i], q[i]) >= SAMPLE_APART)
            });
            if apart {
                break;
            }
            q = random_configuration(chain, &mut rng);
        }
        out.push(q);
    }
    out
}

/// The rank part of a verification: is the chain's Jacobian of rank 6 at every sampled
/// configuration, with no idle joint, and how far is that decision from the tolerance.
///
/// The decision is [`linalg::rank`] with the explicit relative tolerance
/// `settings.rank_tolerance` (of the largest singular value); `gap` and `dropped` say how far
/// the kept and the dropped singular values are from it, so that a near-singular case is
/// visible in the files.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RankCheck {
    /// Generic rank of the chain Jacobian (the largest over the samples).
    pub rank: usize,
    /// Singular values at the sample where the smallest kept one is smallest (rounded to 6
    /// significant digits; those the rank drops, round-off, written as 0).
    pub singular_values: Vec<f64>,
    /// The smallest kept singular value over the largest, at that sample.
    pub gap: f64,
    /// The largest dropped singular value over the largest, over all samples (0 below 1e-12).
    pub dropped: f64,
    /// Joints (1-based) whose removal does not lower the rank at any sample.
    pub idle_joints: Vec<usize>,
    /// Rank 6 at every sample and no idle joint.
    pub is_3t3r: bool,
}

/// The Jacobians of `chain` at the configurations [`verify`] samples for `seed`.
fn sampled_jacobians(chain: &SerialChain, configurations: &[Vec<f64>]) -> Vec<DMatrix<f64>> {
    let n = chain.len();
    configurations
        .iter()
        .map(|q| DMatrix::from_column_slice(6, n, chain.jacobian(q).as_slice()))
        .collect()
}

/// The rank check of a chain alone (no lock patterns): what [`verify`] decides 3T3R by, at the
/// same configurations for the same `seed`. Cheap (a few SVDs of 6×6 matrices), so that every
/// reading of a catalogue entry can be checked ([`crate::catalogue::Catalogue::verify`]).
#[must_use]
pub fn rank_check(chain: &SerialChain, settings: &Settings, seed: u64) -> RankCheck {
    let configurations = configurations(chain, settings, seed);
    rank_check_at(chain, &sampled_jacobians(chain, &configurations), settings)
}

/// [`rank_check`] from the Jacobians at the sampled configurations.
fn rank_check_at(
    chain: &SerialChain,
    jacobians: &[DMatrix<f64>],
    settings: &Settings,
) -> RankCheck {
    let n = chain.len();
    let ranks: Vec<linalg::Rank> = jacobians
        .iter()
        .map(|j| linalg::rank(j, settings.rank_tolerance))
        .collect();
    let rank = ranks.iter().map(|r| r.rank).max().unwrap_or(0);
    let worst = ranks
        .iter()
        .min_by(|a, b| a.gap().0.total_cmp(&b.gap().0))
        .cloned()
        .unwrap_or(linalg::Rank {
            rank: 0,
            singular_values: vec![],
            tolerance: settings.rank_tolerance,
            scale: 0.0,
        });
    let idle_joints: Vec<usize> = (0..n)
        .filter(|&i| {
            jacobians.iter().all(|j| {
                let without = j.clone().remove_column(i);
                linalg::rank(&without, settings.rank_tolerance).rank == rank
            })
        })
        .map(|i| i + 1)
        .collect();
    let is_3t3r = ranks.iter().all(|r| r.rank == 6) && idle_joints.is_empty();
    RankCheck {
        rank,
        // Values the rank drops are round-off: written as 0 so that files carry no noise.
        singular_values: worst
            .singular_values
            .iter()
            .enumerate()
            .map(|(k, &s)| {
                if k < worst.rank {
                    round_significant(s, 6)
                } else {
                    0.0
                }
            })
            .collect(),
        gap: round_significant(worst.gap().0, 6),
        dropped: round_off_to_zero(ranks.iter().map(|r| r.gap().1).fold(0.0, f64::max)),
        idle_joints,
        is_3t3r,
    }
}

/// Verifies a chain (up to 31 joints): rank, idle joints and the patterns of all lock subsets.
///
/// # Complexity
/// Exponential in the number of joints n: every one of the 2^n lock subsets is classified
/// ([`locked_motion`]: Jacobian ranks and brackets at `settings.samples` configurations), and
/// the minimal lock sets of each pattern are found by comparing its subsets pairwise, up to
/// 4^n comparisons. A 6-joint leg of the catalogue has 64 subsets (about 1.7 ms,
/// `cargo bench -p kinsyn-bench --bench verification`); each joint more doubles the classifications, so the
/// 31 joints the `u32` masks allow are a bound on representation, not a practical size.
#[must_use]
pub fn verify(chain: &SerialChain, settings: &Settings, seed: u64) -> Verification {
    let n = chain.len();
    let configurations = configurations(chain, settings, seed);
    let check = rank_check_at(chain, &sampled_jacobians(chain, &configurations), settings);

    // Every lock subset, then the minimal lock sets of each pattern.
    let mut by_pattern: BTreeMap<PatternName, Vec<u32>> = BTreeMap::new();
    for mask in 0u32..(1 << n) {
        let pattern = locked_pattern(chain, mask, &configurations, settings);
        by_pattern.entry(pattern).or_default().push(mask);
    }
    let patterns = by_pattern
        .into_iter()
        .map(|(p, masks)| {
            let minimal: Vec<LockSet> = masks
                .iter()
                .filter(|&&m| !masks.iter().any(|&o| o != m && o & m == o))
                .map(|&m| LockSet::from_mask(m))
                .collect();
            (p, minimal)
        })
        .collect();
    Verification {
        seed,
        rank: check.rank,
        singular_values: check.singular_values,
        gap: check.gap,
        dropped: check.dropped,
        idle_joints: check.idle_joints,
        is_3t3r: check.is_3t3r,
        patterns,
    }
}
