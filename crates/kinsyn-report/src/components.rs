//! `kinsyn components`: the irreducible components of a polynomial system (a Bertini input
//! file) or of a manipulator's constraint variety — its assemblies, self-motions and operation
//! modes — by numerical irreducible decomposition (docs/operation-modes.md).

use crate::manipulator::{input_texts, inputs_or_reference, load, pose_text};
use crate::solve::{paths_text, read_input, weighted_paths};
use crate::{Error, json, terminal};
use kinsyn::homotopy::{
    Component, DecomposeError, DecomposeSettings, Decomposition, MAX_DECOMPOSE_PATHS,
    RegenerationProgress, decompose, decompose_paths, regenerate_with_progress, regeneration_paths,
};
use kinsyn::manipulator::{
    DecompositionMethod, InputValues, LocalMotion, Manipulator, ModeComponent, OperationModeError,
    OperationModeSettings, OperationModes,
};
use kinsyn::poly::{C64, System};
use std::fmt::Write as _;
use std::path::Path;

/// How `kinsyn components` runs.
#[derive(Debug, Clone)]
pub struct ComponentsOptions {
    /// The seed of every random choice.
    pub seed: u64,
    /// The algorithm.
    pub method: DecompositionMethod,
    /// For a manipulator: its inputs (text of `--inputs`), `None` for the reference values.
    pub inputs: Option<String>,
    /// For a manipulator: every input an unknown (modes over input and pose space).
    pub free_inputs: bool,
    /// The most paths to track in all (`--max-paths`;
    /// [`kinsyn::homotopy::DEFAULT_DECOMPOSE_PATHS`] by default, at most
    /// [`MAX_DECOMPOSE_PATHS`]).
    pub max_paths: u64,
}

/// The refusal of a decomposition, in one line naming `source` and, for a path limit, the
/// estimate, the limit and the option that raises it. The same for a Bertini file and for a
/// manipulator's constraints, whose decomposition runs the same library code; for a Bertini
/// file (`system`), the other method's estimate when it is smaller.
fn refusal(
    source: &str,
    method: DecompositionMethod,
    system: Option<&System>,
    e: &DecomposeError,
) -> Error {
    let raise = |limit: u64| {
        if limit < MAX_DECOMPOSE_PATHS {
            format!(
                "more than --max-paths {limit}: raise it (at most {MAX_DECOMPOSE_PATHS} = 2^22)"
            )
        } else {
            format!("more than the limit of {limit} (2^22), the most --max-paths takes")
        }
    };
    Error::Input(match e {
        DecomposeError::TooManyPaths {
            estimate,
            unknowns,
            weight,
            limit,
        } => {
            let other = system
                .map(|s| match method {
                    DecompositionMethod::ByDimension => {
                        (DecompositionMethod::Regeneration, regeneration_paths(s))
                    }
                    DecompositionMethod::Regeneration => {
                        (DecompositionMethod::ByDimension, decompose_paths(s))
                    }
                })
                .filter(|(_, e)| e < estimate)
                .map(|(m, e)| {
                    format!(
                        "; --method {} is estimated at {}",
                        method_name(m),
                        paths_text(e)
                    )
                })
                .unwrap_or_default();
            format!(
                "{source}: {} is estimated at {} before any is tracked ({}), {}{other}",
                method_name(method),
                weighted_paths(*estimate, *weight, *unknowns),
                match method {
                    DecompositionMethod::ByDimension =>
                        "the Bézout numbers of the sliced systems, one per dimension",
                    DecompositionMethod::Regeneration =>
                        "Σ 2·e1⋯em over the equations by increasing degree",
                },
                raise(*limit)
            )
        }
        DecomposeError::PathLimit {
            tracked,
            unknowns,
            weight,
            limit,
            estimate,
        } => format!(
            "{source}: {} stopped after {} (the start systems were estimated at {}; monodromy loops and membership tests took the rest), {}",
            method_name(method),
            weighted_paths(u128::from(*tracked), *weight, *unknowns),
            paths_text(*estimate),
            raise(*limit)
        ),
        other => format!("{source}: {other}"),
    })
}

/// `kinsyn components FILE`: a Bertini input file or a manipulator file, as text or as the
/// `--json` report.
///
/// # Errors
///
/// [`Error::Input`]: a file that cannot be read or is neither kind, `--inputs` or
/// `--free-inputs` for a polynomial system, malformed input values, a manipulator whose legs
/// have no polynomial form, or a decomposition that fails.
pub fn components(
    path: &Path,
    options: &ComponentsOptions,
    as_json: bool,
) -> Result<String, Error> {
    let text = crate::files::read_text(
        path,
        "not a Bertini input file or a kinsyn manipulator file",
    )?;
    let settings = DecomposeSettings {
        seed: options.seed,
        max_paths: options.max_paths,
        ..DecomposeSettings::default()
    };
    if text.trim_start().starts_with('{') {
        return manipulator_components(path, options, settings, as_json);
    }
    if options.inputs.is_some() || options.free_inputs {
        return Err(Error::Input(format!(
            "{}: --inputs and --free-inputs apply to manipulator files, not to polynomial systems",
            path.display()
        )));
    }
    let input = read_input(path)?;
    let system = &input.system;
    let estimate = match options.method {
        DecompositionMethod::Regeneration => regeneration_paths(system),
        DecompositionMethod::ByDimension => decompose_paths(system),
    };
    let d = with_feedback(options.method, Some(estimate), |progress| {
        match options.method {
            DecompositionMethod::Regeneration => {
                regenerate_with_progress(system, &settings, progress)
            }
            DecompositionMethod::ByDimension => decompose(system, &settings),
        }
    })
    .map_err(|e| {
        refusal(
            &path.display().to_string(),
            options.method,
            Some(system),
            &e,
        )
    })?;
    if as_json {
        return Ok(json(&serde_json::json!({
            "file": path.display().to_string(),
            "variables": system.variables(),
            "equations": system.len(),
            "method": method_name(options.method),
            "seed": options.seed,
            "components": d.components.iter().map(component_json).collect::<Vec<_>>(),
            "unresolved": d.unresolved.iter().map(|(dim, x)| serde_json::json!({
                "dimension": dim, "point": complex(x)})).collect::<Vec<_>>(),
            "junk": d.junk,
            "paths": d.paths,
            "estimated_paths": d.estimated_paths.to_string(),
            "seconds": d.seconds,
        })));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{}: {} equations in {} unknowns ({})",
        path.display(),
        system.len(),
        system.nvars(),
        system.variables().join(", ")
    );
    let _ = writeln!(out, "{}", summary(&d, options.method));
    for (k, c) in d.components.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {}. dimension {}, degree {}{}; a point: {}",
            k + 1,
            c.dimension,
            c.degree,
            if c.trace_test_passed {
                ""
            } else {
                " (trace test FAILED: perhaps a union of components)"
            },
            point_text(system.variables(), &c.sample_point)
        );
    }
    unresolved_text(&mut out, &d);
    Ok(out)
}

/// Runs a decomposition with feedback on a terminal: a bar over the equations for
/// regeneration (which reports after each), a spinner otherwise; both state the `estimate` of
/// the paths (when known before the system is built: for a Bertini file).
fn with_feedback<T>(
    method: DecompositionMethod,
    estimate: Option<u128>,
    work: impl FnOnce(&mut dyn FnMut(RegenerationProgress)) -> T,
) -> T {
    let cost = estimate.map_or_else(String::new, |e| {
        format!(" (an estimated {} paths)", paths_text(e))
    });
    match method {
        DecompositionMethod::Regeneration => {
            let bar = terminal::progress(0, "equations", &format!("regeneration{cost}"));
            let result = work(&mut |p: RegenerationProgress| {
                bar.set_length(p.of as u64);
                bar.set_position(p.equations as u64);
            });
            bar.finish_and_clear();
            result
        }
        DecompositionMethod::ByDimension => terminal::working(
            &format!("decomposing, dimension by dimension{cost}"),
            || work(&mut |_| {}),
        ),
    }
}

fn method_name(m: DecompositionMethod) -> &'static str {
    match m {
        DecompositionMethod::Regeneration => "regeneration",
        DecompositionMethod::ByDimension => "by-dimension",
    }
}

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

fn unresolved_text(out: &mut String, d: &Decomposition) {
    if !d.unresolved.is_empty() {
        let mut dims: Vec<usize> = d.unresolved.iter().map(|(k, _)| *k).collect();
        dims.sort_unstable();
        dims.dedup();
        let _ = writeln!(
            out,
            "warning: {} singular witness point{} on no component found (dimension {}): a non-reduced component (multiplicity > 1), not decomposed here",
            d.unresolved.len(),
            if d.unresolved.len() == 1 { "" } else { "s" },
            dims.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
}

fn complex(x: &[C64]) -> Vec<[f64; 2]> {
    x.iter().map(|c| [c.re, c.im]).collect()
}

fn component_json(c: &Component) -> serde_json::Value {
    serde_json::json!({
        "dimension": c.dimension,
        "degree": c.degree,
        "trace_test_passed": c.trace_test_passed,
        "sample_point": complex(&c.sample_point),
        "witness_points": c.witness_points.iter().map(|x| complex(x)).collect::<Vec<_>>(),
    })
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

fn manipulator_components(
    path: &Path,
    options: &ComponentsOptions,
    decompose: DecomposeSettings,
    as_json: bool,
) -> Result<String, Error> {
    let m: Manipulator = load(path)?;
    if options.free_inputs && options.inputs.is_some() {
        return Err(Error::Input(
            "--free-inputs and --inputs exclude each other: free inputs are unknowns".into(),
        ));
    }
    let all = inputs_or_reference(&m, options.inputs.as_deref())?;
    let inputs = if options.free_inputs {
        InputValues::Free
    } else {
        InputValues::Given(&all)
    };
    let settings = OperationModeSettings {
        decompose,
        method: options.method,
        ..OperationModeSettings::default()
    };
    let modes = with_feedback(options.method, None, |progress| {
        m.operation_modes_with_progress(&inputs, &settings, progress)
    })
    .map_err(|e| match e {
        OperationModeError::Decompose(e) => {
            refusal(&path.display().to_string(), options.method, None, &e)
        }
        other @ OperationModeError::System(_) => {
            Error::Input(format!("{}: {other}", path.display()))
        }
    })?;
    let input_text = input_texts(&m, &all);
    if as_json {
        return Ok(json(&manipulator_json(&m, &modes, &input_text, options)));
    }
    Ok(manipulator_text(&m, &modes, &input_text, options))
}

fn local_json(m: &Manipulator, l: &LocalMotion) -> serde_json::Value {
    serde_json::json!({
        "pose": pose_text(m, &l.pose),
        "dof": l.dof,
        "pattern": l.motion.pattern.name().to_string(),
        "group": l.motion.pattern.is_group(),
        "same_span": l.motion.same_span,
        "min_separation": l.motion.min_separation,
        "point": l.point,
    })
}

fn manipulator_json(
    m: &Manipulator,
    modes: &OperationModes,
    inputs: &[String],
    options: &ComponentsOptions,
) -> serde_json::Value {
    let d = &modes.decomposition;
    serde_json::json!({
        "manipulator": m.name(),
        "inputs": if modes.free_inputs { serde_json::Value::String("free".into()) } else { serde_json::json!(inputs) },
        "variables": modes.system.system().variables(),
        "equations": modes.system.system().len(),
        "method": method_name(options.method),
        "seed": options.seed,
        "components": modes.components.iter().map(|c: &ModeComponent| serde_json::json!({
            "dimension": c.dimension,
            "degree": c.degree,
            "trace_test_passed": c.trace_test_passed,
            "sample_point": complex(&c.sample),
            "real_points": c.real_points.len(),
            "motion": c.real.as_ref().map(|l| local_json(m, l)),
            "released": c.released.as_ref().map(|l| local_json(m, l)),
        })).collect::<Vec<_>>(),
        "unresolved": d.unresolved.iter().map(|(dim, x)| serde_json::json!({
            "dimension": dim, "point": complex(x)})).collect::<Vec<_>>(),
        "junk": d.junk,
        "paths": d.paths,
        "estimated_paths": d.estimated_paths.to_string(),
        "seconds": d.seconds,
    })
}

fn manipulator_text(
    m: &Manipulator,
    modes: &OperationModes,
    inputs: &[String],
    options: &ComponentsOptions,
) -> String {
    let system = modes.system.system();
    let d = &modes.decomposition;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{}, {}: {} constraint equations in {} unknowns ({}); Study parameters with x0² + x1² + x2² + x3² = 1, so each pose is two points ±(x, y)",
        m.name(),
        if modes.free_inputs {
            "inputs free (tangents of their half angles are unknowns)".to_string()
        } else {
            format!("inputs {}", inputs.join(", "))
        },
        system.len(),
        system.nvars(),
        system.variables().join(", ")
    );
    let _ = writeln!(out, "{}", summary(d, options.method));
    let (isolated, positive): (Vec<&ModeComponent>, Vec<&ModeComponent>) =
        modes.components.iter().partition(|c| c.dimension == 0);
    for c in &positive {
        let what = if modes.free_inputs {
            format!("operation mode, {} dof", c.dimension)
        } else {
            format!("self-motion, {} dof", c.dimension)
        };
        let motion = c.real.as_ref().map_or_else(
            || "no real point found on 8 real slices: a complex component".to_string(),
            |l| {
                format!(
                    "platform motion {} at the pose {}",
                    motion_text(l),
                    pose_text(m, &l.pose)
                )
            },
        );
        let _ = writeln!(
            out,
            "  dimension {}, degree {}{}: {what}{}; {motion}",
            c.dimension,
            c.degree,
            if c.trace_test_passed {
                ""
            } else {
                " (trace test FAILED)"
            },
            study_label(&c.sample),
        );
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
            if modes.free_inputs {
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
    unresolved_text(&mut out, d);
    out
}
