//! The cost of global analysis on every committed description (`cargo run --release -p
//! kinsyn-bench --example global_analysis`): for `analyze --all-assemblies` at the reference
//! inputs and for `components --free-inputs`, the blocks of the body tree, the unknowns and
//! equations of each, the paths tracked and the wall time, one line per description. A
//! description the body tree does not cover prints why. `-- --regeneration` decomposes by
//! regeneration instead of dimension by dimension.

use kinsyn::geometry::Chart;
use kinsyn::homotopy::{
    SolveSettings, fewest_paths_start, solve_overdetermined, square_randomisation,
};
use kinsyn::manipulator::{InputValues, Manipulator, OperationModeSettings};
use std::time::Instant;

const FILES: [&str; 15] = [
    "mechanisms/3-prrr.json",
    "mechanisms/3-rps.json",
    "mechanisms/3-rrr-planar.json",
    "mechanisms/3-rrr-spherical.json",
    "mechanisms/3-ups.json",
    "mechanisms/4-rrr-configurable.json",
    "mechanisms/4-ruu.json",
    "mechanisms/6-ruu-hexa.json",
    "mechanisms/6-ups.json",
    "mechanisms/multibody/3-rps-3-rps-table-1.json",
    "mechanisms/multibody/3-rps-3-rps.json",
    "mechanisms/multibody/3-rps-3-spr-3-rps.json",
    "mechanisms/multibody/3-rps-3-spr.json",
    "mechanisms/multibody/3-rps-split.json",
    "mechanisms/multibody/3-ups-split.json",
];

fn main() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    println!(
        "{:<46} {:>6} {:>16} {:>7} {:>9} | {:>16} {:>7} {:>9}",
        "description",
        "blocks",
        "unknowns×eqs",
        "paths",
        "seconds",
        "free: unk×eqs",
        "paths",
        "seconds"
    );
    for f in FILES {
        let text = std::fs::read_to_string(format!("{root}/{f}")).expect("a committed file");
        let m = Manipulator::from_json(&text).expect("a valid description");
        let name = f.trim_start_matches("mechanisms/");
        let inputs: Vec<(usize, f64)> = (0..m.actuators().len()).map(|a| (a, 0.0)).collect();
        let blocks = match m.body_blocks(&InputValues::Given(&inputs), &Chart::random_linear(1)) {
            Ok(b) => b,
            Err(e) => {
                println!("{name:<46} refused: {e}");
                continue;
            }
        };
        let shape = |systems: &[&kinsyn::poly::System]| {
            systems
                .iter()
                .map(|s| format!("{}×{}", s.nvars(), s.len()))
                .collect::<Vec<_>>()
                .join("+")
        };
        let start = Instant::now();
        let mut paths = 0;
        let mut refused = None;
        for b in &blocks {
            // The start `analyze --all-assemblies` chooses (after the square randomisation).
            let square = match square_randomisation(b.system.system(), 1) {
                Ok(s) => s,
                Err(e) => {
                    refused = Some(e.to_string());
                    continue;
                }
            };
            let (grouped, start) = fewest_paths_start(&square, &b.system.variable_groupings(), 1);
            let settings = SolveSettings {
                start,
                ..SolveSettings::default()
            };
            match solve_overdetermined(&grouped, &settings) {
                Ok(r) => paths += r.report.paths(),
                Err(e) => refused = Some(e.to_string()),
            }
        }
        let seconds = start.elapsed().as_secs_f64();
        let systems: Vec<&kinsyn::poly::System> =
            blocks.iter().map(|b| b.system.system()).collect();
        let given = match refused {
            None => format!(
                "{name:<46} {:>6} {:>16} {paths:>7} {seconds:>9.3}",
                blocks.len(),
                shape(&systems)
            ),
            Some(e) => format!(
                "{name:<46} {:>6} {:>16} refused: {}",
                blocks.len(),
                shape(&systems),
                e.chars().take(40).collect::<String>()
            ),
        };
        let start = Instant::now();
        let mut settings = OperationModeSettings::default();
        if std::env::args().any(|a| a == "--regeneration") {
            settings.method = kinsyn::manipulator::DecompositionMethod::Regeneration;
        }
        let free =
            m.block_operation_modes_with_progress(&InputValues::Free, &settings, &mut |_| {});
        let seconds = start.elapsed().as_secs_f64();
        match free {
            Ok(modes) => {
                let systems: Vec<&kinsyn::poly::System> =
                    modes.iter().map(|b| b.modes.system.system()).collect();
                let paths: usize = modes.iter().map(|b| b.modes.decomposition.paths).sum();
                println!(
                    "{given} | {:>16} {paths:>7} {seconds:>9.3}",
                    shape(&systems)
                );
            }
            Err(e) => println!("{given} | refused: {e}"),
        }
    }
}
