//! The 3D view of a catalogue entry's leg chain: the serial chain of its numerical verification
//! ([`Entry::serial_chain`]: the catalogue's axis directions at the reference configuration,
//! the primitives of one C, U or S on one point, consecutive joint letters offset by seeded
//! generic vectors) drawn at a generic configuration, with one walk per minimal lock set of its
//! lock table.
//!
//! - The joint symbols are sized by the spread of the joints' points (their RMS distance from
//!   their centroid), the chain's own length.
//! - The **bodies** are the ground, the links between consecutive primitive joints (a C's, U's
//!   or S's intermediate bodies included) and the end link, the view's end-effector; its frame
//!   is the ground frame moved to the last joint's point at the reference configuration.
//! - The **start** is the first configuration the verification samples for the entry
//!   ([`crate::verification::configurations`]: revolutes in [−π, π), prismatics in [−1, 1)).
//! - A **lock set's walk** holds its joints at their reference values (zero), where the
//!   catalogue's directions hold and the verification classified the motion they leave, and
//!   moves the free joints from their start values along the rates that move the end link most
//!   ([`walk`]; without loops a straight line in joint space), [`CHAIN_WALK_STEPS`] steps of
//!   [`CHAIN_WALK_STEP`] to either side.
//!
//! Joint values are rounded to [`DECIMALS`] decimals: a page holds some sixty walks, and any
//! joint values are a configuration of a serial chain, so the rounded walk is still exact
//! motion with the locked joints held (at zero, which rounding keeps).

use super::{FORMAT, ModeView, Roles, Scene, SceneJoint, View, walk};
use crate::catalogue::Entry;
use crate::chain::{ChainError, SerialChain, random_configuration};
use crate::lockset::LockSet;
use crate::mechanism::{JointSpec, Mechanism, MechanismError};
use crate::motion::PatternName;
use crate::notation::Chain;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The steps of a lock set's walk to either side of its start.
pub const CHAIN_WALK_STEPS: usize = 8;

/// The length of a step of a lock set's walk (dimensionless joint rates: radians, prismatic
/// values over the characteristic length): ±0.6 rad over the walk.
pub const CHAIN_WALK_STEP: f64 = 0.075;

/// The decimals the joint values of a chain's view keep.
pub const DECIMALS: i32 = 4;

/// Why an entry's chain cannot be viewed (a damaged entry).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ChainViewError {
    /// The entry's word, axes and notation disagree.
    #[error("{id}: {source}")]
    Chain {
        /// The entry.
        id: String,
        /// Why.
        source: ChainError,
    },
    /// The chain does not make a mechanism.
    #[error("{id}: {source}")]
    Mechanism {
        /// The entry.
        id: String,
        /// Why.
        source: MechanismError,
    },
    /// A lock set names a joint the chain does not have.
    #[error("{id}: lock set {set} names a joint beyond the chain's {joints}")]
    Lock {
        /// The entry.
        id: String,
        /// The lock set.
        set: String,
        /// The chain's primitive joints.
        joints: usize,
    },
}

/// The serial chain `chain` as a mechanism: body 0 the ground, body `k` the link that joint `k`
/// (from 1) moves, the last body the end link; joint `k` joins body `k − 1` to body `k`, so
/// that a body's displacement is the chain's product of exponentials up to it
/// ([`SerialChain::forward`] for the end link).
///
/// # Errors
/// Never for a chain [`SerialChain::new`] accepted (its axes have length, its points are
/// finite); the mechanism's own checks are kept.
pub fn serial_mechanism(chain: &SerialChain) -> Result<Mechanism, MechanismError> {
    let n = chain.len();
    let names: Vec<String> = (0..=n)
        .map(|b| match b {
            0 => "ground".to_string(),
            b if b == n => "end link".to_string(),
            b => format!("link {b}"),
        })
        .collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let joints = chain
        .joints()
        .iter()
        .enumerate()
        .map(|(k, j)| JointSpec::new(j.kind, j.axis, j.point, k, k + 1))
        .collect();
    Mechanism::new(&names, 0, joints)
}

/// The view of `entry`'s leg chain (module documentation) with one mode per lock set of
/// `locks` (each with the pattern the lock table gives it), in that order, so that the page's
/// mode `k` animates the table's row `k`. `base_seed` is the catalogue's verification seed
/// ([`crate::catalogue::VERIFICATION_SEED`]).
///
/// # Errors
/// A damaged entry (word, axes and notation that disagree), or a lock set naming a joint
/// beyond the chain.
pub fn chain_view(
    entry: &Entry,
    base_seed: u64,
    locks: &[(LockSet, PatternName)],
) -> Result<View, ChainViewError> {
    let id = || entry.id.clone();
    let chain = entry
        .serial_chain(base_seed)
        .map_err(|source| ChainViewError::Chain { id: id(), source })?;
    let mech = serial_mechanism(&chain)
        .map_err(|source| ChainViewError::Mechanism { id: id(), source })?;
    let n = chain.len();
    let mut rng = ChaCha8Rng::seed_from_u64(entry.sample_seed(base_seed));
    let start: Vec<f64> = random_configuration(&chain, &mut rng)
        .into_iter()
        .map(round)
        .collect();
    let modes = locks
        .iter()
        .map(|(set, pattern)| {
            if set.joints().any(|j| j == 0 || j > n) {
                return Err(ChainViewError::Lock {
                    id: id(),
                    set: set.to_string(),
                    joints: n,
                });
            }
            Ok(lock_walk(&mech, &start, *set, pattern))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let classification = locks
        .iter()
        .find(|(set, _)| *set == LockSet::NONE)
        .map_or_else(String::new, |(_, p)| {
            format!("{p} ({} dof) with no joint locked", p.dof())
        });
    let end_point = chain.joints().last().map(|j| j.point).unwrap_or_default();
    let mut scene = Scene::of_mechanism(
        &mech,
        Roles {
            name: format!("{} {}", entry.id, entry.notation),
            length_unit: "unit".to_string(),
            angle_unit: "rad",
            joints: scene_joints(entry, &chain, &mech),
            end_effector: n,
            named: Vec::new(),
            end_effector_frame: crate::spatial::displacement(
                nalgebra::Rotation3::identity(),
                end_point,
            ),
        },
    );
    // The revolutes of a chain may all share one point (a PPPS): the joint symbols are sized
    // by the spread of every joint's point instead, the chain's own length.
    let points: Vec<_> = chain.joints().iter().map(|j| j.point).collect();
    scene.scale = crate::mechanism::characteristic_of(&points).1;
    Ok(View {
        format: FORMAT,
        scene,
        start,
        inputs: Vec::new(),
        classification,
        sweeps: Vec::new(),
        modes,
        assemblies: Vec::new(),
        notes: vec![
            "The leg chain of the catalogue's numerical verification at a generic configuration; \
             a lock set's motion holds its joints at their reference values."
                .to_string(),
        ],
    })
}

/// The walk of lock set `set` from `start` with its joints at zero, as the page animates it.
fn lock_walk(mech: &Mechanism, start: &[f64], set: LockSet, pattern: &PatternName) -> ModeView {
    let mut mask = vec![false; start.len()];
    for j in set.joints() {
        mask[j - 1] = true;
    }
    let from: Vec<f64> = start
        .iter()
        .zip(&mask)
        .map(|(&v, &locked)| if locked { 0.0 } else { v })
        .collect();
    let w = walk(
        mech,
        mech.body_count() - 1,
        &from,
        &mask,
        CHAIN_WALK_STEPS,
        CHAIN_WALK_STEP,
    );
    ModeView {
        source: "lock table".to_string(),
        locks: set.to_string(),
        pattern: pattern.to_string(),
        dof: pattern.dof(),
        group: pattern.is_group(),
        parameters: None,
        joint_values: w
            .joint_values
            .into_iter()
            .map(|q| q.into_iter().map(round).collect())
            .collect(),
        start: w.start,
        stops: w.stops,
    }
}

/// The chain's primitive joints as drawn: labelled by kind and position in the word (`R4`, the
/// lock sets' numbers), grouped by the entry's joint letters, each at its own point (a slider
/// on the body before it, its rod the next link).
fn scene_joints(entry: &Entry, chain: &SerialChain, mech: &Mechanism) -> Vec<SceneJoint> {
    let letters: Vec<(char, usize)> = entry
        .notation
        .parse::<Chain>()
        .map(|c| {
            c.joints()
                .iter()
                .map(|j| (j.kind.letter(), j.kind.primitives().len()))
                .collect()
        })
        .unwrap_or_default();
    let mut group_of = Vec::with_capacity(chain.len());
    for (g, &(letter, size)) in letters.iter().enumerate() {
        group_of.extend(std::iter::repeat_n((letter, g), size));
    }
    mech.joints()
        .iter()
        .enumerate()
        .map(|(k, spec)| {
            let (group, group_id) = group_of
                .get(k)
                .copied()
                .unwrap_or((spec.kind.letter(), usize::MAX - k));
            SceneJoint::of(
                spec,
                format!("{}{}", spec.kind.letter(), k + 1),
                (group, group_id),
                1,
                false,
            )
        })
        .collect()
}

/// `x` to [`DECIMALS`] decimals (zero without a sign).
fn round(x: f64) -> f64 {
    let scale = 10f64.powi(DECIMALS);
    // Adding +0 turns −0 into +0 and leaves every other value as it is.
    (x * scale).round() / scale + 0.0
}
