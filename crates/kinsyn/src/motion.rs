//! Motion patterns: the 12 displacement subgroups of Hervé (paper 000 §1, ref. 16) and the
//! non-group patterns `nTmR`, and the classification of a finite motion from its twist spaces.
//!
//! A motion is of group type when its spatial twist space (twists referred to the base origin)
//! is one and the same Lie subalgebra of se(3) at every sampled configuration. The subalgebra is
//! then classified by its dimension, the rank of its rotational part, its pure-translation
//! subspace and its pitch:
//!
//! | dim | rotations | translations | group |
//! |---|---|---|---|
//! | 0 | 0 | 0 | E, identity |
//! | 1 | 0 | 1 | T(u), translation along u |
//! | 1 | 1 | 0 | R(N,u) (pitch 0) or H(N,u,p) (pitch p) |
//! | 2 | 0 | 2 | T2(P), translations parallel to plane P |
//! | 2 | 1 | 1 | C(N,u), rotation about and translation along one line |
//! | 3 | 0 | 3 | T3, spatial translation |
//! | 3 | 1 | 2 | G(P) (pitch 0) planar motion, or Y(w,p) (pitch p) |
//! | 3 | 3 | 0 | S(N), rotations about point N |
//! | 4 | 1 | 3 | X(w), Schönflies motion |
//! | 6 | 3 | 3 | D, every displacement |
//!
//! Any other twist space is a non-group pattern, written `nTmR` with m the rank of its
//! rotational part and n the rest of its dimension (e.g. `1T2R`, the 3-RPS platform).
//!
//! ```
//! use kinsyn::motion::{Pattern, PatternQuery};
//! let q: PatternQuery = "X(z)".parse().unwrap();
//! assert_eq!(q.to_string(), "X(z)");
//! assert!("3T1R".parse::<PatternQuery>().is_ok());
//! assert!("Q(z)".parse::<PatternQuery>().is_err());
//! ```

use crate::linalg;
use crate::notation::Axis;
use crate::screw::{self, Twist, lie_bracket};
use nalgebra::{DMatrix, Vector3};
use serde::Serialize;
use std::fmt;
use std::str::FromStr;

/// The twelve displacement subgroups (their kinds, without parameters).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum GroupKind {
    /// Identity: no motion.
    E,
    /// Translation along a direction.
    T,
    /// Rotation about a line.
    R,
    /// Helical motion about a line with a pitch.
    H,
    /// Translations parallel to a plane.
    T2,
    /// Cylindrical: rotation about and translation along a line.
    C,
    /// Planar: translations parallel to a plane and rotations normal to it.
    G,
    /// Spatial translation.
    T3,
    /// Spherical: rotations about a point.
    S,
    /// Translating screw: translations parallel to a plane and helical motion normal to it.
    Y,
    /// Schönflies: spatial translation and rotations about one direction.
    X,
    /// Every displacement.
    D,
}

impl GroupKind {
    /// All twelve, in order of dimension.
    pub const ALL: [GroupKind; 12] = [
        GroupKind::E,
        GroupKind::T,
        GroupKind::R,
        GroupKind::H,
        GroupKind::T2,
        GroupKind::C,
        GroupKind::G,
        GroupKind::T3,
        GroupKind::S,
        GroupKind::Y,
        GroupKind::X,
        GroupKind::D,
    ];

    /// The symbol used in text.
    #[must_use]
    pub fn symbol(self) -> &'static str {
        match self {
            GroupKind::E => "E",
            GroupKind::T => "T",
            GroupKind::R => "R",
            GroupKind::H => "H",
            GroupKind::T2 => "T2",
            GroupKind::C => "C",
            GroupKind::G => "G",
            GroupKind::T3 => "T3",
            GroupKind::S => "S",
            GroupKind::Y => "Y",
            GroupKind::X => "X",
            GroupKind::D => "D",
        }
    }

    /// Dimension of the group (degrees of freedom of the motion).
    #[must_use]
    pub fn dimension(self) -> usize {
        match self {
            GroupKind::E => 0,
            GroupKind::T | GroupKind::R | GroupKind::H => 1,
            GroupKind::T2 | GroupKind::C => 2,
            GroupKind::G | GroupKind::T3 | GroupKind::S | GroupKind::Y => 3,
            GroupKind::X => 4,
            GroupKind::D => 6,
        }
    }

    /// Rank of the rotational part of the group's Lie algebra: the `m` of the `nTmR` that
    /// counts its motions (`n` = dimension − `m`).
    #[must_use]
    pub fn rotations(self) -> usize {
        match self {
            GroupKind::E | GroupKind::T | GroupKind::T2 | GroupKind::T3 => 0,
            GroupKind::R
            | GroupKind::H
            | GroupKind::C
            | GroupKind::G
            | GroupKind::Y
            | GroupKind::X => 1,
            GroupKind::S | GroupKind::D => 3,
        }
    }

    /// Whether the group's parameter is a direction (T, R, H, C, Y, X) or a plane normal (T2, G).
    fn parameter(self) -> Parameter {
        match self {
            GroupKind::T
            | GroupKind::R
            | GroupKind::H
            | GroupKind::C
            | GroupKind::Y
            | GroupKind::X => Parameter::Direction,
            GroupKind::T2 | GroupKind::G => Parameter::Plane,
            _ => Parameter::None,
        }
    }
}

#[derive(PartialEq)]
enum Parameter {
    None,
    Direction,
    Plane,
}

/// A displacement subgroup with its parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Group {
    /// Which of the twelve.
    pub kind: GroupKind,
    /// The direction u or w (T, R, H, C, Y, X) or the normal of the plane P (T2, G); unit.
    pub direction: Option<[f64; 3]>,
    /// A point N of the axis (R, H, C) or the centre (S).
    pub point: Option<[f64; 3]>,
    /// The pitch (H, Y).
    pub pitch: Option<f64>,
}

/// A motion pattern: a displacement subgroup, or a non-group pattern with its numbers of
/// independent translations and rotations.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Pattern {
    /// One of the 12 displacement subgroups.
    Group(Group),
    /// Not a group: `translations`T`rotations`R, dimension their sum.
    NonGroup {
        /// Dimension minus rotational rank.
        translations: usize,
        /// Rank of the rotational part.
        rotations: usize,
    },
}

impl Pattern {
    /// Degrees of freedom of the motion.
    #[must_use]
    pub fn dof(&self) -> usize {
        match self {
            Pattern::Group(g) => g.kind.dimension(),
            Pattern::NonGroup {
                translations,
                rotations,
            } => translations + rotations,
        }
    }

    /// Whether the pattern is one of the 12 groups.
    #[must_use]
    pub fn is_group(&self) -> bool {
        matches!(self, Pattern::Group(_))
    }
}

impl Pattern {
    /// The pattern's name: its kind and the axis-aligned or rounded direction of its axis or
    /// plane normal, without the points and pitches that depend on the geometry.
    #[must_use]
    pub fn name(&self) -> PatternName {
        match *self {
            Pattern::NonGroup {
                translations,
                rotations,
            } => PatternName::NonGroup {
                translations,
                rotations,
            },
            Pattern::Group(g) => PatternName::Group {
                kind: g.kind,
                direction: match g.kind.parameter() {
                    Parameter::None => None,
                    Parameter::Direction | Parameter::Plane => {
                        g.direction.map(|d| Direction::of(&d))
                    }
                },
            },
        }
    }
}

impl fmt::Display for Pattern {
    /// The text form, its [`Pattern::name`]: the group symbol with its direction (`X(z)`,
    /// `G(xy)`, `T3`, `S`), or `nTmR`. Points and pitches are in the JSON form only (they depend
    /// on the geometry).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.name().fmt(f)
    }
}

/// The direction that names a group's axis (T, R, H, C, Y, X) or plane normal (T2, G).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Along a frame axis, in either sense: written `x`, `y`, `z` (planes `yz`, `xz`, `xy`).
    Along(Axis),
    /// Any other unit direction, by its components in thousandths (rounded, −0 as 0): written
    /// `[0.707,0.707,0.000]` (planes `n=[…]`, by their normal).
    Oblique([i32; 3]),
}

impl Direction {
    /// Names a unit direction: along an axis when one component is ±1 (within 1e-6), else
    /// rounded to thousandths, so that one direction always gets the same name.
    #[must_use]
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a unit vector's components in thousandths are within ±1000 (`as` saturates \
                  beyond and reads NaN as 0)"
    )]
    pub fn of(d: &[f64; 3]) -> Self {
        if let Some(a) = Axis::ALL
            .into_iter()
            .find(|a| (d[a.index()].abs() - 1.0).abs() < 1e-6)
        {
            return Direction::Along(a);
        }
        // Thousandths fit an i32 for a unit vector; a non-finite component reads as 0.
        Direction::Oblique(d.map(|x| (x * 1000.0).round() as i32))
    }

    /// `x`, `y`, `z`, or the components.
    fn text(self) -> String {
        match self {
            Direction::Along(a) => a.to_string(),
            Direction::Oblique(m) => {
                let c = |k: i32| f64::from(k) / 1000.0;
                format!("[{:.3},{:.3},{:.3}]", c(m[0]), c(m[1]), c(m[2]))
            }
        }
    }

    /// The plane with this normal: `yz` for x, `xz` for y, `xy` for z, else `n=[…]`.
    fn plane_text(self) -> String {
        match self {
            Direction::Along(a) => ["yz", "xz", "xy"][a.index()].to_string(),
            Direction::Oblique(_) => format!("n={}", self.text()),
        }
    }

    /// Reads the components of `[a,b,c]` (the oblique form).
    #[expect(
        clippy::cast_possible_truncation,
        reason = "components are checked to be within ±1, so thousandths within ±1000"
    )]
    fn parse_oblique(text: &str) -> Option<Self> {
        let inner = text.strip_prefix('[')?.strip_suffix(']')?;
        let c: Vec<f64> = inner
            .split(',')
            .map(|x| {
                x.parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite() && v.abs() <= 1.0)
            })
            .collect::<Option<_>>()?;
        let d: [f64; 3] = c.try_into().ok()?;
        Some(Direction::Oblique(d.map(|x| (x * 1000.0).round() as i32)))
    }
}

/// A motion pattern by name: what the text form of a classified [`Pattern`] says — the group
/// with the direction of its axis or plane normal, or `nTmR` — without the points and pitches
/// that depend on the geometry. The keys of [`crate::verification::Verification::patterns`]:
/// one name per pattern a chain gives with some joints locked.
///
/// Names are ordered by their text (`0T2R` < `C(x)` < `D` < `E` < `G(xy)` …), the order in
/// which the catalogue's files list them; they serialise as that text.
///
/// ```
/// use kinsyn::motion::{Direction, GroupKind, PatternName};
/// use kinsyn::notation::Axis;
/// let x: PatternName = "X(z)".parse().unwrap();
/// assert_eq!(x, PatternName::Group { kind: GroupKind::X, direction: Some(Direction::Along(Axis::Z)) });
/// assert_eq!(x.to_string(), "X(z)");
/// assert!("1T2R".parse::<PatternName>().unwrap() < x);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PatternName {
    /// One of the 12 displacement subgroups.
    Group {
        /// Which group.
        kind: GroupKind,
        /// Its direction or plane normal; `None` for the groups without one (E, T3, S, D).
        direction: Option<Direction>,
    },
    /// A non-group pattern `nTmR`.
    NonGroup {
        /// Dimension minus rotational rank.
        translations: usize,
        /// Rank of the rotational part.
        rotations: usize,
    },
}

impl PatternName {
    /// Whether the pattern is one of the 12 groups.
    #[must_use]
    pub fn is_group(&self) -> bool {
        matches!(self, PatternName::Group { .. })
    }

    /// The degrees of freedom of the motion it names (a group's dimension, `n + m` for
    /// `nTmR`).
    #[must_use]
    pub fn dof(&self) -> usize {
        match *self {
            PatternName::Group { kind, .. } => kind.dimension(),
            PatternName::NonGroup {
                translations,
                rotations,
            } => translations + rotations,
        }
    }
}

impl PatternName {
    /// The text form: `X(z)`, `G(xy)`, `T3`, `1T2R`.
    fn text(&self) -> String {
        match *self {
            PatternName::NonGroup {
                translations,
                rotations,
            } => format!("{translations}T{rotations}R"),
            PatternName::Group { kind, direction } => {
                let symbol = kind.symbol();
                match (kind.parameter(), direction) {
                    (Parameter::Direction, Some(d)) => format!("{symbol}({})", d.text()),
                    (Parameter::Plane, Some(n)) => format!("{symbol}({})", n.plane_text()),
                    _ => symbol.to_string(),
                }
            }
        }
    }
}

impl fmt::Display for PatternName {
    /// The text form, padded as a string is (`{:<8}`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(&self.text())
    }
}

impl FromStr for PatternName {
    type Err = PatternError;

    /// Reads what [`PatternQuery`] reads, and oblique directions (`R([0.707,0.707,0.000])`,
    /// `G(n=[…])`).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let text: String = s.chars().filter(|c| !c.is_whitespace()).collect();
        if let Some((symbol, rest)) = text.split_once('(')
            && let Some(param) = rest.strip_suffix(')')
            && param.contains('[')
            && let Some(kind) = GroupKind::ALL.into_iter().find(|k| k.symbol() == symbol)
        {
            let components = match kind.parameter() {
                Parameter::Direction => Some(param),
                Parameter::Plane => param.strip_prefix("n="),
                Parameter::None => None,
            };
            return match components.and_then(Direction::parse_oblique) {
                Some(d) => Ok(PatternName::Group {
                    kind,
                    direction: Some(d),
                }),
                None => Err(PatternError::BadParameter {
                    why: format!("{param:?} is not a direction of {symbol}"),
                    text,
                }),
            };
        }
        Ok(match text.parse::<PatternQuery>()? {
            PatternQuery::Group { kind, axis } => PatternName::Group {
                kind,
                direction: axis.map(Direction::Along),
            },
            PatternQuery::NonGroup {
                translations,
                rotations,
            } => PatternName::NonGroup {
                translations,
                rotations,
            },
        })
    }
}

/// A name equals its text form (`X(z)`, `2T3R`).
impl PartialEq<str> for PatternName {
    fn eq(&self, other: &str) -> bool {
        other.parse::<PatternName>().is_ok_and(|n| n == *self)
    }
}

/// A name equals its text form (`X(z)`, `2T3R`).
impl PartialEq<&str> for PatternName {
    fn eq(&self, other: &&str) -> bool {
        self == *other
    }
}

impl PartialOrd for PatternName {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for PatternName {
    /// By text, the order of the catalogue's files (one name, one text).
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.text().cmp(&other.text())
    }
}

impl Serialize for PatternName {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl<'de> serde::Deserialize<'de> for PatternName {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let text = String::deserialize(deserializer)?;
        text.parse().map_err(serde::de::Error::custom)
    }
}

/// A pattern asked for by the user: a group kind with an optional direction or plane (axis
/// aligned), or `nTmR`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PatternQuery {
    /// A group, with `axis` the direction or the plane normal when given.
    Group {
        /// Which group.
        kind: GroupKind,
        /// Direction or plane normal along x, y or z; `None` matches any.
        axis: Option<Axis>,
    },
    /// A non-group pattern.
    NonGroup {
        /// Translations.
        translations: usize,
        /// Rotations.
        rotations: usize,
    },
}

/// Why a pattern string was rejected.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PatternError {
    /// Not a known form.
    #[error(
        "{0:?} is not a motion pattern; write a group (E, T(x), R(z), H(z), T2(xy), C(z), G(xy), T3, S, Y(z), X(z), D) or nTmR such as 3T1R"
    )]
    Unknown(String),
    /// A group that takes no direction was given one, or a bad direction.
    #[error("{text:?}: {why}")]
    BadParameter {
        /// The input.
        text: String,
        /// What is wrong.
        why: String,
    },
}

impl FromStr for PatternQuery {
    type Err = PatternError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let text: String = s.chars().filter(|c| !c.is_whitespace()).collect();
        if let Some((t, r)) = text.strip_suffix('R').and_then(|x| x.split_once('T'))
            && let (Ok(translations), Ok(rotations)) = (t.parse::<usize>(), r.parse::<usize>())
        {
            if translations > 3 || rotations > 3 {
                return Err(PatternError::BadParameter {
                    text,
                    why: "at most 3 translations and 3 rotations".into(),
                });
            }
            return Ok(PatternQuery::NonGroup {
                translations,
                rotations,
            });
        }
        let (symbol, param) = match text.split_once('(') {
            Some((sym, rest)) => {
                let Some(p) = rest.strip_suffix(')') else {
                    return Err(PatternError::BadParameter {
                        text: text.clone(),
                        why: "unclosed parenthesis".into(),
                    });
                };
                (sym.to_string(), Some(p.to_string()))
            }
            None => (text.clone(), None),
        };
        let kind = GroupKind::ALL
            .into_iter()
            .find(|k| k.symbol() == symbol)
            .ok_or_else(|| PatternError::Unknown(text.clone()))?;
        let axis = match (kind.parameter(), param.as_deref()) {
            (_, None) => None,
            (Parameter::None, Some(_)) => {
                return Err(PatternError::BadParameter {
                    text,
                    why: format!("{symbol} takes no direction"),
                });
            }
            (Parameter::Direction, Some(p)) => Some(match p {
                "x" => Axis::X,
                "y" => Axis::Y,
                "z" => Axis::Z,
                _ => {
                    return Err(PatternError::BadParameter {
                        text,
                        why: format!("direction {p:?} is not x, y or z"),
                    });
                }
            }),
            (Parameter::Plane, Some(p)) => Some(match p {
                "yz" | "zy" => Axis::X,
                "xz" | "zx" => Axis::Y,
                "xy" | "yx" => Axis::Z,
                _ => {
                    return Err(PatternError::BadParameter {
                        text,
                        why: format!("plane {p:?} is not xy, yz or xz"),
                    });
                }
            }),
        };
        Ok(PatternQuery::Group { kind, axis })
    }
}

impl fmt::Display for PatternQuery {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PatternQuery::NonGroup {
                translations,
                rotations,
            } => write!(f, "{translations}T{rotations}R"),
            PatternQuery::Group { kind, axis } => {
                f.write_str(kind.symbol())?;
                match (kind.parameter(), axis) {
                    (Parameter::Direction, Some(a)) => write!(f, "({a})"),
                    (Parameter::Plane, Some(a)) => {
                        write!(f, "({})", Direction::Along(a).plane_text())
                    }
                    _ => Ok(()),
                }
            }
        }
    }
}

impl PatternQuery {
    /// The group that every motion named by this `nTmR` is: `0T0R` is E (no motion), `3T0R` is
    /// T3 (three independent translations span every translation at every configuration) and
    /// `3T3R` is D (six dimensions fill a neighbourhood of SE(3)). `None` for the other names,
    /// which a non-group motion can have, and for groups.
    #[must_use]
    pub fn forced_group(&self) -> Option<GroupKind> {
        match *self {
            PatternQuery::NonGroup {
                translations: 0,
                rotations: 0,
            } => Some(GroupKind::E),
            PatternQuery::NonGroup {
                translations: 3,
                rotations: 0,
            } => Some(GroupKind::T3),
            PatternQuery::NonGroup {
                translations: 3,
                rotations: 3,
            } => Some(GroupKind::D),
            _ => None,
        }
    }

    /// The groups whose motions have the numbers of translations and rotations of this
    /// `nTmR` (`2T1R`: G and Y): a non-group query does not match them, so these are the
    /// queries to try for the group motions of the same type. Empty for groups.
    #[must_use]
    pub fn groups_of_the_same_type(&self) -> Vec<GroupKind> {
        match *self {
            PatternQuery::NonGroup {
                translations,
                rotations,
            } => GroupKind::ALL
                .into_iter()
                .filter(|k| k.rotations() == rotations && k.dimension() == translations + rotations)
                .collect(),
            PatternQuery::Group { .. } => Vec::new(),
        }
    }

    /// Whether a classified pattern is the one asked for (a direction must be parallel). An
    /// `nTmR` that is always a group ([`PatternQuery::forced_group`]) matches that group.
    #[must_use]
    pub fn matches(&self, p: &Pattern) -> bool {
        if let (Some(kind), Pattern::Group(g)) = (self.forced_group(), p) {
            return g.kind == kind;
        }
        match (self, p) {
            (
                PatternQuery::NonGroup {
                    translations,
                    rotations,
                },
                Pattern::NonGroup {
                    translations: t,
                    rotations: r,
                },
            ) => translations == t && rotations == r,
            (PatternQuery::Group { kind, axis }, Pattern::Group(g)) => {
                g.kind == *kind
                    && axis.is_none_or(|a| {
                        g.direction
                            .is_some_and(|d| (d[a.index()].abs() - 1.0).abs() < 1e-6)
                    })
            }
            _ => false,
        }
    }
}

impl PatternQuery {
    /// Whether a pattern, by its name (a key of the catalogue's verification), is the one
    /// asked for: the same group, along the asked axis when the question names one, or the same
    /// `nTmR`. An `nTmR` that is always a group ([`PatternQuery::forced_group`]) names that group.
    #[must_use]
    pub fn covers(&self, name: &PatternName) -> bool {
        if let (Some(kind), PatternName::Group { kind: k, .. }) = (self.forced_group(), name) {
            return kind == *k;
        }
        match (*self, *name) {
            (PatternQuery::Group { kind, axis }, PatternName::Group { kind: k, direction }) => {
                kind == k && axis.is_none_or(|a| direction == Some(Direction::Along(a)))
            }
            (
                PatternQuery::NonGroup {
                    translations,
                    rotations,
                },
                PatternName::NonGroup {
                    translations: t,
                    rotations: r,
                },
            ) => translations == t && rotations == r,
            _ => false,
        }
    }
}

/// The relative tolerance for deciding that twists lie in a subspace, that a bracket closes,
/// or that a pitch is zero.
pub const SUBSPACE_TOLERANCE: f64 = 1e-7;

/// The smallest distance between two sampled configurations (dimensionless: radians, lengths
/// over the characteristic length) for their twist spaces to count as evidence: the twist
/// spaces of a non-group motion at configurations this far apart differ by about this much,
/// four orders of magnitude above [`SUBSPACE_TOLERANCE`]. A group is claimed only from at least
/// two samples this far apart (`docs/verification.md`).
pub const MIN_SEPARATION: f64 = 1e-3;

/// The residual of `x` after projection onto the span of the orthonormal columns of `basis`.
fn residual(basis: &DMatrix<f64>, x: &nalgebra::DVector<f64>) -> f64 {
    if basis.ncols() == 0 {
        return x.norm();
    }
    (x - basis * (basis.transpose() * x)).norm()
}

/// Whether two orthonormal bases span the same subspace.
#[must_use]
pub fn same_span(a: &DMatrix<f64>, b: &DMatrix<f64>, tolerance: f64) -> bool {
    a.ncols() == b.ncols()
        && (0..b.ncols()).all(|j| residual(a, &b.column(j).into_owned()) < tolerance)
}

fn v3(col: nalgebra::DVectorView<'_, f64>) -> Vector3<f64> {
    Vector3::new(col[0], col[1], col[2])
}

fn twist_of(col: nalgebra::DVectorView<'_, f64>) -> Twist {
    Twist {
        w: Vector3::new(col[0], col[1], col[2]),
        v: Vector3::new(col[3], col[4], col[5]),
    }
}

/// The singular values at or below which the small least-squares problems of
/// [`classify_subalgebra`] (with unit-size blocks of an orthonormal basis) drop a direction.
const SOLVE_CUTOFF: f64 = 1e-12;

/// Whether the span of the orthonormal twists `basis` is closed under the Lie bracket, i.e. the
/// Lie algebra of a displacement subgroup.
#[must_use]
pub fn is_subalgebra(basis: &DMatrix<f64>, tolerance: f64) -> bool {
    let n = basis.ncols();
    for i in 0..n {
        for j in i + 1..n {
            let b = lie_bracket(&twist_of(basis.column(i)), &twist_of(basis.column(j)));
            let v = nalgebra::DVector::from_column_slice(b.to_vector().as_slice());
            if residual(basis, &v) > tolerance * (1.0 + v.norm()) {
                return false;
            }
        }
    }
    true
}

/// The displacement subgroup whose Lie algebra is the span of `basis` (orthonormal twists),
/// assuming [`is_subalgebra`] holds; `None` if the subalgebra is none of the twelve (which
/// cannot happen for a closed span, but numerical noise is reported rather than guessed).
#[must_use]
pub fn classify_subalgebra(basis: &DMatrix<f64>, tolerance: f64) -> Option<Group> {
    let k = basis.ncols();
    let omega = basis.rows(0, 3).into_owned();
    // The basis is orthonormal, so the blocks are judged against 1, not their own largest value.
    // One SVD gives the rotations' span (left vectors) and the pure translations (right).
    let d = linalg::svd(&omega);
    let r = d.rank(tolerance, Some(1.0)).rank;
    let rot_basis = d.u.columns(0, r);
    // Pure translations in the span: combinations x with ω-part zero.
    let null = d.v.columns(r, k - r);
    let translations = basis * null; // 6 × (k − r)
    let t_dirs = translations.rows(3, 3).into_owned();
    let group = |kind,
                 direction: Option<Vector3<f64>>,
                 point: Option<Vector3<f64>>,
                 pitch: Option<f64>| Group {
        kind,
        direction: direction.map(|d| canonical_sign(d.normalize()).into()),
        point: point.map(Into::into),
        pitch,
    };
    match (k, r) {
        (0, _) => Some(group(GroupKind::E, None, None, None)),
        (6, 3) => Some(group(GroupKind::D, None, None, None)),
        (_, 0) => match k {
            1 => Some(group(GroupKind::T, Some(v3(t_dirs.column(0))), None, None)),
            2 => Some(group(
                GroupKind::T2,
                Some(v3(t_dirs.column(0)).cross(&v3(t_dirs.column(1)))),
                None,
                None,
            )),
            3 => Some(group(GroupKind::T3, None, None, None)),
            _ => None,
        },
        (_, 1) => {
            let w: Vector3<f64> = v3(rot_basis.column(0)).normalize();
            // A twist of the span whose rotation is exactly w: solve basis·c with ω-part = w
            // (the smallest such c).
            let w_dyn = nalgebra::DVector::from_column_slice(w.as_slice());
            let c = linalg::least_squares(&omega, &w_dyn, SOLVE_CUTOFF).x;
            let mut t = twist_of((basis * c).column(0));
            // Remove pure translations from v, then read axis and pitch.
            if translations.ncols() > 0 {
                let (tb, _) = linalg::span_basis_scaled(&t_dirs, tolerance, Some(1.0));
                for j in 0..tb.ncols() {
                    let d = v3(tb.column(j));
                    t.v -= d * d.dot(&t.v);
                }
            }
            let pitch = t.w.dot(&t.v);
            let point = t.w.cross(&t.v);
            let zero_pitch = pitch.abs() < tolerance.sqrt();
            match k {
                1 => Some(if zero_pitch {
                    group(GroupKind::R, Some(w), Some(point), None)
                } else {
                    group(GroupKind::H, Some(w), Some(point), Some(pitch))
                }),
                2 => Some(group(GroupKind::C, Some(w), Some(point), None)),
                3 => Some(if zero_pitch {
                    group(GroupKind::G, Some(w), None, None)
                } else {
                    group(GroupKind::Y, Some(w), None, Some(pitch))
                }),
                4 => Some(group(GroupKind::X, Some(w), None, None)),
                _ => None,
            }
        }
        (3, 3) => {
            // Rotations about N: every twist is (ω; N × ω); solve for N by least squares.
            let mut a = DMatrix::zeros(9, 3);
            let mut b = nalgebra::DVector::zeros(9);
            for j in 0..3 {
                let t = twist_of(basis.column(j));
                // N × ω = v  ⇔  −[ω] N = v.
                let m = -screw::skew(&t.w);
                a.view_mut((3 * j, 0), (3, 3)).copy_from(&m);
                b.rows_mut(3 * j, 3).copy_from(&t.v);
            }
            let n = linalg::least_squares(&a, &b, SOLVE_CUTOFF).x;
            Some(group(
                GroupKind::S,
                None,
                Some(Vector3::new(n[0], n[1], n[2])),
                None,
            ))
        }
        _ => None,
    }
}

/// A direction with its first non-zero component positive, so that `u` and `−u` print alike.
fn canonical_sign(d: Vector3<f64>) -> Vector3<f64> {
    let first = d.iter().copied().find(|c| c.abs() > 1e-9).unwrap_or(1.0);
    if first < 0.0 { -d } else { d }
}

/// The result of classifying a sampled finite motion.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Classification {
    /// The pattern.
    pub pattern: Pattern,
    /// Dimension of the twist space (the largest over the samples: the generic local dof).
    pub dof: usize,
    /// Whether the twist spaces agreed at every sample.
    pub same_span: bool,
    /// The smallest distance between two samples (dimensionless), `None` with fewer than two.
    pub min_separation: Option<f64>,
    /// The gap of the rank decisions behind `dof`, over the samples.
    pub rank_gap: RankGap,
    /// When the motion was sampled from a configuration where the mechanism has more degrees
    /// of freedom than anywhere along the sampled motion: a singular start, whose motion is not
    /// one pattern (see [`SingularStart`]). `None` for a regular start, and for classifications
    /// of twist spaces alone.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub singular_start: Option<SingularStart>,
}

/// A start configuration at which the (locked) mechanism is singular: its loop-closure
/// equations leave more joint rates free there than at the configurations its motion reaches
/// (the start is a bifurcation of operation modes, or a singular point of the motion). Random
/// walks from it then end on different branches from seed to seed, and the pattern sampled
/// from it is not one answer: it is reported, not counted as a pattern reached.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct SingularStart {
    /// The mechanism's degrees of freedom (closure nullity over the free joints) at the start.
    pub start_dof: usize,
    /// The smallest over the sampled configurations.
    pub motion_dof: usize,
}

/// The worst gap over several rank decisions, each singular value relative to the scale its
/// decision was judged against ([`screw::Rank::gap`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RankGap {
    /// The smallest kept singular value (`None` when every rank is 0).
    pub smallest_kept: Option<f64>,
    /// The largest dropped singular value (0 when none is dropped).
    pub largest_dropped: f64,
}

/// Classifies a motion from its twist spaces at several sampled configurations (the columns of
/// each matrix span the spatial twists there; any common reference point and length unit), at
/// least `min_separation` apart (dimensionless). The motion is the group whose Lie algebra is the
/// common span when all spans agree, the span is closed under the bracket, and the samples could
/// have shown otherwise: a motion with degrees of freedom needs two samples at least
/// [`MIN_SEPARATION`] apart. Otherwise it is `nTmR` from the generic dimension and rotational
/// rank.
#[must_use]
pub fn classify(samples: &[DMatrix<f64>], min_separation: f64, tolerance: f64) -> Classification {
    let spans: Vec<(DMatrix<f64>, linalg::Rank)> = samples
        .iter()
        .map(|m| linalg::span_basis(m, linalg::DEFAULT_RANK_TOLERANCE))
        .collect();
    let bases: Vec<(DMatrix<f64>, usize)> =
        spans.iter().map(|(b, r)| (b.clone(), r.rank)).collect();
    classify_spans(
        &bases,
        (samples.len() >= 2).then_some(min_separation),
        tolerance,
        gap_over(spans.iter().map(|(_, r)| r)),
    )
}

/// [`classify`] deciding each sample's rank by a certified QR where its twists are
/// independent, and by the SVD only where they are not (the same decisions,
/// `docs/verification.md`): for callers that want the pattern, not the singular values
/// behind it. The classification's `rank_gap` is `rank_gap` as given.
#[must_use]
pub fn classify_quick(
    samples: &[DMatrix<f64>],
    min_separation: f64,
    tolerance: f64,
    rank_gap: RankGap,
) -> Classification {
    let spans: Vec<(DMatrix<f64>, usize)> = samples
        .iter()
        .map(|m| linalg::span_basis_quick(m, linalg::DEFAULT_RANK_TOLERANCE))
        .collect();
    classify_spans(
        &spans,
        (samples.len() >= 2).then_some(min_separation),
        tolerance,
        rank_gap,
    )
}

/// The classification of the motion whose twist spaces at the samples are the orthonormal
/// bases `spans` (each with its dimension), the samples at least `min_separation` apart (`None`
/// with fewer than two), the rank decisions' gap `rank_gap` (see [`classify`]).
fn classify_spans(
    spans: &[(DMatrix<f64>, usize)],
    min_separation: Option<f64>,
    tolerance: f64,
    rank_gap: RankGap,
) -> Classification {
    let dof = spans.iter().map(|(_, r)| *r).max().unwrap_or(0);
    let generic: Vec<&DMatrix<f64>> = spans
        .iter()
        .filter(|(_, r)| *r == dof)
        .map(|(b, _)| b)
        .collect();
    let same = spans.iter().all(|(_, r)| *r == dof)
        && generic.windows(2).all(|w| same_span(w[0], w[1], tolerance));
    let evidence = dof == 0 || min_separation.is_some_and(|d| d >= MIN_SEPARATION);
    if let Some(first) = generic.first()
        && same
        && evidence
        && is_subalgebra(first, tolerance)
        && let Some(g) = classify_subalgebra(first, tolerance)
    {
        return Classification {
            pattern: Pattern::Group(g),
            dof,
            same_span: true,
            min_separation,
            rank_gap,
            singular_start: None,
        };
    }
    let rotations = generic
        .iter()
        // The rank of the rotation rows of an orthonormal basis, judged against 1.
        .map(|b| linalg::rank_quick(&b.rows(0, 3).into_owned(), tolerance, Some(1.0)))
        .max()
        .unwrap_or(0);
    Classification {
        pattern: Pattern::NonGroup {
            translations: dof - rotations,
            rotations,
        },
        dof,
        same_span: same,
        min_separation,
        rank_gap,
        singular_start: None,
    }
}

/// The worst gap over several rank decisions ([`RankGap`]).
#[must_use]
pub fn gap_over<'a>(ranks: impl Iterator<Item = &'a linalg::Rank>) -> RankGap {
    ranks.fold(
        RankGap {
            smallest_kept: None,
            largest_dropped: 0.0,
        },
        |gap, r| {
            let (kept, dropped) = r.gap();
            RankGap {
                smallest_kept: if r.rank == 0 {
                    gap.smallest_kept
                } else {
                    Some(gap.smallest_kept.map_or(kept, |k| k.min(kept)))
                },
                largest_dropped: gap.largest_dropped.max(dropped),
            }
        },
    )
}
