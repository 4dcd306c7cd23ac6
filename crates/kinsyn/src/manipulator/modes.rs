//! Multioperation capacity (paper 000 §1, §5): the motion patterns a manipulator's platform
//! produces when subsets of its inputs are locked.
//!
//! For every subset of the inputs asked for, the locked joints are held at their values at a
//! start configuration (the reference, or any assembled configuration) and the platform's finite
//! motion is sampled from there by loop closure and classified
//! ([`crate::mechanism::Mechanism::motion_pattern`]). The distinct displacement groups reached
//! are the paper's measure of a manipulator's practical effectiveness.
//!
//! The work is exponential in the number of inputs n: all subsets are 2^n, those of at most k
//! locks Σ_{j≤k} C(n, j) ([`Manipulator::lock_subset_count`]). Each subset is one sampled motion
//! (three random walks of three Newton-corrected steps by default: ten loop closures, one when
//! the locks leave the start rigid; [`Manipulator::modes_cost`] counts them before sampling),
//! so callers choose the subsets ([`Manipulator::lock_subsets`]) and are told of each one
//! finished (the `progress` callback of [`Manipulator::modes_from`]).

use super::Manipulator;
use crate::mechanism::{SampleSettings, rotation_log};
use crate::motion::{Classification, Group, GroupKind, Pattern, PatternName};
use itertools::Itertools;
use nalgebra::Vector3;
use rayon::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The platform's motion with one subset of the inputs locked.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Mode {
    /// The locked inputs (indices into the actuators).
    pub locked: Vec<usize>,
    /// The locked inputs' labels, `-` for none.
    pub lock_text: String,
    /// The platform's degrees of freedom.
    pub dof: usize,
    /// The pattern's name (`X(z)`, `1T2R`, ...), `None` when the motion could not be sampled
    /// (written `?` in JSON).
    #[serde(serialize_with = "name_or_unknown")]
    pub pattern: Option<PatternName>,
    /// Whether the pattern is one of the 12 displacement groups.
    pub group: bool,
    /// The group's parameters in words, in the file's length unit: the axis point of R, H and
    /// C (the point of the axis nearest the ground origin), the centre of S, the pitch of H and
    /// Y; `None` for groups without them and for non-group patterns.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameters: Option<String>,
    /// The classification (with the group's point and pitch), when sampled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub classification: Option<Classification>,
    /// Why the motion could not be sampled, if it could not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// The loop closures the sampling ran ([`crate::mechanism::SampledMotion::closures`]: the
    /// unit of [`crate::manipulator::ModesCost`]), `None` when the motion could not be sampled.
    /// Not written in JSON: the work, not the answer.
    #[serde(skip)]
    pub closures: Option<usize>,
}

impl Mode {
    /// Whether the motion was sampled from a singular start ([`crate::motion::SingularStart`]):
    /// its pattern is then not one answer, and is not counted as reached.
    #[must_use]
    pub fn is_singular_start(&self) -> bool {
        self.classification
            .as_ref()
            .is_some_and(|c| c.singular_start.is_some())
    }

    /// The pattern's name as text, `?` when the motion could not be sampled.
    #[must_use]
    pub fn pattern_text(&self) -> String {
        self.pattern
            .as_ref()
            .map_or_else(|| "?".to_string(), ToString::to_string)
    }
}

/// A pattern reached (a displacement subgroup with its parameters, or an `nTmR` pattern), with
/// the minimal lock sets that reach it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PatternModes {
    /// The pattern's name.
    pub pattern: PatternName,
    /// The group's parameters in words (see [`Mode::parameters`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameters: Option<String>,
    /// The platform's degrees of freedom in this pattern.
    pub dof: usize,
    /// How many of the sampled lock subsets give it.
    pub subsets: usize,
    /// The minimal lock sets (no proper subset gives the same pattern), as label lists.
    pub lock_sets: Vec<String>,
}

/// The lock subsets sampled and the patterns reached.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Modes {
    /// The manipulator's name.
    pub manipulator: String,
    /// The input labels, in actuator order.
    pub actuators: Vec<String>,
    /// How the motions were sampled (the seed included).
    pub settings: SampleSettings,
    /// The configuration the motions are sampled from (joint values, assembled); each subset's
    /// locked inputs are held at their values there.
    pub start_joint_values: Vec<f64>,
    /// The platform frame's origin at the start configuration, in the file's length unit.
    pub start_position: [f64; 3],
    /// The platform frame's rotation vector at the start configuration, in radians.
    pub start_rotation_vector_rad: [f64; 3],
    /// One mode per lock subset sampled, by number of locks then lexicographically.
    pub modes: Vec<Mode>,
    /// The distinct displacement subgroups reached (a group with its direction or plane), with
    /// their minimal lock sets.
    pub groups: Vec<PatternModes>,
    /// The distinct kinds among them (of the 12: `R` once however many axes it turns about).
    pub group_kinds: Vec<String>,
    /// The distinct non-group patterns reached, with their minimal lock sets.
    pub non_groups: Vec<PatternModes>,
    /// The minimal lock sets (label lists) of the subsets whose start is a singular
    /// configuration of the locked mechanism ([`crate::motion::SingularStart`]): their sampled
    /// pattern depends on which branch the random walks take, so it is not counted among the
    /// patterns reached.
    pub singular_starts: Vec<String>,
}

/// The largest number of inputs whose lock subsets [`Manipulator::modes`] enumerates all of
/// (2^16 subsets); [`Manipulator::modes_from`] takes any list of subsets.
pub const MAX_INPUTS: usize = 16;

/// The number of subsets of `n` inputs with at most `max_locks` locked, Σ_{`k≤max_locks`} C(n, k)
/// (2^n when `max_locks ≥ n`), saturating at `u128::MAX`.
#[must_use]
pub fn lock_subset_count(n: usize, max_locks: usize) -> u128 {
    let mut total: u128 = 0;
    let mut binomial: u128 = 1; // C(n, k)
    for k in 0..=max_locks.min(n) {
        total = total.saturating_add(binomial);
        // C(n, k + 1) = C(n, k) (n − k) / (k + 1); exact because C(n, k)(n − k) is a multiple
        // of k + 1.
        binomial = match binomial.checked_mul((n - k) as u128) {
            Some(b) => b / (k as u128 + 1),
            None => return u128::MAX,
        };
    }
    total
}

/// Whether the sorted index set `a` is a subset of the sorted index set `b`.
fn is_subset(a: &[usize], b: &[usize]) -> bool {
    let mut rest = b.iter();
    a.iter().all(|x| rest.any(|y| y == x))
}

/// The lock sets among `sets` (sorted by size) that contain no other one of them: the minimal
/// ways to reach a pattern. Each set is compared only with the minimal ones found before it,
/// since any set of `sets` inside it contains one of those.
fn minimal_sets<'a>(sets: impl Iterator<Item = &'a Mode>) -> Vec<&'a Mode> {
    let mut minimal: Vec<&Mode> = Vec::new();
    for m in sets {
        if !minimal.iter().any(|o| is_subset(&o.locked, &m.locked)) {
            minimal.push(m);
        }
    }
    minimal
}

impl Manipulator {
    /// The platform's motion with the `locked` inputs held, sampled from the reference
    /// configuration with the seed of `settings` as given.
    #[must_use]
    pub fn mode(&self, locked: &[usize], settings: &SampleSettings) -> Mode {
        self.mode_from(&self.reference(), locked, settings)
    }

    /// The platform's motion with the `locked` inputs held at their values in the configuration
    /// `start` (joint values; assembled first if it does not quite close), sampled from there;
    /// relative to the body of [`Manipulator::relative_to`] when one is set.
    #[must_use]
    pub fn mode_from(&self, start: &[f64], locked: &[usize], settings: &SampleSettings) -> Mode {
        let mask = self.lock_mask(locked);
        let lock_text = self.lock_text(locked);
        let motion = match self.relative_to {
            None => self
                .mechanism
                .sample_motion(self.platform, start, &mask, settings),
            Some(base) => self.mechanism.sample_relative_motion(
                self.platform,
                self.bodies[base].body,
                start,
                &mask,
                settings,
            ),
        };
        match motion {
            Ok(motion) => {
                let c = self.mechanism.classify_motion(&motion);
                Mode {
                    locked: locked.to_vec(),
                    lock_text,
                    dof: c.dof,
                    pattern: Some(c.pattern.name()),
                    group: c.pattern.is_group(),
                    parameters: match &c.pattern {
                        Pattern::Group(g) => self.parameters(g),
                        Pattern::NonGroup { .. } => None,
                    },
                    classification: Some(c),
                    error: None,
                    closures: Some(motion.closures),
                }
            }
            Err(e) => Mode {
                locked: locked.to_vec(),
                lock_text,
                dof: 0,
                pattern: None,
                group: false,
                parameters: None,
                classification: None,
                error: Some(e.to_string()),
                closures: None,
            },
        }
    }

    /// A group's parameters in words, in the file's length unit (see [`Mode::parameters`]).
    fn parameters(&self, g: &Group) -> Option<String> {
        let unit = &self.units.length;
        let point = |p: &[f64; 3]| {
            format!(
                "[{}, {}, {}] {unit}",
                number(p[0], self.mechanism.scale()),
                number(p[1], self.mechanism.scale()),
                number(p[2], self.mechanism.scale())
            )
        };
        let pitch = |h: f64| format!("pitch {} {unit}/rad", number(h, self.mechanism.scale()));
        let parts: Vec<String> = match g.kind {
            GroupKind::R | GroupKind::C => g
                .point
                .iter()
                .map(|p| format!("axis through {}", point(p)))
                .collect(),
            GroupKind::H => g
                .point
                .iter()
                .map(|p| format!("axis through {}", point(p)))
                .chain(g.pitch.map(pitch))
                .collect(),
            GroupKind::S => g
                .point
                .iter()
                .map(|p| format!("centre {}", point(p)))
                .collect(),
            GroupKind::Y => g.pitch.map(pitch).into_iter().collect(),
            _ => Vec::new(),
        };
        (!parts.is_empty()).then(|| parts.join(", "))
    }

    /// What tells two displacement subgroups apart: the pattern (kind and direction) and its
    /// parameters made dimensionless (about the centre, over the length scale) and rounded, so
    /// that the same subgroup reached by two lock sets is counted once whatever the unit.
    fn subgroup_key(&self, mode: &Mode) -> String {
        let Some(Pattern::Group(g)) = mode.classification.as_ref().map(|c| c.pattern) else {
            return mode.pattern_text();
        };
        let m = &self.mechanism;
        let round = |x: f64| format!("{:.4}", (x * 1e4).round() / 1e4 + 0.0);
        let mut key = mode.pattern_text();
        if let Some(p) = g.point {
            let d = (Vector3::from(p) - m.centre()) / m.scale();
            // An axis point: the one nearest the centre, so that any point of the axis gives it.
            let d = match g.direction {
                Some(u) => {
                    let u = Vector3::from(u);
                    d - u * u.dot(&d)
                }
                None => d,
            };
            let _ = write!(key, " [{}, {}, {}]", round(d.x), round(d.y), round(d.z));
        }
        if let Some(h) = g.pitch {
            let _ = write!(key, " {}", round(h / m.scale()));
        }
        key
    }

    /// Labels of a set of inputs, space separated, `-` for none.
    #[must_use]
    pub fn lock_text(&self, locked: &[usize]) -> String {
        if locked.is_empty() {
            return "-".into();
        }
        locked
            .iter()
            .map(|&a| self.actuators[a].label())
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// The number of lock subsets with at most `max_locks` of the inputs locked,
    /// Σ_{`k≤max_locks`} C(n, k) for n inputs (2^n when `max_locks ≥ n`), saturating at
    /// `u128::MAX`: the number of sampled motions [`Manipulator::modes_from`] costs.
    #[must_use]
    pub fn lock_subset_count(&self, max_locks: usize) -> u128 {
        lock_subset_count(self.actuators.len(), max_locks)
    }

    /// The lock subsets with at most `max_locks` inputs locked (indices into the actuators), by
    /// number of locks then lexicographically; as many as
    /// [`Manipulator::lock_subset_count`] says, so check that first.
    #[must_use]
    pub fn lock_subsets(&self, max_locks: usize) -> Vec<Vec<usize>> {
        let n = self.actuators.len();
        (0..=max_locks.min(n))
            .flat_map(|k| (0..n).combinations(k))
            .collect()
    }

    /// The seed of one subset's walks: `settings.seed` mixed with the subset, so that a subset's
    /// motion is the same whichever other subsets are sampled with it, and whatever the thread
    /// count.
    fn subset_settings(locked: &[usize], settings: &SampleSettings) -> SampleSettings {
        let mask: u64 = locked.iter().fold(0, |m, &a| m | 1u64 << (a % 64));
        SampleSettings {
            seed: settings.seed ^ mask.wrapping_mul(0x9e37_79b9_7f4a_7c15),
            ..*settings
        }
    }

    /// The motion of every lock subset of the inputs from the reference configuration, and the
    /// patterns reached ([`Manipulator::modes_from`] with every subset).
    ///
    /// # Complexity
    /// Exponential in the number of inputs n: 2^n lock subsets, each one sampled motion (three
    /// random walks of three Newton-corrected loop closures by default): about 0.3 ms of CPU per
    /// subset for the 3-UPS (64 subsets) and 1 ms for the 6-UPS, one closure where the locks
    /// leave the start rigid, and far more at singular starts ([`Manipulator::modes_cost`]
    /// counts them before sampling; `docs/limits.md`). Hence the refusal above [`MAX_INPUTS`]
    /// (2^16 subsets); [`Manipulator::modes_from`] with [`Manipulator::lock_subsets`] samples
    /// only the subsets of at most k locks.
    ///
    /// # Errors
    /// More than [`MAX_INPUTS`] inputs.
    pub fn modes(&self, settings: &SampleSettings) -> Result<Modes, super::RequestError> {
        let n = self.actuators.len();
        if n > MAX_INPUTS {
            return Err(super::RequestError::TooManyInputs {
                manipulator: self.name.clone(),
                inputs: n,
            });
        }
        Ok(self.modes_from(&self.reference(), &self.lock_subsets(n), settings, &|| {}))
    }

    /// The motion of each of the lock `subsets` (indices into the actuators), with the locked
    /// inputs held at their values in the configuration `start` and the motion sampled from
    /// there, and the patterns reached with their minimal lock sets among these subsets.
    ///
    /// The subsets are sampled in parallel (rayon); each has its own seed derived from
    /// `settings.seed` and the subset, so a subset's mode does not depend on the other subsets
    /// or the thread count. `progress` is called once per subset finished (from any thread):
    /// the hook for a progress bar.
    ///
    /// # Complexity
    /// One sampled motion per subset, so linear in `subsets.len()`; the minimal lock sets of a
    /// pattern are found by comparing its subsets with the minimal ones found before, at worst
    /// quadratic in the number of subsets. Every subset of n inputs is 2^n of them, those of at
    /// most k locks Σ_{j≤k} C(n, j) ([`Manipulator::lock_subset_count`]): count them before
    /// calling with [`Manipulator::lock_subsets`].
    #[must_use]
    pub fn modes_from(
        &self,
        start: &[f64],
        subsets: &[Vec<usize>],
        settings: &SampleSettings,
        progress: &(dyn Fn() + Sync),
    ) -> Modes {
        let mut subsets: Vec<Vec<usize>> = subsets
            .iter()
            .map(|s| {
                let mut s = s.clone();
                s.sort_unstable();
                s.dedup();
                s
            })
            .collect();
        subsets.sort_by(|a, b| a.len().cmp(&b.len()).then(a.cmp(b)));
        subsets.dedup();
        let modes: Vec<Mode> = subsets
            .par_iter()
            .map(|locked| {
                let mode = self.mode_from(start, locked, &Self::subset_settings(locked, settings));
                progress();
                mode
            })
            .collect();
        let (groups, non_groups) = self.patterns_reached(&modes);
        let singular_starts = minimal_sets(modes.iter().filter(|m| m.is_singular_start()))
            .iter()
            .map(|m| m.lock_text.clone())
            .collect();
        let frame = self.platform_frame(start);
        Modes {
            manipulator: self.name.clone(),
            group_kinds: group_kinds(&modes),
            actuators: self.actuators.iter().map(super::Actuator::label).collect(),
            settings: *settings,
            start_joint_values: start.to_vec(),
            start_position: frame.translation.vector.into(),
            start_rotation_vector_rad: rotation_log(&frame.rotation).into(),
            modes,
            groups,
            non_groups,
            singular_starts,
        }
    }

    /// The distinct subgroups and the distinct non-group patterns among the sampled `modes`
    /// (sorted by number of locks), each with how many subsets give it and its minimal lock
    /// sets. Subsets whose motion could not be sampled, or was sampled from a singular start,
    /// are left out.
    fn patterns_reached(&self, modes: &[Mode]) -> (Vec<PatternModes>, Vec<PatternModes>) {
        let mut by_pattern: BTreeMap<(bool, String), Vec<&Mode>> = BTreeMap::new();
        for m in modes
            .iter()
            .filter(|m| m.error.is_none() && !m.is_singular_start())
        {
            by_pattern
                .entry((!m.group, self.subgroup_key(m)))
                .or_default()
                .push(m);
        }
        let mut groups = Vec::new();
        let mut non_groups = Vec::new();
        for ((non_group, _), ms) in by_pattern {
            let Some(pattern) = ms[0].pattern else {
                continue; // unreachable: unsampled subsets are left out above
            };
            let entry = PatternModes {
                pattern,
                parameters: ms[0].parameters.clone(),
                dof: ms[0].dof,
                subsets: ms.len(),
                lock_sets: minimal_sets(ms.iter().copied())
                    .iter()
                    .map(|m| m.lock_text.clone())
                    .collect(),
            };
            if non_group {
                non_groups.push(entry);
            } else {
                groups.push(entry);
            }
        }
        (groups, non_groups)
    }
}

/// Writes a pattern name, or `?` for a motion that could not be sampled.
#[expect(
    clippy::ref_option,
    reason = "serde's `serialize_with` passes the field, an `Option`, by reference"
)]
fn name_or_unknown<S: serde::Serializer>(
    name: &Option<PatternName>,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    match name {
        Some(n) => n.serialize(serializer),
        None => serializer.serialize_str("?"),
    }
}

/// The kinds of displacement group among `modes` (regular starts), each once, in the order of
/// the 12.
fn group_kinds(modes: &[Mode]) -> Vec<String> {
    let mut kinds: Vec<GroupKind> = modes
        .iter()
        .filter(|m| !m.is_singular_start())
        .filter_map(|m| match m.classification.as_ref().map(|c| c.pattern) {
            Some(Pattern::Group(g)) => Some(g.kind),
            _ => None,
        })
        .collect();
    kinds.sort_by_key(|k| GroupKind::ALL.iter().position(|g| g == k));
    kinds.dedup();
    kinds.iter().map(|k| k.symbol().to_string()).collect()
}

/// A length printed with six significant digits relative to the mechanism's scale: values below
/// a millionth of it are round-off and print as 0.
fn number(x: f64, scale: f64) -> String {
    if x.abs() < 1e-6 * scale {
        return "0".into();
    }
    #[expect(
        clippy::cast_possible_truncation,
        reason = "the decimal exponent of a finite f64 is within ±324 (`as` saturates for an \
                  infinite one, which the clamp below absorbs)"
    )]
    let exponent = x.abs().log10().floor() as i32;
    #[expect(clippy::cast_sign_loss, reason = "clamped to 0..=12")]
    let digits = (6 - exponent - 1).clamp(0, 12) as usize;
    let text = format!("{x:.digits$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}
