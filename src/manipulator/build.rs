//! From a leg chain to a manipulator: a symmetric geometry in which any catalogue chain can be
//! tried as a leg (`kinsyn build`).
//!
//! The legs stand on a base circle and reach a platform circle above it, one every `360°/n`,
//! so they lie in different planes as paper 000 §3 asks for rigidity. Each leg has its own
//! **leg frame**: `z` along the leg (base point to platform point), `y` horizontal and
//! perpendicular to it, `x = y × z`. The catalogue's axis letters x, y, z are read in that frame,
//! so the UPS entry (`xyzxyz`) gets its slider along the leg, its U's second axis horizontal
//! (the R of the 3-RPS when the first is locked) and its first in the leg's vertical plane.
//! Joints between the first and the last are spaced along the leg and pushed off it by
//! `±0.15` of its length, alternately, so that parallel revolutes are not coaxial.

use super::file::{AngleUnit, AxisSpec, Description, FORMAT, LegSpec, PlatformSpec, Units};
use crate::catalogue::Catalogue;
use crate::notation::Chain;
use nalgebra::Vector3;
use serde::Serialize;

/// The geometry and legs asked for.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BuildSpec {
    /// Number of legs (3 to 6, paper 000 §3).
    pub legs: usize,
    /// The leg chain: notation (with `!` marks) or a catalogue id.
    pub chain: String,
    /// Axis letters x, y, z per primitive joint in the leg frame; default the catalogue's.
    pub axes: Option<String>,
    /// Actuated primitive joints (1-based) instead of `!` marks.
    pub actuated: Option<Vec<usize>>,
    /// Radius of the circle of base points.
    pub base_radius: f64,
    /// Radius of the circle of platform points.
    pub platform_radius: f64,
    /// Height of the platform above the base.
    pub height: f64,
    /// Angle (degrees) by which each leg's platform point is turned from its base point about
    /// the vertical.
    pub twist: f64,
    /// Turn the platform points of legs 2, 4, 6 the other way (−twist): with an even number of
    /// legs this pairs the platform points, as in the usual Gough–Stewart platform, whose
    /// regular-hexagon form is singular everywhere.
    pub alternate: bool,
    /// The manipulator's name (default `n-CHAIN`).
    pub name: Option<String>,
}

impl Default for BuildSpec {
    fn default() -> Self {
        BuildSpec {
            legs: 3,
            chain: String::new(),
            axes: None,
            actuated: None,
            base_radius: 1.0,
            platform_radius: 0.5,
            height: 1.0,
            twist: 0.0,
            alternate: false,
            name: None,
        }
    }
}

/// The leg frame `[x, y, z]` of a leg from `base` to `end` (see the module documentation).
#[must_use]
pub fn leg_frame(base: &Vector3<f64>, end: &Vector3<f64>) -> [Vector3<f64>; 3] {
    let z = (end - base).try_normalize(1e-12).unwrap_or_else(Vector3::z);
    let y = Vector3::z()
        .cross(&z)
        .try_normalize(1e-9)
        .unwrap_or_else(|| {
            // A vertical leg: the horizontal direction perpendicular to the base point's radius.
            Vector3::z()
                .cross(base)
                .try_normalize(1e-9)
                .unwrap_or_else(Vector3::y)
        });
    [y.cross(&z), y, z]
}

/// Rounds to 12 decimals so that written files do not carry round-off digits.
fn tidy(v: Vector3<f64>) -> [f64; 3] {
    v.map(|x| (x * 1e12).round() / 1e12 + 0.0).into()
}

/// A manipulator description with the symmetric geometry of the module documentation.
///
/// # Errors
/// A number of legs outside 3–6, a chain that does not parse or is not in the catalogue when
/// its axes are needed, an axis word of the wrong length or letters, no actuated joint, or
/// geometry numbers that are not positive.
pub fn build(spec: &BuildSpec) -> Result<Description, String> {
    if !(3..=6).contains(&spec.legs) {
        return Err(format!(
            "--legs {}: paper 000 §3 builds manipulators of three to six legs",
            spec.legs
        ));
    }
    for (name, x) in [
        ("--base-radius", spec.base_radius),
        ("--platform-radius", spec.platform_radius),
        ("--height", spec.height),
    ] {
        if !(x.is_finite() && x > 0.0) {
            return Err(format!("{name} {x}: must be a positive length"));
        }
    }
    if !spec.twist.is_finite() {
        return Err(format!("--twist {}: not a number", spec.twist));
    }
    let mut catalogue = None;
    let (chain, entry_axes) = super::leg_chain(&spec.chain, &mut catalogue)?;
    let primitives = chain.primitives().count();
    let axes = match (&spec.axes, entry_axes) {
        (Some(word), _) => word.clone(),
        (None, Some(word)) => word,
        (None, None) => {
            return Err(format!(
                "{chain} is not a catalogue chain; give its axes with --axes (one of x, y, z per primitive joint, in the leg frame)"
            ));
        }
    };
    if axes.len() != primitives || !axes.bytes().all(|b| matches!(b, b'x' | b'y' | b'z')) {
        return Err(format!(
            "--axes '{axes}': one letter x, y or z per primitive joint of {chain} ({primitives})"
        ));
    }
    let marked: Vec<usize> = chain
        .primitives()
        .enumerate()
        .filter(|(_, (_, m))| m.actuated)
        .map(|(k, _)| k + 1)
        .collect();
    let actuated = match &spec.actuated {
        Some(list) => list.clone(),
        None => marked,
    };
    if actuated.is_empty() {
        return Err(format!(
            "no actuated joint: mark them with '!' in the chain or give --actuated (1 to {primitives})"
        ));
    }
    let plain: Chain = chain.without_actuation();
    let letters = plain.joints().len();
    let n = spec.legs;
    let mut legs = Vec::with_capacity(n);
    for k in 0..n {
        let theta = std::f64::consts::TAU * k as f64 / n as f64;
        let sense = if spec.alternate && k % 2 == 1 {
            -1.0
        } else {
            1.0
        };
        let phi = theta + sense * spec.twist.to_radians();
        let base = Vector3::new(theta.cos(), theta.sin(), 0.0) * spec.base_radius;
        let attach = Vector3::new(phi.cos(), phi.sin(), 0.0) * spec.platform_radius;
        let end = attach + Vector3::new(0.0, 0.0, spec.height);
        let frame = leg_frame(&base, &end);
        let length = (end - base).norm();
        let off = (frame[0] + frame[1]) / 2f64.sqrt() * (0.15 * length);
        let points: Vec<[f64; 3]> = (1..letters.saturating_sub(1))
            .map(|m| {
                let sign = if m % 2 == 1 { 1.0 } else { -1.0 };
                tidy(base + (end - base) * (m as f64 / (letters - 1) as f64) + off * sign)
            })
            .collect();
        legs.push(LegSpec {
            chain: plain.to_string(),
            base: tidy(base),
            platform: tidy(attach),
            points: (letters > 2).then_some(points),
            axes: Some(
                axes.bytes()
                    .map(|b| AxisSpec::Vector(tidy(frame[(b - b'x') as usize])))
                    .collect(),
            ),
            actuated: Some(actuated.clone()),
        });
    }
    let source = if Catalogue::synthesise(&Default::default())
        .find(&spec.chain)
        .is_some_and(|e| e.id.eq_ignore_ascii_case(spec.chain.trim()))
    {
        format!(
            "kinsyn build: legs of catalogue entry {}",
            spec.chain.trim()
        )
    } else {
        "kinsyn build".to_string()
    };
    Ok(Description {
        format: FORMAT.into(),
        name: spec
            .name
            .clone()
            .unwrap_or_else(|| format!("{n}-{}", plain.letters())),
        source: Some(format!(
            "{source} --legs {n} --axes {axes} (base radius {}, platform radius {}, height {}, twist {}°{})",
            spec.base_radius,
            spec.platform_radius,
            spec.height,
            spec.twist,
            if spec.alternate { ", alternate" } else { "" }
        )),
        units: Units {
            length: "m".into(),
            angle: AngleUnit::Deg,
        },
        platform: PlatformSpec {
            position: [0.0, 0.0, spec.height],
            orientation: [0.0; 3],
            point: [0.0; 3],
        },
        legs,
    })
}
