//! Mechanisms with several moving bodies: the description format
//! `kinsyn-manipulator/2`, its reading of `/1` files, and the mobility and dof of stacked
//! modules and split platforms against hand derivations (Grübler–Kutzbach and the constraints
//! each leg imposes). docs/mechanism-format.md, "Format /2".

use kinsyn::manipulator::Manipulator;
use kinsyn::manipulator::file::{AnyDescription, Description, MultibodyDescription};
use kinsyn::mechanism::SampleSettings;

fn read(path: &str) -> String {
    std::fs::read_to_string(path).unwrap()
}

fn load(path: &str) -> Manipulator {
    Manipulator::from_json(&read(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn two_three_rps_modules_in_series_have_six_dof() {
    // Paper 002 §2, with an RPS distal module: base → coupler by three RPS legs, coupler →
    // end-effector by three more. Grübler–Kutzbach: 15 bodies (base, coupler, end-effector and
    // two links per leg), 18 joints; each RPS leg's R, P and S remove 5, 5 and 3 freedoms, so
    // M = 6·(15 − 1) − 6·13 = 6. Each module is a 3-RPS: 3 dof, 2R1T (one constraint force
    // per leg, paper 000 §5.2), so the coupler has 3 dof. At a generic configuration (the
    // distal module turned 60° about z and the end-effector tilted, so the two modules'
    // zero-torsion axes differ, paper 002 §4) the end-effector has all 6.
    let m = load("../../mechanisms/multibody/3-rps-3-rps.json");
    assert_eq!(m.bodies().len(), 2);
    assert_eq!(m.bodies()[m.end_effector()].name, "end-effector");
    assert!(!m.has_leg_wrench_jacobians());
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!(a.mobility, 6);
    let coupler = m.body_named("coupler").unwrap();
    let ee = m.body_named("end-effector").unwrap();
    assert_eq!(a.body_dof[coupler], 3);
    assert_eq!(a.body_dof[ee], 6);
    assert_eq!(a.platform_dof, 6);
    // Six sliders, six end-effector dof: with every input held the end-effector is fixed, and
    // with the end-effector held no input moves (mobility 6 = end-effector dof).
    assert_eq!(6 - a.jd_rank.rank, 0);
    assert_eq!(a.inputs_with_end_effector_held, 0);
    assert!(a.singularities.is_empty(), "{:?}", a.singularities);
    // J_D, J_I of paper 000 are not defined (legs 4–6 do not start on the ground): no rows.
    assert!(!a.leg_wrench_jacobians);
    assert!(a.jacobians.rows.is_empty());
    assert_eq!(a.jacobians.jd.nrows(), 0);
    // The coupler analysed as the end-effector: the lower module alone, 3 dof, and three
    // sliders of the upper module move with it held.
    let c = m.with_end_effector("coupler").unwrap();
    let ac = c
        .analyse(&c.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!(ac.platform_dof, 3);
    assert_eq!(ac.inputs_with_end_effector_held, 3);
}

#[test]
fn a_three_rps_with_a_split_platform_has_four_dof() {
    // The platform cut into A (legs 1, 2) and B (leg 3), joined by a revolute. A: 6 − 2 = 4
    // dof (each RPS leg imposes one constraint force, paper 000 §5.2); B = A's 4 + 1 (the R)
    // − 1 (leg 3's constraint) = 4. Grübler: 9 bodies (base, A, B, two links per leg),
    // 6·8 − (3·13 + 5) = 4.
    let m = load("../../mechanisms/multibody/3-rps-split.json");
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!(a.mobility, 4);
    assert_eq!(a.body_dof, [4, 4]);
    assert_eq!(a.platform_dof, 4);
    // Three inputs for four dof: with every input held, B keeps 4 − 3 = 1 dof everywhere, an
    // architecture feature reported as such.
    assert_eq!(6 - a.generic.jd, 1);
    assert!(
        a.singularities
            .iter()
            .any(|s| s.detail().contains("never fix the end-effector"))
    );
}

#[test]
fn a_three_ups_with_a_split_platform_has_seven_dof() {
    // UPS legs impose no constraint (U 2 + P 1 + S 3 = 6 freedoms): A has 6 dof, B = 6 + 1
    // (the R) − 0 = 7 joint freedoms of which 6 are its pose. Grübler: 6·8 − (3·(4 + 5 + 3) +
    // 5) = 7. Both bodies have 6 dof, one motion is internal (A turning about the R with B
    // held).
    let m = load("../../mechanisms/multibody/3-ups-split.json");
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!(a.mobility, 7);
    assert_eq!(a.body_dof, [6, 6]);
}

/// What must be identical between a `/1` file and its `/2` translation.
fn summary(
    m: &Manipulator,
) -> (
    usize,
    usize,
    usize,
    usize,
    Vec<usize>,
    String,
    String,
    String,
) {
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    let mode = m.mode(&[0], &SampleSettings::default());
    (
        a.mobility,
        a.platform_dof,
        a.jd_rank.rank,
        a.constraint_rank.rank,
        a.leg_ranks.iter().map(|r| r.rank).collect(),
        format!("{}", a.jacobians.jd),
        format!("{}", a.jacobians.ji),
        mode.pattern_text(),
    )
}

#[test]
fn a_v1_file_and_its_v2_translation_analyse_alike() {
    // The /2 form of a /1 file names the ground `ground` and the platform `platform`, every leg
    // from one to the other with the same points: the same mechanism, so the same numbers.
    for name in ["3-ups", "3-rps", "6-ups", "3-prrr", "3-rrr-planar"] {
        let path = format!("../../mechanisms/{name}.json");
        let v1 = Description::from_json(&read(&path)).unwrap();
        let v2 = v1.to_multibody();
        let text = v2.to_json();
        assert!(
            text.contains("\"format\": \"kinsyn-manipulator/2\""),
            "{text}"
        );
        let read_back = MultibodyDescription::from_json(&text).unwrap();
        assert_eq!(read_back, v2, "{path}");
        assert!(matches!(
            AnyDescription::from_json(&text).unwrap(),
            AnyDescription::V2(_)
        ));
        let a = load(&path);
        let b = Manipulator::from_json(&text).unwrap();
        assert!(b.has_leg_wrench_jacobians());
        assert_eq!(summary(&a), summary(&b), "{path}");
    }
}

/// A small `/2` description (the split 3-RPS) with `edit` applied to its JSON.
fn edited(edit: impl FnOnce(&mut serde_json::Value)) -> String {
    let mut v: serde_json::Value =
        serde_json::from_str(&read("../../mechanisms/multibody/3-rps-split.json")).unwrap();
    edit(&mut v);
    serde_json::to_string_pretty(&v).unwrap()
}

#[test]
fn bad_v2_descriptions_name_the_field() {
    let cases: Vec<(&str, String, &str, &str)> = vec![
        (
            "unknown body",
            edited(|v| v["legs"][3]["to"] = "C".into()),
            "legs[3].to",
            "\"C\" is not a body (bodies: base, A, B)",
        ),
        (
            "a leg from a body to itself",
            edited(|v| v["legs"][3]["to"] = "A".into()),
            "legs[3].to",
            "a leg joins two distinct bodies",
        ),
        (
            "duplicate body names",
            edited(|v| v["bodies"][1]["name"] = "A".into()),
            "bodies[1].name",
            "\"A\" names bodies[0] too",
        ),
        (
            "a body named like the ground",
            edited(|v| v["bodies"][0]["name"] = "base".into()),
            "bodies[0].name",
            "is the ground's name",
        ),
        (
            "a body not joined to the ground",
            edited(|v| {
                v["bodies"]
                    .as_array_mut()
                    .unwrap()
                    .push(serde_json::json!({"name": "C", "position": [0, 0, 2]}));
            }),
            "bodies[2]",
            "\"C\" is joined to the ground \"base\" by no chain of legs",
        ),
        (
            "an unknown end-effector",
            edited(|v| v["end_effector"] = "Z".into()),
            "end_effector",
            "\"Z\" is not a moving body (moving bodies: A, B)",
        ),
        (
            "no end-effector among several bodies",
            edited(|v| {
                v.as_object_mut().unwrap().remove("end_effector");
            }),
            "end_effector",
            "missing: name the end-effector among the 2 moving bodies (A, B)",
        ),
        (
            "a one-joint leg whose points differ",
            edited(|v| v["legs"][3]["last"] = serde_json::json!([0.1, 0, 0])),
            "legs[3].last",
            "the leg R has one joint, so its first point",
        ),
        (
            "an unknown field",
            edited(|v| v["legs"][0]["base"] = serde_json::json!([1, 0, 0])),
            "legs[0].base",
            "unknown field `base`",
        ),
        (
            "a /2 tag on /1 fields",
            read("../../mechanisms/3-rps.json").replace("manipulator/1", "manipulator/2"),
            "file",
            "expected \"kinsyn-manipulator/1\" for a description with a \"platform\" and no \"bodies\"",
        ),
        (
            "an unknown format",
            edited(|v| v["format"] = "kinsyn-manipulator/3".into()),
            "file",
            "expected \"kinsyn-manipulator/1\" or \"kinsyn-manipulator/2\"",
        ),
    ];
    for (what, text, field, needle) in cases {
        let e = Manipulator::from_json(&text)
            .err()
            .unwrap_or_else(|| panic!("{what}: accepted"));
        let line = e.to_string();
        assert!(line.starts_with(&format!("{field}: ")), "{what}: {line}");
        assert!(line.contains(needle), "{what}: {needle:?} not in {line}");
        assert_eq!(line.lines().count(), 1, "{what}: {line}");
    }
}
