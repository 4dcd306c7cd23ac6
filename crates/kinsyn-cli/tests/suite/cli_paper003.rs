//! `kinsyn configurable …`: paper 003's example end to end from the command line (§5).

use crate::common;
use common::kinsyn;

fn json(args: &[&str]) -> serde_json::Value {
    let out = kinsyn(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn inverse_example_has_16_sets_with_the_published_q() {
    // §5: θ = 75°, φ = 100°, C = (20, −30) mm gives 16 configurations (Fig. 9), one of them
    // q = (141.956°, 203.366°, 337.773°, 305.499°) — printed within 6.4e-4° of the exact
    // (docs/deviations.md, Paper 003).
    let v = json(&[
        "configurable",
        "inverse",
        "--centre",
        "20,-30",
        "--theta",
        "75",
        "--phi",
        "100",
        "--json",
    ]);
    let sets = v["q_deg"].as_array().unwrap();
    assert_eq!(sets.len(), 16);
    let published = [141.956, 203.366, 337.773, 305.499];
    assert!(
        sets.iter()
            .any(|q| (0..4).all(|i| (q[i].as_f64().unwrap() - published[i]).abs() < 1e-3))
    );
}

#[test]
fn forward_example_has_two_real_assemblies_one_of_them_table_1() {
    // §5, Fig. 10: two real solutions; Table 1: x4 = 25.112, y4 = −147.043, θ = 79.999°,
    // φ = 105.000° (to 1.3e-3 mm and 8.5e-4°).
    for method in ["1", "2"] {
        let v = json(&[
            "configurable",
            "forward",
            "--q",
            "141.956,203.366,337.773,305.499",
            "--method",
            method,
            "--json",
        ]);
        let real = v["assemblies"].as_array().unwrap();
        assert_eq!(real.len(), 2, "method {method}");
        assert!(real.iter().all(|a| a["certified"] == true));
        assert!(real.iter().any(|a| {
            (a["c4"][0].as_f64().unwrap() - 25.112).abs() < 2e-3
                && (a["c4"][1].as_f64().unwrap() + 147.043).abs() < 2e-3
                && (a["theta_deg"].as_f64().unwrap() - 79.999).abs() < 1e-3
                && (a["phi_deg"].as_f64().unwrap() - 105.0).abs() < 1e-3
        }));
    }
}

#[test]
fn velocity_of_opposite_links_is_the_same_rotation() {
    // Eq. 27: m1 and m3 turn alike (opposite sides of the rhombus stay parallel).
    let v = json(&[
        "configurable",
        "velocity",
        "--q",
        "141.956,203.366,337.773,305.499",
        "--qdot=-1.5,-1.25,-2,1.5",
        "--json",
    ]);
    assert!((v["omega_m1"].as_f64().unwrap() - v["omega_m3"].as_f64().unwrap()).abs() < 1e-9);
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    for args in [
        vec![
            "configurable",
            "inverse",
            "--centre",
            "500,0",
            "--theta",
            "75",
            "--phi",
            "100",
        ],
        vec!["configurable", "inverse", "--theta", "75", "--phi", "100"],
        vec!["configurable", "forward", "--q", "1,2,3"],
        vec!["configurable", "forward", "--q", "1,2,3,nan"],
        vec!["configurable", "forward", "--q", "1,2,3,4", "--method", "3"],
        // §5's inputs at t = 0.3 s: outside the workspace (no real assembly, tests of
        // crates/kinsyn-papers/tests/suite/configurable_trajectory.rs), so no assembly to differentiate.
        vec![
            "configurable",
            "velocity",
            "--q",
            "117.66,183.12,305.41,329.71",
            "--qdot",
            "1,1,1,1",
        ],
    ] {
        let out = kinsyn(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("kinsyn: error:"), "{err}");
    }
}
