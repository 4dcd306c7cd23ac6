//! `kinsyn configurable …`: paper 003's planar 4-RRR with a configurable platform by the
//! paper's own formulas (`kinsyn_papers::configurable`), with the geometry of §5 (a = 80, b = 120,
//! c = 120 mm, `A_i` at (±200, 0), (0, ±200) mm). Angles are in degrees at this interface.

use crate::Error;
use kinsyn_papers::configurable::trajectory::assemble;
use kinsyn_papers::configurable::velocity::{Configuration, velocities};
use kinsyn_papers::configurable::{
    CentrePose, Configurable, CornerPose, ForwardMethod, forward_position,
};
use nalgebra::{Vector2, Vector4};
use serde::Serialize;

/// Reads `n` comma-separated finite numbers for `option`.
///
/// # Errors
///
/// [`Error::Input`], `OPTION "TEXT": …` when the text is not `n` finite numbers.
pub fn numbers(option: &str, text: &str, n: usize) -> Result<Vec<f64>, Error> {
    let values: Vec<f64> = text
        .split(',')
        .map(|t| {
            t.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && v.abs() <= 1e12)
        })
        .collect::<Option<_>>()
        .ok_or_else(|| {
            Error::Input(format!(
                "{option} {text:?}: give {n} finite numbers separated by commas"
            ))
        })?;
    if values.len() == n {
        Ok(values)
    } else {
        Err(Error::Input(format!(
            "{option} {text:?}: {} numbers given, {n} expected",
            values.len()
        )))
    }
}

fn inputs(text: &str) -> Result<[f64; 4], Error> {
    let v = numbers("--q", text, 4)?;
    Ok(std::array::from_fn(|i| v[i].to_radians()))
}

/// A point of the plane as `[x, y]`.
fn xy(v: Vector2<f64>) -> [f64; 2] {
    [v.x, v.y]
}

/// The report of `kinsyn configurable inverse (--centre X,Y | --c4 X,Y) --theta T --phi P`
/// (and of Python's `configurable.inverse`): the platform pose's corners and its up to 16 input
/// sets (§3.2). Lengths are in mm, angles in degrees.
///
/// Printed through [`crate::sorted_value`]: its keys come in alphabetical order, as they did
/// when the report was built with `serde_json::json!`.
#[derive(Debug, Clone, Serialize)]
pub struct InverseReport {
    /// The platform's corners `C1…C4` at the pose, each `[x, y]` (mm).
    pub corners: Vec<[f64; 2]>,
    /// The input sets that reach the pose (two elbows per leg), each `[q1, q2, q3, q4]`
    /// (degrees).
    pub q_deg: Vec<[f64; 4]>,
    /// The pose asked for, as given (not in the JSON).
    #[serde(skip)]
    pub asked: InversePose,
}

/// The platform pose `kinsyn configurable inverse` was asked for.
#[derive(Debug, Clone, Copy)]
pub struct InversePose {
    /// The point given: the centre or the corner C4 (mm).
    pub given: GivenPoint,
    /// θ (degrees; eq. 11's sense for the centre, eq. 13's for the corner).
    pub theta_deg: f64,
    /// φ (degrees, in the same sense as θ).
    pub phi_deg: f64,
}

/// The point a platform pose is given by, `[x, y]` (mm).
#[derive(Debug, Clone, Copy)]
pub enum GivenPoint {
    /// `--centre X,Y`: the platform's centre C.
    Centre([f64; 2]),
    /// `--c4 X,Y`: its corner C4.
    Corner([f64; 2]),
}

/// The input sets of a platform pose given by its centre (`centre`, `--centre X,Y`) or its
/// corner C4 (`corner`, `--c4 X,Y`), with the angles `theta` and `phi` (degrees).
///
/// # Errors
///
/// [`Error::Input`], naming the option: malformed numbers, neither or both of `--centre`
/// and `--c4`, or a pose the legs cannot reach.
pub fn inverse_report(
    centre: Option<&str>,
    corner: Option<&str>,
    theta: f64,
    phi: f64,
) -> Result<InverseReport, Error> {
    let m = Configurable::paper003();
    let (theta, phi) = (theta.to_radians(), phi.to_radians());
    let (inverse, given) = match (centre, corner) {
        (Some(text), None) => {
            let c = numbers("--centre", text, 2)?;
            let pose = CentrePose {
                centre: Vector2::new(c[0], c[1]),
                theta,
                phi,
            };
            (
                m.inverse_centre_pose(&pose),
                GivenPoint::Centre([c[0], c[1]]),
            )
        }
        (None, Some(text)) => {
            let c = numbers("--c4", text, 2)?;
            let pose = CornerPose {
                c4: Vector2::new(c[0], c[1]),
                theta,
                phi,
            };
            (
                m.inverse_corner_pose(&pose),
                GivenPoint::Corner([c[0], c[1]]),
            )
        }
        _ => {
            return Err(Error::Input(
                "give the pose by --centre X,Y or by --c4 X,Y".into(),
            ));
        }
    };
    let inverse = inverse.map_err(|e| Error::Input(e.to_string()))?;
    Ok(InverseReport {
        corners: inverse.corners.iter().copied().map(xy).collect(),
        q_deg: inverse
            .sets()
            .iter()
            .map(|q| q.map(f64::to_degrees))
            .collect(),
        asked: InversePose {
            given,
            theta_deg: theta.to_degrees(),
            phi_deg: phi.to_degrees(),
        },
    })
}

/// The report of `kinsyn configurable forward --q Q --method M` (and of Python's
/// `configurable.forward`): every assembly of paper 003's 4-RRR at given inputs, by homotopy
/// continuation on §3.2's equations. Lengths are in mm, angles in degrees.
///
/// Printed through [`crate::sorted_value`]: its keys come in alphabetical order, as they did
/// when the report was built with `serde_json::json!`.
#[derive(Debug, Clone, Serialize)]
pub struct ForwardReport {
    /// §3.2's method: 1 (the formulation in the centre's pose) or 2 (in the corner C4's).
    pub method: u8,
    /// The distinct non-singular complex solutions of the method's system found by all runs.
    pub complex_solutions: usize,
    /// Of those, the real ones.
    pub real_solutions: usize,
    /// The distinct complex corner sets among the non-singular solutions.
    pub complex_assemblies: usize,
    /// Whether the last run had no failed path and (method 1) every solution's mirror was
    /// found too (false: the counts may be short).
    pub complete: bool,
    /// The runs of the homotopy (seeds one apart).
    pub runs: usize,
    /// The real assemblies: distinct corner sets, sorted by θ then φ.
    pub assemblies: Vec<ForwardAssembly>,
    /// `--q` as given: the inputs (degrees; not in the JSON).
    #[serde(skip)]
    pub q_text: String,
    /// The paths tracked over every run (not in the JSON).
    #[serde(skip)]
    pub paths: usize,
}

/// A real assembly of paper 003's 4-RRR.
#[derive(Debug, Clone, Serialize)]
pub struct ForwardAssembly {
    /// The platform's corners `C1…C4`, each `[x, y]` (mm).
    pub corners: Vec<[f64; 2]>,
    /// The corner C4 `[x, y]` (mm).
    pub c4: [f64; 2],
    /// θ in eq. 13's sense: the direction of `C4 → C1`, in `[0, 360)` degrees.
    pub theta_deg: f64,
    /// φ in eq. 13's sense: the direction of `C4 → C3`, in `[0, 360)` degrees.
    pub phi_deg: f64,
    /// Whether every solution of the method's system giving these corners is a
    /// Krawczyk-certified, distinct, real root.
    pub certified: bool,
    /// The largest loop-closure error `| |C_i − B_i| − b |` (mm).
    pub closure_error: f64,
}

/// Every assembly of paper 003's 4-RRR at the inputs `q_text` (`--q`, degrees) by §3.2's
/// method `method` (1 or 2), with a spinner on stderr when it is a terminal.
///
/// # Errors
///
/// [`Error::Input`], naming the option: malformed numbers, a method other than 1 and 2,
/// or a homotopy that fails.
pub fn forward_report(q_text: &str, method: u8) -> Result<ForwardReport, Error> {
    let m = Configurable::paper003();
    let q = inputs(q_text)?;
    let method = match method {
        1 => ForwardMethod::Centre,
        2 => ForwardMethod::Corner,
        k => {
            return Err(Error::Input(format!(
                "--method {k}: the paper's methods are 1 and 2"
            )));
        }
    };
    let f = crate::terminal::working("forward position", || forward_position(&m, q, method))
        .map_err(|e| Error::Input(e.to_string()))?;
    Ok(ForwardReport {
        method: method.number(),
        complex_solutions: f.complex,
        real_solutions: f.real,
        complex_assemblies: f.complex_assemblies,
        complete: f.complete,
        runs: f.reports.len(),
        assemblies: f
            .assemblies
            .iter()
            .map(|a| ForwardAssembly {
                corners: a.corners.iter().copied().map(xy).collect(),
                c4: xy(a.pose.c4),
                theta_deg: a.pose.theta.to_degrees(),
                phi_deg: a.pose.phi.to_degrees(),
                certified: a.certified,
                closure_error: a.closure_error,
            })
            .collect(),
        q_text: q_text.to_string(),
        paths: f
            .reports
            .iter()
            .map(kinsyn::homotopy::SolveReport::paths)
            .sum(),
    })
}

/// The report of `kinsyn configurable velocity --q Q --qdot QDOT [--near N]` (and of Python's
/// `configurable.velocity`): the assembly near a pose and its velocities by screw theory (§4,
/// eqs. 16–29). Lengths are in mm, angles in degrees, rates per second.
///
/// Printed through [`crate::sorted_value`]: its keys come in alphabetical order, as they did
/// when the report was built with `serde_json::json!`.
#[derive(Debug, Clone, Serialize)]
pub struct VelocityReport {
    /// The assembly's corner C4 `[x, y]` (mm).
    pub c4: [f64; 2],
    /// The assembly's θ in eq. 13's sense: the direction of `C4 → C1` (degrees).
    pub theta_deg: f64,
    /// The assembly's φ in eq. 13's sense: the direction of `C4 → C3` (degrees).
    pub phi_deg: f64,
    /// The angular velocity of link m1 (`C1 C2`, eq. 26; rad/s).
    pub omega_m1: f64,
    /// The angular velocity of link m3 (`C3 C4`, eqs. 27–28; rad/s): that of m1.
    pub omega_m3: f64,
    /// The passive loop rate `m1ωm2 = θ̇ − φ̇` (eq. 24; rad/s).
    pub loop_rate: f64,
    /// The corners' velocities `Ċ1…Ċ4` (eq. 29), each `[ẋ, ẏ]` (mm/s).
    pub corner_velocities: Vec<[f64; 2]>,
    /// `--q` as given: the inputs (degrees; not in the JSON).
    #[serde(skip)]
    pub q_text: String,
    /// `--qdot` as given: the input rates (rad/s; not in the JSON).
    #[serde(skip)]
    pub qdot_text: String,
}

/// The velocities of paper 003's 4-RRR at the inputs `q_text` (`--q`, degrees) with the input
/// rates `qdot_text` (`--qdot`, rad/s), at the assembly nearest `near` (`--near C4x,C4y,θ,φ`;
/// Table 1's pose by default).
///
/// # Errors
///
/// [`Error::Input`], naming the option: malformed numbers, no assembly near the pose, or
/// a singular configuration.
pub fn velocity_report(
    q_text: &str,
    qdot_text: &str,
    near: Option<&str>,
) -> Result<VelocityReport, Error> {
    let m = Configurable::paper003();
    let q = inputs(q_text)?;
    let rates = numbers("--qdot", qdot_text, 4)?;
    let guess = match near {
        Some(text) => {
            let v = numbers("--near", text, 4)?;
            CornerPose {
                c4: Vector2::new(v[0], v[1]),
                theta: v[2].to_radians(),
                phi: v[3].to_radians(),
            }
        }
        None => CornerPose {
            c4: Vector2::new(25.112, -147.043),
            theta: 79.999f64.to_radians(),
            phi: 105.0f64.to_radians(),
        },
    };
    let pose = assemble(&m, &q, &guess).ok_or_else(|| {
        Error::Input(format!(
            "--q {q_text:?}: no assembly near the pose given (Newton does not converge)"
        ))
    })?;
    let v = velocities(
        &Configuration::new(&m, q, &pose),
        &Vector4::new(rates[0], rates[1], rates[2], rates[3]),
    )
    .map_err(|e| Error::Input(e.to_string()))?;
    Ok(VelocityReport {
        c4: xy(pose.c4),
        theta_deg: pose.theta.to_degrees(),
        phi_deg: pose.phi.to_degrees(),
        omega_m1: v.m1.w.z,
        omega_m3: v.m3.w.z,
        loop_rate: v.loop_rate,
        corner_velocities: v.corners.iter().map(|c| [c.x, c.y]).collect(),
        q_text: q_text.to_string(),
        qdot_text: qdot_text.to_string(),
    })
}
