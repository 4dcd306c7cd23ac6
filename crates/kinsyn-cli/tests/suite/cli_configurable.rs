//! `kinsyn modes` and `kinsyn analyze` on paper 003's configurable 4-RRR
//! (`mechanisms/4-rrr-configurable.json`); the library side is in
//! `crates/kinsyn-papers/tests/suite/configurable_mechanism.rs`.

use crate::common;

use common::{kinsyn, stderr, stdout};

const FILE: &str = "mechanisms/4-rrr-configurable.json";

#[test]
fn analyze_reports_four_dof_and_three_per_link() {
    // Planar Grübler–Kutzbach: 13 bodies (ground, m1..m4, an arm and a forearm per leg), 16
    // revolutes (3 per leg, 1 per corner): 3·12 − 2·16 = 4 (paper 003 §2). Each link keeps the
    // 3 dof of the plane; with m1 held, the redundant fourth input still turns (1 rate).
    let o = kinsyn(&["analyze", FILE, "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["mobility"], 4);
    assert_eq!(v["end_effector"], "m1");
    for k in 0..4 {
        assert_eq!(v["bodies"][k]["name"], format!("m{}", k + 1));
        assert_eq!(v["bodies"][k]["dof"], 3);
    }
    assert_eq!(v["inputs_with_end_effector_held"]["here"], 1);
    assert!(v["singularities"].as_array().unwrap().is_empty());
    // e1 = C1 (m1's point) and, with --body m3, e2 = C3 = Table 2's (−5.947, −31.133) mm.
    let o = kinsyn(&["analyze", FILE, "--body", "m3", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let p = &v["point"];
    assert!((p[0].as_f64().unwrap() + 5.947).abs() < 2e-3, "{p}");
    assert!((p[1].as_f64().unwrap() + 31.133).abs() < 2e-3, "{p}");
}

#[test]
fn modes_gives_the_planar_group_for_every_link() {
    // Every axis along z: each link's twists are (0, 0, ω; v_x, v_y, 0), the group G(xy).
    for body in ["m1", "m2", "m3", "m4"] {
        let o = kinsyn(&["modes", FILE, "--body", body, "--lock", "-"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let out = stdout(&o);
        assert!(out.contains("G(xy)"), "{body}: {out}");
    }
}

#[test]
fn relative_motion_of_opposite_links_is_a_translation_and_of_adjacent_ones_a_rotation() {
    // Opposite sides of the rhombus stay parallel (a parallelogram): m3 has m1's angular
    // velocity (§2.1 option 2, eq. 27), one relative dof, every relative twist a translation;
    // its direction (normal to m2) turns, so the finite motion is 1T0R, not a group.
    let o = kinsyn(&["analyze", FILE, "--body", "m3", "--relative-to", "m1"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains(
            "motion of \"m3\" relative to \"m1\": 1 dof; every relative twist is a translation"
        ),
        "{out}"
    );
    let o = kinsyn(&[
        "analyze",
        FILE,
        "--body",
        "m3",
        "--relative-to",
        "m1",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let r = &v["relative_motion"];
    assert_eq!(
        (r["dof"].as_u64(), r["rotations"].as_u64()),
        (Some(1), Some(0))
    );
    let t: Vec<f64> = r["twists_at_point"][0]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    // v of C3 normal to C2C3 (C3 turns about C2 as seen from m1), with Table 2's corners.
    let c2c3 = [-5.947 - 14.889, -31.133 - 87.042];
    let cos = (t[0] * c2c3[0] + t[1] * c2c3[1]) / (t[0].hypot(t[1]) * c2c3[0].hypot(c2c3[1]));
    assert!(cos.abs() < 1e-4, "{cos}");
    let o = kinsyn(&[
        "modes",
        FILE,
        "--body",
        "m3",
        "--relative-to",
        "m1",
        "--lock",
        "-",
    ]);
    let out = stdout(&o);
    assert!(out.contains("1T0R"), "{out}");
    // Adjacent links share the revolute at C2: relative to m1, m2 turns about it, R(z).
    let o = kinsyn(&[
        "modes",
        FILE,
        "--body",
        "m2",
        "--relative-to",
        "m1",
        "--lock",
        "-",
    ]);
    let out = stdout(&o);
    assert!(out.contains("R(z)"), "{out}");
    assert!(
        out.contains("axis through [14.8903, 87.0443, 0] mm"),
        "{out}"
    );
    // Every input locked: nothing moves relative to anything.
    let o = kinsyn(&[
        "modes",
        FILE,
        "--body",
        "m3",
        "--relative-to",
        "m1",
        "--lock",
        "R1.1,R2.1,R3.1,R4.1",
    ]);
    assert!(stdout(&o).contains("E "), "{}", stdout(&o));
}

#[test]
fn relative_to_refuses_unknown_bodies_and_the_body_itself_in_one_line() {
    for (args, expected) in [
        (
            vec!["analyze", FILE, "--relative-to", "m9"],
            "--relative-to \"m9\": \"m9\" is not a moving body",
        ),
        (
            vec!["modes", FILE, "--relative-to", "m1"],
            "--relative-to \"m1\": \"m1\" is the body analysed",
        ),
    ] {
        let o = kinsyn(&args);
        assert_eq!(o.status.code(), Some(2));
        let err = stderr(&o);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(expected), "{err}");
    }
}
