//! `kinsyn modes` and `kinsyn analyze` on paper 001's HEXA (`mechanisms/6-ruu-hexa.json`),
//! and `modes --legs` for its sub-mechanisms; the library side is in
//! `crates/kinsyn-papers/tests/suite/hexa_mechanism.rs`.

use crate::common;

use common::{assert_refused, kinsyn, stderr, stdout};

const FILE: &str = "mechanisms/6-ruu-hexa.json";

#[test]
fn analyze_gives_mobility_six_and_both_end_effectors_four_dof() {
    // Mobility by hand: χ's seven coordinates (eq. 10a) less eq. 7a's one, no idle freedom: 6.
    let o = kinsyn(&["analyze", FILE, "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["mobility"], 6);
    assert_eq!(v["end_effector"], "ee1");
    let dof = |name: &str| {
        v["bodies"]
            .as_array()
            .unwrap()
            .iter()
            .find(|b| b["name"] == name)
            .unwrap()["dof"]
            .clone()
    };
    // Eqs. 2–3: X(k) for both end-effectors; the sub-platforms translate (T3).
    assert_eq!(
        (dof("ee1"), dof("ee2"), dof("sub16"), dof("sub23")),
        (4.into(), 4.into(), 3.into(), 3.into())
    );
    assert!(stderr(&o).is_empty(), "no leg warning: {}", stderr(&o));
}

#[test]
fn modes_shows_schoenflies_motion_for_both_end_effectors() {
    for body in ["ee1", "ee2"] {
        let o = kinsyn(&["modes", FILE, "--body", body, "--lock", "-"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let out = stdout(&o);
        assert!(out.contains("dof: 4\npattern: X(z)"), "{body}: {out}");
    }
    // Every input locked at the generic reference: end-effector 1 is fixed.
    let o = kinsyn(&["modes", FILE, "--lock", "R1.1,R5.1,R9.1,R13.1,R17.1,R21.1"]);
    assert!(stdout(&o).contains("dof: 0"), "{}", stdout(&o));
    // One input locked: 2T1R each (a Schönflies robot less one input), X(z) with none.
    let o = kinsyn(&["modes", FILE, "--max-locks", "1"]);
    assert!(
        stdout(&o).contains("X(z)     group     3 subsets  lock -"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn a_limbs_legs_give_its_bond() {
    // Eq. 1: legs 1–4 (limb 1) move sub16, the body after R(C_1), in X(u_1) = X(x).
    let o = kinsyn(&[
        "modes", FILE, "--legs", "1-4", "--body", "sub16", "--lock", "-",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("1 inputs (R1.1)"), "{out}");
    assert!(
        out.contains("moving bodies: upper1, lower1, sub16 (end-effector)"),
        "{out}"
    );
    assert!(out.contains("dof: 4\npattern: X(x)"), "{out}");
    // The lower bar, before R(C_1): R(A_1) R(B_1) T(n_1), three dof, one rotation.
    let o = kinsyn(&[
        "modes", FILE, "--legs", "1-4", "--body", "lower1", "--lock", "-",
    ]);
    assert!(
        stdout(&o).contains("dof: 3\npattern: 2T1R"),
        "{}",
        stdout(&o)
    );
    // Eq. 2: limbs 1 and 6 with sub16 → ee1: X(k).
    let o = kinsyn(&[
        "modes",
        FILE,
        "--legs",
        "1-4,21-25",
        "--body",
        "ee1",
        "--lock",
        "-",
    ]);
    assert!(
        stdout(&o).contains("dof: 4\npattern: X(z)"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn bad_leg_lists_are_refused_in_one_line() {
    for (legs, body, needle) in [
        (
            "1-40",
            None,
            "leg 40 does not exist: the mechanism has legs 1 to 33",
        ),
        ("0", None, "leg 0 does not exist"),
        ("4-1", None, "the range 4-1 runs backwards"),
        (
            "a-b",
            None,
            "\"a-b\" is not a leg number or a range of them",
        ),
        ("", None, "no leg listed"),
        (
            "1-4",
            None,
            "the end-effector \"ee1\" is not joined to the ground \"base\" by the legs kept",
        ),
        (
            "1-4",
            Some("ee2"),
            "the body \"ee2\" is not joined to the ground \"base\" by the legs kept (bodies kept: upper1, lower1, sub16)",
        ),
    ] {
        let mut args = vec!["modes", FILE, "--legs", legs, "--lock", "-"];
        if let Some(b) = body {
            args.extend(["--body", b]);
        }
        let o = kinsyn(&args);
        assert_refused(&o, legs, &[&format!("--legs {legs:?}: "), needle]);
    }
}
