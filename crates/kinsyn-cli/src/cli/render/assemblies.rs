//! The text of `kinsyn analyze FILE --all-assemblies`: the position system of each block of the
//! body tree, its solve, and every real assembly as a `--pose`.

use super::solve::certificate_line;
use kinsyn::manipulator::Manipulator;
use kinsyn_report::manipulator::{AllAssemblies, BlockAssemblies, input_texts, pose_text};
use std::fmt::Write as _;
use std::path::Path;

/// The text report of `kinsyn analyze FILE --all-assemblies` for the manipulator `m` of the
/// file at `path`.
pub(in crate::cli) fn text(m: &Manipulator, all: &AllAssemblies, path: &Path) -> String {
    let assemblies = &all.assemblies;
    let input_text = input_texts(m, &all.inputs);
    let mut out = String::new();
    let _ = writeln!(out, "{} at {}", m.name(), input_text.join(", "));
    let one = all.blocks.len() == 1;
    if !one {
        let _ = writeln!(
            out,
            "body tree: {} blocks, each body's frame relative to its parent's, solved apart (their unknowns are separate); the mechanism's assemblies are the combinations of one per block",
            all.blocks.len()
        );
    }
    for b in &all.blocks {
        block_text(&mut out, b, all.seed, one);
    }
    let unit = m.units();
    let listed = if all.combinations > assemblies.len() as u128 {
        format!(", the first {} listed", assemblies.len())
    } else {
        String::new()
    };
    let _ = writeln!(
        out,
        "real assemblies ({}{listed}), {}as --pose x,y,z,rx,ry,rz ({}, {}):",
        all.combinations,
        if one {
            String::new()
        } else {
            format!(
                "the end-effector's ({}) then every body's frame, ",
                m.bodies()[m.end_effector()].name
            )
        },
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
        if !one {
            for (body, g) in m.bodies().iter().zip(&a.frames) {
                let _ = writeln!(out, "         {}: {}", body.name, pose_text(m, g));
            }
        }
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

/// One block's formulation and solve (`one`: the only block, named as the platform).
fn block_text(out: &mut String, b: &BlockAssemblies, seed: u64, one: bool) {
    let (report, system, solved) = (&b.report, &b.system, &b.solved);
    let mut randomised = if solved.len() < system.len() {
        format!(
            "; over-constrained: randomised to {} equations, Bézout number {}",
            solved.len(),
            solved.bezout_number()
        )
    } else {
        format!(", Bézout number {}", system.bezout_number())
    };
    if report.start == kinsyn::homotopy::StartSystem::MultiHomogeneous {
        let groups: Vec<String> = kinsyn_report::manipulator::start_groups(solved, report.start)
            .iter()
            .map(|g| format!("{{{}}}", g.join(",")))
            .collect();
        let _ = write!(
            randomised,
            "; multi-homogeneous start over {}: {} paths",
            groups.join(" "),
            solved.multihomogeneous_bezout().unwrap_or(0)
        );
    }
    let frame = if one {
        "the platform frame".to_string()
    } else {
        format!("{} relative to {}", b.body, b.parent)
    };
    let _ = writeln!(
        out,
        "formulation: {} equations in the Study parameters x0…y3 of {frame} (legs: {}; the Study quadric; a random linear chart, seed {seed}){randomised}",
        system.len(),
        b.kinds.join(", "),
    );
    let _ = writeln!(
        out,
        "{}",
        report.summary().replace("solutions", "assemblies")
    );
    if b.spurious > 0 {
        let _ = writeln!(
            out,
            "{} endpoints of the randomised system are not solutions: the original equations refuse them",
            b.spurious
        );
    }
    let _ = writeln!(out, "{}", certificate_line(report));
    if b.null_cone > 0 {
        let _ = writeln!(
            out,
            "{} of the singular endpoints lie on the null cone x0² + x1² + x2² + x3² = 0, which solves the constraints without being a displacement",
            b.null_cone
        );
    }
    let _ = writeln!(out, "time: {:.3} s", report.seconds);
}
