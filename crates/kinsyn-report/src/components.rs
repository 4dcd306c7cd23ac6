//! `kinsyn components`: the irreducible components of a polynomial system (a Bertini input
//! file) or of a manipulator's constraint variety — its assemblies, self-motions and operation
//! modes — by numerical irreducible decomposition (docs/operation-modes.md).

use crate::manipulator::{input_texts, inputs_or_reference, load, pose_text};
use crate::solve::{paths_text, read_input, weighted_paths};
use crate::{Error, terminal};
use itertools::Itertools;
use kinsyn::homotopy::{
    DecomposeError, DecomposeSettings, Decomposition, MAX_DECOMPOSE_PATHS, RegenerationProgress,
    decompose, decompose_paths, regenerate_with_progress, regeneration_paths,
};
use kinsyn::manipulator::{
    BlockModes, BlockPart, ComponentMotion, DecompositionMethod, InputValues, LocalMotion,
    Manipulator, OperationModeError, OperationModeSettings,
};
use kinsyn::mechanism::SampleSettings;
use kinsyn::poly::{C64, System};
use serde::Serialize;
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
    /// For a manipulator: some inputs unknowns (their labels, `--free`), the others held.
    pub free: Option<String>,
    /// For a manipulator: the body whose motion is classified on each component (`--body`),
    /// the end-effector when `None`.
    pub body: Option<String>,
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

/// A decomposition as `kinsyn components` runs it: of a polynomial system, or of a
/// manipulator's constraint variety.
pub struct Components {
    /// The options it ran with.
    pub options: ComponentsOptions,
    /// What was decomposed, and the result.
    pub decomposed: Decomposed,
}

/// What `kinsyn components` decomposed, and the result.
pub enum Decomposed {
    /// A Bertini input file's system.
    System {
        /// The file, as messages name it.
        source: String,
        /// The system.
        system: System,
        /// Its components.
        decomposition: Decomposition,
    },
    /// A manipulator's constraint variety.
    Manipulator {
        /// The manipulator.
        m: Box<Manipulator>,
        /// The operation modes (or assemblies and self-motions at given inputs) of each block
        /// of its body tree, parents first: one block for a one-platform manipulator.
        blocks: Vec<BlockModes>,
        /// Its inputs as `LABEL = value` ([`input_texts`]).
        inputs: Vec<String>,
        /// The whole mechanism on each of its components (one block: the block's; several:
        /// the products of one component per block, in [`product_factors`] order) at the
        /// component's first real point: `None` for a component without one, an `Err` with
        /// the reason where the mechanism could not be placed there.
        mechanism: Vec<Option<Result<ComponentMotion, String>>>,
        /// The free inputs (indices into [`Manipulator::actuators`]): all with
        /// `--free-inputs`, those of `--free`, none at given inputs.
        free: Vec<usize>,
    },
}

/// The factors of the products of one component per block (each block's component index),
/// in the order the products are reported.
#[must_use]
pub fn product_factors(counts: &[usize]) -> Vec<Vec<usize>> {
    counts
        .iter()
        .map(|&n| 0..n)
        .multi_cartesian_product()
        .collect()
}

/// The most products of components the whole mechanism is placed on (each a continuation
/// and a sampled motion); the others are reported without it.
pub const MAX_PLACED_PRODUCTS: usize = 256;

/// The inputs `text` names free (`--free`, labels such as `R1.1` separated by commas), none
/// of which `given` (the text of `--inputs`) may give a value.
fn free_labels(m: &Manipulator, text: &str, given: Option<&str>) -> Result<Vec<usize>, Error> {
    let free = m
        .parse_locks(text)
        .map_err(|e| Error::Input(format!("--free {text:?}: {e}")))?;
    if free.is_empty() {
        return Err(Error::Input(format!(
            "--free {text:?}: name at least one input (e.g. {}); --free-inputs frees them all",
            m.actuators()
                .first()
                .map_or_else(String::new, kinsyn::manipulator::Actuator::label)
        )));
    }
    if let Some(given) = given {
        let named = m
            .parse_inputs(given)
            .map_err(|e| Error::Input(format!("--inputs {given:?}: {e}")))?;
        if let Some((a, _)) = named.iter().find(|(a, _)| free.contains(a)) {
            return Err(Error::Input(format!(
                "--free {text:?}: {} is given a value by --inputs too; a free input is an unknown",
                m.actuators()[*a].label()
            )));
        }
    }
    Ok(free)
}

/// The most real points of a component tried for placing the whole mechanism.
const MAX_PLACEMENT_TRIES: usize = 16;

/// The whole mechanism on each component of `blocks` ([`Decomposed::Manipulator`]'s
/// `mechanism`), the inputs `held` locked.
fn mechanism_on_components(
    m: &Manipulator,
    blocks: &[BlockModes],
    held: &[(usize, f64)],
) -> Vec<Option<Result<ComponentMotion, String>>> {
    let parts: Vec<BlockPart<'_>> = blocks
        .iter()
        .map(|b| (b.parent, b.body, &b.modes.system))
        .collect();
    let counts: Vec<usize> = blocks.iter().map(|b| b.modes.components.len()).collect();
    let settings = SampleSettings::default();
    product_factors(&counts)
        .into_iter()
        .enumerate()
        .map(|(k, pick)| {
            if k >= MAX_PLACED_PRODUCTS {
                return None;
            }
            let factors: Vec<&Vec<Vec<f64>>> = pick
                .iter()
                .zip(blocks)
                .map(|(&c, b)| &b.modes.components[c].real_points)
                .collect();
            let most = factors.iter().map(|p| p.len()).max()?;
            if factors.iter().any(|p| p.is_empty()) {
                return None;
            }
            // The first real point (of each factor, side by side) that the legs reach.
            let mut last = None;
            for k in 0..most.min(MAX_PLACEMENT_TRIES) {
                let points: Vec<Option<&[f64]>> = factors
                    .iter()
                    .map(|p| Some(p[k % p.len()].as_slice()))
                    .collect();
                match m.component_motion(&parts, &points, held, &settings) {
                    Ok(c) => return Some(Ok(c)),
                    Err(e) => last = Some(e.to_string()),
                }
            }
            last.map(Err)
        })
        .collect()
}

/// The irreducible components of the file at `path`: of its system (a Bertini input file) or
/// of its manipulator's constraint variety (a description), decomposed as `options` say, with
/// feedback on stderr when it is a terminal.
///
/// # Errors
///
/// [`Error::Input`]: a file that cannot be read or is neither kind, `--inputs` or
/// `--free-inputs` for a polynomial system, malformed input values, a manipulator whose legs
/// have no polynomial form, or a decomposition that fails.
pub fn components_of(path: &Path, options: &ComponentsOptions) -> Result<Components, Error> {
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
        return manipulator_components(path, options, settings);
    }
    if options.inputs.is_some()
        || options.free_inputs
        || options.free.is_some()
        || options.body.is_some()
    {
        return Err(Error::Input(format!(
            "{}: --inputs, --free-inputs, --free and --body apply to manipulator files, not to polynomial systems",
            path.display()
        )));
    }
    let input = read_input(path)?;
    let system = input.system;
    let estimate = match options.method {
        DecompositionMethod::Regeneration => regeneration_paths(&system),
        DecompositionMethod::ByDimension => decompose_paths(&system),
    };
    let decomposition = with_feedback(options.method, Some(estimate), |progress| {
        match options.method {
            DecompositionMethod::Regeneration => {
                regenerate_with_progress(&system, &settings, progress)
            }
            DecompositionMethod::ByDimension => decompose(&system, &settings),
        }
    })
    .map_err(|e| {
        refusal(
            &path.display().to_string(),
            options.method,
            Some(&system),
            &e,
        )
    })?;
    Ok(Components {
        options: options.clone(),
        decomposed: Decomposed::System {
            source: path.display().to_string(),
            system,
            decomposition,
        },
    })
}

impl Components {
    /// The report of `kinsyn components --json`.
    #[must_use]
    pub fn report(&self) -> ComponentsReport {
        let options = &self.options;
        match &self.decomposed {
            Decomposed::System {
                source,
                system,
                decomposition,
            } => ComponentsReport::System(SystemComponentsReport {
                file: source.clone(),
                decomposition: DecompositionReport::new(system, decomposition, options),
                components: decomposition
                    .components
                    .iter()
                    .map(|c| SystemComponent {
                        component: ComponentSummary {
                            dimension: c.dimension,
                            degree: c.degree,
                            multiplicity: c.multiplicity,
                            trace_test_passed: c.trace_test_passed,
                            sample_point: complex(&c.sample_point),
                        },
                        witness_points: c.witness_points.iter().map(|x| complex(x)).collect(),
                    })
                    .collect(),
            }),
            Decomposed::Manipulator {
                m,
                blocks,
                inputs,
                mechanism,
                free: free_inputs,
            } => {
                let reports: Vec<BlockComponentsReport> = blocks
                    .iter()
                    .map(|b| BlockComponentsReport::new(m, b, options))
                    .collect();
                let free = blocks.first().is_some_and(|b| b.modes.free_inputs);
                let (decomposition, mut components, blocks) = if let [one] = &reports[..] {
                    (
                        one.decomposition.clone(),
                        one.components.clone(),
                        Vec::new(),
                    )
                } else {
                    (
                        DecompositionReport::of_blocks(&reports),
                        products(&reports),
                        reports,
                    )
                };
                for (c, on) in components.iter_mut().zip(mechanism) {
                    c.mechanism = on.as_ref().map(|r| MechanismReport::new(m, r.as_ref()));
                }
                ComponentsReport::Manipulator(ManipulatorComponentsReport {
                    manipulator: m.name().to_string(),
                    free_inputs: free_inputs
                        .iter()
                        .map(|&a| m.actuators()[a].label())
                        .collect(),
                    inputs: if free {
                        ComponentInputs::Free
                    } else {
                        ComponentInputs::Given(inputs.clone())
                    },
                    decomposition,
                    components,
                    blocks,
                })
            }
        }
    }
}

/// The components of a mechanism of several blocks: the products of one component per block
/// (dimensions add, degrees multiply, a point is the blocks' points side by side), each
/// naming its factors; the motion is reported per block.
fn products(blocks: &[BlockComponentsReport]) -> Vec<ModeComponentReport> {
    let counts: Vec<usize> = blocks.iter().map(|b| b.components.len()).collect();
    product_factors(&counts)
        .into_iter()
        .map(|pick| {
            let factors: Vec<&ModeComponentReport> = pick
                .iter()
                .zip(blocks)
                .map(|(&k, b)| &b.components[k])
                .collect();
            ModeComponentReport {
                component: ComponentSummary {
                    dimension: factors.iter().map(|f| f.component.dimension).sum(),
                    degree: factors
                        .iter()
                        .fold(1_usize, |d, f| d.saturating_mul(f.component.degree)),
                    multiplicity: factors
                        .iter()
                        .fold(1_usize, |d, f| d.saturating_mul(f.component.multiplicity)),
                    trace_test_passed: factors.iter().all(|f| f.component.trace_test_passed),
                    sample_point: factors
                        .iter()
                        .flat_map(|f| f.component.sample_point.iter().copied())
                        .collect(),
                },
                real_points: factors
                    .iter()
                    .fold(1_usize, |n, f| n.saturating_mul(f.real_points)),
                motion: None,
                released: None,
                mechanism: None,
                factors: pick,
            }
        })
        .collect()
}

impl BlockComponentsReport {
    /// The report of one block's components.
    fn new(m: &Manipulator, b: &BlockModes, options: &ComponentsOptions) -> Self {
        let modes = &b.modes;
        let name = |k: Option<usize>| {
            k.map_or_else(
                || m.ground_name().to_string(),
                |k| m.bodies()[k].name.clone(),
            )
        };
        Self {
            body: name(Some(b.body)),
            parent: name(b.parent),
            decomposition: DecompositionReport::new(
                modes.system.system(),
                &modes.decomposition,
                options,
            ),
            components: modes
                .components
                .iter()
                .map(|c| ModeComponentReport {
                    component: ComponentSummary {
                        dimension: c.dimension,
                        degree: c.degree,
                        multiplicity: c.multiplicity,
                        trace_test_passed: c.trace_test_passed,
                        sample_point: complex(&c.sample),
                    },
                    real_points: c.real_points.len(),
                    motion: c.real.as_ref().map(|l| LocalMotionReport::new(m, l)),
                    released: c.released.as_ref().map(|l| LocalMotionReport::new(m, l)),
                    mechanism: None,
                    factors: Vec::new(),
                })
                .collect(),
        }
    }
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

/// The method's name as `--method` takes it: `regeneration` or `by-dimension`.
#[must_use]
pub fn method_name(m: DecompositionMethod) -> &'static str {
    match m {
        DecompositionMethod::Regeneration => "regeneration",
        DecompositionMethod::ByDimension => "by-dimension",
    }
}

fn complex(x: &[C64]) -> Vec<[f64; 2]> {
    x.iter().map(|c| [c.re, c.im]).collect()
}

/// [`components_of`] for the description at `path`.
fn manipulator_components(
    path: &Path,
    options: &ComponentsOptions,
    decompose: DecomposeSettings,
) -> Result<Components, Error> {
    manipulator_components_of(load(path)?, &path.display().to_string(), options, decompose)
}

/// The operation modes of the manipulator `m` (named `source` in messages) as `kinsyn
/// components FILE` finds them with `options` (the end-effector, inputs held or free) and the
/// decomposition's `settings`.
///
/// # Errors
/// As [`components_of`] for a manipulator file.
pub fn manipulator_components_of(
    m: Manipulator,
    source: &str,
    options: &ComponentsOptions,
    decompose: DecomposeSettings,
) -> Result<Components, Error> {
    let m = match &options.body {
        None => m,
        Some(name) => m
            .with_end_effector(name)
            .map_err(|e| Error::Input(format!("--body {name:?}: {e}")))?,
    };
    if options.free_inputs && options.inputs.is_some() {
        return Err(Error::Input(
            "--free-inputs and --inputs exclude each other: free inputs are unknowns".into(),
        ));
    }
    let free: Vec<usize> = match (&options.free, options.free_inputs) {
        (Some(text), _) => free_labels(&m, text, options.inputs.as_deref())?,
        (None, true) => (0..m.actuators().len()).collect(),
        (None, false) => Vec::new(),
    };
    let all = inputs_or_reference(&m, options.inputs.as_deref())?;
    let held: Vec<(usize, f64)> = all
        .iter()
        .copied()
        .filter(|(a, _)| !free.contains(a))
        .collect();
    let inputs = if held.is_empty() {
        InputValues::Free
    } else {
        InputValues::Given(&held)
    };
    let settings = OperationModeSettings {
        decompose,
        method: options.method,
        ..OperationModeSettings::default()
    };
    let blocks = with_feedback(options.method, None, |progress| {
        m.block_operation_modes_with_progress(&inputs, &settings, progress)
    })
    .map_err(|e| match e {
        OperationModeError::Decompose(e) => refusal(source, options.method, None, &e),
        other @ OperationModeError::System(_) => Error::Input(format!("{source}: {other}")),
    })?;
    let inputs = input_texts(&m, &held);
    let mechanism = mechanism_on_components(&m, &blocks, &held);
    Ok(Components {
        options: options.clone(),
        decomposed: Decomposed::Manipulator {
            m: Box::new(m),
            blocks,
            inputs,
            mechanism,
            free,
        },
    })
}

/// The report of `kinsyn components --json` (and of Python's `components`): a polynomial
/// system's irreducible components, or a manipulator's.
///
/// Printed through [`crate::sorted_value`]: its keys come in alphabetical order, as they did
/// when the report was built with `serde_json::json!`, not in the order of the fields.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum ComponentsReport {
    /// The components of a Bertini input file's system.
    System(SystemComponentsReport),
    /// The components of a manipulator's constraint variety.
    Manipulator(ManipulatorComponentsReport),
}

/// The irreducible components of a Bertini input file's system.
#[derive(Debug, Clone, Serialize)]
pub struct SystemComponentsReport {
    /// The file, as given.
    pub file: String,
    /// The system and the decomposition's counts, at the top level of the report.
    #[serde(flatten)]
    pub decomposition: DecompositionReport,
    /// The components found, each with its witness set.
    pub components: Vec<SystemComponent>,
}

/// The irreducible components of a manipulator's constraint variety (paper 004): in the Study
/// parameters of the platform (`x0² + x1² + x2² + x3² = 1`, so each pose is two points
/// `±(x, y)`) and, with free inputs, the tangents of the inputs' half angles.
#[derive(Debug, Clone, Serialize)]
pub struct ManipulatorComponentsReport {
    /// The manipulator's name (the description's `name`).
    pub manipulator: String,
    /// The inputs: given (those held, when some are free), or free (unknowns).
    pub inputs: ComponentInputs,
    /// The free inputs' labels: all with `--free-inputs`, those of `--free`, none at given
    /// inputs.
    pub free_inputs: Vec<String>,
    /// The constraint system and the decomposition's counts, at the top level of the report.
    #[serde(flatten)]
    pub decomposition: DecompositionReport,
    /// The components found: assemblies (dimension 0) and self-motions, or operation modes
    /// with free inputs. Of several moving bodies: the products of one component per block
    /// (each naming its `factors`).
    pub components: Vec<ModeComponentReport>,
    /// Of several moving bodies: each block of the body tree (a body's frame relative to its
    /// parent's), decomposed on its own, parents first; empty for one platform. The
    /// decomposition's counts above are then the blocks' summed.
    pub blocks: Vec<BlockComponentsReport>,
}

/// One block of a manipulator's body tree in [`ManipulatorComponentsReport::blocks`]: a moving
/// body's frame relative to its parent's, and its components.
#[derive(Debug, Clone, Serialize)]
pub struct BlockComponentsReport {
    /// The body's name.
    pub body: String,
    /// Its parent's name (the ground's for a body the ground holds).
    pub parent: String,
    /// Its constraint system and the decomposition's counts, at the top level of the entry.
    #[serde(flatten)]
    pub decomposition: DecompositionReport,
    /// Its components, the motion that of the body relative to its parent.
    pub components: Vec<ModeComponentReport>,
}

/// The inputs of a manipulator's decomposition.
#[derive(Debug, Clone, Serialize)]
pub enum ComponentInputs {
    /// `--free-inputs`: every input an unknown; `"free"` in JSON.
    #[serde(rename = "free")]
    Free,
    /// Every input's value, `LABEL = value` (angles in the description's angle unit); a list
    /// in JSON.
    #[serde(untagged)]
    Given(Vec<String>),
}

/// The system decomposed and the decomposition's counts, the same for a Bertini file and for
/// a manipulator.
#[derive(Debug, Clone, Serialize)]
pub struct DecompositionReport {
    /// The unknowns' names.
    pub variables: Vec<String>,
    /// How many equations.
    pub equations: usize,
    /// The algorithm: `by-dimension` or `regeneration`.
    pub method: &'static str,
    /// The seed of every random choice.
    pub seed: u64,
    /// Singular witness points on no component found, by dimension: points that stayed
    /// singular after deflation.
    pub unresolved: Vec<UnresolvedPoint>,
    /// The junk points removed (witness points of higher-dimensional components).
    pub junk: usize,
    /// The paths tracked in all.
    pub paths: usize,
    /// The paths the start systems were estimated at before any was tracked, as decimal text.
    pub estimated_paths: String,
    /// The decomposition's wall-clock time (seconds).
    pub seconds: f64,
}

/// A singular witness point on no component found.
#[derive(Debug, Clone, Serialize)]
pub struct UnresolvedPoint {
    /// The dimension it was found at.
    pub dimension: usize,
    /// The point: each variable as `[re, im]`.
    pub point: Vec<[f64; 2]>,
}

/// What every irreducible component reports.
#[derive(Debug, Clone, Serialize)]
pub struct ComponentSummary {
    /// Its dimension (for a manipulator: its dof).
    pub dimension: usize,
    /// Its degree: the points it meets a generic linear space of complementary dimension in.
    pub degree: usize,
    /// Its multiplicity: 1 when reduced; at least 2 for a non-reduced component, found by
    /// deflation (a product of blocks: the product of its factors').
    pub multiplicity: usize,
    /// Whether the trace test confirmed its witness set is one irreducible component (false:
    /// perhaps a union of components).
    pub trace_test_passed: bool,
    /// A point on it: each variable as `[re, im]`.
    pub sample_point: Vec<[f64; 2]>,
}

/// An irreducible component of a polynomial system.
#[derive(Debug, Clone, Serialize)]
pub struct SystemComponent {
    /// Its dimension, degree, trace test and a point, at the top level of the entry.
    #[serde(flatten)]
    pub component: ComponentSummary,
    /// Its witness points (as many as its degree): each variable as `[re, im]`.
    pub witness_points: Vec<Vec<[f64; 2]>>,
}

/// An irreducible component of a manipulator's constraint variety.
#[derive(Debug, Clone, Serialize)]
pub struct ModeComponentReport {
    /// Its dimension, degree, trace test and a point, at the top level of the entry.
    #[serde(flatten)]
    pub component: ComponentSummary,
    /// How many real points were found on it (on 8 real slices for a positive dimension).
    pub real_points: usize,
    /// The platform's motion at its first real point; `null` for a complex component.
    pub motion: Option<LocalMotionReport>,
    /// At an assembly (dimension 0, given inputs): the platform's motion on the operation mode
    /// with the inputs released; `null` otherwise, or where it was not found.
    pub released: Option<LocalMotionReport>,
    /// The whole mechanism at its first real point (every body placed there, the legs'
    /// joints by assembly): the end-effector's motion with the held inputs locked, and the
    /// inputs that move; `null` for a complex component and in a block's own list.
    pub mechanism: Option<MechanismReport>,
    /// Of a product of the blocks' components (several moving bodies): the index of its
    /// factor in each block's `components`; empty otherwise.
    pub factors: Vec<usize>,
}

/// The whole mechanism at a real point of a component ([`ComponentMotion`]).
#[derive(Debug, Clone, Serialize)]
pub struct MechanismReport {
    /// The body whose motion is classified: the end-effector (or `--body`).
    pub body: String,
    /// Its dof there with the held inputs locked; `null` where the mechanism could not be
    /// placed.
    pub dof: Option<usize>,
    /// The pattern of its motion (`3T`, `X(z)`, `1T2R`, …; `?` where it could not be sampled).
    pub pattern: Option<String>,
    /// Whether the pattern is one of the 12 displacement groups.
    pub group: bool,
    /// The inputs that move on the component (labels such as `R1.1`).
    pub moving_inputs: Vec<String>,
    /// The inputs held at their given values.
    pub held_inputs: Vec<String>,
    /// The free inputs that do not move on the component.
    pub still_inputs: Vec<String>,
    /// Why the mechanism could not be placed at the point, if it could not.
    pub error: Option<String>,
}

impl MechanismReport {
    /// The report of the mechanism `m` placed on a component (or why it could not be).
    #[must_use]
    pub fn new(m: &Manipulator, on: Result<&ComponentMotion, &String>) -> Self {
        let body = m
            .bodies()
            .get(m.end_effector())
            .map_or_else(|| "platform".to_string(), |b| b.name.clone());
        match on {
            Err(e) => Self {
                body,
                dof: None,
                pattern: None,
                group: false,
                moving_inputs: Vec::new(),
                held_inputs: Vec::new(),
                still_inputs: Vec::new(),
                error: Some(e.clone()),
            },
            Ok(c) => {
                let label = |a: usize| m.actuators()[a].label();
                let (moving, other): (Vec<usize>, Vec<usize>) =
                    (0..m.actuators().len()).partition(|&a| c.moving[a]);
                let (held, still): (Vec<usize>, Vec<usize>) =
                    other.into_iter().partition(|a| c.held.contains(a));
                Self {
                    body,
                    dof: Some(c.mode.dof),
                    pattern: Some(
                        c.mode
                            .pattern
                            .as_ref()
                            .map_or_else(|| "?".to_string(), ToString::to_string),
                    ),
                    group: c.mode.group,
                    moving_inputs: moving.into_iter().map(label).collect(),
                    held_inputs: held.into_iter().map(label).collect(),
                    still_inputs: still.into_iter().map(label).collect(),
                    error: c.mode.error.clone(),
                }
            }
        }
    }
}

/// The platform's motion at a real point of a component.
#[derive(Debug, Clone, Serialize)]
pub struct LocalMotionReport {
    /// The platform's pose there as `--pose` takes it: `x,y,z,rx,ry,rz` (length unit, the
    /// rotation vector in the description's angle unit).
    pub pose: String,
    /// The component's dimension at the point: the platform's dof there.
    pub dof: usize,
    /// The pattern of the motion (`3T`, `X(z)`, `1T2R`, …).
    pub pattern: String,
    /// Whether the pattern is one of the 12 displacement groups.
    pub group: bool,
    /// Whether the twist spaces agreed at every sample of the motion.
    pub same_span: bool,
    /// The smallest distance between two samples (dimensionless), `null` with fewer than two.
    pub min_separation: Option<f64>,
    /// The real point: the system's variables.
    pub point: Vec<f64>,
}

impl DecompositionReport {
    /// The counts of the blocks' decompositions together: their variables (each named after its
    /// body) and equations side by side, the points, paths and times summed.
    fn of_blocks(blocks: &[BlockComponentsReport]) -> Self {
        let first = &blocks[0].decomposition;
        Self {
            variables: blocks
                .iter()
                .flat_map(|b| {
                    b.decomposition
                        .variables
                        .iter()
                        .map(move |v| format!("{}.{v}", b.body))
                })
                .collect(),
            equations: blocks.iter().map(|b| b.decomposition.equations).sum(),
            method: first.method,
            seed: first.seed,
            unresolved: Vec::new(),
            junk: blocks.iter().map(|b| b.decomposition.junk).sum(),
            paths: blocks.iter().map(|b| b.decomposition.paths).sum(),
            estimated_paths: blocks
                .iter()
                .map(|b| b.decomposition.estimated_paths.parse::<u128>().unwrap_or(0))
                .sum::<u128>()
                .to_string(),
            seconds: blocks.iter().map(|b| b.decomposition.seconds).sum(),
        }
    }

    /// The report of the decomposition `d` of `system`, run with `options`.
    fn new(system: &System, d: &Decomposition, options: &ComponentsOptions) -> Self {
        Self {
            variables: system.variables().to_vec(),
            equations: system.len(),
            method: method_name(options.method),
            seed: options.seed,
            unresolved: d
                .unresolved
                .iter()
                .map(|(dimension, x)| UnresolvedPoint {
                    dimension: *dimension,
                    point: complex(x),
                })
                .collect(),
            junk: d.junk,
            paths: d.paths,
            estimated_paths: d.estimated_paths.to_string(),
            seconds: d.seconds,
        }
    }
}

impl LocalMotionReport {
    /// The report of the motion `l` of `m`'s platform.
    fn new(m: &Manipulator, l: &LocalMotion) -> Self {
        Self {
            pose: pose_text(m, &l.pose),
            dof: l.dof,
            pattern: l.motion.pattern.name().to_string(),
            group: l.motion.pattern.is_group(),
            same_span: l.motion.same_span,
            min_separation: l.motion.min_separation,
            point: l.point.clone(),
        }
    }
}
