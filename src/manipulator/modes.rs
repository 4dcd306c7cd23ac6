//! Multioperation capacity (paper 000 §1, §5): the motion patterns a manipulator's platform
//! produces when subsets of its inputs are locked.
//!
//! For every subset of the inputs, the locked joints are held at their reference values and the
//! platform's finite motion is sampled by loop closure and classified
//! ([`crate::mechanism::Mechanism::motion_pattern`]). The distinct displacement groups reached
//! are the paper's measure of a manipulator's practical effectiveness.

use super::Manipulator;
use crate::mechanism::SampleSettings;
use crate::motion::{Classification, Group, GroupKind, Pattern};
use nalgebra::Vector3;
use rayon::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;

/// The platform's motion with one subset of the inputs locked.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Mode {
    /// The locked inputs (indices into the actuators).
    pub locked: Vec<usize>,
    /// The locked inputs' labels, `-` for none.
    pub lock_text: String,
    /// The platform's degrees of freedom.
    pub dof: usize,
    /// The pattern's text form (`X(z)`, `1T2R`, ...), or `?` when the motion could not be
    /// sampled.
    pub pattern: String,
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
}

/// A group pattern reached, with the minimal lock sets that reach it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PatternModes {
    /// The pattern's text form.
    pub pattern: String,
    /// The group's parameters in words (see [`Mode::parameters`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameters: Option<String>,
    /// The minimal lock sets (no proper subset gives the same pattern), as label lists.
    pub lock_sets: Vec<String>,
}

/// Every lock subset and the group patterns reached.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Modes {
    /// The manipulator's name.
    pub manipulator: String,
    /// The input labels, in actuator order.
    pub actuators: Vec<String>,
    /// How the motions were sampled (the seed included).
    pub settings: SampleSettings,
    /// One mode per subset of the inputs, by number of locks then lexicographically.
    pub modes: Vec<Mode>,
    /// The distinct displacement subgroups reached (a group with its direction or plane), with
    /// their minimal lock sets.
    pub groups: Vec<PatternModes>,
    /// The distinct kinds among them (of the 12: `R` once however many axes it turns about).
    pub group_kinds: Vec<String>,
    /// The distinct non-group patterns reached, with their minimal lock sets.
    pub non_groups: Vec<PatternModes>,
}

/// The largest number of inputs whose lock subsets are all enumerated (2^16 subsets).
pub const MAX_INPUTS: usize = 16;

impl Manipulator {
    /// The platform's motion with the `locked` inputs held, sampled from the reference
    /// configuration.
    #[must_use]
    pub fn mode(&self, locked: &[usize], settings: &SampleSettings) -> Mode {
        let mask = self.lock_mask(locked);
        let lock_text = self.lock_text(locked);
        match self
            .mechanism
            .motion_pattern(self.platform, &self.reference(), &mask, settings)
        {
            Ok(c) => Mode {
                locked: locked.to_vec(),
                lock_text,
                dof: c.dof,
                pattern: c.pattern.to_string(),
                group: c.pattern.is_group(),
                parameters: match &c.pattern {
                    Pattern::Group(g) => self.parameters(g),
                    Pattern::NonGroup { .. } => None,
                },
                classification: Some(c),
                error: None,
            },
            Err(e) => Mode {
                locked: locked.to_vec(),
                lock_text,
                dof: 0,
                pattern: "?".into(),
                group: false,
                parameters: None,
                classification: None,
                error: Some(e.to_string()),
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
            return mode.pattern.clone();
        };
        let m = &self.mechanism;
        let round = |x: f64| format!("{:.4}", (x * 1e4).round() / 1e4 + 0.0);
        let mut key = mode.pattern.clone();
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
            key += &format!(" [{}, {}, {}]", round(d.x), round(d.y), round(d.z));
        }
        if let Some(h) = g.pitch {
            key += &format!(" {}", round(h / m.scale()));
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

    /// The motion of every lock subset of the inputs, and the patterns reached (in parallel
    /// over the subsets; each subset's walk has its own seed derived from `settings.seed`, so the
    /// result does not depend on the thread count).
    ///
    /// # Errors
    /// More than [`MAX_INPUTS`] inputs.
    pub fn modes(&self, settings: &SampleSettings) -> Result<Modes, String> {
        let n = self.actuators.len();
        if n > MAX_INPUTS {
            return Err(format!(
                "{} has {n} inputs; at most {MAX_INPUTS} can have all their lock subsets enumerated",
                self.name
            ));
        }
        let mut subsets: Vec<Vec<usize>> = (0u32..(1 << n))
            .map(|mask| (0..n).filter(|a| mask & (1 << a) != 0).collect())
            .collect();
        subsets.sort_by(|a, b| a.len().cmp(&b.len()).then(a.cmp(b)));
        let modes: Vec<Mode> = subsets
            .par_iter()
            .map(|locked| {
                let mask: u64 = locked.iter().map(|a| 1u64 << a).sum();
                let own = SampleSettings {
                    seed: settings.seed ^ mask.wrapping_mul(0x9e37_79b9_7f4a_7c15),
                    ..*settings
                };
                self.mode(locked, &own)
            })
            .collect();
        let mut by_pattern: BTreeMap<(bool, String), Vec<&Mode>> = BTreeMap::new();
        for m in modes.iter().filter(|m| m.error.is_none()) {
            by_pattern
                .entry((!m.group, self.subgroup_key(m)))
                .or_default()
                .push(m);
        }
        let mut groups = Vec::new();
        let mut non_groups = Vec::new();
        for ((non_group, _), ms) in by_pattern {
            let pattern = ms[0].pattern.clone();
            let parameters = ms[0].parameters.clone();
            let minimal: Vec<String> = ms
                .iter()
                .filter(|m| {
                    !ms.iter().any(|o| {
                        o.locked.len() < m.locked.len()
                            && o.locked.iter().all(|a| m.locked.contains(a))
                    })
                })
                .map(|m| m.lock_text.clone())
                .collect();
            let entry = PatternModes {
                pattern,
                parameters,
                lock_sets: minimal,
            };
            if non_group {
                non_groups.push(entry);
            } else {
                groups.push(entry);
            }
        }
        let mut group_kinds: Vec<String> = modes
            .iter()
            .filter_map(|m| match m.classification.as_ref().map(|c| c.pattern) {
                Some(crate::motion::Pattern::Group(g)) => Some(g.kind.symbol().to_string()),
                _ => None,
            })
            .collect();
        group_kinds.sort_by_key(|k| {
            crate::motion::GroupKind::ALL
                .iter()
                .position(|g| g.symbol() == k)
                .unwrap_or(usize::MAX)
        });
        group_kinds.dedup();
        Ok(Modes {
            manipulator: self.name.clone(),
            group_kinds,
            actuators: self.actuators.iter().map(super::Actuator::label).collect(),
            settings: *settings,
            modes,
            groups,
            non_groups,
        })
    }
}

/// A length printed with six significant digits relative to the mechanism's scale: values below
/// a millionth of it are round-off and print as 0.
fn number(x: f64, scale: f64) -> String {
    if x.abs() < 1e-6 * scale {
        return "0".into();
    }
    let digits = (6 - (x.abs().log10().floor() as i32) - 1).clamp(0, 12) as usize;
    let text = format!("{x:.digits$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}
