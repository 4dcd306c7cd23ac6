//! Chain notation: joint letters with the marks that paper 000 sets in typography.
//!
//! Paper 000 (§2, rule 4) writes a serial chain as a word of joint letters — P (prismatic),
//! R (revolute), C (cylindrical = coaxial P and R), U (universal = two intersecting
//! perpendicular R), S (spherical = three intersecting mutually perpendicular R) — and marks
//! with underline, italics and bold the groups of R joints whose axes are parallel, and with a
//! double underline the actuated joint. The plain-text copy lost those marks; kinsyn keeps them
//! in ASCII:
//!
//! * a parallel group is a lower-case letter after the revolute it holds: `a` for the first
//!   group (the paper's underline), `b` for the second (italics), `c` for the third (bold);
//! * an actuated primitive joint is marked with `!`;
//! * a letter holding several primitive joints (C = P then R, U = R R, S = R R R) takes one
//!   slot per primitive in parentheses, `-` for an unmarked slot: `U(a,-)`, `S(-,-,b)`,
//!   `C(!,-)`. `Ca` is short for `C(-,a)` (the group mark of a C always belongs to its R).
//!
//! The paper's rule-4 example, the 3T3R chain RRRRRR with three parallel groups, is
//! `RaRaRbRbRcRc`, read in C/U/S letters as `RaU(a,b)U(b,c)Rc`. See `docs/notation.md`.
//!
//! ```
//! use kinsyn::notation::Chain;
//! let chain: Chain = "RaU(a,b)U(b,c)Rc".parse().unwrap();
//! assert_eq!(chain.letters(), "RUUR");
//! assert_eq!(chain.primitive_word(), "RRRRRR");
//! assert_eq!(chain.to_string(), "RaU(a,b)U(b,c)Rc");
//! assert!("RaRRa".parse::<Chain>().is_err()); // §2.3: RRR = RRR, not a parallel group
//! ```

use std::fmt;
use std::str::FromStr;

/// The most primitive joints a leg may have (paper 000 §2: non-redundant 6-dof chains).
pub const MAX_PRIMITIVES: usize = 6;

/// The two first-class kinematic pairs every chain is built from (paper 000 §2).
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
pub enum Primitive {
    /// Prismatic joint: a translation along its guide.
    P,
    /// Revolute joint: a rotation about its axis.
    R,
}

impl Primitive {
    /// The joint's letter.
    #[must_use]
    pub fn letter(self) -> char {
        match self {
            Primitive::P => 'P',
            Primitive::R => 'R',
        }
    }
}

/// One of the three mutually perpendicular directions of paper 000 §2, rule 1: every joint axis
/// of a catalogue chain lies along one of them at the reference configuration, so that
/// consecutive axes are parallel or perpendicular. Written `x`, `y`, `z` (the catalogue's axis
/// words, `kinsyn build --axes`); in a leg frame they are the frame's three axes.
///
/// ```
/// use kinsyn::notation::Axis;
/// let z: Axis = "z".parse().unwrap();
/// assert_eq!(z, Axis::Z);
/// assert_eq!(z.to_string(), "z");
/// assert_eq!(z.unit(), nalgebra::Vector3::z());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Axis {
    /// The first direction (the first joint's, in a canonical axis word).
    X,
    /// The second direction.
    Y,
    /// The third direction.
    Z,
}

impl Axis {
    /// The three directions, in the order x, y, z.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// The position of the direction in `x, y, z` (0, 1, 2): the coordinate its unit vector
    /// has, and the column of a frame it picks.
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The direction at position `i` (0, 1, 2) of `x, y, z`; `None` beyond.
    #[must_use]
    pub fn from_index(i: usize) -> Option<Axis> {
        Axis::ALL.get(i).copied()
    }

    /// The direction's letter, `x`, `y` or `z`.
    #[must_use]
    pub fn letter(self) -> char {
        ['x', 'y', 'z'][self.index()]
    }

    /// The direction of a letter `x`, `y` or `z` (lower case only, as files write them).
    #[must_use]
    pub fn from_letter(c: char) -> Option<Axis> {
        match c {
            'x' => Some(Axis::X),
            'y' => Some(Axis::Y),
            'z' => Some(Axis::Z),
            _ => None,
        }
    }

    /// The unit vector along the direction in the frame it is read in: `(1, 0, 0)` for x, and
    /// so on.
    #[must_use]
    pub fn unit(self) -> nalgebra::Vector3<f64> {
        nalgebra::Vector3::ith(self.index(), 1.0)
    }
}

impl fmt::Display for Axis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(["x", "y", "z"][self.index()])
    }
}

/// Why a text is not an axis direction or an axis word.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum AxisError {
    /// A character that is not `x`, `y` or `z` (or a direction text of another length).
    #[error("{text:?}: {found:?} is not an axis direction; write x, y or z")]
    NotAnAxis {
        /// The whole text.
        text: String,
        /// What stands where a direction should.
        found: String,
    },
}

impl FromStr for Axis {
    type Err = AxisError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let mut chars = s.chars();
        match (chars.next().and_then(Axis::from_letter), chars.next()) {
            (Some(a), None) => Ok(a),
            _ => Err(AxisError::NotAnAxis {
                text: s.to_string(),
                found: s.to_string(),
            }),
        }
    }
}

/// The axis directions of a chain's primitive joints at the reference configuration, one
/// [`Axis`] letter each: the catalogue's axis word, such as `xyzxyz` for PPPS (three
/// perpendicular guides, then the spherical joint's three perpendicular revolutes).
///
/// It reads as the text it is written as (it dereferences to `str`, and serialises as that
/// string), and holds only the letters `x`, `y`, `z`, which [`AxisWord::axes`] gives as
/// directions.
///
/// ```
/// use kinsyn::notation::{Axis, AxisWord};
/// let word: AxisWord = "xyzxyz".parse().unwrap();
/// assert_eq!(word.axes().take(3).collect::<Vec<_>>(), [Axis::X, Axis::Y, Axis::Z]);
/// assert_eq!(word.as_str(), "xyzxyz");
/// assert!("xyw".parse::<AxisWord>().is_err());
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct AxisWord(String);

impl AxisWord {
    /// The word as text.
    #[must_use]
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// The directions, joint by joint.
    #[must_use]
    pub fn axes(&self) -> impl ExactSizeIterator<Item = Axis> + '_ {
        // Only x, y and z are ever stored.
        self.0.bytes().map(|b| Axis::ALL[usize::from(b - b'x')])
    }
}

impl FromIterator<Axis> for AxisWord {
    fn from_iter<I: IntoIterator<Item = Axis>>(iter: I) -> Self {
        AxisWord(iter.into_iter().map(Axis::letter).collect())
    }
}

impl std::ops::Deref for AxisWord {
    type Target = str;

    fn deref(&self) -> &str {
        &self.0
    }
}

impl fmt::Display for AxisWord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(&self.0)
    }
}

impl FromStr for AxisWord {
    type Err = AxisError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.chars().find(|&c| Axis::from_letter(c).is_none()) {
            Some(c) => Err(AxisError::NotAnAxis {
                text: s.to_string(),
                found: c.to_string(),
            }),
            None => Ok(AxisWord(s.to_string())),
        }
    }
}

impl serde::Serialize for AxisWord {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(&self.0)
    }
}

impl<'de> serde::Deserialize<'de> for AxisWord {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let text = String::deserialize(deserializer)?;
        text.parse().map_err(serde::de::Error::custom)
    }
}

/// The joint letters of paper 000: first-class pairs P, R and the pairs built from them.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
pub enum JointKind {
    /// Prismatic.
    P,
    /// Revolute.
    R,
    /// Cylindrical: a P and an R with the same axis (rule 2), written P first.
    C,
    /// Universal: two perpendicular R with intersecting axes (rule 3).
    U,
    /// Spherical: three mutually perpendicular R with intersecting axes (rule 3).
    S,
}

impl JointKind {
    /// Parses a joint letter.
    #[must_use]
    pub fn from_letter(c: char) -> Option<Self> {
        Some(match c {
            'P' => JointKind::P,
            'R' => JointKind::R,
            'C' => JointKind::C,
            'U' => JointKind::U,
            'S' => JointKind::S,
            _ => return None,
        })
    }

    /// The joint's letter.
    #[must_use]
    pub fn letter(self) -> char {
        match self {
            JointKind::P => 'P',
            JointKind::R => 'R',
            JointKind::C => 'C',
            JointKind::U => 'U',
            JointKind::S => 'S',
        }
    }

    /// The primitive joints the letter stands for, in the order the notation's slots use.
    #[must_use]
    pub fn primitives(self) -> &'static [Primitive] {
        match self {
            JointKind::P => &[Primitive::P],
            JointKind::R => &[Primitive::R],
            JointKind::C => &[Primitive::P, Primitive::R],
            JointKind::U => &[Primitive::R, Primitive::R],
            JointKind::S => &[Primitive::R, Primitive::R, Primitive::R],
        }
    }
}

/// What the paper's typography says of one primitive joint.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Mark {
    /// Index of the parallel group (0 = `a`, underline; 1 = `b`, italics; 2 = `c`, bold).
    pub group: Option<u8>,
    /// Whether this primitive joint is actuated (double underline).
    pub actuated: bool,
}

impl Mark {
    /// Whether the mark says nothing.
    #[must_use]
    pub fn is_plain(self) -> bool {
        self.group.is_none() && !self.actuated
    }
}

/// One joint of a chain: its letter and a mark per primitive joint it holds.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Joint {
    /// The joint letter.
    pub kind: JointKind,
    /// One mark per primitive of `kind`, in slot order.
    pub marks: Vec<Mark>,
}

impl Joint {
    /// An unmarked joint.
    #[must_use]
    pub fn plain(kind: JointKind) -> Self {
        Joint {
            kind,
            marks: vec![Mark::default(); kind.primitives().len()],
        }
    }
}

/// A serial chain in paper 000's notation, with parallel groups and actuation kept.
///
/// Parallel groups are always numbered in order of first appearance (the paper's underline,
/// italics, bold), so two chains with the same groups compare equal and print the same.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Chain {
    joints: Vec<Joint>,
}

/// Why a chain string was rejected. `column` is 1-based, counting characters of the input.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NotationError {
    /// The string holds no joint.
    #[error("empty chain: write joint letters such as UPS or RaRaRbRbRcRc")]
    Empty,
    /// A character that is no joint letter, mark or bracket.
    #[error(
        "column {column}: {found:?} is not a joint letter (P, R, C, U, S) or a mark (a, b, c, !)"
    )]
    UnknownCharacter {
        /// Where.
        column: usize,
        /// What was found.
        found: char,
    },
    /// A mark, bracket or comma with no joint letter before it.
    #[error(
        "column {column}: mark {found:?} refers to no joint; marks follow the joint letter they belong to"
    )]
    DanglingMark {
        /// Where.
        column: usize,
        /// What was found.
        found: char,
    },
    /// The slot list of a joint has the wrong length or form.
    #[error(
        "column {column}: {letter} holds {expected} primitive joint(s) and takes {expected} slot(s) in parentheses, found {found}"
    )]
    SlotCount {
        /// Where the joint letter is.
        column: usize,
        /// The joint letter.
        letter: char,
        /// Slots the letter needs.
        expected: usize,
        /// Slots written.
        found: usize,
    },
    /// A slot that is not `-`, a group letter, `!` or a group letter followed by `!`.
    #[error(
        "column {column}: bad slot {slot:?}; a slot is '-', a group letter a/b/c, '!' or both as in 'a!'"
    )]
    BadSlot {
        /// Where the slot starts.
        column: usize,
        /// The slot text.
        slot: String,
    },
    /// An opening parenthesis without its closing one.
    #[error("column {column}: '(' is never closed")]
    Unclosed {
        /// Where the parenthesis is.
        column: usize,
    },
    /// A short-form mark on a letter that needs the slot list.
    #[error(
        "column {column}: {letter} holds several primitive joints; mark them with one slot each in parentheses, e.g. U(!,-) or C(!,a)"
    )]
    NeedsSlots {
        /// Where the mark is.
        column: usize,
        /// The joint letter.
        letter: char,
    },
    /// More primitive joints than a non-redundant 6-dof leg has.
    #[error(
        "the chain has {count} primitive joints; a leg has at most {MAX_PRIMITIVES} (paper 000 §2)"
    )]
    TooManyPrimitives {
        /// Primitive joints counted.
        count: usize,
    },
    /// A parallel-group mark on a prismatic joint.
    #[error(
        "column {column}: parallel-group marks belong to revolute axes; a prismatic guide takes only '!'"
    )]
    GroupOnPrismatic {
        /// Where the mark is.
        column: usize,
    },
    /// A group mark used once: a group needs two parallel axes.
    #[error(
        "column {column}: group '{group}' marks one revolute only; a parallel group needs at least two"
    )]
    LoneGroup {
        /// Where the mark is.
        column: usize,
        /// The group letter.
        group: char,
    },
    /// Two revolutes of one U or S marked parallel: their axes are perpendicular.
    #[error(
        "column {column}: {letter} cannot hold two revolutes of group '{group}': its axes are perpendicular (rule 3)"
    )]
    GroupInsideJoint {
        /// Where the joint letter is.
        column: usize,
        /// The joint letter.
        letter: char,
        /// The group letter.
        group: char,
    },
    /// A revolute not in the group lies between two of its members.
    #[error(
        "column {column}: the revolute here splits group '{group}'; parallel axes separated by a non-parallel revolute do not stay parallel (paper 000 §2.3: RRR = RRR)"
    )]
    BrokenGroup {
        /// Where the splitting revolute's letter is.
        column: usize,
        /// The group letter.
        group: char,
    },
}

/// A letter and its column, kept while parsing so that errors can name positions.
struct Parsed {
    joint: Joint,
    column: usize,
    /// Column of each slot's mark (for errors), same length as `joint.marks`.
    slot_columns: Vec<usize>,
}

fn group_index(c: char) -> Option<u8> {
    match c {
        'a' => Some(0),
        'b' => Some(1),
        'c' => Some(2),
        _ => None,
    }
}

fn group_letter(g: u8) -> char {
    (b'a' + g) as char
}

fn parse_slot(text: &str, column: usize) -> Result<Mark, NotationError> {
    let bad = || NotationError::BadSlot {
        column,
        slot: text.to_string(),
    };
    let mut chars = text.chars();
    let mut mark = Mark::default();
    match chars.next() {
        None | Some('-') => {
            if chars.next().is_some() {
                return Err(bad());
            }
            return Ok(mark);
        }
        Some('!') => mark.actuated = true,
        Some(c) => mark.group = Some(group_index(c).ok_or_else(bad)?),
    }
    match chars.next() {
        None => {}
        Some('!') if !mark.actuated => mark.actuated = true,
        Some(_) => return Err(bad()),
    }
    if chars.next().is_some() {
        return Err(bad());
    }
    Ok(mark)
}

/// The marks of a joint written with slots, `U(a,b!)`: one slot per primitive joint of the
/// letter (a C's prismatic then its revolute, a U's two revolutes, an S's three). `open` is the
/// index of the `(` in `chars`; `column` and `letter` are the joint's. Returns the index just
/// past the `)`.
fn parse_slots(
    chars: &[(usize, char)],
    open: usize,
    column: usize,
    letter: char,
    joint: &mut Joint,
    slot_columns: &mut [usize],
) -> Result<usize, NotationError> {
    let open_column = chars[open].0;
    let close = chars[open..]
        .iter()
        .position(|&(_, c)| c == ')')
        .map(|k| open + k)
        .ok_or(NotationError::Unclosed {
            column: open_column,
        })?;
    let inner = &chars[open + 1..close];
    let mut slots: Vec<(usize, String)> = vec![(
        inner.first().map_or(open_column + 1, |x| x.0),
        String::new(),
    )];
    for &(col, ch) in inner {
        if ch == ',' {
            slots.push((col + 1, String::new()));
        } else {
            slots.last_mut().expect("one slot at least").1.push(ch);
        }
    }
    if slots.len() != joint.marks.len() {
        return Err(NotationError::SlotCount {
            column,
            letter,
            expected: joint.marks.len(),
            found: slots.len(),
        });
    }
    for (k, (col, text)) in slots.iter().enumerate() {
        joint.marks[k] = parse_slot(text, *col)?;
        slot_columns[k] = *col;
    }
    Ok(close + 1)
}

/// The short form of a mark, `[group][!]` directly after P, R or C (`Ra!`, `Cb`): the mark of
/// the joint's one axis, or the group of a C's revolute (an actuated C needs slots, `C(!,-)`).
/// `start` is the index just past the letter; returns the index just past the mark (`start`
/// when there is none).
fn parse_short_marks(
    chars: &[(usize, char)],
    start: usize,
    letter: char,
    joint: &mut Joint,
    slot_columns: &mut [usize],
) -> Result<usize, NotationError> {
    let mut i = start;
    let mut text = String::new();
    while i < chars.len()
        && (group_index(chars[i].1).is_some() || chars[i].1 == '!')
        && text.len() < 2
    {
        text.push(chars[i].1);
        i += 1;
    }
    if !text.is_empty() {
        let col = chars[start].0;
        let mark = parse_slot(&text, col)?;
        match joint.kind {
            JointKind::P | JointKind::R => {
                joint.marks[0] = mark;
                slot_columns[0] = col;
            }
            JointKind::C if !mark.actuated => {
                joint.marks[1] = mark;
                slot_columns[1] = col;
            }
            _ => {
                return Err(NotationError::NeedsSlots {
                    column: col,
                    letter,
                });
            }
        }
    }
    Ok(i)
}

impl FromStr for Chain {
    type Err = NotationError;

    /// Parses a chain such as `UP!S`, `RaU(a,b)U(b,c)Rc` or `CaRaS(a,-,-)`. Whitespace is ignored.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let chars: Vec<(usize, char)> = s
            .chars()
            .enumerate()
            .map(|(i, c)| (i + 1, c))
            .filter(|(_, c)| !c.is_whitespace())
            .collect();
        if chars.is_empty() {
            return Err(NotationError::Empty);
        }
        let mut parsed: Vec<Parsed> = Vec::new();
        let mut i = 0;
        while i < chars.len() {
            let (column, c) = chars[i];
            let Some(kind) = JointKind::from_letter(c) else {
                return Err(
                    if group_index(c).is_some() || matches!(c, '!' | '(' | ')' | ',' | '-') {
                        NotationError::DanglingMark { column, found: c }
                    } else {
                        NotationError::UnknownCharacter { column, found: c }
                    },
                );
            };
            i += 1;
            let mut joint = Joint::plain(kind);
            let mut slot_columns = vec![column; kind.primitives().len()];
            i = if i < chars.len() && chars[i].1 == '(' {
                parse_slots(&chars, i, column, c, &mut joint, &mut slot_columns)?
            } else {
                parse_short_marks(&chars, i, c, &mut joint, &mut slot_columns)?
            };
            parsed.push(Parsed {
                joint,
                column,
                slot_columns,
            });
        }
        let count: usize = parsed.iter().map(|p| p.joint.marks.len()).sum();
        if count > MAX_PRIMITIVES {
            return Err(NotationError::TooManyPrimitives { count });
        }
        validate_groups(&parsed)?;
        Ok(Chain::from_joints(
            parsed.into_iter().map(|p| p.joint).collect(),
        ))
    }
}

/// Checks the parallel-group marks against rules 3 and 5 of the reading of §2.
fn validate_groups(parsed: &[Parsed]) -> Result<(), NotationError> {
    // Primitive-level view: (primitive, mark, column, index of the joint holding it).
    let mut prims = Vec::new();
    for (j, p) in parsed.iter().enumerate() {
        for (k, prim) in p.joint.kind.primitives().iter().enumerate() {
            prims.push((*prim, p.joint.marks[k], p.slot_columns[k], j));
        }
    }
    for &(prim, mark, col, _) in &prims {
        if prim == Primitive::P && mark.group.is_some() {
            return Err(NotationError::GroupOnPrismatic { column: col });
        }
    }
    for g in 0..3u8 {
        let members: Vec<usize> = prims
            .iter()
            .enumerate()
            .filter(|(_, x)| x.1.group == Some(g))
            .map(|(i, _)| i)
            .collect();
        if members.len() == 1 {
            return Err(NotationError::LoneGroup {
                column: prims[members[0]].2,
                group: group_letter(g),
            });
        }
        if members.len() < 2 {
            continue;
        }
        for w in members.windows(2) {
            let (a, b) = (w[0], w[1]);
            if prims[a].3 == prims[b].3
                && matches!(parsed[prims[a].3].joint.kind, JointKind::U | JointKind::S)
            {
                let joint = &parsed[prims[a].3];
                return Err(NotationError::GroupInsideJoint {
                    column: joint.column,
                    letter: joint.joint.kind.letter(),
                    group: group_letter(g),
                });
            }
            if let Some(split) = (a + 1..b).find(|&k| prims[k].0 == Primitive::R) {
                return Err(NotationError::BrokenGroup {
                    column: parsed[prims[split].3].column,
                    group: group_letter(g),
                });
            }
        }
    }
    Ok(())
}

impl Chain {
    /// Builds a chain from joints, renumbering parallel groups in order of first appearance.
    ///
    /// The caller is trusted to give groups that the rules allow; parse a string to have them
    /// checked.
    #[must_use]
    pub fn from_joints(mut joints: Vec<Joint>) -> Self {
        // The new number of each group given, by its given number: the count of groups seen
        // before its first mark.
        let mut renumbered: [Option<u8>; 256] = [None; 256];
        let mut next: u8 = 0;
        for m in joints.iter_mut().flat_map(|j| &mut j.marks) {
            if let Some(g) = m.group {
                let new = *renumbered[usize::from(g)].get_or_insert_with(|| {
                    let new = next;
                    // Wraps only after the 256th group, when no group is left to number.
                    next = next.wrapping_add(1);
                    new
                });
                m.group = Some(new);
            }
        }
        Chain { joints }
    }

    /// The joints, base to platform.
    #[must_use]
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The joint letters without marks, e.g. `RUUR`: the paper's "letters only" identity.
    #[must_use]
    pub fn letters(&self) -> String {
        self.joints.iter().map(|j| j.kind.letter()).collect()
    }

    /// The primitive joints with their marks, base to platform.
    pub fn primitives(&self) -> impl Iterator<Item = (Primitive, Mark)> + '_ {
        self.joints.iter().flat_map(|j| {
            j.kind
                .primitives()
                .iter()
                .copied()
                .zip(j.marks.iter().copied())
        })
    }

    /// The P/R word the chain expands to, a C written as PR.
    #[must_use]
    pub fn primitive_word(&self) -> String {
        self.primitives().map(|(p, _)| p.letter()).collect()
    }

    /// The parallel groups as lists of 1-based positions in [`Chain::primitive_word`] (a C
    /// expanded as PR), in group order.
    #[must_use]
    pub fn parallel_groups(&self) -> Vec<Vec<usize>> {
        let mut groups: Vec<Vec<usize>> = Vec::new();
        for (i, (_, m)) in self.primitives().enumerate() {
            if let Some(g) = m.group {
                let g = g as usize;
                if groups.len() <= g {
                    groups.resize(g + 1, Vec::new());
                }
                groups[g].push(i + 1);
            }
        }
        groups
    }

    /// The same chain with every actuation mark removed.
    #[must_use]
    pub fn without_actuation(&self) -> Chain {
        let mut c = self.clone();
        for j in &mut c.joints {
            for m in &mut j.marks {
                m.actuated = false;
            }
        }
        c
    }
}

fn write_slot(f: &mut fmt::Formatter<'_>, m: Mark) -> fmt::Result {
    if m.is_plain() {
        return f.write_str("-");
    }
    if let Some(g) = m.group {
        write!(f, "{}", group_letter(g))?;
    }
    if m.actuated {
        f.write_str("!")?;
    }
    Ok(())
}

impl fmt::Display for Chain {
    /// The canonical text: short forms where they exist, slot lists only where needed.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for j in &self.joints {
            write!(f, "{}", j.kind.letter())?;
            let short = match j.kind {
                JointKind::P | JointKind::R => Some(j.marks[0]),
                JointKind::C if j.marks[0].is_plain() && !j.marks[1].actuated => Some(j.marks[1]),
                _ => None,
            };
            match short {
                Some(m) if m.is_plain() => {}
                Some(m) => write_slot(f, m)?,
                None if j.marks.iter().all(|m| m.is_plain()) => {}
                None => {
                    f.write_str("(")?;
                    for (k, m) in j.marks.iter().enumerate() {
                        if k > 0 {
                            f.write_str(",")?;
                        }
                        write_slot(f, *m)?;
                    }
                    f.write_str(")")?;
                }
            }
        }
        Ok(())
    }
}

/// Whether a string of joint letters (no marks) can be read from a P/R word: P→P, R→R,
/// C→PR or RP (a coaxial pair commutes), U→RR, S→RRR.
///
/// Used to tell a misprinted name in the Appendix from a chain the rules merely did not give.
#[must_use]
pub fn letters_fit_word(letters: &str, word: &str) -> bool {
    fn fit(l: &[u8], w: &[u8]) -> bool {
        match l.split_first() {
            None => w.is_empty(),
            Some((&c, rest)) => {
                let options: &[&[u8]] = match c {
                    b'P' => &[b"P"],
                    b'R' => &[b"R"],
                    b'C' => &[b"PR", b"RP"],
                    b'U' => &[b"RR"],
                    b'S' => &[b"RRR"],
                    _ => &[],
                };
                options
                    .iter()
                    .any(|o| w.starts_with(o) && fit(rest, &w[o.len()..]))
            }
        }
    }
    fit(letters.as_bytes(), word.as_bytes())
}
