//! Lock sets: which joints of a serial chain are locked (held at their reference values) when
//! the motion it leaves is classified — paper 000's multioperation capacity of a leg, one motion
//! pattern per set of locked joints.
//!
//! Joints are numbered from 1 along the chain's primitive word (base to platform), as the
//! catalogue numbers them. The text form is the catalogue's:
//!
//! * `-` for no joint locked;
//! * when every locked joint is 1 to 9, their digits in increasing order: `124` for joints 1,
//!   2 and 4 (the catalogue's 6-joint legs, whose files keep this form);
//! * when some locked joint is 10 or more, the joint numbers in increasing order separated by
//!   commas: `1,10,12`, and a single such joint with a trailing comma, `12,`, so that a text
//!   without a comma always reads digit by digit.
//!
//! Reading accepts both forms, and blanks as well as commas between numbers (`1, 4, 5`,
//! `1 4 5`): a text with a separator reads number by number, one without reads digit by digit
//! (`45` is joints 4 and 5, `11` names joint 1 twice). A blank text is no joint, like `-`.
//!
//! ```
//! use kinsyn::lockset::LockSet;
//! let s: LockSet = "124".parse().unwrap();
//! assert_eq!(s.joints().collect::<Vec<_>>(), [1, 2, 4]);
//! let long: LockSet = [1, 10, 12].into_iter().collect();
//! assert_eq!(long.to_string(), "1,10,12");
//! assert_eq!("1,10,12".parse::<LockSet>(), Ok(long));
//! ```

use std::fmt;
use std::str::FromStr;

/// A set of locked joints of a serial chain, by 1-based position in its primitive word; at most
/// [`LockSet::MAX_JOINT`] joints (the bit mask of [`crate::verification::locked_motion`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct LockSet(u32);

/// Why a text is not a lock set.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum LockSetError {
    /// A character or number that is not a joint position.
    #[error(
        "lock set {text:?}: {found:?} is not a joint number; write joints such as 45 or 1,10,12, or - for none"
    )]
    NotANumber {
        /// The whole text.
        text: String,
        /// What stands where a joint number should.
        found: String,
    },
    /// A joint the chain does not have (0, or beyond the chain or [`LockSet::MAX_JOINT`]).
    #[error("lock set {text:?}: joint {joint} is not a joint of this chain (joints 1 to {joints})")]
    NotAJoint {
        /// The whole text.
        text: String,
        /// The joint number read.
        joint: usize,
        /// How many joints the chain has.
        joints: usize,
    },
    /// A joint written twice.
    #[error("lock set {text:?}: joint {joint} named twice")]
    Repeated {
        /// The whole text.
        text: String,
        /// The joint.
        joint: usize,
    },
}

impl LockSet {
    /// The highest joint number a lock set can hold.
    pub const MAX_JOINT: usize = 32;

    /// No joint locked: the chain's full motion.
    pub const NONE: LockSet = LockSet(0);

    /// The set whose bit `i` is joint `i + 1`.
    #[must_use]
    pub fn from_mask(mask: u32) -> Self {
        LockSet(mask)
    }

    /// The bit mask: bit `i` set when joint `i + 1` is locked.
    #[must_use]
    pub fn mask(self) -> u32 {
        self.0
    }

    /// How many joints are locked.
    #[must_use]
    pub fn len(self) -> usize {
        self.0.count_ones() as usize
    }

    /// Whether no joint is locked.
    #[must_use]
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// Whether joint `joint` (1-based) is locked.
    #[must_use]
    pub fn contains(self, joint: usize) -> bool {
        (1..=Self::MAX_JOINT).contains(&joint) && self.0 & (1 << (joint - 1)) != 0
    }

    /// Whether every joint of `self` is locked in `other` too.
    #[must_use]
    pub fn is_subset(self, other: LockSet) -> bool {
        self.0 & other.0 == self.0
    }

    /// The locked joints, 1-based, in increasing order.
    pub fn joints(self) -> impl Iterator<Item = usize> {
        (0..Self::MAX_JOINT)
            .filter(move |i| self.0 & (1 << i) != 0)
            .map(|i| i + 1)
    }

    /// Reads a lock set for a chain of `joints` joints (see the module doc for the forms).
    ///
    /// # Errors
    /// A character or number that is not a joint number, a joint outside 1 to `joints`, or a
    /// joint named twice.
    pub fn parse_for(text: &str, joints: usize) -> Result<Self, LockSetError> {
        let joints = joints.min(Self::MAX_JOINT);
        let trimmed = text.trim();
        if trimmed == "-" {
            return Ok(LockSet::NONE);
        }
        let separated = trimmed.contains(|c: char| c == ',' || c.is_whitespace());
        let tokens: Vec<&str> = if separated {
            trimmed
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|t| !t.is_empty())
                .collect()
        } else {
            trimmed
                .char_indices()
                .map(|(i, c)| &trimmed[i..i + c.len_utf8()])
                .collect()
        };
        let mut set = LockSet::NONE;
        for token in tokens {
            let joint: usize = token
                .parse()
                .ok()
                .filter(|_| token.bytes().all(|b| b.is_ascii_digit()))
                .ok_or_else(|| LockSetError::NotANumber {
                    text: text.to_string(),
                    found: token.to_string(),
                })?;
            if joint == 0 || joint > joints {
                return Err(LockSetError::NotAJoint {
                    text: text.to_string(),
                    joint,
                    joints,
                });
            }
            if set.contains(joint) {
                return Err(LockSetError::Repeated {
                    text: text.to_string(),
                    joint,
                });
            }
            set.0 |= 1 << (joint - 1);
        }
        Ok(set)
    }
}

impl FromIterator<usize> for LockSet {
    /// The set of the given 1-based joints.
    ///
    /// # Panics
    /// If a joint is 0 or above [`LockSet::MAX_JOINT`].
    fn from_iter<I: IntoIterator<Item = usize>>(iter: I) -> Self {
        LockSet(iter.into_iter().fold(0, |mask, joint| {
            assert!(
                (1..=Self::MAX_JOINT).contains(&joint),
                "joint {joint} of a lock set: joints are 1 to {}",
                Self::MAX_JOINT
            );
            mask | 1 << (joint - 1)
        }))
    }
}

impl LockSet {
    /// The text form (module doc).
    fn text(self) -> String {
        if self.is_empty() {
            return "-".to_string();
        }
        if self.joints().all(|j| j <= 9) {
            return self.joints().map(|j| j.to_string()).collect();
        }
        let numbers: Vec<String> = self.joints().map(|j| j.to_string()).collect();
        let mut s = numbers.join(",");
        if numbers.len() == 1 {
            s.push(',');
        }
        s
    }
}

impl fmt::Display for LockSet {
    /// `-`, digits (`124`), or comma-separated numbers when a joint is 10 or more (`1,10,12`,
    /// `12,`); padded as a string is (`{:<6}`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(&self.text())
    }
}

impl FromStr for LockSet {
    type Err = LockSetError;

    /// Reads either form, joints 1 to [`LockSet::MAX_JOINT`].
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        LockSet::parse_for(s, Self::MAX_JOINT)
    }
}

/// A lock set equals the text that writes it, so that `lock_sets == ["456"]` reads as the
/// catalogue does.
impl PartialEq<str> for LockSet {
    fn eq(&self, other: &str) -> bool {
        self.text() == other
    }
}

impl PartialEq<&str> for LockSet {
    fn eq(&self, other: &&str) -> bool {
        self == *other
    }
}

impl serde::Serialize for LockSet {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl<'de> serde::Deserialize<'de> for LockSet {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let text = String::deserialize(deserializer)?;
        text.parse().map_err(serde::de::Error::custom)
    }
}
