//! `kinsyn modes` refuses more lock subsets than `--max-subsets` before any sampling, stating
//! the cost model (docs/limits.md, "kinsyn modes"): a subset's loop closures by what its
//! locks leave at the start, with the `--samples` asked for.

use crate::common;

use common::{assert_refused, kinsyn};

#[test]
fn the_refusal_states_the_closures_of_a_motion_with_the_samples_asked_for() {
    // The 3-UPS's 64 subsets against a limit of 10. A motion is 1 closure where the locks leave
    // the start rigid, 1 + samples × 3 steps from a regular start (10 with the default 3
    // samples, 16 with 5), and at most 1 + samples × 16 walks × 3 steps × 5 tries (721, 1201)
    // of at most 100 Newton steps each from a singular one.
    for (samples, regular, most) in [("3", "10", "721"), ("5", "16", "1201")] {
        let o = kinsyn(&[
            "modes",
            "mechanisms/3-ups.json",
            "--max-subsets",
            "10",
            "--samples",
            samples,
        ]);
        assert_refused(
            &o,
            &format!("--samples {samples}"),
            &[
                "mechanisms/3-ups.json: 6 inputs give 64 lock subsets (all 2^6), more than --max-subsets 10",
                "1 loop closure where the locks leave the start rigid",
                &format!("{regular} from a regular start (1 + {samples} samples × 3 steps)"),
                &format!("up to {most} of up to 100 Newton steps each from a singular one"),
                "docs/limits.md",
                "--max-locks 1 (7 subsets)",
            ],
        );
    }
}
