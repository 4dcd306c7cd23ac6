//! Series-parallel stacks as data (paper 002 §2–3, eq. 8's n modules): a description
//! `kinsyn-manipulator/2` of equilateral platforms joined in series by three-legged modules,
//! each a 3-RPS (revolutes on the lower platform) or a 3-SPR (revolutes on the upper one), with
//! the paper's frames (origin at the circumcentre, x towards vertex A, B and C at 120° and 240°)
//! and revolute axes tangent to the circumcircles. Each module's reference pose is generic and
//! assembled: its height and tilt are chosen, and its in-plane coordinates (x, y and the turn
//! about the normal) solved by Newton's method on the three revolute-plane conditions.

use super::file::{
    AngleUnit, AxisSpec, BodySpec, FORMAT_2, LegBetween, MultibodyDescription, Units,
};
use crate::spatial::{Displacement, displacement, rotation_log};
use nalgebra::{Matrix3, Rotation3, Vector3};

/// A module of a stack.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModuleKind {
    /// Revolutes at the lower platform's vertices, spherical joints at the upper's.
    Rps,
    /// Spherical joints at the lower platform's vertices, revolutes at the upper's.
    Spr,
}

/// The stack asked for: the modules from the ground up and the platforms' circum-radii (one
/// more than the modules: the base first).
#[derive(Debug, Clone, PartialEq)]
pub struct StackSpec {
    /// The modules, ground first.
    pub modules: Vec<ModuleKind>,
    /// The circum-radius of each platform, the base first.
    pub radii: Vec<f64>,
    /// The height of each module's upper platform above (positive) or below (negative) its
    /// lower one, along the lower platform's normal.
    pub heights: Vec<f64>,
}

/// Why a stack could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StackError {
    /// No module, or radii and heights that do not match the modules.
    #[error(
        "{modules} modules need {} radii and {modules} heights (got {radii} and {heights})",
        modules + 1
    )]
    Sizes {
        /// Modules asked for.
        modules: usize,
        /// Radii given.
        radii: usize,
        /// Heights given.
        heights: usize,
    },
    /// More modules than a `/2` description holds: fifteen primitive joints each, at most
    /// [`super::MAX_JOINTS`] (docs/limits.md).
    #[error("{0} modules: at most {max} (fifteen primitive joints each, at most {joints}; docs/limits.md)", max = MAX_MODULES, joints = super::MAX_JOINTS)]
    TooManyModules(usize),
    /// A radius or height that is not a finite non-zero length (radii positive).
    #[error("radius or height {0} is not a usable length")]
    Length(f64),
    /// Newton's method found no in-plane pose for a module at the chosen height and tilt.
    #[error("module {module}: no assembled reference at this height (residual {residual:.3e})")]
    NotAssembled {
        /// The module, 1-based.
        module: usize,
        /// The revolute-plane residual reached.
        residual: f64,
    },
}

/// The most modules of a stack: three five-joint legs each, within the joints (and legs) of a
/// `/2` description (docs/limits.md): 72 / 15 = 4.
pub const MAX_MODULES: usize = super::MAX_JOINTS / 15;

/// Vertex `i` of a platform of circum-radius `h`, in its frame.
fn vertex(h: f64, i: usize) -> Vector3<f64> {
    let (s, c) = (120.0 * i as f64).to_radians().sin_cos();
    Vector3::new(h * c, h * s, 0.0)
}

/// The unit tangent of the circumcircle at vertex `i`, in the platform's plane.
fn tangent(i: usize) -> Vector3<f64> {
    let (s, c) = (120.0 * i as f64).to_radians().sin_cos();
    Vector3::new(-s, c, 0.0)
}

/// The tilt of module `k` (0-based), a rotation vector in radians with no component along the
/// lower normal: different for each module and away from the parallel platforms of paper 002
/// Table 1 row 1, where the stack is singular.
fn tilt(k: usize) -> Vector3<f64> {
    let sign = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
    Vector3::new(sign * (10.0 + 7.0 * k as f64), -15.0 + 27.0 * k as f64, 0.0).map(f64::to_radians)
}

/// The pose of the upper platform in the lower one's frame for in-plane coordinates
/// `(x, y, ψ)`: translation `(x, y, height)`, rotation vector `tilt + ψ z`.
fn relative_pose(c: &Vector3<f64>, height: f64, tilt: &Vector3<f64>) -> Displacement {
    displacement(
        Rotation3::from_scaled_axis(tilt + Vector3::z() * c.z),
        Vector3::new(c.x, c.y, height),
    )
}

/// The three revolute-plane conditions of a module at the relative pose `g` (lower frame):
/// each spherical-joint centre lies in the plane through its revolute's point normal to the
/// revolute axis (paper 002 §4: the leg's constraint force lies along that axis).
fn plane_conditions(kind: ModuleKind, g: &Displacement, lower: f64, upper: f64) -> Vector3<f64> {
    Vector3::from_fn(|i, _| {
        let a = vertex(lower, i);
        let b = g.transform_point(&vertex(upper, i).into()).coords;
        match kind {
            ModuleKind::Rps => tangent(i).dot(&(b - a)),
            ModuleKind::Spr => (g.rotation * tangent(i)).dot(&(a - b)),
        }
    })
}

/// A module's assembled relative pose: Newton on `(x, y, ψ)` from the centred pose.
fn assemble_module(
    kind: ModuleKind,
    k: usize,
    lower: f64,
    upper: f64,
    height: f64,
) -> Result<Displacement, StackError> {
    let t = tilt(k);
    let f = |c: &Vector3<f64>| plane_conditions(kind, &relative_pose(c, height, &t), lower, upper);
    let mut c = Vector3::zeros();
    for _ in 0..50 {
        let r = f(&c);
        if r.norm() < 1e-14 * lower.max(upper) {
            return Ok(relative_pose(&c, height, &t));
        }
        let h = 1e-7;
        let j = Matrix3::from_fn(|row, col| {
            let mut p = c;
            let mut m = c;
            p[col] += h;
            m[col] -= h;
            (f(&p)[row] - f(&m)[row]) / (2.0 * h)
        });
        let Some(step) = j.lu().solve(&r) else { break };
        c -= step;
    }
    Err(StackError::NotAssembled {
        module: k + 1,
        residual: f(&c).norm(),
    })
}

/// The stack as a description: bodies `platform 1` … `platform n` (the last the
/// end-effector) above the ground `base`, three legs per module (`RP!S` from the lower
/// platform, or `SP!R`; the prismatic joints actuated), lengths in `m` and angles in degrees.
///
/// # Errors
/// [`StackError`]: sizes that do not match, unusable lengths, or a module that does not
/// assemble at its height.
pub fn stack(spec: &StackSpec) -> Result<MultibodyDescription, StackError> {
    let n = spec.modules.len();
    if n == 0 || spec.radii.len() != n + 1 || spec.heights.len() != n {
        return Err(StackError::Sizes {
            modules: n,
            radii: spec.radii.len(),
            heights: spec.heights.len(),
        });
    }
    if n > MAX_MODULES {
        return Err(StackError::TooManyModules(n));
    }
    for &x in spec.radii.iter().chain(&spec.heights) {
        if !x.is_finite() || x == 0.0 || x.abs() > super::LARGEST_COORDINATE {
            return Err(StackError::Length(x));
        }
    }
    if let Some(&r) = spec.radii.iter().find(|&&r| r < 0.0) {
        return Err(StackError::Length(r));
    }
    let name = |k: usize| {
        if k == 0 {
            "base".to_string()
        } else {
            format!("platform {k}")
        }
    };
    let tidy = |v: Vector3<f64>| -> [f64; 3] { v.map(|x| (x * 1e12).round() / 1e12 + 0.0).into() };
    let mut frames = vec![crate::spatial::identity()];
    let mut bodies = Vec::with_capacity(n);
    let mut legs = Vec::with_capacity(3 * n);
    for (k, &kind) in spec.modules.iter().enumerate() {
        let (lower, upper) = (spec.radii[k], spec.radii[k + 1]);
        let relative = assemble_module(kind, k, lower, upper, spec.heights[k])?;
        let frame = frames[k] * relative;
        let rotation = rotation_log(&frame.rotation).map(f64::to_degrees);
        bodies.push(BodySpec {
            name: name(k + 1),
            position: tidy(frame.translation.vector),
            orientation: tidy(rotation),
            point: [0.0; 3],
        });
        for i in 0..3 {
            let spherical =
                [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(AxisSpec::Vector);
            let (chain, axes) = match kind {
                ModuleKind::Rps => {
                    let r = AxisSpec::Vector(tidy(frames[k].rotation * tangent(i)));
                    let mut axes = vec![r, AxisSpec::Named("leg".into())];
                    axes.extend(spherical);
                    ("RP!S", axes)
                }
                ModuleKind::Spr => {
                    let r = AxisSpec::Vector(tidy(frame.rotation * tangent(i)));
                    let mut axes = spherical.to_vec();
                    axes.extend([AxisSpec::Named("leg".into()), r]);
                    ("SP!R", axes)
                }
            };
            legs.push(LegBetween {
                chain: chain.into(),
                from: name(k),
                to: name(k + 1),
                first: tidy(vertex(lower, i)),
                last: tidy(vertex(upper, i)),
                points: None,
                axes: Some(axes),
                actuated: None,
            });
        }
        frames.push(frame);
    }
    let word: Vec<&str> = spec
        .modules
        .iter()
        .map(|m| match m {
            ModuleKind::Rps => "3-RPS",
            ModuleKind::Spr => "3-SPR",
        })
        .collect();
    Ok(MultibodyDescription {
        format: FORMAT_2.into(),
        name: word.join("-"),
        source: Some(format!(
            "kinsyn stack (paper 002 §2 frames): radii {:?}, heights {:?}; module tilts chosen generic, in-plane coordinates solved by Newton",
            spec.radii, spec.heights
        )),
        units: Units {
            length: "m".into(),
            angle: AngleUnit::Deg,
        },
        ground: "base".into(),
        end_effector: Some(name(n)),
        bodies,
        legs,
    })
}
