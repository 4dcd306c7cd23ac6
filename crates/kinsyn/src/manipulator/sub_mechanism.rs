//! Sub-mechanisms: a description cut down to some of its legs (`kinsyn modes --legs 1-4`), so
//! that the displacement group one limb or one loop generates — its kinematic bond (paper 001
//! eqs. 1–3) — can be read from the same file as the whole mechanism.
//!
//! The legs kept are those listed; the moving bodies kept are those the kept legs still join to
//! the ground by a chain of legs. A listed leg between two bodies that are no longer joined to
//! the ground is dropped with them (it cannot move anything the ground sees).

use super::file::MultibodyDescription;
use std::collections::BTreeSet;

/// Why a list of legs cannot be kept.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SubMechanismError {
    /// The list does not parse.
    #[error("{item:?} is not a leg number or a range of them (e.g. 1-4,29)")]
    NotALeg {
        /// The item at fault.
        item: String,
    },
    /// An empty list.
    #[error("no leg listed (e.g. 1-4,29)")]
    Empty,
    /// A range whose end is before its start.
    #[error("the range {start}-{end} runs backwards")]
    Backwards {
        /// Its start.
        start: usize,
        /// Its end.
        end: usize,
    },
    /// A leg number the description does not have.
    #[error("leg {leg} does not exist: the mechanism has legs 1 to {count}")]
    OutOfRange {
        /// The number (1-based).
        leg: usize,
        /// The number of legs.
        count: usize,
    },
    /// The body to analyse is not joined to the ground by the legs kept.
    #[error(
        "{role} {body:?} is not joined to the ground {ground:?} by the legs kept (bodies kept: {kept})"
    )]
    Dropped {
        /// `the end-effector` or `the body`.
        role: &'static str,
        /// Its name.
        body: String,
        /// The ground's name.
        ground: String,
        /// The moving bodies that remain, comma separated (`none`).
        kept: String,
    },
}

/// The legs of a list such as `1-4,8,29` (1-based, ranges inclusive, commas or spaces between
/// items), as sorted 0-based indices without repeats, for a mechanism of `count` legs.
///
/// # Errors
/// An item that is not a number or a range, a backward range, a leg outside `1 … count`, an
/// empty list.
pub fn parse_leg_list(text: &str, count: usize) -> Result<Vec<usize>, SubMechanismError> {
    let mut legs = BTreeSet::new();
    for item in text
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|s| !s.is_empty())
    {
        let number = |s: &str| {
            s.trim()
                .parse::<usize>()
                .map_err(|_| SubMechanismError::NotALeg { item: item.into() })
        };
        let (start, end) = match item.split_once('-') {
            Some((a, b)) => (number(a)?, number(b)?),
            None => (number(item)?, number(item)?),
        };
        if end < start {
            return Err(SubMechanismError::Backwards { start, end });
        }
        for leg in [start, end] {
            if leg == 0 || leg > count {
                return Err(SubMechanismError::OutOfRange { leg, count });
            }
        }
        legs.extend(start - 1..end);
    }
    if legs.is_empty() {
        return Err(SubMechanismError::Empty);
    }
    Ok(legs.into_iter().collect())
}

impl MultibodyDescription {
    /// The sub-mechanism of the `legs` (0-based indices, in file order): those legs whose bodies
    /// the kept legs join to the ground, and those bodies (in file order). Its end-effector is
    /// `body` when given, else this description's end-effector.
    ///
    /// # Errors
    /// [`SubMechanismError::OutOfRange`] for an index beyond the legs;
    /// [`SubMechanismError::Dropped`] when `body`, or the end-effector when no body is given, is
    /// not joined to the ground by the legs kept (or is not a moving body at all).
    pub fn with_legs(
        &self,
        legs: &[usize],
        body: Option<&str>,
    ) -> Result<MultibodyDescription, SubMechanismError> {
        if let Some(&leg) = legs.iter().find(|&&l| l >= self.legs.len()) {
            return Err(SubMechanismError::OutOfRange {
                leg: leg + 1,
                count: self.legs.len(),
            });
        }
        // The bodies reached from the ground through the listed legs, either way along a leg.
        let mut joined: BTreeSet<&str> = BTreeSet::from([self.ground.as_str()]);
        loop {
            let before = joined.len();
            for &l in legs {
                let leg = &self.legs[l];
                if joined.contains(leg.from.as_str()) || joined.contains(leg.to.as_str()) {
                    joined.insert(&leg.from);
                    joined.insert(&leg.to);
                }
            }
            if joined.len() == before {
                break;
            }
        }
        let bodies: Vec<_> = self
            .bodies
            .iter()
            .filter(|b| joined.contains(b.name.as_str()))
            .cloned()
            .collect();
        let (role, name) = match body {
            Some(b) => ("the body", b.to_string()),
            None => (
                "the end-effector",
                self.end_effector
                    .clone()
                    .or_else(|| self.bodies.first().map(|b| b.name.clone()))
                    .unwrap_or_default(),
            ),
        };
        if !bodies.iter().any(|b| b.name == name) {
            let kept: Vec<&str> = bodies.iter().map(|b| b.name.as_str()).collect();
            return Err(SubMechanismError::Dropped {
                role,
                body: name,
                ground: self.ground.clone(),
                kept: if kept.is_empty() {
                    "none".into()
                } else {
                    kept.join(", ")
                },
            });
        }
        let mut kept: Vec<usize> = legs.to_vec();
        kept.sort_unstable();
        kept.dedup();
        Ok(MultibodyDescription {
            legs: kept
                .into_iter()
                .map(|l| &self.legs[l])
                .filter(|leg| joined.contains(leg.from.as_str()))
                .cloned()
                .collect(),
            bodies,
            end_effector: Some(name),
            ..self.clone()
        })
    }
}
