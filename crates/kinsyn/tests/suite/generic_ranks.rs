//! Generic ranks are seed-stable: the singularities `Manipulator::analyse` reports at a
//! description's reference configuration do not depend on the seed of the random assemblies
//! that decide the generic ranks (`GenericRanks`: assemblies reached by continuation on the
//! configuration's component, each rank the largest over them, a freedom the difference of two
//! such ranks).
//!
//! The default test runs every committed description at a few seeds, among them the three
//! besides the default (2026) at which the HEXA's old generic ranks reported an inverse
//! singularity (an assembly on another component, a parallelogram closed as an
//! anti-parallelogram); `every_description_at_40_seeds` (ignored, run by the exhaustive CI step)
//! runs seeds 0 to 39.

use kinsyn::manipulator::Manipulator;
use kinsyn::mechanism::SampleSettings;

/// Every committed description: `mechanisms/*.json` and `mechanisms/multibody/*.json`.
fn descriptions() -> Vec<(String, Manipulator)> {
    let mut out = Vec::new();
    for dir in ["../../mechanisms", "../../mechanisms/multibody"] {
        let mut paths: Vec<_> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        paths.sort();
        for p in paths {
            let text = std::fs::read_to_string(&p).unwrap();
            let m =
                Manipulator::from_json(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            out.push((p.display().to_string(), m));
        }
    }
    assert!(out.len() >= 14, "{} descriptions", out.len());
    out
}

/// The singularities at the reference, every input free, as `kind: detail` lines, with the
/// generic ranks they were judged against (the count of assemblies below them aside).
fn report(m: &Manipulator, seed: u64) -> (Vec<String>, String) {
    let settings = SampleSettings {
        seed,
        ..SampleSettings::default()
    };
    let a = m.analyse(&m.reference(), &[], &settings).unwrap();
    let lines = a
        .singularities
        .iter()
        .map(|s| format!("{:?}: {}", s.kind, s.detail()))
        .collect();
    let g = &a.generic;
    (
        lines,
        format!(
            "jd {} constraint {} legs {:?} inputs held {}",
            g.jd, g.constraint, g.legs, g.inputs_with_end_effector_held
        ),
    )
}

/// Each (description, seed) pair is independent: they run on every core.
fn check(seeds: &[u64]) {
    use rayon::prelude::*;
    descriptions().par_iter().for_each(|(path, m)| {
        let first = report(m, SampleSettings::default().seed);
        seeds.par_iter().for_each(|&seed| {
            assert_eq!(report(m, seed), first, "{path}, seed {seed}");
        });
    });
}

#[test]
fn every_description_has_the_same_singularities_at_several_seeds() {
    // 0, 1 and the HEXA's three outlier seeds of the old definition besides the default.
    check(&[0, 1, 28, 30, 34]);
}

#[test]
#[ignore = "exhaustive: 40 seeds × every committed description (about a minute)"]
fn every_description_at_40_seeds() {
    check(&(0..40).collect::<Vec<_>>());
}

#[test]
fn the_hexas_reference_is_not_singular() {
    // The HEXA at its reference (P1 = (30, −20, −600) mm, φ1 = 10°, φ2 = −5°; docs/hexa.md) is
    // regular: end-effector 1 (the description's) has 4 dof, and with it held inputs 4 and 5
    // keep two independent rates, end-effector 2's two freedoms (the four-bar and φ2; paper
    // 001 eqs. 7–8) mapped through its 2 × 2 Jacobian, which is regular there (ξ4 = 0.514,
    // ξ5 = 0.205, `kinsyn_papers::hexa`). So no inverse singularity, whatever the seed.
    let text = std::fs::read_to_string("../../mechanisms/6-ruu-hexa.json").unwrap();
    let m = Manipulator::from_json(&text).unwrap();
    let a = m
        .analyse(&m.reference(), &[], &SampleSettings::default())
        .unwrap();
    assert_eq!(a.inputs_with_end_effector_held, 2);
    assert_eq!(a.generic.inputs_with_end_effector_held, 2);
    assert!(a.singularities.is_empty(), "{:?}", a.singularities);
}
