//! The cost model of modes (`Manipulator::modes_cost`, docs/limits.md "kinsyn modes"): the
//! estimate made before sampling, in loop closures, against the closures the sampling counts.

use kinsyn::manipulator::build::{BuildSpec, build};
use kinsyn::manipulator::{Manipulator, ModesCost};
use kinsyn::mechanism::SampleSettings;

fn load(name: &str) -> Manipulator {
    let text = std::fs::read_to_string(format!("../../mechanisms/{name}.json")).unwrap();
    Manipulator::from_json(&text).unwrap()
}

/// A six-legged UPS whose U's first axis and P are the inputs (12 of them), the platform
/// points turned by `twist` degrees, alternately when `alternate` (`kinsyn build --legs 6
/// --chain 'U(!,-)P!S'`).
fn six_ups(twist: f64, alternate: bool) -> Manipulator {
    let spec = BuildSpec {
        legs: 6,
        chain: "U(!,-)P!S".into(),
        twist,
        alternate,
        ..BuildSpec::default()
    };
    Manipulator::new(&build(&spec).unwrap()).unwrap()
}

/// The closures the sampling ran for each of `subsets` (every one sampled).
fn sampled_closures(
    m: &Manipulator,
    subsets: &[Vec<usize>],
    settings: &SampleSettings,
) -> Vec<usize> {
    let modes = m.modes_from(&m.reference(), subsets, settings, &|| {});
    modes
        .modes
        .iter()
        .map(|mode| {
            mode.closures
                .unwrap_or_else(|| panic!("{}: {:?}", mode.lock_text, mode.error))
        })
        .collect()
}

#[test]
fn a_motion_costs_one_closure_and_steps_per_sample_from_a_regular_start() {
    // The 3-UPS at its reference: six independent inputs of a platform with six dof, so k < 6
    // locks leave 6 − k dof at a regular start and only all six leave it rigid. A motion is the
    // start's closure and `steps` (3) per sample: 1 + 3 samples × 3 = 10 closures (16 with 5
    // samples, 7 with 2), one for the rigid subset; at most 1 + samples × 16 walks × 3 steps ×
    // 5 tries. A walk that ends too near an earlier sample is walked again (three closures
    // more: at a regular start no step needs halving), which happens on one-dof motions.
    let m = load("3-ups");
    let subsets = m.lock_subsets(6);
    for (samples, per_motion, most) in [(3, 10, 721), (5, 16, 1201), (2, 7, 481)] {
        let settings = SampleSettings {
            samples,
            ..SampleSettings::default()
        };
        assert_eq!(ModesCost::closures_per_motion(&settings), per_motion);
        assert_eq!(ModesCost::most_closures_per_motion(&settings), most);
        let cost = m.modes_cost(&m.reference(), &subsets, &settings);
        assert_eq!(
            cost,
            ModesCost {
                subsets: 64,
                rigid: 1,
                singular: 0,
                closures: 1 + 63 * per_motion,
                most_closures: 1 + 63 * most,
            },
            "{samples} samples"
        );
        let closures = sampled_closures(&m, &subsets, &settings);
        let mut walked_again = 0;
        for (subset, &c) in subsets.iter().zip(&closures) {
            let c = c as u64;
            if subset.len() == 6 {
                assert_eq!(c, 1, "{subset:?}, {samples} samples");
                continue;
            }
            assert!(
                per_motion <= c && c <= most,
                "{subset:?}, {samples} samples: {c}"
            );
            let steps = settings.steps as u64;
            assert_eq!(
                (c - per_motion) % steps,
                0,
                "{subset:?}, {samples} samples: {c}"
            );
            walked_again += (c - per_motion) / steps;
        }
        // Rare: fewer walks again than subsets with one dof (six).
        assert!(
            walked_again < 6,
            "{samples} samples: {walked_again} walks again"
        );
    }
}

#[test]
fn a_gough_stewart_platform_with_its_legs_locked_is_rigid_unless_its_hexagons_are_regular() {
    // Six UPS legs with their six prismatic joints locked: a Gough–Stewart platform, rigid at a
    // generic pose (the alternating, twisted form: one closure, the start's). With the legs
    // pairing base and platform points of two regular hexagons it is singular everywhere
    // (`kinsyn build --alternate`): the locks leave the start free to move to first order,
    // more than at random assemblies nearby, and the sampling takes its walks (more than one
    // closure) from a start it finds singular.
    let settings = SampleSettings::default();
    for (alternate, rigid, singular) in [(true, 1, 0), (false, 0, 1)] {
        let m = six_ups(20.0, alternate);
        let legs = vec![m.parse_locks("P1.3,P2.3,P3.3,P4.3,P5.3,P6.3").unwrap()];
        let cost = m.modes_cost(&m.reference(), &legs, &settings);
        assert_eq!(
            (cost.rigid, cost.singular),
            (rigid, singular),
            "alternate {alternate}"
        );
        let modes = m.modes_from(&m.reference(), &legs, &settings, &|| {});
        let mode = &modes.modes[0];
        assert_eq!(
            mode.closures == Some(1),
            rigid == 1,
            "alternate {alternate}"
        );
        assert_eq!(
            mode.is_singular_start(),
            singular == 1,
            "alternate {alternate}"
        );
    }
}

#[test]
fn the_estimate_classes_and_bounds_the_work_of_a_twelve_input_six_ups() {
    // The regular-hexagon 6-UPS with 12 inputs, its subsets of five and six locks (every sixth
    // of the C(12, 5) + C(12, 6) = 1716, in order): rigid, regular and singular starts side by
    // side. Subset by
    // subset, the estimate's class (decided on the null space of the closure equations) must
    // match what the sampling (deciding on the locked equations) meets: a rigid start is one
    // closure and a free one more, a start the sampling finds singular is one the estimate
    // calls singular, a regular start takes at least its ten closures; and no subset runs more
    // than the bound.
    let m = six_ups(0.0, false);
    let settings = SampleSettings::default();
    let subsets: Vec<Vec<usize>> = m
        .lock_subsets(6)
        .into_iter()
        .filter(|s| s.len() >= 5)
        .step_by(6)
        .collect();
    assert_eq!(subsets.len(), 286);
    let modes = m.modes_from(&m.reference(), &subsets, &settings, &|| {});
    let (mut rigid, mut singular, mut total) = (0, 0, 0);
    for (subset, mode) in subsets.iter().zip(&modes.modes) {
        let cost = m.modes_cost(&m.reference(), std::slice::from_ref(subset), &settings);
        let closures = mode.closures.unwrap() as u64;
        let what = &mode.lock_text;
        assert!(
            closures <= cost.most_closures,
            "{what}: {closures} closures"
        );
        assert_eq!(
            cost.rigid == 1,
            closures == 1,
            "{what}: {closures} closures"
        );
        if mode.is_singular_start() {
            assert_eq!(cost.singular, 1, "{what}: a singular start not foreseen");
        }
        if cost.rigid == 0 && cost.singular == 0 {
            assert!(closures >= cost.closures, "{what}: {closures} closures");
        }
        rigid += cost.rigid;
        singular += cost.singular;
        total += closures;
    }
    // All three classes are there, and the whole estimate bounds the whole work.
    let cost = m.modes_cost(&m.reference(), &subsets, &settings);
    assert_eq!((cost.rigid, cost.singular), (rigid, singular));
    assert!(rigid > 0 && singular > 0 && rigid + singular < subsets.len());
    assert!(total <= cost.most_closures);
}
