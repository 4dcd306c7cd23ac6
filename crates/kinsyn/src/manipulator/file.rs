//! Manipulator description files (`mechanisms/*.json`, formats `kinsyn-manipulator/1` and
//! `kinsyn-manipulator/2`), documented in `docs/mechanism-format.md`.
//!
//! A `/1` file ([`Description`]) gives one platform's reference pose and reference point, and
//! each leg as a chain (in kinsyn notation, or a catalogue id) from the ground to the platform,
//! with the points and axes of its joints in the ground frame at the reference configuration,
//! and which of its joints are actuated.
//!
//! A `/2` file ([`MultibodyDescription`]) names its bodies: the ground and any number of moving
//! bodies (sub-platforms, a coupler, end-effectors), each with a reference pose and point, one of
//! them the end-effector; each leg runs `from` one body `to` another. A `/1` description reads as
//! the `/2` description of one moving body named `platform` ([`Description::to_multibody`]);
//! [`AnyDescription::from_json`] reads either.

use serde::{Deserialize, Serialize};

/// The format tag of a one-platform description ([`Description`]), the format `kinsyn build`
/// writes.
pub const FORMAT: &str = "kinsyn-manipulator/1";

/// The format tag of a description with named bodies ([`MultibodyDescription`]).
pub const FORMAT_2: &str = "kinsyn-manipulator/2";

/// The name the ground and the platform of a `/1` description get in its `/2` form (and in the
/// mechanism graph).
pub const V1_GROUND: &str = "ground";

/// See [`V1_GROUND`].
pub const V1_PLATFORM: &str = "platform";

/// A whole manipulator file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Description {
    /// Always [`FORMAT`].
    pub format: String,
    /// A name, e.g. `3-UPS`.
    pub name: String,
    /// Where the manipulator comes from (paper, section, figure).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source: Option<String>,
    /// Units of lengths and angles in this file.
    pub units: Units,
    /// The moving platform.
    pub platform: PlatformSpec,
    /// The legs, each from the ground to the platform.
    pub legs: Vec<LegSpec>,
}

/// Units of a file. Lengths are kept in the file's unit; angles are read in `angle` and used in
/// radians inside.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Units {
    /// The length unit's name (e.g. `m`, `mm`); a label, lengths are not converted.
    pub length: String,
    /// The unit of angles: `deg` or `rad`.
    pub angle: AngleUnit,
}

/// Degrees or radians.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum AngleUnit {
    /// Degrees.
    Deg,
    /// Radians.
    Rad,
}

impl AngleUnit {
    /// An angle in this unit, in radians.
    #[must_use]
    pub fn to_radians(self, a: f64) -> f64 {
        match self {
            AngleUnit::Deg => a.to_radians(),
            AngleUnit::Rad => a,
        }
    }

    /// An angle in radians, in this unit.
    #[must_use]
    pub fn from_radians(self, a: f64) -> f64 {
        match self {
            AngleUnit::Deg => a.to_degrees(),
            AngleUnit::Rad => a,
        }
    }

    /// The unit's symbol, as descriptions write it and reports print it: `deg` or `rad`.
    #[must_use]
    pub fn symbol(self) -> &'static str {
        match self {
            AngleUnit::Deg => "deg",
            AngleUnit::Rad => "rad",
        }
    }

    /// The unit's name in words: `degrees` or `radians`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            AngleUnit::Deg => "degrees",
            AngleUnit::Rad => "radians",
        }
    }
}

/// The platform at the reference configuration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlatformSpec {
    /// The platform frame's origin in the ground frame.
    #[serde(deserialize_with = "point")]
    pub position: [f64; 3],
    /// The platform frame's orientation: a rotation vector (axis × angle, in the file's angle
    /// unit) from the ground frame.
    #[serde(default, deserialize_with = "point")]
    pub orientation: [f64; 3],
    /// The reference point P, in the platform frame (the paper's P; default the origin).
    #[serde(default, deserialize_with = "point")]
    pub point: [f64; 3],
}

/// One leg.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LegSpec {
    /// The chain from ground to platform: kinsyn notation (`U(!,-)!PS`, `!` marks actuated
    /// joints) or a catalogue id (`T4-034`).
    pub chain: String,
    /// The point of the first joint, in the ground frame (the centre of a U or S, a point of an
    /// R or C axis; unused for a P).
    #[serde(deserialize_with = "point")]
    pub base: [f64; 3],
    /// The point of the last joint, in the platform frame.
    #[serde(deserialize_with = "point")]
    pub platform: [f64; 3],
    /// The points of the joints between the first and the last, one per joint letter, in the
    /// ground frame at the reference configuration; default evenly spaced from base to platform.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "optional_points"
    )]
    pub points: Option<Vec<[f64; 3]>>,
    /// One axis per primitive joint (ground frame, reference configuration): a vector, or
    /// `"leg"` for the unit vector from the base point to the platform point. Default: the
    /// catalogue entry's axes read in the leg frame (docs/mechanism-format.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axes: Option<Vec<AxisSpec>>,
    /// Actuated primitive joints, 1-based positions in the leg (instead of `!` marks).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub actuated: Option<Vec<usize>>,
}

/// A description with named bodies (format `kinsyn-manipulator/2`): the ground, the moving
/// bodies with their reference poses, the end-effector among them, and legs between any two
/// bodies. This is also the in-memory form every description is built from: a `/1` file is
/// converted to it ([`Description::to_multibody`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MultibodyDescription {
    /// Always [`FORMAT_2`].
    pub format: String,
    /// A name, e.g. `3-RPS-3-SPR`.
    pub name: String,
    /// Where the mechanism comes from (paper, section, figure).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source: Option<String>,
    /// Units of lengths and angles in this file.
    pub units: Units,
    /// The ground's name (e.g. `base`): its frame is the ground frame.
    pub ground: String,
    /// The moving bodies, each with its reference pose.
    pub bodies: Vec<BodySpec>,
    /// The moving body analysed by default (the one `--pose`, `J_D`, `J_I` refer to); may be
    /// left out when there is one moving body.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_effector: Option<String>,
    /// The legs, each a serial chain from one body to another.
    pub legs: Vec<LegBetween>,
}

/// A moving body at the reference configuration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// The body's name, unique among the bodies and the ground.
    pub name: String,
    /// The body frame's origin in the ground frame.
    #[serde(deserialize_with = "point")]
    pub position: [f64; 3],
    /// The body frame's orientation: a rotation vector (axis × angle, in the file's angle
    /// unit) from the ground frame.
    #[serde(default, deserialize_with = "point")]
    pub orientation: [f64; 3],
    /// The body's reference point, in the body frame (default the origin).
    #[serde(default, deserialize_with = "point")]
    pub point: [f64; 3],
}

/// One leg of a `/2` description: a serial chain from body `from` to body `to`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LegBetween {
    /// The chain from `from` to `to`: kinsyn notation or a catalogue id, as in `/1`.
    pub chain: String,
    /// The body the first joint is on (the ground or a moving body).
    pub from: String,
    /// The body the last joint is on.
    pub to: String,
    /// The point of the first joint, in the frame of `from` (the ground frame for the ground).
    #[serde(deserialize_with = "point")]
    pub first: [f64; 3],
    /// The point of the last joint, in the frame of `to`.
    #[serde(deserialize_with = "point")]
    pub last: [f64; 3],
    /// The points of the joints between the first and the last, one per joint letter, in the
    /// ground frame at the reference configuration; default evenly spaced from first to last.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "optional_points"
    )]
    pub points: Option<Vec<[f64; 3]>>,
    /// One axis per primitive joint (ground frame, reference configuration), or `"leg"` for the
    /// unit vector from the first point to the last; default the catalogue's axes in the leg
    /// frame.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axes: Option<Vec<AxisSpec>>,
    /// Actuated primitive joints, 1-based positions in the leg (instead of `!` marks).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub actuated: Option<Vec<usize>>,
}

impl Description {
    /// The same manipulator as a `/2` description: the ground named [`V1_GROUND`], one moving
    /// body named [`V1_PLATFORM`] with the platform's pose and point (the end-effector), and
    /// every leg from the ground to it, its base point as `first` and its platform point as
    /// `last`. Nothing is recomputed: the frames of the two formats are the same.
    #[must_use]
    pub fn to_multibody(&self) -> MultibodyDescription {
        MultibodyDescription {
            format: FORMAT_2.into(),
            name: self.name.clone(),
            source: self.source.clone(),
            units: self.units.clone(),
            ground: V1_GROUND.into(),
            bodies: vec![BodySpec {
                name: V1_PLATFORM.into(),
                position: self.platform.position,
                orientation: self.platform.orientation,
                point: self.platform.point,
            }],
            end_effector: Some(V1_PLATFORM.into()),
            legs: self
                .legs
                .iter()
                .map(|l| LegBetween {
                    chain: l.chain.clone(),
                    from: V1_GROUND.into(),
                    to: V1_PLATFORM.into(),
                    first: l.base,
                    last: l.platform,
                    points: l.points.clone(),
                    axes: l.axes.clone(),
                    actuated: l.actuated.clone(),
                })
                .collect(),
        }
    }
}

/// A description in either format, as read.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyDescription {
    /// Format `kinsyn-manipulator/1`: one platform.
    V1(Description),
    /// Format `kinsyn-manipulator/2`: named bodies.
    V2(MultibodyDescription),
}

impl AnyDescription {
    /// Reads a description of either format, by its `format` tag.
    ///
    /// # Errors
    /// Text that is not JSON, a missing or unknown `format`, a `/2` tag on a description with
    /// the fields of `/1` (a `platform` and no `bodies`), and the field errors of each format.
    pub fn from_json(text: &str) -> Result<Self, DescriptionError> {
        let value = json_object(text, &[FORMAT, FORMAT_2])?;
        if value.get("format").and_then(serde_json::Value::as_str) == Some(FORMAT) {
            return Description::from_json(text).map(AnyDescription::V1);
        }
        if value.get("platform").is_some() && value.get("bodies").is_none() {
            return Err(DescriptionError::not_a_description(&format!(
                "\"format\" is \"{FORMAT_2}\", expected \"{FORMAT}\" for a description with a \"platform\" and no \"bodies\" (docs/mechanism-format.md)"
            )));
        }
        deserialize(text).map(AnyDescription::V2)
    }

    /// The description in the `/2` form every description is built from.
    #[must_use]
    pub fn to_multibody(&self) -> MultibodyDescription {
        match self {
            AnyDescription::V1(d) => d.to_multibody(),
            AnyDescription::V2(d) => d.clone(),
        }
    }
}

impl MultibodyDescription {
    /// Reads a description of either format, a `/1` one converted
    /// ([`Description::to_multibody`]).
    ///
    /// # Errors
    /// See [`AnyDescription::from_json`].
    pub fn from_json(text: &str) -> Result<Self, DescriptionError> {
        AnyDescription::from_json(text).map(|d| d.to_multibody())
    }

    /// The description as pretty JSON with a final newline, points and axes on one line each.
    #[must_use]
    pub fn to_json(&self) -> String {
        let mut s = collapse_number_arrays(&serde_json::to_string_pretty(self).unwrap_or_default());
        s.push('\n');
        s
    }
}

/// The JSON value of `text`, checked to be an object whose `format` is one of `accepted`.
fn json_object(text: &str, accepted: &[&str]) -> Result<serde_json::Value, DescriptionError> {
    let value: serde_json::Value = serde_json::from_str(text)
        .map_err(|e| DescriptionError::not_a_description(&format!("not JSON: {e}")))?;
    let expected = accepted
        .iter()
        .map(|f| format!("\"{f}\""))
        .collect::<Vec<_>>()
        .join(" or ");
    match value.get("format") {
        Some(serde_json::Value::String(f)) if accepted.contains(&f.as_str()) => Ok(value),
        Some(serde_json::Value::String(other)) => Err(DescriptionError::not_a_description(
            &format!("\"format\" is {other:?}, expected {expected}"),
        )),
        Some(other) => Err(DescriptionError::not_a_description(&format!(
            "\"format\" is {other}, expected {expected}"
        ))),
        None if !value.is_object() => Err(DescriptionError::not_a_description(
            "JSON, but not an object",
        )),
        None => Err(DescriptionError::not_a_description(&format!(
            "no \"format\": {expected}"
        ))),
    }
}

/// Deserialises `text` with the path of the offending field (`legs[2].axes[0]`).
fn deserialize<T: serde::de::DeserializeOwned>(text: &str) -> Result<T, DescriptionError> {
    let mut de = serde_json::Deserializer::from_str(text);
    serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let field = if path == "." {
            "file".to_string()
        } else {
            path
        };
        DescriptionError::new(field, e.into_inner().to_string())
    })
}

/// An axis as written in a file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged, expecting = "an axis: a vector [x, y, z] or \"leg\"")]
pub enum AxisSpec {
    /// A direction (normalised when read).
    Vector(#[serde(deserialize_with = "point")] [f64; 3]),
    /// A named direction: `leg`.
    Named(String),
}

/// A point or vector `[x, y, z]`, read with an error that says how many coordinates it has
/// when it does not have three (serde's fixed-size arrays say "trailing characters").
struct Point([f64; 3]);

impl<'de> Deserialize<'de> for Point {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Coordinates;
        impl<'de> serde::de::Visitor<'de> for Coordinates {
            type Value = Point;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("3 coordinates [x, y, z]")
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<Point, A::Error> {
                let mut p = [0.0; 3];
                let mut n = 0;
                while let Some(x) = seq.next_element::<f64>()? {
                    if let Some(slot) = p.get_mut(n) {
                        *slot = x;
                    }
                    n += 1;
                }
                if n == 3 {
                    Ok(Point(p))
                } else {
                    Err(serde::de::Error::invalid_length(n, &self))
                }
            }
        }
        d.deserialize_seq(Coordinates)
    }
}

fn point<'de, D: serde::Deserializer<'de>>(d: D) -> Result<[f64; 3], D::Error> {
    Point::deserialize(d).map(|p| p.0)
}

fn optional_points<'de, D: serde::Deserializer<'de>>(
    d: D,
) -> Result<Option<Vec<[f64; 3]>>, D::Error> {
    Option::<Vec<Point>>::deserialize(d).map(|o| o.map(|v| v.into_iter().map(|p| p.0).collect()))
}

/// A description file that cannot be used, with the field at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct DescriptionError {
    /// The field, e.g. `legs[2].axes[4]`.
    pub field: String,
    /// What is wrong and how to fix it.
    pub message: String,
}

/// The message of a [`DescriptionError`] whose text is not a description file at all.
pub const NOT_A_DESCRIPTION: &str = "not a kinsyn manipulator file";

impl DescriptionError {
    /// Text that is not a manipulator description at all (not JSON, or JSON without this
    /// format's marker): the field is `file`, the message says why.
    #[must_use]
    pub fn not_a_description(why: &str) -> Self {
        DescriptionError::new("file", format!("{NOT_A_DESCRIPTION} ({why})"))
    }

    /// Whether the text was not a description file at all (rather than a description with a
    /// faulty field).
    #[must_use]
    pub fn is_not_a_description(&self) -> bool {
        self.field == "file" && self.message.starts_with(NOT_A_DESCRIPTION)
    }

    /// An error at `field`.
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        DescriptionError {
            field: field.into(),
            message: message.into(),
        }
    }
}

impl Description {
    /// Reads a description from JSON text, checking first that it claims to be a manipulator
    /// file of this format.
    ///
    /// # Errors
    /// Text that is not JSON, a missing or different `format`, unknown or missing fields,
    /// values of the wrong type (serde's message, with line and column).
    pub fn from_json(text: &str) -> Result<Self, DescriptionError> {
        json_object(text, &[FORMAT])?;
        deserialize(text)
    }

    /// The description as pretty JSON with a final newline.
    #[must_use]
    pub fn to_json(&self) -> String {
        let mut s = collapse_number_arrays(&serde_json::to_string_pretty(self).unwrap_or_default());
        s.push('\n');
        s
    }
}

/// Pretty JSON with every array of plain numbers on one line (`[0.5, 0.0, 1.0]`), so that
/// points and axes read as points and axes.
fn collapse_number_arrays(pretty: &str) -> String {
    let mut out = String::with_capacity(pretty.len());
    let lines: Vec<&str> = pretty.lines().collect();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        if line.trim_end().ends_with('[') {
            // Collect the items up to the closing bracket if they are all numbers.
            let mut items = Vec::new();
            let mut j = i + 1;
            while j < lines.len() {
                let t = lines[j].trim();
                if t.starts_with(']') {
                    break;
                }
                let item = t.trim_end_matches(',');
                if item.parse::<f64>().is_err() {
                    items.clear();
                    break;
                }
                items.push(item);
                j += 1;
            }
            if !items.is_empty() && j < lines.len() {
                let close = lines[j].trim();
                out.push_str(line.trim_end());
                out.push_str(&items.join(", "));
                out.push_str(close);
                out.push('\n');
                i = j + 1;
                continue;
            }
        }
        out.push_str(line);
        out.push('\n');
        i += 1;
    }
    out.pop();
    out
}
