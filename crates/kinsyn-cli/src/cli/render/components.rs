//! The text of `kinsyn components`: the irreducible components of a polynomial system, or a
//! manipulator's self-motions, operation modes and assemblies.

use kinsyn::homotopy::Decomposition;
use kinsyn::manipulator::{
    BlockModes, ComponentMotion, DecompositionMethod, LocalMotion, Manipulator, ModeComponent,
    OperationModes,
};
use kinsyn::poly::{C64, System};
use kinsyn_report::components::{
    Components, ComponentsOptions, Decomposed, MechanismReport, method_name, product_factors,
};
use kinsyn_report::manipulator::pose_text;
use std::fmt::Write as _;

/// The text report of `kinsyn components`.
pub(in crate::cli) fn text(c: &Components) -> String {
    match &c.decomposed {
        Decomposed::System {
            source,
            system,
            decomposition,
        } => system_text(source, system, decomposition, c.options.method),
        Decomposed::Manipulator {
            m,
            blocks,
            inputs,
            mechanism,
            free,
        } => {
            let held = held_text(m, inputs, free);
            if let [one] = &blocks[..] {
                manipulator_text(m, one, &held, &c.options, mechanism)
            } else {
                blocks_text(m, blocks, &held, &c.options, mechanism)
            }
        }
    }
}

/// The text report of the components `d` of the Bertini file `source`'s `system`.
fn system_text(
    source: &str,
    system: &System,
    d: &Decomposition,
    method: DecompositionMethod,
) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{source}: {} equations in {} unknowns ({})",
        system.len(),
        system.nvars(),
        system.variables().join(", ")
    );
    let _ = writeln!(out, "{}", summary(d, method));
    for (k, c) in d.components.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {}. dimension {}, degree {}{}{}; a point: {}",
            k + 1,
            c.dimension,
            c.degree,
            multiplicity_text(c.multiplicity),
            if c.trace_test_passed {
                ""
            } else {
                " (trace test FAILED: perhaps a union of components)"
            },
            point_text(system.variables(), &c.sample_point)
        );
    }
    unresolved_text(&mut out, d);
    out
}

/// The components found, the method, its paths and time, the junk removed.
fn summary(d: &Decomposition, method: DecompositionMethod) -> String {
    format!(
        "{} irreducible component{} ({}: {} paths, {:.2} s; {} junk point{} removed)",
        d.components.len(),
        if d.components.len() == 1 { "" } else { "s" },
        method_name(method),
        d.paths,
        d.seconds,
        d.junk,
        if d.junk == 1 { "" } else { "s" }
    )
}

/// The warning line on singular witness points on no component, if any.
fn unresolved_text(out: &mut String, d: &Decomposition) {
    if !d.unresolved.is_empty() {
        let mut dims: Vec<usize> = d.unresolved.iter().map(|(k, _)| *k).collect();
        dims.sort_unstable();
        dims.dedup();
        let _ = writeln!(
            out,
            "warning: {} singular witness point{} on no component found (dimension {}): singular still after deflation, not decomposed here",
            d.unresolved.len(),
            if d.unresolved.len() == 1 { "" } else { "s" },
            dims.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
}

/// `name = value` for each variable, complex values as `a+bi`, six significant digits.
fn point_text(names: &[String], x: &[C64]) -> String {
    names
        .iter()
        .zip(x)
        .map(|(n, v)| {
            let re = if v.re.abs() < 1e-10 { 0.0 } else { v.re };
            if v.im.abs() < 1e-10 * (1.0 + v.norm()) {
                format!("{n}={re:.6}")
            } else {
                format!("{n}={re:.6}{:+.6}i", v.im)
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// A platform motion in words: its dof and pattern.
fn motion_text(m: &LocalMotion) -> String {
    let name = m.motion.pattern.name();
    let group = if m.motion.pattern.is_group() {
        ""
    } else {
        " (not a displacement group)"
    };
    format!("{} dof, {}{group}", m.dof, name)
}

/// Which of paper 004's Schönflies modes a unit Study point is in, if either: `x0 = x3 = 0`
/// (the platform upside down) or `x1 = x2 = 0` (parallel, upright).
fn study_label(x: &[C64]) -> &'static str {
    let small = |v: C64| v.norm() < 1e-8;
    if small(x[0]) && small(x[3]) {
        " [x0 = x3 = 0: platform turned upside down]"
    } else if small(x[1]) && small(x[2]) {
        " [x1 = x2 = 0: platform upright]"
    } else {
        ""
    }
}

/// How the free inputs enter the system: eliminated with their legs' motion (passive joints),
/// or as the tangents `t_k` of their half angles.
fn free_inputs_text(m: &Manipulator, system: &kinsyn::manipulator::PositionSystem) -> String {
    let (variables, eliminated): (Vec<usize>, Vec<usize>) =
        (0..m.actuators().len()).partition(|a| system.input_variable(*a).is_some());
    let labels = |v: &[usize]| {
        v.iter()
            .map(|a| m.actuators()[*a].label())
            .collect::<Vec<_>>()
            .join(" ")
    };
    match (variables.is_empty(), eliminated.is_empty()) {
        (true, _) => "inputs free (passive joints, eliminated with their legs' motion)".to_string(),
        (false, true) => "inputs free (tangents of their half angles are unknowns)".to_string(),
        (false, false) => format!(
            "inputs free ({} as tangents of their half angles; {} passive, eliminated with their legs' motion)",
            labels(&variables),
            labels(&eliminated)
        ),
    }
}

/// The given inputs in words (`LABEL = value`, then the free ones of `--free` named).
fn held_text(m: &Manipulator, inputs: &[String], free: &[usize]) -> String {
    let mut text = format!("inputs {}", inputs.join(", "));
    if !free.is_empty() {
        let _ = write!(
            text,
            "; {} free",
            free.iter()
                .map(|&a| m.actuators()[a].label())
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
    text
}

/// The text report of the operation modes (or assemblies and self-motions) of `m`.
fn manipulator_text(
    m: &Manipulator,
    block: &BlockModes,
    held: &str,
    options: &ComponentsOptions,
    mechanism: &[Placed],
) -> String {
    let modes = &block.modes;
    let system = modes.system.system();
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{}, {}: {} constraint equations in {} unknowns ({}); Study parameters with x0² + x1² + x2² + x3² = 1, so each pose is two points ±(x, y)",
        m.name(),
        if modes.free_inputs {
            free_inputs_text(m, &modes.system)
        } else {
            held.to_string()
        },
        system.len(),
        system.nvars(),
        system.variables().join(", ")
    );
    // A block with members: the motion classified is its root body's.
    let body = if modes.system.has_members() {
        m.bodies()[block.body].name.clone()
    } else {
        "platform".to_string()
    };
    components_text(&mut out, m, modes, options, &body, Some(mechanism));
    out
}

/// The whole mechanism on one component, if placed ([`Decomposed::Manipulator`]).
type Placed = Option<Result<ComponentMotion, String>>;

/// The whole mechanism on a component in words ([`MechanismReport`]): the end-effector's
/// motion with the held inputs locked, and the inputs that move; `None` for a component
/// without a real point.
fn mechanism_text(m: &Manipulator, placed: &Placed) -> Option<String> {
    let r = MechanismReport::new(m, placed.as_ref()?.as_ref());
    if r.dof.is_none() {
        return Some(format!(
            "the whole mechanism not placed on a real point of it ({})",
            r.error.unwrap_or_default()
        ));
    }
    let labels = |l: &[String]| {
        if l.is_empty() {
            "none".to_string()
        } else {
            l.join(" ")
        }
    };
    let mut text = format!(
        "whole mechanism: \"{}\" {} dof, {}; inputs moving: {}",
        r.body,
        r.dof.unwrap_or(0),
        r.pattern.unwrap_or_default(),
        labels(&r.moving_inputs)
    );
    if !r.still_inputs.is_empty() || r.held_inputs.len() < m.actuators().len() {
        let _ = write!(text, "; free but still: {}", labels(&r.still_inputs));
    }
    Some(text)
}

/// The text report of a manipulator of several moving bodies: each block of its body tree,
/// then the products of one component per block.
fn blocks_text(
    m: &Manipulator,
    blocks: &[BlockModes],
    held: &str,
    options: &ComponentsOptions,
    mechanism: &[Placed],
) -> String {
    let mut out = String::new();
    let free = blocks.first().is_some_and(|b| b.modes.free_inputs);
    let name = |k: Option<usize>| {
        k.map_or_else(
            || m.ground_name().to_string(),
            |k| m.bodies()[k].name.clone(),
        )
    };
    let _ = writeln!(
        out,
        "{}, {}: body tree of {} blocks, each body's frame relative to its parent's, decomposed apart (their unknowns are separate); Study parameters with x0² + x1² + x2² + x3² = 1, so each relative pose is two points ±(x, y)",
        m.name(),
        if free {
            "inputs free".to_string()
        } else {
            held.to_string()
        },
        blocks.len()
    );
    for (k, b) in blocks.iter().enumerate() {
        let system = b.modes.system.system();
        let _ = writeln!(
            out,
            "block {}: {} relative to {}{}: {} constraint equations in {} unknowns ({})",
            k + 1,
            name(Some(b.body)),
            name(b.parent),
            if free {
                format!(", {}", free_inputs_text(m, &b.modes.system))
            } else {
                String::new()
            },
            system.len(),
            system.nvars(),
            system.variables().join(", ")
        );
        components_text(&mut out, m, &b.modes, options, &name(Some(b.body)), None);
    }
    let counts: Vec<usize> = blocks.iter().map(|b| b.modes.components.len()).collect();
    let total: usize = counts.iter().product();
    let _ = writeln!(
        out,
        "the mechanism's components: {total} products of one component per block ({}); dimensions add, degrees multiply",
        counts
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(" × ")
    );
    for (pick, placed) in product_factors(&counts).iter().zip(mechanism) {
        let components: Vec<&ModeComponent> = pick
            .iter()
            .zip(blocks)
            .map(|(&k, b)| &b.modes.components[k])
            .collect();
        let dimension: usize = components.iter().map(|c| c.dimension).sum();
        let Some(text) = mechanism_text(m, placed).filter(|_| dimension > 0) else {
            continue;
        };
        let _ = writeln!(
            out,
            "  product ({}): dimension {dimension}, degree {}; {text}",
            pick.iter()
                .map(|k| (k + 1).to_string())
                .collect::<Vec<_>>()
                .join(", "),
            components
                .iter()
                .fold(1_usize, |d, c| d.saturating_mul(c.degree))
        );
    }
    out
}

/// The decomposition `modes` of one system (a one-platform manipulator, or one block whose
/// moving body is `body`): its summary, then its components.
fn components_text(
    out: &mut String,
    m: &Manipulator,
    modes: &OperationModes,
    options: &ComponentsOptions,
    body: &str,
    mechanism: Option<&[Placed]>,
) {
    let d = &modes.decomposition;
    let _ = writeln!(out, "{}", summary(d, options.method));
    let (isolated, positive): (Vec<&ModeComponent>, Vec<&ModeComponent>) =
        modes.components.iter().partition(|c| c.dimension == 0);
    for c in &positive {
        let index = modes
            .components
            .iter()
            .position(|o| std::ptr::eq(o, *c))
            .unwrap_or(0);
        let what = if modes.free_inputs || options.free.is_some() {
            format!("operation mode, {} dof", c.dimension)
        } else {
            format!("self-motion, {} dof", c.dimension)
        };
        let motion = c.real.as_ref().map_or_else(
            || "no real point found on 8 real slices: a complex component".to_string(),
            |l| {
                format!(
                    "{body} motion {} at the pose {}",
                    motion_text(l),
                    pose_text(m, &l.pose)
                )
            },
        );
        let _ = writeln!(
            out,
            "  dimension {}, degree {}{}{}: {what}{}; {motion}",
            c.dimension,
            c.degree,
            multiplicity_text(c.multiplicity),
            if c.trace_test_passed {
                ""
            } else {
                " (trace test FAILED)"
            },
            study_label(&c.sample),
        );
        if let Some(text) = mechanism
            .and_then(|on| on.get(index))
            .and_then(|placed| mechanism_text(m, placed))
        {
            let _ = writeln!(out, "    {text}");
        }
    }
    if !isolated.is_empty() {
        let real: Vec<&&ModeComponent> = isolated
            .iter()
            .filter(|c| !c.real_points.is_empty())
            .collect();
        let _ = writeln!(
            out,
            "  dimension 0: {} isolated point{} ({} real){}",
            isolated.len(),
            if isolated.len() == 1 { "" } else { "s" },
            real.len(),
            if modes.free_inputs || options.free.is_some() {
                ""
            } else {
                ": the assemblies"
            }
        );
        let mut shown: Vec<kinsyn::spatial::Displacement> = Vec::new();
        for c in real {
            let Some(l) = &c.real else { continue };
            if shown
                .iter()
                .any(|g| (g.to_homogeneous() - l.pose.to_homogeneous()).amax() < 1e-7)
            {
                continue;
            }
            shown.push(l.pose);
            let mode = c.released.as_ref().map_or_else(
                || "its operation mode not found (an input 180° from the reference, where tan(δ/2) is infinite, or a singular point of the released variety)".to_string(),
                |r| {
                    format!(
                        "operation mode with the inputs released: {}",
                        motion_text(r)
                    )
                },
            );
            let _ = writeln!(
                out,
                "    assembly at the pose {}{}: {mode}",
                pose_text(m, &l.pose),
                study_label(&c.sample),
            );
        }
    }
    unresolved_text(out, d);
}

/// `, multiplicity μ` for a non-reduced component (found by deflation), nothing when reduced.
fn multiplicity_text(multiplicity: usize) -> String {
    if multiplicity > 1 {
        format!(", multiplicity {multiplicity} (non-reduced, by deflation)")
    } else {
        String::new()
    }
}
