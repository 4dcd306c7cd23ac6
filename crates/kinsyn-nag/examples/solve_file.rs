//! Every isolated solution of a square Bertini input file, or the irreducible components of a
//! non-square one, with kinsyn-nag alone (no kinematics):
//!
//! ```text
//! cargo run -p kinsyn-nag --example solve_file -- examples/systems/katsura5.bertini
//! cargo run -p kinsyn-nag --example solve_file -- examples/systems/twisted-cubic-and-line.bertini
//! ```

use kinsyn_nag::homotopy::{DecomposeSettings, SolveSettings, decompose, solve};
use kinsyn_nag::poly::bertini;
use std::process::ExitCode;

/// The largest file read (the `kinsyn` binary's limit for an input file).
const MAX_FILE_BYTES: u64 = 1 << 20;

fn main() -> ExitCode {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: solve_file FILE.bertini");
        return ExitCode::from(2);
    };
    match run(&path) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("solve_file: {}", message.escape_debug());
            ExitCode::from(2)
        }
    }
}

fn run(path: &str) -> Result<(), String> {
    let size = std::fs::metadata(path)
        .map_err(|e| format!("{path}: {e}"))?
        .len();
    if size > MAX_FILE_BYTES {
        return Err(format!("{path}: {size} bytes, more than {MAX_FILE_BYTES}"));
    }
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let input = bertini::parse(&text).map_err(|e| format!("{path}: {e}"))?;
    let system = &input.system;
    if system.equations().len() == system.variables().len() {
        let report = solve(system, &SolveSettings::default()).map_err(|e| e.to_string())?;
        println!(
            "{} paths: {} regular solutions ({} real), {} certified",
            report.paths(),
            report.nonsingular(),
            report.real(),
            report.certified()
        );
        for s in &report.solutions {
            let x: Vec<String> =
                s.x.iter()
                    .map(|z| format!("{:.6}{:+.6}i", z.re, z.im))
                    .collect();
            println!("  {}", x.join("  "));
        }
    } else {
        let d = decompose(system, &DecomposeSettings::default()).map_err(|e| e.to_string())?;
        for c in &d.components {
            println!(
                "component of dimension {} and degree {} (trace test {})",
                c.dimension,
                c.degree,
                if c.trace_test_passed {
                    "passed"
                } else {
                    "FAILED"
                }
            );
        }
    }
    Ok(())
}
