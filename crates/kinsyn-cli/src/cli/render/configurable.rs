//! The text of `kinsyn configurable inverse|forward|velocity` (paper 003's 4-RRR).

use kinsyn_report::configurable::{ForwardReport, GivenPoint, InverseReport, VelocityReport};
use std::fmt::Write as _;

/// The text report of `kinsyn configurable inverse`.
pub(in crate::cli) fn inverse(r: &InverseReport) -> String {
    let mut out = String::new();
    let asked = &r.asked;
    let described = match asked.given {
        GivenPoint::Centre([x, y]) => {
            format!("centre C = ({x}, {y}) mm, θ, φ in eq. 11's sense")
        }
        GivenPoint::Corner([x, y]) => {
            format!("corner C4 = ({x}, {y}) mm, θ, φ in eq. 13's sense")
        }
    };
    let _ = writeln!(
        out,
        "paper 003 inverse position (§3.2): {described}, θ = {:.3}°, φ = {:.3}°",
        asked.theta_deg, asked.phi_deg
    );
    let corners: Vec<String> = r
        .corners
        .iter()
        .enumerate()
        .map(|(i, c)| format!("C{} = {}", i + 1, point(*c)))
        .collect();
    let _ = writeln!(out, "corners: {}", corners.join(", "));
    let _ = writeln!(
        out,
        "{} input sets (two elbows per leg), q1, q2, q3, q4 in degrees:",
        r.q_deg.len()
    );
    for (k, q) in r.q_deg.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {:>2}  {:.3}, {:.3}, {:.3}, {:.3}",
            k + 1,
            q[0],
            q[1],
            q[2],
            q[3]
        );
    }
    out
}

/// The text report of `kinsyn configurable forward`.
pub(in crate::cli) fn forward(r: &ForwardReport) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "paper 003 forward position (§3.2, method {}) at q = {} deg",
        r.method, r.q_text
    );
    let _ = writeln!(
        out,
        "{} complex solutions ({} real), {} distinct assemblies; {} run{} of the homotopy, {} paths{}",
        r.complex_solutions,
        r.real_solutions,
        r.complex_assemblies,
        r.runs,
        if r.runs == 1 { "" } else { "s" },
        r.paths,
        if r.complete {
            ""
        } else {
            " (some paths lost: the count may be short)"
        }
    );
    let _ = writeln!(out, "real assemblies ({}):", r.assemblies.len());
    for (k, a) in r.assemblies.iter().enumerate() {
        let corners: Vec<String> = a.corners.iter().map(|c| point(*c)).collect();
        let _ = writeln!(
            out,
            "  {}  C4 = {}, θ = {:.3}°, φ = {:.3}°; corners {}{}",
            k + 1,
            point(a.c4),
            a.theta_deg,
            a.phi_deg,
            corners.join(" "),
            if a.certified { " [certified]" } else { "" }
        );
    }
    out
}

/// The text report of `kinsyn configurable velocity`.
pub(in crate::cli) fn velocity(r: &VelocityReport) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "paper 003 velocities by screw theory (§4, eqs. 16–29) at q = {} deg, q̇ = {} rad/s",
        r.q_text, r.qdot_text
    );
    let _ = writeln!(
        out,
        "assembly: C4 = {}, θ = {:.5}°, φ = {:.5}°",
        point(r.c4),
        r.theta_deg,
        r.phi_deg
    );
    let _ = writeln!(
        out,
        "ω(m1) = ω(m3) = {:.6} rad/s (eq. 27), loop rate m1ωm2 = {:.6} rad/s",
        r.omega_m1, r.loop_rate
    );
    for (i, [x, y]) in r.corner_velocities.iter().enumerate() {
        let _ = writeln!(out, "  Ċ{} = ({x:.4}, {y:.4}) mm/s", i + 1);
    }
    out
}
/// A point `[x, y]` as text: `(x, y)`, three decimals.
fn point([x, y]: [f64; 2]) -> String {
    format!("({x:.3}, {y:.3})")
}
