//! Global analysis of the committed descriptions through the command line
//! (`analyze --all-assemblies`, `components`): every one that the body tree covers succeeds,
//! its reference configuration is among the assemblies found, and the stacks of paper 002 give
//! the products of their modules' assemblies and operation modes.

use crate::common::{kinsyn, stderr, stdout};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let o = kinsyn(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

/// The descriptions global analysis covers: every committed one but the loops between moving
/// bodies (the split platforms, the configurable 4-RRR's ring, the HEXA).
const COVERED: [&str; 11] = [
    "mechanisms/3-prrr.json",
    "mechanisms/3-rps.json",
    "mechanisms/3-rrr-planar.json",
    "mechanisms/3-rrr-spherical.json",
    "mechanisms/3-ups.json",
    "mechanisms/4-ruu.json",
    "mechanisms/6-ups.json",
    "mechanisms/multibody/3-rps-3-rps-table-1.json",
    "mechanisms/multibody/3-rps-3-rps.json",
    "mechanisms/multibody/3-rps-3-spr-3-rps.json",
    "mechanisms/multibody/3-rps-3-spr.json",
];

#[test]
fn every_covered_description_finds_its_reference_among_its_assemblies() {
    for f in COVERED {
        let v = json(&["analyze", f, "--all-assemblies", "--json"]);
        let real = v["real_assemblies"].as_array().unwrap();
        assert_eq!(
            real.iter()
                .filter(|a| a["continued_from_reference"] == true)
                .count(),
            1,
            "{f}"
        );
        // Every real assembly closes every leg.
        for a in real {
            assert!(
                a["largest_leg_residual"].as_f64().unwrap() < 1e-9,
                "{f}: {a}"
            );
        }
    }
}

#[test]
fn the_3_rps_3_spr_has_sixteen_assemblies_per_module_and_their_products() {
    // Schadlbauer, Walter & Husty 2014 (Mech. Mach. Theory 75, §5): the direct kinematics of
    // the 3-RPS has 16 solutions. The 3-SPR is a 3-RPS with base and platform exchanged: its
    // assemblies are the inverses of a 3-RPS's, 16 too. The stack's assemblies are the pairs:
    // 16 × 16 complex, and the real ones the pairs of real ones.
    let v = json(&[
        "analyze",
        "mechanisms/multibody/3-rps-3-spr.json",
        "--all-assemblies",
        "--json",
    ]);
    let blocks = v["blocks"].as_array().unwrap();
    assert_eq!(blocks.len(), 2);
    assert_eq!(
        (blocks[0]["body"].as_str(), blocks[0]["parent"].as_str()),
        (Some("coupler"), Some("base"))
    );
    assert_eq!(
        (blocks[1]["body"].as_str(), blocks[1]["parent"].as_str()),
        (Some("end-effector"), Some("coupler"))
    );
    for b in blocks {
        assert_eq!(b["nonsingular"], 16);
        assert_eq!(b["certified"], 16);
    }
    let real: Vec<u64> = blocks.iter().map(|b| b["real"].as_u64().unwrap()).collect();
    assert_eq!(v["nonsingular"], 256);
    assert_eq!(v["real"].as_u64().unwrap(), real[0] * real[1]);
    assert_eq!(
        v["real_assemblies"].as_array().unwrap().len() as u64,
        real[0] * real[1]
    );
    // Each stack assembly's end-effector pose is the composition of its blocks': the
    // end-effector's entry among the bodies is the reported pose.
    for a in v["real_assemblies"].as_array().unwrap() {
        let bodies = a["bodies"].as_array().unwrap();
        assert_eq!(bodies.len(), 2);
        assert_eq!(bodies[1]["pose"], a["pose"]);
    }
    // The one continued from the reference puts both bodies at the description's own frames
    // (position, rotation vector in degrees): the composition of the relative solves gives
    // back the absolute poses written in the file.
    let file: Value = serde_json::from_str(
        &std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../mechanisms/multibody/3-rps-3-spr.json"),
        )
        .unwrap(),
    )
    .unwrap();
    let current: Vec<&Value> = v["real_assemblies"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|a| a["continued_from_reference"] == true)
        .collect();
    assert_eq!(current.len(), 1);
    for (k, b) in current[0]["bodies"].as_array().unwrap().iter().enumerate() {
        let pose: Vec<f64> = b["pose"]
            .as_str()
            .unwrap()
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        let body = &file["bodies"][k];
        for i in 0..3 {
            assert!(
                (pose[i] - body["position"][i].as_f64().unwrap()).abs() < 1e-6,
                "{b}"
            );
            assert!(
                (pose[3 + i] - body["orientation"][i].as_f64().unwrap()).abs() < 1e-6,
                "{b}"
            );
        }
    }
}

#[test]
fn the_3_rps_3_spr_with_free_inputs_has_paper_002s_four_operation_modes() {
    // Paper 002 §5, eq. 11: the 3-RPS and the 3-SPR have two operation modes each (x0 = 0,
    // x3 = 0 in the Study parameters of the coupler, y0 = 0, y3 = 0 in those of the
    // end-effector relative to the coupler); the S-PM's four, K1 … K4, are their products, of
    // dimension 6.
    let v = json(&[
        "components",
        "mechanisms/multibody/3-rps-3-spr.json",
        "--free-inputs",
        "--json",
    ]);
    let blocks = v["blocks"].as_array().unwrap();
    assert_eq!(blocks.len(), 2);
    for b in blocks {
        let components = b["components"].as_array().unwrap();
        assert_eq!(components.len(), 2);
        // One component with x0 = 0 at its sample point, the other with x3 = 0.
        let zero = |c: &Value, k: usize| {
            let p = c["sample_point"][k].as_array().unwrap();
            p[0].as_f64().unwrap().hypot(p[1].as_f64().unwrap()) < 1e-8
        };
        assert!(components.iter().all(|c| c["dimension"] == 3));
        assert!(components.iter().any(|c| zero(c, 0)) && components.iter().any(|c| zero(c, 3)));
    }
    let products = v["components"].as_array().unwrap();
    assert_eq!(products.len(), 4);
    let mut factors: Vec<&Value> = products.iter().map(|c| &c["factors"]).collect();
    factors.dedup();
    assert_eq!(factors.len(), 4);
    assert!(products.iter().all(|c| c["dimension"] == 6));
}

/// The number after `mobility ` in `kinsyn analyze FILE`'s text: the local analysis's dof of
/// the mechanism (the rank of its loop-closure Jacobian at the reference configuration).
fn local_mobility(file: &str) -> u64 {
    let o = kinsyn(&["analyze", file]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    let at = text.find("mobility ").expect("a mobility line") + "mobility ".len();
    text[at..]
        .split(|c: char| !c.is_ascii_digit())
        .next()
        .and_then(|n| n.parse().ok())
        .expect("a number")
}

#[test]
fn the_split_platforms_have_the_modes_and_self_motions_of_the_local_analysis() {
    // The 3-RPS and 3-UPS with their platforms cut in two bodies joined by a revolute: one
    // block, the second body merged into the first through the revolute's unknown angle. The
    // local analysis (screw theory, a method that shares nothing with the polynomials) gives
    // the mechanism's mobility with its inputs free, and 1 dof with them held: the global one
    // must find one component of each dimension, with real points.
    for f in [
        "mechanisms/multibody/3-rps-split.json",
        "mechanisms/multibody/3-ups-split.json",
    ] {
        let mobility = local_mobility(f);
        let v = json(&["components", f, "--free-inputs", "--json"]);
        let modes = v["components"].as_array().unwrap();
        assert_eq!(modes.len(), 1, "{f}");
        assert_eq!(modes[0]["dimension"].as_u64(), Some(mobility), "{f}");
        assert!(modes[0]["real_points"].as_u64().unwrap() > 0, "{f}");
        // With the inputs held: a self-motion of 1 dof through real configurations (by
        // regeneration: seconds; by dimension the witness supersets take minutes).
        let v = json(&["components", f, "--method", "regeneration", "--json"]);
        let real_curves: Vec<&Value> = v["components"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["dimension"] == 1 && c["real_points"].as_u64().unwrap() > 0)
            .collect();
        assert_eq!(real_curves.len(), 1, "{f}: {v}");
        assert_eq!(real_curves[0]["trace_test_passed"], true, "{f}");
        // `--all-assemblies` names it rather than listing no assembly.
        let o = kinsyn(&["analyze", f, "--all-assemblies"]);
        assert_eq!(o.status.code(), Some(2), "{f}");
        assert!(
            stderr(&o).contains("a self-motion rather than isolated assemblies"),
            "{f}"
        );
    }
}

#[test]
fn the_configurable_4_rrr_with_free_inputs_has_the_rhombus_three_modes() {
    // Paper 003's platform is a rhombus: four links of 120 mm hinged in a ring. An equilateral
    // four-bar moves in three ways — as a parallelogram, and folded onto either diagonal
    // (C1 = C3 or C2 = C4) — so with the cranks free (passive RRR legs constrain nothing in
    // the plane) the mechanism has three operation modes, each of the local analysis's
    // mobility (the rhombus's 1 dof and the plane's 3).
    let f = "mechanisms/4-rrr-configurable.json";
    let mobility = local_mobility(f);
    let v = json(&["components", f, "--free-inputs", "--json"]);
    let modes = v["components"].as_array().unwrap();
    assert_eq!(modes.len(), 3, "{v}");
    for c in modes {
        assert_eq!(c["dimension"].as_u64(), Some(mobility));
        assert!(c["real_points"].as_u64().unwrap() > 0);
    }
}

#[test]
#[ignore = "exhaustive: the distal block's quadrics of revolution, about 15 s"]
fn the_3_rps_3_rps_with_free_inputs_has_the_mobility_of_the_local_analysis() {
    // Its distal RPS legs have their sliders off the planes normal to their revolutes, so each
    // keeps its S centre on a quadric of revolution: one block of three such legs, whose
    // operation mode's dimension, added to the proximal block's, must be the mobility that
    // the local analysis (screw theory) gives.
    let f = "mechanisms/multibody/3-rps-3-rps.json";
    let mobility = local_mobility(f);
    let v = json(&["components", f, "--free-inputs", "--json"]);
    let products = v["components"].as_array().unwrap();
    assert!(!products.is_empty());
    assert!(
        products
            .iter()
            .any(|c| c["dimension"].as_u64() == Some(mobility))
    );
    assert!(
        products
            .iter()
            .all(|c| c["dimension"].as_u64() <= Some(mobility))
    );
}

/// Each component's `mechanism` entry: the body, its dof, the inputs that move.
fn placed(c: &Value) -> (String, u64, Vec<String>) {
    let m = &c["mechanism"];
    assert!(m["error"].is_null(), "placed: {m}");
    let labels = |v: &Value| -> Vec<String> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|s| s.as_str().unwrap().to_string())
            .collect()
    };
    (
        m["body"].as_str().unwrap().to_string(),
        m["dof"].as_u64().unwrap(),
        labels(&m["moving_inputs"]),
    )
}

#[test]
fn on_the_3_rps_modes_every_free_input_moves() {
    // At fixed inputs the 3-RPS has isolated assemblies (16, Schadlbauer et al. 2014), so the
    // map from a component to its inputs is finite-to-one: a component of dimension k moves k
    // independent free inputs. With all three free (modes of dimension 3) every leg length
    // moves; with P1.2 alone free (curves, the others held) P1.2 moves.
    let v = json(&[
        "components",
        "mechanisms/3-rps.json",
        "--free-inputs",
        "--json",
    ]);
    for c in v["components"].as_array().unwrap() {
        let (body, dof, moving) = placed(c);
        assert_eq!((body.as_str(), dof), ("platform", 3));
        assert_eq!(moving, ["P1.2", "P2.2", "P3.2"]);
    }
    let v = json(&[
        "components",
        "mechanisms/3-rps.json",
        "--free",
        "P1.2",
        "--inputs",
        "P2.2=0.1,P3.2=-0.1",
        "--json",
    ]);
    assert_eq!(v["free_inputs"], serde_json::json!(["P1.2"]));
    let components = v["components"].as_array().unwrap();
    assert!(!components.is_empty());
    for c in components {
        assert_eq!(c["dimension"], 1);
        let (_, dof, moving) = placed(c);
        assert_eq!((dof, moving), (1, vec!["P1.2".to_string()]));
        assert_eq!(
            c["mechanism"]["held_inputs"],
            serde_json::json!(["P2.2", "P3.2"])
        );
    }
}

#[test]
fn a_stacks_coupler_moves_with_its_own_module_only() {
    // The 3-RPS-3-SPR's coupler hangs from the ground by the lower module alone: on each
    // product of paper 002's modes it has the lower block's 3 dof, the end-effector 6 (K1 … K4,
    // eq. 11), and all six inputs move.
    let v = json(&[
        "components",
        "mechanisms/multibody/3-rps-3-spr.json",
        "--free-inputs",
        "--body",
        "coupler",
        "--json",
    ]);
    let products = v["components"].as_array().unwrap();
    assert_eq!(products.len(), 4);
    for c in products {
        let (body, dof, moving) = placed(c);
        assert_eq!((body.as_str(), dof), ("coupler", 3));
        assert_eq!(moving.len(), 6, "{moving:?}");
    }
}
