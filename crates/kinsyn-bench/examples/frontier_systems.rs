//! Writes the systems of the solver's frontier benchmark (`benches/frontier/run.sh`) as
//! Bertini input for `kinsyn solve` and as PHCpack input for `phc -b`: Katsura-8 to -12,
//! cyclic-8 and the 4-RUU of paper 004 at generic inputs (its ten equations randomised to
//! eight by the same `[I | A]` combination for both solvers).
//!
//! `cargo run --release -p kinsyn-bench --example frontier_systems -- DIR`

use kinsyn::geometry::Chart;
use kinsyn::homotopy::square_randomisation;
use kinsyn::manipulator::{InputValues, Manipulator};
use kinsyn::poly::{System, bertini, families, phc};

fn main() {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "target/frontier".to_string());
    std::fs::create_dir_all(&dir).expect("the output folder");
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let text = std::fs::read_to_string(format!("{root}/mechanisms/4-ruu.json"))
        .expect("the committed 4-RUU");
    let m = Manipulator::from_json(&text).expect("a valid description");
    // Generic inputs (radians): the half-angle tangents 0.3, −0.7, 1.1, 0.2.
    let inputs: Vec<(usize, f64)> = [0.3f64, -0.7, 1.1, 0.2]
        .iter()
        .enumerate()
        .map(|(a, t)| (a, 2.0 * t.atan()))
        .collect();
    let ruu = m
        .constraint_system(&InputValues::Given(&inputs), &Chart::random_linear(3))
        .expect("the 4-RUU's constraint system");
    let ruu = square_randomisation(ruu.system(), 7).expect("more equations than unknowns");
    let mut systems: Vec<(String, System)> = (8..=12)
        .map(|n| (format!("katsura-{n}"), families::katsura(n)))
        .collect();
    systems.push(("cyclic-8".into(), families::cyclic(8)));
    systems.push(("4-ruu-generic".into(), ruu));
    for (name, system) in systems {
        std::fs::write(format!("{dir}/{name}.bertini"), bertini::write(&system)).expect("writable");
        std::fs::write(format!("{dir}/{name}.phc"), phc::write(&system)).expect("writable");
        println!(
            "{dir}/{name}: {} unknowns, Bézout {}",
            system.nvars(),
            system.bezout_number()
        );
    }
}
