//! `kinsyn modes` and `kinsyn analyze` on paper 004's 4-RUU (`mechanisms/4-ruu.json`, reference
//! in the 2nd Schönflies mode K2) and on a test-only description in the 1st (K1): both are
//! 4-dof Schönflies modes X(z) (paper 004 §4.1.1–4.1.2, §4.3).

use crate::common;
use serde_json::Value;

use common::{kinsyn, stderr, stdout};
use std::f64::consts::{FRAC_PI_2, SQRT_2};

/// The 1st Schönflies mode (test only): the platform turned by π about (1, 1, 0)/√2 (z down),
/// at height √2, the cranks at 180°, −atan(3/4), 0°, 90°, so that `B_i` = (1, 0, 0),
/// (0.8, 1.4, 0), (−1, 0, 0), (0, −1, 0) and `C_i` = (0, 1, √2), (1, 0, √2), (0, −1, √2),
/// (−1, 0, √2): every `|C_i − B_i|² = 4` (leg 2: 0.04 + 1.96 + 2). The inner U axes are normal
/// to the links' horizontal projections, the platform's last axes along its z (= −Z).
const K1: &str = r#"{
  "format": "kinsyn-manipulator/1",
  "name": "4-RUU (paper 004), 1st Schönflies mode",
  "units": { "length": "m", "angle": "deg" },
  "platform": {
    "position": [0.0, 0.0, 1.4142135623730951],
    "orientation": [127.27922061357856, 127.27922061357856, 0.0]
  },
  "legs": [
    { "chain": "R!UU", "base": [2.0, 0.0, 0.0], "platform": [1.0, 0.0, 0.0],
      "points": [[1.0, 0.0, 0.0]],
      "axes": [[0, 0, 1], [0, 0, 1], [1, 1, 0], [1, 1, 0], [0, 0, -1]] },
    { "chain": "R!UU", "base": [0.0, 2.0, 0.0], "platform": [0.0, 1.0, 0.0],
      "points": [[0.8, 1.4, 0.0]],
      "axes": [[0, 0, 1], [0, 0, 1], [7, 1, 0], [7, 1, 0], [0, 0, -1]] },
    { "chain": "R!UU", "base": [-2.0, 0.0, 0.0], "platform": [-1.0, 0.0, 0.0],
      "points": [[-1.0, 0.0, 0.0]],
      "axes": [[0, 0, 1], [0, 0, 1], [1, 1, 0], [1, 1, 0], [0, 0, -1]] },
    { "chain": "R!UU", "base": [0.0, -2.0, 0.0], "platform": [0.0, -1.0, 0.0],
      "points": [[0.0, -1.0, 0.0]],
      "axes": [[0, 0, 1], [0, 0, 1], [1, 1, 0], [1, 1, 0], [0, 0, -1]] }
  ]
}"#;

fn json(args: &[&str]) -> Value {
    let o = kinsyn(args);
    assert_eq!(o.status.code(), Some(0), "kinsyn {args:?}: {}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

/// The unlocked mode's dof and pattern from `modes --json`.
fn unlocked_mode(file: &str) -> (u64, String) {
    let v = json(&["modes", file, "--json"]);
    let m = v["modes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["locked"].as_array().unwrap().is_empty())
        .unwrap();
    (
        m["dof"].as_u64().unwrap(),
        m["pattern"].as_str().unwrap().to_string(),
    )
}

fn k1_file(dir: &tempfile::TempDir) -> String {
    let path = dir.path().join("4-ruu-k1.json");
    std::fs::write(&path, K1).unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn modes_finds_schoenflies_x_z_with_four_dof_in_k2_and_k1() {
    // Paper 004 §4.1.1–4.1.2: both modes are Schönflies motions (3 translations, rotation
    // about the vertical), dof 4 with every input free.
    assert_eq!(
        unlocked_mode("mechanisms/4-ruu.json"),
        (4, "X(z)".to_string())
    );
    let dir = tempfile::tempdir().unwrap();
    assert_eq!(unlocked_mode(&k1_file(&dir)), (4, "X(z)".to_string()));
}

#[test]
fn analyze_gives_four_dof_at_both_references() {
    let v = json(&["analyze", "mechanisms/4-ruu.json", "--json"]);
    assert_eq!(v["platform_dof"], 4);
    assert_eq!(v["mobility"], 4);
    let p: Vec<f64> = serde_json::from_value(v["platform_position"].clone()).unwrap();
    assert!(
        (p[0].abs() + p[1].abs() + (p[2] - SQRT_2).abs()) < 1e-12,
        "{p:?}"
    );
    let dir = tempfile::tempdir().unwrap();
    let v = json(&["analyze", &k1_file(&dir), "--json"]);
    assert_eq!(v["platform_dof"], 4);
    assert_eq!(v["mobility"], 4);
    let r: Vec<f64> = serde_json::from_value(v["platform_rotation_vector_rad"].clone()).unwrap();
    // π about (1, 1, 0)/√2: (π/√2, π/√2, 0).
    let h = std::f64::consts::PI / SQRT_2;
    assert!(
        (r[0] - h).abs() + (r[1] - h).abs() + r[2].abs() < 1e-9,
        "{r:?}"
    );
}

#[test]
fn an_input_moves_the_platform_within_k2_and_the_legs_stay_closed() {
    // R1.1 turned 10°: the platform stays parallel to the base (rotation about Z only, K2) and
    // every leg keeps |C_i − B_i| = r = 2 with B_i from paper 004 eq. 2 at the new angles.
    let v = json(&[
        "analyze",
        "mechanisms/4-ruu.json",
        "--inputs",
        "R1.1=10",
        "--json",
    ]);
    assert_eq!(v["platform_dof"], 4);
    let p: Vec<f64> = serde_json::from_value(v["platform_position"].clone()).unwrap();
    let r: Vec<f64> = serde_json::from_value(v["platform_rotation_vector_rad"].clone()).unwrap();
    assert!(r[0].abs() < 1e-9 && r[1].abs() < 1e-9, "{r:?}");
    let theta = [-FRAC_PI_2 + 10f64.to_radians(), 0.0, FRAC_PI_2, 0.0];
    let (c, s) = (r[2].cos(), r[2].sin());
    for (i, th) in theta.iter().enumerate() {
        let e = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]][i];
        let b = [2.0 * e[0] + th.cos(), 2.0 * e[1] + th.sin(), 0.0];
        let cp = [c * e[0] - s * e[1] + p[0], s * e[0] + c * e[1] + p[1], p[2]];
        let d = ((cp[0] - b[0]).powi(2) + (cp[1] - b[1]).powi(2) + (cp[2] - b[2]).powi(2)).sqrt();
        assert!((d - 2.0).abs() < 1e-6, "leg {}: |C − B| = {d}", i + 1);
    }
    // The move is real: the platform left its reference.
    assert!(p[0].abs() + p[1].abs() + r[2].abs() > 1e-2, "{p:?} {r:?}");
}

/// The 4-RUU is over-constrained (4 legs × 2 equations = 8 > 6): `--all-assemblies` solves its
/// ten equations in the eight Study parameters through their square randomisation and keeps
/// the endpoints every equation accepts. A second method on the same equations, the numerical
/// irreducible decomposition of `kinsyn components` (normalised Study parameters, so each pose
/// twice as ±(x, y)), finds twice as many isolated points and twice as many real ones; at the
/// reference inputs the description's reference configuration (the platform at height √2,
/// `mechanisms/4-ruu.json`) is among the real assemblies.
#[test]
fn all_assemblies_of_the_over_constrained_4_ruu_are_the_decompositions_isolated_points() {
    for inputs in [None, Some("R1.1=17,R2.1=-11,R3.1=14,R4.1=6")] {
        let mut args = vec![
            "analyze",
            "mechanisms/4-ruu.json",
            "--all-assemblies",
            "--json",
        ];
        let mut parts = vec!["components", "mechanisms/4-ruu.json", "--json"];
        if let Some(i) = inputs {
            args.extend(["--inputs", i]);
            parts.extend(["--inputs", i]);
        }
        let o = kinsyn(&args);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let a: Value = serde_json::from_str(&stdout(&o)).unwrap();
        assert_eq!(a["formulation"]["equations"], 10);
        assert_eq!(a["formulation"]["randomised"], true);
        assert!(a["spurious"].as_u64().unwrap() > 0, "{inputs:?}");
        assert_eq!(a["singular"], 0, "{inputs:?}");
        assert_eq!(a["certified"], a["nonsingular"], "{inputs:?}");
        let d: Value = serde_json::from_str(&stdout(&kinsyn(&parts))).unwrap();
        let isolated: Vec<&Value> = d["components"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["dimension"] == 0)
            .collect();
        let real_points: u64 = isolated
            .iter()
            .map(|c| c["real_points"].as_u64().unwrap())
            .sum();
        assert_eq!(
            2 * a["nonsingular"].as_u64().unwrap(),
            isolated.len() as u64,
            "{inputs:?}"
        );
        assert_eq!(2 * a["real"].as_u64().unwrap(), real_points, "{inputs:?}");
        if inputs.is_none() {
            let poses: Vec<&str> = a["real_assemblies"]
                .as_array()
                .unwrap()
                .iter()
                .map(|r| r["pose"].as_str().unwrap())
                .collect();
            assert_eq!(poses.len(), 2);
            let reference = a["real_assemblies"]
                .as_array()
                .unwrap()
                .iter()
                .find(|r| r["continued_from_reference"] == true)
                .expect("the reference assembly");
            let z = reference["position"][2].as_f64().unwrap();
            assert!((z - SQRT_2).abs() < 1e-12, "{z}");
        }
    }
}
