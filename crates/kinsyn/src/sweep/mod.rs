//! Multioperation capacity over the whole catalogue (paper 000 §1, §6): every verified chain
//! built into symmetric manipulators, every choice of actuated joints per leg, every lock
//! subset of the inputs, and the displacement groups the platform reaches.
//!
//! A **design** is a verified catalogue chain used as every leg of a symmetric manipulator
//! ([`crate::manipulator::build`]: `legs` legs, the default geometry) with the same primitive
//! joints of each leg actuated. The sweep's designs are, chain by chain in catalogue order,
//! every set of `k` actuated joints per leg for each `k` asked for (1 and 2 by default), the
//! sets in lexicographic order: 446 chains × (C(6,1) + C(6,2)) = 9366 designs with the committed
//! catalogue. A design's [`DesignRow`] is its multioperation capacity: the platform's degrees of
//! freedom, every displacement subgroup and non-group pattern reached by locking inputs with its
//! minimal lock sets, and how many distinct subgroups and group kinds there are (the paper's
//! measure).
//!
//! A row depends on its design and the settings only (each lock subset's walk has its own seed,
//! [`crate::manipulator::Manipulator::modes_from`]), never on which other designs are evaluated
//! with it or on the thread count, so a sweep can be split into shards, interrupted and
//! resumed, and its parts merged, with the same rows as one run.

pub mod ranking;
pub mod rows;

use crate::catalogue::Catalogue;
use crate::manipulator::build::{BuildSpec, build};
use crate::manipulator::{Manipulator, PatternModes};
use crate::mechanism::SampleSettings;
use itertools::Itertools;
use serde::{Deserialize, Serialize};

/// The legs of a sweep's manipulators: 3 to 6, as [`build`] builds them (paper 000 §3).
pub const LEGS: std::ops::RangeInclusive<usize> = 3..=6;

/// What a sweep evaluates: the manipulators built and how their motions are sampled.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepSettings {
    /// Legs of every manipulator (3 to 6).
    pub legs: usize,
    /// The numbers of actuated joints per leg tried (each between 1 and the leg's joints).
    pub actuated_per_leg: Vec<usize>,
    /// How each lock subset's motion is sampled (the seed included).
    pub sampling: SampleSettings,
}

impl Default for SweepSettings {
    fn default() -> Self {
        SweepSettings {
            legs: 3,
            actuated_per_leg: vec![1, 2],
            sampling: SampleSettings::default(),
        }
    }
}

/// One manipulator of a sweep: a catalogue chain as every leg, with the same joints actuated.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Design {
    /// Its place in the sweep's list of designs (0-based): the row order of the results.
    pub index: usize,
    /// The catalogue id of the leg chain (`T1-003`).
    pub chain: String,
    /// The chain's notation (`PPRCR`).
    pub notation: String,
    /// The chain's family: its prismatic then revolute joints (`PRRRRR` for the UPS).
    pub family: String,
    /// The actuated primitive joints of each leg, 1-based, increasing.
    pub actuated: Vec<usize>,
}

/// The designs of a sweep over the verified entries of `catalogue`, in order (see the module
/// documentation). Sizes of actuated sets larger than a leg's joints give no design.
#[must_use]
pub fn designs(catalogue: &Catalogue, settings: &SweepSettings) -> Vec<Design> {
    let mut out = Vec::new();
    for entry in catalogue.verified() {
        let joints = entry.family.len();
        for &k in &settings.actuated_per_leg {
            for set in (1..=joints).combinations(k) {
                out.push(Design {
                    index: out.len(),
                    chain: entry.id.clone(),
                    notation: entry.notation.clone(),
                    family: entry.family.clone(),
                    actuated: set,
                });
            }
        }
    }
    out
}

/// A pattern a design reaches, with the lock sets that reach it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Reached {
    /// The pattern's name (`X(z)`, `T3`, `2T1R`, ...).
    pub pattern: String,
    /// A group's parameters in words (axis point, centre, pitch), when it has any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub parameters: Option<String>,
    /// The platform's degrees of freedom in it.
    pub dof: usize,
    /// How many lock subsets give it.
    pub subsets: usize,
    /// The minimal lock sets (input labels, space separated; `-` for none).
    pub lock_sets: Vec<String>,
}

impl From<&PatternModes> for Reached {
    fn from(p: &PatternModes) -> Self {
        Reached {
            pattern: p.pattern.to_string(),
            parameters: p.parameters.clone(),
            dof: p.dof,
            subsets: p.subsets,
            lock_sets: p.lock_sets.clone(),
        }
    }
}

/// One design's multioperation capacity: a row of the sweep's results. Rows read back from a
/// file are checked by [`rows::Known`] (a known design, fields that agree).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DesignRow {
    /// The design's index in the sweep.
    pub design: usize,
    /// The leg chain's catalogue id.
    pub chain: String,
    /// The leg chain's notation.
    pub notation: String,
    /// The leg chain's family.
    pub family: String,
    /// Legs.
    pub legs: usize,
    /// The actuated primitive joints of each leg, 1-based.
    pub actuated: Vec<usize>,
    /// The manipulator's inputs (legs × actuated joints per leg).
    pub inputs: usize,
    /// The platform's degrees of freedom with no input locked (0 when the design could not be
    /// built).
    pub dof: usize,
    /// The number of distinct displacement subgroups reached (a group with its axis, plane or
    /// centre), over all lock subsets.
    pub subgroups: usize,
    /// The kinds of displacement group reached, each once, in the order of the 12.
    pub group_kinds: Vec<String>,
    /// How many kinds: the paper's measure of multioperation capacity.
    pub kinds: usize,
    /// The subgroups reached with their minimal lock sets.
    pub groups: Vec<Reached>,
    /// The non-group patterns reached with their minimal lock sets.
    pub non_groups: Vec<Reached>,
    /// Lock subsets whose motion could not be sampled (left out of the patterns).
    pub unsampled: usize,
    /// Lock subsets whose start (the reference) is a singular configuration of the locked
    /// manipulator ([`crate::motion::SingularStart`]): left out of the patterns, because the
    /// motion sampled from a bifurcation depends on the branch the walks take.
    #[serde(default)]
    pub singular: usize,
    /// Their minimal lock sets.
    #[serde(default)]
    pub singular_lock_sets: Vec<String>,
    /// Why the design could not be built (its leg is singular at every configuration, say);
    /// the counts are then zero.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

impl Design {
    /// The manipulator of this design: `legs` copies of the chain with the default geometry
    /// of [`BuildSpec`].
    ///
    /// # Errors
    /// The build's, as text (a leg singular at every configuration, for instance).
    pub fn manipulator(&self, legs: usize) -> Result<Manipulator, String> {
        let spec = BuildSpec {
            legs,
            chain: self.chain.clone(),
            actuated: Some(self.actuated.clone()),
            ..BuildSpec::default()
        };
        let description = build(&spec).map_err(|e| e.to_string())?;
        Manipulator::new(&description).map_err(|e| e.to_string())
    }

    /// This design's multioperation capacity: the motion of every lock subset of its inputs
    /// from the reference configuration ([`Manipulator::modes`]).
    #[must_use]
    pub fn evaluate(&self, settings: &SweepSettings) -> DesignRow {
        let inputs = settings.legs * self.actuated.len();
        let mut row = DesignRow {
            design: self.index,
            chain: self.chain.clone(),
            notation: self.notation.clone(),
            family: self.family.clone(),
            legs: settings.legs,
            actuated: self.actuated.clone(),
            inputs,
            dof: 0,
            subgroups: 0,
            group_kinds: Vec::new(),
            kinds: 0,
            groups: Vec::new(),
            non_groups: Vec::new(),
            unsampled: 0,
            singular: 0,
            singular_lock_sets: Vec::new(),
            error: None,
        };
        let manipulator = match self.manipulator(settings.legs) {
            Ok(m) => m,
            Err(e) => {
                row.error = Some(e);
                return row;
            }
        };
        let modes = match manipulator.modes(&settings.sampling) {
            Ok(m) => m,
            Err(e) => {
                row.error = Some(e.to_string());
                return row;
            }
        };
        row.dof = modes
            .modes
            .iter()
            .find(|m| m.locked.is_empty())
            .map_or(0, |m| m.dof);
        row.unsampled = modes.modes.iter().filter(|m| m.error.is_some()).count();
        row.singular = modes.modes.iter().filter(|m| m.is_singular_start()).count();
        row.singular_lock_sets = modes.singular_starts;
        row.groups = modes.groups.iter().map(Reached::from).collect();
        row.non_groups = modes.non_groups.iter().map(Reached::from).collect();
        row.subgroups = row.groups.len();
        row.kinds = modes.group_kinds.len();
        row.group_kinds = modes.group_kinds;
        row
    }
}
