//! `kinsyn configurable …`: paper 003's planar 4-RRR with a configurable platform by the
//! paper's own formulas (`kinsyn_papers::configurable`), with the geometry of §5 (a = 80, b = 120,
//! c = 120 mm, `A_i` at (±200, 0), (0, ±200) mm). Angles are in degrees at this interface.

use crate::{Error, json};
use kinsyn_papers::configurable::trajectory::assemble;
use kinsyn_papers::configurable::velocity::{Configuration, velocities};
use kinsyn_papers::configurable::{
    CentrePose, Configurable, CornerPose, ForwardMethod, forward_position,
};
use nalgebra::{Vector2, Vector4};
use std::fmt::Write as _;

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

fn point(v: Vector2<f64>) -> String {
    format!("({:.3}, {:.3})", v.x, v.y)
}

/// `kinsyn configurable inverse`: the up to 16 input sets of a platform pose (§3.2), as text
/// or as the `--json` report.
///
/// # Errors
///
/// [`Error::Input`], naming the option: malformed numbers, neither or both of `--centre`
/// and `--c4`, or a pose the legs cannot reach.
pub fn inverse(
    centre: Option<&str>,
    corner: Option<&str>,
    theta: f64,
    phi: f64,
    as_json: bool,
) -> Result<String, Error> {
    let m = Configurable::paper003();
    let (theta, phi) = (theta.to_radians(), phi.to_radians());
    let (inverse, described) = match (centre, corner) {
        (Some(text), None) => {
            let c = numbers("--centre", text, 2)?;
            let pose = CentrePose {
                centre: Vector2::new(c[0], c[1]),
                theta,
                phi,
            };
            (
                m.inverse_centre_pose(&pose),
                format!("centre C = ({}, {}) mm, θ, φ in eq. 11's sense", c[0], c[1]),
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
                format!(
                    "corner C4 = ({}, {}) mm, θ, φ in eq. 13's sense",
                    c[0], c[1]
                ),
            )
        }
        _ => {
            return Err(Error::Input(
                "give the pose by --centre X,Y or by --c4 X,Y".into(),
            ));
        }
    };
    let inverse = inverse.map_err(|e| Error::Input(e.to_string()))?;
    let sets = inverse.sets();
    if as_json {
        return Ok(json(&serde_json::json!({
            "corners": inverse.corners.iter().map(|c| [c.x, c.y]).collect::<Vec<_>>(),
            "q_deg": sets.iter().map(|q| q.map(f64::to_degrees)).collect::<Vec<_>>(),
        })));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "paper 003 inverse position (§3.2): {described}, θ = {:.3}°, φ = {:.3}°",
        theta.to_degrees(),
        phi.to_degrees()
    );
    let corners: Vec<String> = inverse
        .corners
        .iter()
        .enumerate()
        .map(|(i, c)| format!("C{} = {}", i + 1, point(*c)))
        .collect();
    let _ = writeln!(out, "corners: {}", corners.join(", "));
    let _ = writeln!(
        out,
        "{} input sets (two elbows per leg), q1, q2, q3, q4 in degrees:",
        sets.len()
    );
    for (k, q) in sets.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {:>2}  {:.3}, {:.3}, {:.3}, {:.3}",
            k + 1,
            q[0].to_degrees(),
            q[1].to_degrees(),
            q[2].to_degrees(),
            q[3].to_degrees()
        );
    }
    Ok(out)
}

/// `kinsyn configurable forward`: every assembly at the inputs `q_text` (degrees) by §3.2's
/// method 1 or 2, as text or as the `--json` report.
///
/// # Errors
///
/// [`Error::Input`], naming the option: malformed numbers, a method other than 1 and 2,
/// or a homotopy that fails.
pub fn forward(q_text: &str, method: u8, as_json: bool) -> Result<String, Error> {
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
    if as_json {
        return Ok(json(&serde_json::json!({
            "method": method.number(),
            "complex_solutions": f.complex,
            "real_solutions": f.real,
            "complex_assemblies": f.complex_assemblies,
            "complete": f.complete,
            "runs": f.reports.len(),
            "assemblies": f.assemblies.iter().map(|a| serde_json::json!({
                "corners": a.corners.iter().map(|c| [c.x, c.y]).collect::<Vec<_>>(),
                "c4": [a.pose.c4.x, a.pose.c4.y],
                "theta_deg": a.pose.theta.to_degrees(),
                "phi_deg": a.pose.phi.to_degrees(),
                "certified": a.certified,
                "closure_error": a.closure_error,
            })).collect::<Vec<_>>(),
        })));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "paper 003 forward position (§3.2, method {}) at q = {q_text} deg",
        method.number()
    );
    let paths: usize = f
        .reports
        .iter()
        .map(kinsyn::homotopy::SolveReport::paths)
        .sum();
    let _ = writeln!(
        out,
        "{} complex solutions ({} real), {} distinct assemblies; {} run{} of the homotopy, {paths} paths{}",
        f.complex,
        f.real,
        f.complex_assemblies,
        f.reports.len(),
        if f.reports.len() == 1 { "" } else { "s" },
        if f.complete {
            ""
        } else {
            " (some paths lost: the count may be short)"
        }
    );
    let _ = writeln!(out, "real assemblies ({}):", f.assemblies.len());
    for (k, a) in f.assemblies.iter().enumerate() {
        let corners: Vec<String> = a.corners.iter().map(|c| point(*c)).collect();
        let _ = writeln!(
            out,
            "  {}  C4 = {}, θ = {:.3}°, φ = {:.3}°; corners {}{}",
            k + 1,
            point(a.pose.c4),
            a.pose.theta.to_degrees(),
            a.pose.phi.to_degrees(),
            corners.join(" "),
            if a.certified { " [certified]" } else { "" }
        );
    }
    Ok(out)
}

/// `kinsyn configurable velocity`: the corner velocities by screw theory (§4) at the assembly
/// nearest a given pose (default Table 1's), as text or as the `--json` report.
///
/// # Errors
///
/// [`Error::Input`], naming the option: malformed numbers, no assembly near the pose, or
/// a singular configuration.
pub fn velocity(
    q_text: &str,
    qdot_text: &str,
    near: Option<&str>,
    as_json: bool,
) -> Result<String, Error> {
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
    if as_json {
        return Ok(json(&serde_json::json!({
            "c4": [pose.c4.x, pose.c4.y], "theta_deg": pose.theta.to_degrees(), "phi_deg": pose.phi.to_degrees(),
            "omega_m1": v.m1.w.z, "omega_m3": v.m3.w.z, "loop_rate": v.loop_rate,
            "corner_velocities": v.corners.iter().map(|c| [c.x, c.y]).collect::<Vec<_>>(),
        })));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "paper 003 velocities by screw theory (§4, eqs. 16–29) at q = {q_text} deg, q̇ = {qdot_text} rad/s"
    );
    let _ = writeln!(
        out,
        "assembly: C4 = {}, θ = {:.5}°, φ = {:.5}°",
        point(pose.c4),
        pose.theta.to_degrees(),
        pose.phi.to_degrees()
    );
    let _ = writeln!(
        out,
        "ω(m1) = ω(m3) = {:.6} rad/s (eq. 27), loop rate m1ωm2 = {:.6} rad/s",
        v.m1.w.z, v.loop_rate
    );
    for (i, c) in v.corners.iter().enumerate() {
        let _ = writeln!(out, "  Ċ{} = ({:.4}, {:.4}) mm/s", i + 1, c.x, c.y);
    }
    Ok(out)
}
