//! `kinsyn view FILE`: the data of a manipulator's 3D page ([`kinsyn::view`]) — the start
//! configuration at the given inputs, a sweep per input, a walk per operation mode reached by
//! locking inputs, and every real assembly at those inputs when the global analysis can
//! compute them.

use crate::Error;
use crate::components::{ComponentsOptions, Decomposed, manipulator_components_of};
use crate::manipulator::{all_assemblies_of, input_texts, inputs_or_reference};
use kinsyn::homotopy::{DEFAULT_DECOMPOSE_PATHS, DecomposeSettings};
use kinsyn::manipulator::{Manipulator, PositionRequest};
use kinsyn::mechanism::SampleSettings;
use kinsyn::notation::Primitive;
use kinsyn::view::{AssemblyView, FORMAT, ModeView, Scene, View, input_sweep, mode_walk};

/// The default steps to either side of a sweep or a walk.
pub const DEFAULT_STEPS: usize = 16;

/// The most lock subsets sampled for the modes: every subset of up to 8 inputs, of fewer
/// locks beyond.
pub const MAX_MODE_SUBSETS: u128 = 256;

/// The most configurations a page holds (sweeps and walks together): each is a continuation
/// step or a Newton closure before the page is written, and a row of joint values in it.
pub const MAX_CONFIGURATIONS: usize = 8192;

/// The configurations already counted plus `walks` more of `steps` to either side, or the
/// refusal when that passes [`MAX_CONFIGURATIONS`]: `what` names the walks.
fn counted(so_far: usize, walks: usize, steps: usize, what: &str) -> Result<usize, Error> {
    let total = so_far.saturating_add(walks.saturating_mul(2 * steps + 1));
    if total > MAX_CONFIGURATIONS {
        return Err(Error::Input(format!(
            "--steps {steps}: {what} would bring the page to {total} configurations, beyond the {MAX_CONFIGURATIONS} it holds (docs/limits.md); give fewer --steps"
        )));
    }
    Ok(total)
}

/// How far a sweep moves a revolute input to either side (radians): 30°.
pub const REVOLUTE_SPAN: f64 = std::f64::consts::PI / 6.0;

/// How far a sweep moves a slider to either side, as a fraction of the characteristic length.
pub const SLIDER_SPAN: f64 = 0.2;

/// What `kinsyn view` is asked for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ViewOptions {
    /// `--inputs`: the input values of the start configuration (the reference when `None`).
    pub inputs: Option<String>,
    /// Steps to either side of each sweep and walk (1 to [`kinsyn::view::MAX_STEPS`]).
    pub steps: usize,
    /// Whether to solve for every assembly at the inputs.
    pub assemblies: bool,
    /// Whether to add the operation modes of the global decomposition (`kinsyn components`):
    /// at the inputs, or with `free_inputs` over input and pose space.
    pub components: bool,
    /// With `components`: every input an unknown.
    pub free_inputs: bool,
    /// With `components`: the most paths the decomposition tracks (`--max-paths`).
    pub max_paths: u64,
    /// The seed of the sampled modes and of the assembly solve.
    pub seed: u64,
}

impl Default for ViewOptions {
    fn default() -> Self {
        Self {
            inputs: None,
            steps: DEFAULT_STEPS,
            assemblies: true,
            components: false,
            free_inputs: false,
            max_paths: DEFAULT_DECOMPOSE_PATHS,
            seed: 1,
        }
    }
}

/// The view of `m` (module documentation).
///
/// # Errors
/// [`Error::Input`] for inputs that do not read or that the manipulator cannot reach from its
/// reference configuration, steps out of range, and a page that would hold more than
/// [`MAX_CONFIGURATIONS`] (known before the sweeps from the inputs, before the walks from the
/// patterns reached), and the decomposition's refusal with `components`.
pub fn view_of(m: &Manipulator, options: &ViewOptions) -> Result<View, Error> {
    if options.steps == 0 || options.steps > kinsyn::view::MAX_STEPS {
        return Err(Error::Input(format!(
            "--steps {}: from 1 to {} steps to either side",
            options.steps,
            kinsyn::view::MAX_STEPS
        )));
    }
    let inputs = inputs_or_reference(m, options.inputs.as_deref())?;
    let mut budget = counted(
        0,
        m.actuators().len(),
        options.steps,
        &format!("the sweeps of {} inputs", m.actuators().len()),
    )?;
    let mut notes = Vec::new();
    // The decomposition first: where the inputs leave a self-motion, its real point is the
    // start the continuation cannot give.
    let found = if options.components {
        components(m, options, &mut budget, &mut notes)?
    } else {
        Vec::new()
    };
    let start = match options.inputs.as_deref() {
        None => m.reference(),
        Some(text) => {
            let request = PositionRequest {
                inputs: inputs.clone(),
                ..PositionRequest::default()
            };
            match m.solve_position(&m.reference(), &request) {
                Ok(p) => p.q,
                Err(e) => match found.first() {
                    Some(mode) => {
                        notes.push(format!(
                            "The start is a point of the first component shown: at these inputs {e}."
                        ));
                        mode.joint_values[mode.start].clone()
                    }
                    None => return Err(Error::Input(format!("--inputs {text:?}: {e}"))),
                },
            }
        }
    };
    let settings = SampleSettings {
        seed: options.seed,
        ..SampleSettings::default()
    };
    let free = m.mode_from(&start, &[], &settings);
    let classification = format!(
        "With every input free the end-effector has {} dof: {}.",
        free.dof,
        free.pattern_text()
    );
    // Progress on stderr when it is a terminal (the HEXA's sweeps take seconds).
    let bar = crate::terminal::progress(m.actuators().len(), "inputs", "view: sweeps");
    let sweeps = (0..m.actuators().len())
        .map(|a| {
            let span = match m.actuators()[a].kind {
                Primitive::R => REVOLUTE_SPAN,
                Primitive::P => SLIDER_SPAN * m.mechanism().scale(),
            };
            let sweep = input_sweep(m, &start, a, span, options.steps);
            bar.inc(1);
            sweep
        })
        .collect();
    bar.finish_and_clear();
    let mut modes = modes(
        m,
        &start,
        &settings,
        (options.steps, &mut budget),
        &mut notes,
    )?;
    modes.extend(found);
    let assemblies = if options.assemblies {
        assemblies(m, options, &mut notes)
    } else {
        notes.push("Assemblies not computed (--no-assemblies).".to_string());
        Vec::new()
    };
    Ok(View {
        format: FORMAT,
        scene: Scene::of(m),
        start,
        inputs: input_texts(m, &inputs),
        classification,
        sweeps,
        modes,
        assemblies,
        notes,
    })
}

/// One walk per pattern reached by locking inputs (its first minimal lock set), every lock
/// subset sampled when there are at most [`MAX_MODE_SUBSETS`], else those of the most locks
/// that stay within it.
fn modes(
    m: &Manipulator,
    start: &[f64],
    settings: &SampleSettings,
    (steps, budget): (usize, &mut usize),
    notes: &mut Vec<String>,
) -> Result<Vec<ModeView>, Error> {
    let n = m.actuators().len();
    let max_locks = (0..=n)
        .take_while(|&k| m.lock_subset_count(k) <= MAX_MODE_SUBSETS)
        .last()
        .unwrap_or(0);
    if max_locks < n {
        notes.push(format!(
            "Modes: the lock subsets of at most {max_locks} of the {n} inputs ({} subsets).",
            m.lock_subset_count(max_locks)
        ));
    }
    let subsets = m.lock_subsets(max_locks);
    let bar = crate::terminal::progress(subsets.len(), "lock subsets", "view: modes");
    let sampled = m.modes_from(start, &subsets, settings, &|| bar.inc(1));
    bar.finish_and_clear();
    let patterns = sampled.groups.len() + sampled.non_groups.len();
    *budget = counted(
        *budget,
        patterns,
        steps,
        &format!("the walks of {patterns} operation modes"),
    )?;
    let mut out = Vec::new();
    for p in sampled.groups.iter().chain(&sampled.non_groups) {
        let Some(text) = p.lock_sets.first() else {
            continue;
        };
        let locked = if text == "-" {
            Vec::new()
        } else {
            match m.parse_locks(&text.replace(' ', ",")) {
                Ok(l) => l,
                Err(_) => continue,
            }
        };
        let walk = mode_walk(m, start, &locked, steps);
        out.push(ModeView {
            source: "modes".to_string(),
            locks: text.clone(),
            pattern: p.pattern.to_string(),
            dof: p.dof,
            group: sampled.groups.iter().any(|g| std::ptr::eq(g, p)),
            parameters: p.parameters.clone(),
            joint_values: walk.joint_values,
            start: walk.start,
            stops: walk.stops,
        });
    }
    if !sampled.singular_starts.is_empty() {
        notes.push(format!(
            "Modes not shown: the start is singular with {} locked.",
            sampled.singular_starts.join("; ")
        ));
    }
    Ok(out)
}

/// One walk per component of the global decomposition (`kinsyn components`) that has a real
/// point at which the mechanism can be placed and moves there: from that point, with the held
/// inputs locked. The decomposition's refusal (past its path limit) is an input error: it was
/// asked for.
fn components(
    m: &Manipulator,
    options: &ViewOptions,
    budget: &mut usize,
    notes: &mut Vec<String>,
) -> Result<Vec<ModeView>, Error> {
    let asked = ComponentsOptions {
        seed: options.seed,
        method: kinsyn::manipulator::DecompositionMethod::default(),
        inputs: options.inputs.clone(),
        free_inputs: options.free_inputs,
        free: None,
        body: None,
        max_paths: options.max_paths,
    };
    let settings = DecomposeSettings {
        seed: options.seed,
        max_paths: options.max_paths,
        ..DecomposeSettings::default()
    };
    let found = manipulator_components_of(m.clone(), m.name(), &asked, settings)
        .map_err(|e| Error::Input(format!("--components: {e}")))?;
    let Decomposed::Manipulator { mechanism, .. } = &found.decomposed else {
        return Ok(Vec::new());
    };
    let moving = mechanism
        .iter()
        .filter(|on| matches!(on, Some(Ok(c)) if c.mode.dof > 0))
        .count();
    *budget = counted(
        *budget,
        moving,
        options.steps,
        &format!("the walks of {moving} components"),
    )?;
    let mut out = Vec::new();
    let (mut complex, mut unplaced) = (0, 0);
    for (k, on) in mechanism.iter().enumerate() {
        match on {
            None => complex += 1,
            Some(Err(_)) => unplaced += 1,
            Some(Ok(c)) if c.mode.dof > 0 => {
                let walk = mode_walk(m, &c.q, &c.held, options.steps);
                out.push(ModeView {
                    source: format!("components: component {}", k + 1),
                    locks: m.lock_text(&c.held),
                    pattern: c.mode.pattern_text(),
                    dof: c.mode.dof,
                    group: c.mode.group,
                    parameters: c.mode.parameters.clone(),
                    joint_values: walk.joint_values,
                    start: walk.start,
                    stops: walk.stops,
                });
            }
            Some(Ok(_)) => {}
        }
    }
    if complex + unplaced > 0 {
        notes.push(format!(
            "Components not animated: {complex} without a real point, {unplaced} where the mechanism could not be placed."
        ));
    }
    Ok(out)
}

/// The real assemblies at the view's inputs as joint values, or none with a note saying why.
fn assemblies(
    m: &Manipulator,
    options: &ViewOptions,
    notes: &mut Vec<String>,
) -> Vec<AssemblyView> {
    let all = match all_assemblies_of(m, options.inputs.as_deref(), options.seed) {
        Ok(all) => all,
        Err(e) => {
            notes.push(format!("Assemblies not computed: {e}"));
            return Vec::new();
        }
    };
    let mut out = Vec::new();
    let mut missed = 0;
    for (k, a) in all.assemblies.iter().enumerate() {
        match m.assemble_at_frames(&a.frames, &all.inputs) {
            Ok(q) => out.push(AssemblyView {
                label: format!("assembly {}", k + 1),
                certified: a.certified,
                continued_from_reference: a.current,
                joint_values: q,
            }),
            Err(_) => missed += 1,
        }
    }
    if all.combinations > all.assemblies.len() as u128 {
        notes.push(format!(
            "Assemblies: the first {} of {} real combinations.",
            all.assemblies.len(),
            all.combinations
        ));
    }
    if missed > 0 {
        notes.push(format!(
            "Assemblies: {missed} real assemblies found whose legs' joint values could not be solved are not shown."
        ));
    }
    out
}
