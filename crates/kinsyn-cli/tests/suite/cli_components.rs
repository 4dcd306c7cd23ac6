//! `kinsyn components`: a Bertini system with known components (the twisted cubic and a line,
//! Sommese & Wampler 2005 ch. 13), paper 004's 4-RUU at generic and at equal inputs (§4, §5.2),
//! and one-line refusals.

use crate::common;

use common::{assert_refused, kinsyn, stderr, stdout};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let o = kinsyn(args);
    assert_eq!(o.status.code(), Some(0), "kinsyn {args:?}: {}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

fn signature(v: &Value) -> Vec<(u64, u64)> {
    let mut s: Vec<(u64, u64)> = v["components"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["dimension"].as_u64().unwrap(),
                c["degree"].as_u64().unwrap(),
            )
        })
        .collect();
    s.sort_unstable();
    s
}

#[test]
fn the_twisted_cubic_and_a_line_by_both_methods() {
    // Degrees by hand: a + b t + c t² + d t³ = 0 has three roots (the cubic), a plane meets
    // the line once.
    for method in ["regeneration", "by-dimension"] {
        let v = json(&[
            "components",
            "examples/systems/twisted-cubic-and-line.bertini",
            "--method",
            method,
            "--json",
        ]);
        assert_eq!(signature(&v), vec![(1, 1), (1, 3)], "{method}");
        assert!(
            v["components"]
                .as_array()
                .unwrap()
                .iter()
                .all(|c| c["trace_test_passed"] == true)
        );
    }
    let o = kinsyn(&[
        "components",
        "examples/systems/twisted-cubic-and-line.bertini",
    ]);
    assert!(
        stdout(&o).contains("dimension 1, degree 3"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn the_four_ruu_at_generic_inputs_has_32_isolated_solutions_in_schoenflies_modes() {
    // Absolute crank angles 2 atan(0.3, −0.7, 1.1, 0.45) minus the file's reference
    // (−90°, 0°, 90°, 0°): 32 isolated solutions (Singular's vdim, tests/suite/ruu_self_motions.rs);
    // every real one released into a 4-dof X(z) (paper 004 §4.1.1–4.1.2).
    let theta = [0.3f64, -0.7, 1.1, 0.45].map(|t| 2.0 * t.atan().to_degrees());
    let reference = [-90.0, 0.0, 90.0, 0.0];
    let inputs: Vec<String> = (0..4)
        .map(|i| format!("R{}.1={}", i + 1, theta[i] - reference[i]))
        .collect();
    let v = json(&[
        "components",
        "mechanisms/4-ruu.json",
        "--inputs",
        &inputs.join(","),
        "--json",
    ]);
    assert_eq!(signature(&v), vec![(0, 1); 32]);
    let released: Vec<&Value> = v["components"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|c| c["released"].as_object().map(|_| &c["released"]))
        .collect();
    assert!(!released.is_empty());
    for r in released {
        assert_eq!(r["dof"], 4);
        assert_eq!(r["pattern"], "X(z)", "{r}");
    }
}

#[test]
fn equal_crank_angles_give_a_self_motion() {
    // Paper 004 §5.2, Fig. 9: all four absolute crank angles 0 (inputs 90°, 0°, −90°, 0°).
    let o = kinsyn(&[
        "components",
        "mechanisms/4-ruu.json",
        "--inputs",
        "R1.1=90,R2.1=0,R3.1=-90,R4.1=0",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(
        text.contains("dimension 1, degree 8: self-motion, 1 dof"),
        "{text}"
    );
}

#[test]
fn bad_requests_are_refused_in_one_line() {
    let o = kinsyn(&[
        "components",
        "examples/systems/twisted-cubic-and-line.bertini",
        "--inputs",
        "R1.1=3",
    ]);
    assert_refused(
        &o,
        "--inputs with a polynomial system",
        &["apply to manipulator files"],
    );
    let o = kinsyn(&[
        "components",
        "mechanisms/4-ruu.json",
        "--inputs",
        "R1.1=3",
        "--free-inputs",
    ]);
    assert_refused(&o, "--inputs with --free-inputs", &["exclude each other"]);
    let o = kinsyn(&["components", "mechanisms/4-ruu.json", "--inputs", "R9.1=3"]);
    assert_refused(&o, "an unknown input", &["R9.1"]);
    for (args, what, words) in [
        (
            &["--free", "R1.1"][..],
            "--free with a polynomial system",
            &["apply to manipulator files"][..],
        ),
        (
            &["--body", "B"][..],
            "--body with a polynomial system",
            &["apply to manipulator files"][..],
        ),
    ] {
        let mut all = vec![
            "components",
            "examples/systems/twisted-cubic-and-line.bertini",
        ];
        all.extend_from_slice(args);
        assert_refused(&kinsyn(&all), what, words);
    }
    for (args, what, words) in [
        (
            &["--free", ""][..],
            "an empty --free",
            &["name at least one input"][..],
        ),
        (
            &["--free", "R1.1\u{1b}[31m"][..],
            "an unknown --free label",
            &["is not an actuator"][..],
        ),
        (
            &["--free", "R1.1", "--inputs", "R1.1=3"][..],
            "an input both free and given",
            &["is given a value by --inputs too"][..],
        ),
        (
            &["--free", "R1.1", "--free-inputs"][..],
            "--free with --free-inputs",
            &["cannot be used with"][..],
        ),
        (
            &["--body", "nothing"][..],
            "an unknown --body",
            &["is not a moving body"][..],
        ),
    ] {
        let mut all = vec!["components", "mechanisms/4-ruu.json"];
        all.extend_from_slice(args);
        assert_refused(&kinsyn(&all), what, words);
    }
    let o = kinsyn(&["components", "mechanisms/6-ruu-hexa.json"]);
    assert_refused(
        &o,
        "a mechanism without a polynomial form",
        &["6-ruu-hexa.json"],
    );
}
