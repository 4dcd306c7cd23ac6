//! `kinsyn plot trajectory`: paper 003 §5's trajectory drawn, and where it ends said.

use crate::common;
use common::kinsyn;
use std::f64::consts::{FRAC_PI_2, PI};

#[test]
fn the_trajectory_figure_is_written_and_the_turning_point_named() {
    let dir = tempfile::tempdir().unwrap();
    let out = kinsyn(&[
        "plot",
        "trajectory",
        "--out",
        dir.path().to_str().unwrap(),
        "--steps",
        "400",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    // The turning point found by the library test (crates/kinsyn-papers/tests/suite/configurable_trajectory.rs,
    // checked there by the homotopy's real-assembly counts on either side).
    assert!(text.contains("followed to t = 0.1785"), "{text}");
    assert!(text.contains("turning point"), "{text}");
    // The inputs are functions of sin 2t: the values of [0, t*] recur on [π/2 − t*, π + t*] and
    // [3π/2 − t*, 2π] (by hand from q(t) = q0 + a sin t cos t).
    let t_star: f64 = text
        .split("followed to t = ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|v| v.parse().ok())
        .expect("t*");
    let line = text
        .lines()
        .find(|l| l.contains("sin 2t only"))
        .unwrap_or_else(|| panic!("{text}"));
    let printed: Vec<f64> = line
        .split("= [")
        .skip(1)
        .flat_map(|part| part.split(']').next().unwrap().split(", "))
        .map(|v| v.parse().unwrap())
        .collect();
    let expected = [
        FRAC_PI_2 - t_star,
        PI + t_star,
        3.0 * FRAC_PI_2 - t_star,
        2.0 * PI,
    ];
    assert_eq!(printed.len(), 4, "{line}");
    for (p, e) in printed.iter().zip(expected) {
        assert!((p - e).abs() < 2e-6, "{p} against {e}: {line}");
    }
    let svg = std::fs::read_to_string(dir.path().join("trajectory-velocities.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("C1") && svg.contains("C4"));
}

#[test]
fn bad_steps_are_one_line_and_exit_2() {
    for steps in ["0", "1", "100001"] {
        let out = kinsyn(&["plot", "trajectory", "--steps", steps]);
        assert_eq!(out.status.code(), Some(2), "--steps {steps}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("--steps"), "{err}");
    }
}

#[test]
fn the_inverse_figure_has_the_16_configurations_of_section_5() {
    // Paper 003 §5, Fig. 9: 16 configurations for θ = 75°, φ = 100°, C = (20, −30) mm.
    let dir = tempfile::tempdir().unwrap();
    let out = kinsyn(&["plot", "inverse", "--out", dir.path().to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        String::from_utf8(out.stdout)
            .unwrap()
            .starts_with("16 configurations")
    );
    let svg = std::fs::read_to_string(dir.path().join("inverse-configurations.svg")).unwrap();
    // One label of input angles per panel; the published q (141.956°, …) in one of them.
    assert_eq!(
        svg.matches("<text").count(),
        17,
        "a title and 16 panel labels"
    );
    assert!(svg.contains("142.0, 203.4, 337.8, 305.5"));
}
