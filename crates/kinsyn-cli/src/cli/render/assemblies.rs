//! The text of `kinsyn analyze FILE --all-assemblies`: the position system, the solve and every
//! real assembly as a `--pose`.

use super::solve::certificate_line;
use kinsyn::manipulator::Manipulator;
use kinsyn_report::manipulator::{AllAssemblies, input_texts, pose_text};
use std::fmt::Write as _;
use std::path::Path;

/// The text report of `kinsyn analyze FILE --all-assemblies` for the manipulator `m` of the
/// file at `path`.
pub(in crate::cli) fn text(m: &Manipulator, all: &AllAssemblies, path: &Path) -> String {
    let (report, assemblies, null_cone) = (&all.report, &all.assemblies, all.null_cone);
    let seed = all.seed;
    let input_text = input_texts(m, &all.inputs);
    let kinds = &all.kinds;
    let (system, solved) = (&all.system, &all.solved);
    let mut out = String::new();
    let _ = writeln!(out, "{} at {}", m.name(), input_text.join(", "));
    let randomised = if solved.len() < system.len() {
        format!(
            "; over-constrained: randomised to {} equations, Bézout number {}",
            solved.len(),
            solved.bezout_number()
        )
    } else {
        format!(", Bézout number {}", system.bezout_number())
    };
    let _ = writeln!(
        out,
        "formulation: {} equations in the Study parameters x0…y3 of the platform frame (legs: {}; the Study quadric; a random linear chart, seed {seed}){randomised}",
        system.len(),
        kinds.join(", "),
    );
    let _ = writeln!(
        out,
        "{}",
        report.summary().replace("solutions", "assemblies")
    );
    if all.spurious > 0 {
        let _ = writeln!(
            out,
            "{} endpoints of the randomised system are not solutions: the original equations refuse them",
            all.spurious
        );
    }
    let _ = writeln!(out, "{}", certificate_line(report));
    if null_cone > 0 {
        let _ = writeln!(
            out,
            "{null_cone} of the singular endpoints lie on the null cone x0² + x1² + x2² + x3² = 0, which solves the constraints without being a displacement"
        );
    }
    let _ = writeln!(out, "time: {:.3} s", report.seconds);
    let unit = m.units();
    let _ = writeln!(
        out,
        "real assemblies ({}), as --pose x,y,z,rx,ry,rz ({}, {}):",
        assemblies.len(),
        unit.length,
        unit.angle.name()
    );
    for (k, a) in assemblies.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {:>3}  {}  [legs within {:.1e}{}{}]",
            k + 1,
            pose_text(m, &a.pose),
            a.residual,
            if a.certified { ", certified" } else { "" },
            if a.current {
                "; the assembly continued from the reference"
            } else {
                ""
            }
        );
    }
    if !assemblies.is_empty() {
        let _ = writeln!(
            out,
            "analyse one with: kinsyn analyze {} --pose=X,Y,Z,RX,RY,RZ",
            path.display()
        );
    }
    out
}
