//! `kinsyn build`, `kinsyn modes`, `kinsyn analyze`: manipulators from description files. This
//! module reads a file (`load`, refusing what is not a description) and builds one (`build`);
//! `modes` and `analyze` are in their own files, each returning what it found as typed values
//! ([`Loaded`]); the front ends print them.

mod analyze;
mod assemblies;
mod modes;

pub use analyze::{
    AnalyzeReport, Analyzed, BodyReport, HeldInputs, JacobianRow, ModuleReport, NearestReport,
    Placement, RankGap, RankReport, RelativeMotionReport, SeriesParallelReport, StudyReport,
    analyse_placed, analyze,
};
pub use assemblies::{
    AllAssemblies, AssembliesReport, Assembly, AssemblyCounts, BlockAssemblies, BlockReport,
    BodyPose, Formulation, MAX_COMBINATIONS, RealAssembly, all_assemblies, all_assemblies_of,
    pose_text, start_groups,
};
pub use modes::{
    DEFAULT_MAX_SUBSETS, MAX_SAMPLES, MAX_SUBSETS_CEILING, ModesReport, Selection, modes,
    modes_report, sample_modes,
};

use crate::Error;
use crate::output::OutputFile;
use kinsyn::manipulator::build::{BuildField, BuildSpec, build};
use kinsyn::manipulator::file::Description;
use kinsyn::manipulator::{Manipulator, ManipulatorError, file};
use std::path::Path;

/// Reads and builds a manipulator file; errors name the file and the field. A path that is
/// not a regular file, a file over [`crate::files::MAX_FILE_BYTES`], or text that is not UTF-8 or not a
/// description is refused as "not a kinsyn manipulator file" before it is parsed further.
///
/// # Errors
/// [`Error::Input`] for a path that is not a readable regular file within the size limit, or text that is not a description (naming the field).
pub fn load(path: &Path) -> Result<Manipulator, Error> {
    let text = crate::files::read_text(path, file::NOT_A_DESCRIPTION)?;
    parse_description(&text, &path.display().to_string())
}

/// The manipulator the description `text` describes, `source` naming it in messages (the
/// file's path, or `<string>`).
///
/// # Errors
///
/// [`Error::Input`]: `SOURCE is not a kinsyn manipulator file (why)` when the text is not a
/// description, `SOURCE: …` naming the faulty field otherwise.
pub fn parse_description(text: &str, source: &str) -> Result<Manipulator, Error> {
    Manipulator::from_json(text).map_err(|e| match &e {
        ManipulatorError::Description(d) if d.is_not_a_description() => {
            Error::Input(format!("{source} is {}", d.message))
        }
        _ => Error::Input(format!("{source}: {e}")),
    })
}

/// The description a file holds, as the description of several bodies (a `/1` file as its `/2`
/// form), without building the mechanism.
///
/// # Errors
/// As [`load`].
pub fn load_description(path: &Path) -> Result<file::MultibodyDescription, Error> {
    let text = crate::files::read_text(path, file::NOT_A_DESCRIPTION)?;
    parse_multibody(&text, &path.display().to_string())
}

/// The description `text` as the description of several bodies (a `/1` description as its `/2`
/// form), `source` naming it in messages, without building the mechanism.
fn parse_multibody(text: &str, source: &str) -> Result<file::MultibodyDescription, Error> {
    file::MultibodyDescription::from_json(text).map_err(|e| {
        if e.is_not_a_description() {
            Error::Input(format!("{source} is {}", e.message))
        } else {
            Error::Input(format!("{source}: {e}"))
        }
    })
}

/// The manipulator the description `text` describes (`source` naming it in messages) cut down
/// to the legs of `legs` (`--legs 1-4,29`) and the bodies they still join to the ground: the
/// sub-mechanism, its end-effector `body` when given.
///
/// # Errors
///
/// [`Error::Input`]: what [`parse_description`] refuses, or `--legs "…": …` for a malformed
/// leg list or one that leaves no mechanism.
pub fn parse_description_legs(
    text: &str,
    source: &str,
    legs: &str,
    body: Option<&str>,
) -> Result<Manipulator, Error> {
    let d = parse_multibody(text, source)?;
    let refuse = |e: &dyn std::fmt::Display| Error::Input(format!("--legs {legs:?}: {e}"));
    let kept = kinsyn::manipulator::parse_leg_list(legs, d.legs.len())
        .and_then(|list| d.with_legs(&list, body))
        .map_err(|e| refuse(&e))?;
    Manipulator::from_bodies(&kept).map_err(|e| refuse(&e))
}

/// `m` with the moving body `body` (`--body NAME`) as the end-effector when given, and its
/// motion taken relative to the moving body `relative` (`--relative-to NAME`) when given.
///
/// # Errors
///
/// [`Error::Input`]: `--body "…": …` or `--relative-to "…": …` for a body the manipulator
/// does not have.
pub fn select_body(
    m: Manipulator,
    body: Option<&str>,
    relative: Option<&str>,
) -> Result<Manipulator, Error> {
    let m = match body {
        None => m,
        Some(name) => m
            .with_end_effector(name)
            .map_err(|e| Error::Input(format!("--body {name:?}: {e}")))?,
    };
    match relative {
        None => Ok(m),
        Some(name) => m
            .relative_to(name)
            .map_err(|e| Error::Input(format!("--relative-to {name:?}: {e}"))),
    }
}

/// [`load`], cut down to the legs `legs` (`--legs`, [`parse_description_legs`]) when given,
/// with the end-effector and reference body of [`select_body`].
fn load_with_body(
    path: &Path,
    body: Option<&str>,
    relative: Option<&str>,
    legs: Option<&str>,
) -> Result<Manipulator, Error> {
    let m = match legs {
        Some(list) => {
            let text = crate::files::read_text(path, file::NOT_A_DESCRIPTION)?;
            parse_description_legs(&text, &path.display().to_string(), list, body)?
        }
        None => load(path)?,
    };
    select_body(m, body, relative)
}

/// The leg warnings of `m` (docs/mechanism-format.md, "Leg checks").
fn leg_warnings(m: &Manipulator) -> Vec<String> {
    m.leg_warnings().iter().map(ToString::to_string).collect()
}

/// A manipulator read for a command (`analyze`, `modes`, `analyze --all-assemblies`), what the
/// command found on it, and the description's leg warnings, for the front end to print or hand
/// on.
pub struct Loaded<T> {
    /// The manipulator, with the end-effector (`--body`) and reference body (`--relative-to`)
    /// asked for.
    pub manipulator: Manipulator,
    /// What the command found.
    pub result: T,
    /// The leg warnings of the description, one line each, without the file's name
    /// (docs/mechanism-format.md, "Leg checks"); the command prints them on stderr once it
    /// has succeeded.
    pub warnings: Vec<String>,
}

/// The `kinsyn build` option that sets a [`BuildSpec`] field (`--legs`, `--chain`, …): the
/// name refusals of a specification use.
#[must_use]
pub fn build_flag(field: BuildField) -> String {
    match field {
        BuildField::Legs => "--legs",
        BuildField::Chain => "--chain",
        BuildField::Axes => "--axes",
        BuildField::Actuated => "--actuated",
        BuildField::BaseRadius => "--base-radius",
        BuildField::PlatformRadius => "--platform-radius",
        BuildField::Height => "--height",
        BuildField::Twist => "--twist",
    }
    .to_string()
}

/// The description `kinsyn build` writes for `spec`, and the manipulator it builds, checked
/// as the command checks it: the description builds a mechanism, and its legs are generic.
///
/// # Errors
///
/// [`Error::Input`]: a faulty specification (naming the option, [`build_flag`]), or a chain
/// that in this geometry makes no usable manipulator or legs that are not generic.
pub fn build_checked(spec: &BuildSpec) -> Result<(Description, Manipulator), Error> {
    let description = build(spec).map_err(|e| Error::Input(e.describe(build_flag)))?;
    // Check that what is written can be read back and built.
    let m = Manipulator::new(&description).map_err(|e| {
        Error::Input(format!(
            "--chain {:?} in this geometry makes no usable manipulator: {e}",
            spec.chain.trim()
        ))
    })?;
    // `build` refuses legs that are not generic; the file as read back must agree.
    if let Some(w) = m.leg_warnings().first() {
        return Err(Error::Input(format!(
            "--chain {:?}: {w}",
            spec.chain.trim()
        )));
    }
    Ok((description, m))
}

/// `kinsyn build`: writes a description (to `output`, replacing an existing file only when
/// `force`, or returns it for stdout).
///
/// # Errors
/// [`Error::Input`] for a faulty specification or an output that exists (without `force`); [`Error::Io`] when the output cannot be written.
pub fn build_command(
    spec: &BuildSpec,
    output: Option<&Path>,
    force: bool,
) -> Result<String, Error> {
    let target = output
        .map(|path| OutputFile::check("--output", path, force))
        .transpose()?;
    let (description, m) = build_checked(spec)?;
    let text = description.to_json();
    match target {
        Some(target) => {
            target.write(text.as_bytes())?;
            let path = target.path();
            let mobility = m.mechanism().mobility(&m.reference(), &[]).dof;
            let (twists, _) = m.platform_twists(&m.reference(), &[]);
            let dof = twists.ncols();
            Ok(format!(
                "wrote {} ({}: {} legs, {} inputs; mobility {mobility}, platform dof {dof} at the reference pose)\n",
                path.display(),
                description.name,
                description.legs.len(),
                m.actuators().len()
            ))
        }
        None => Ok(text),
    }
}

/// The inputs of `--inputs` (none: `None`), every input not named held at its reference value
/// (0); errors quote the text.
///
/// # Errors
/// [`Error::Input`] for inputs that do not read (unknown labels, values that are not numbers, an input given twice).
pub fn inputs_or_reference(
    m: &Manipulator,
    text: Option<&str>,
) -> Result<Vec<(usize, f64)>, Error> {
    let mut inputs = match text {
        Some(text) => m
            .parse_inputs(text)
            .map_err(|e| Error::Input(format!("--inputs {text:?}: {e}")))?,
        None => Vec::new(),
    };
    for a in 0..m.actuators().len() {
        if !inputs.iter().any(|(b, _)| *b == a) {
            inputs.push((a, 0.0));
        }
    }
    Ok(inputs)
}

/// `LABEL = value` for each input, angles in the file's unit, rounded to 1e-9.
#[must_use]
pub fn input_texts(m: &Manipulator, inputs: &[(usize, f64)]) -> Vec<String> {
    inputs
        .iter()
        .map(|(a, v)| {
            let actuator = &m.actuators()[*a];
            let value = if actuator.label().starts_with('R') {
                m.units().angle.from_radians(*v)
            } else {
                *v
            };
            format!(
                "{} = {}",
                actuator.label(),
                clean((value * 1e9).round() / 1e9)
            )
        })
        .collect()
}

/// A value to be printed with six decimals, without a "-0.000000" for round-off: 0 below 5e-7
/// in magnitude, the value otherwise.
#[must_use]
pub fn clean(x: f64) -> f64 {
    if x.abs() < 5e-7 { 0.0 } else { x }
}

/// `kinsyn stack`: a series-parallel stack of three-legged modules as a description, checked
/// by reading it back (to `output`, replacing an existing file only when `force`, or returned
/// for stdout).
///
/// # Errors
/// [`Error::Input`] for module names, radii or heights that do not make a stack, or an output that exists (without `force`); [`Error::Io`] when the output cannot be written.
pub fn stack_command(
    modules: &[String],
    radii: Vec<f64>,
    heights: Vec<f64>,
    output: Option<&Path>,
    force: bool,
) -> Result<String, Error> {
    use kinsyn::manipulator::stacking::{ModuleKind, StackSpec, stack};
    let target = output
        .map(|path| OutputFile::check("--output", path, force))
        .transpose()?;
    let modules = modules
        .iter()
        .map(|t| match t.trim().to_ascii_uppercase().as_str() {
            "RPS" | "3-RPS" => Ok(ModuleKind::Rps),
            "SPR" | "3-SPR" => Ok(ModuleKind::Spr),
            _ => Err(Error::Input(format!(
                "--modules: {t:?} is not a module (RPS or SPR)"
            ))),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let d = stack(&StackSpec {
        modules,
        radii,
        heights,
    })
    .map_err(|e| Error::Input(format!("kinsyn stack: {e}")))?;
    Manipulator::from_bodies(&d)
        .map_err(|e| Error::Internal(format!("the stack written does not read back: {e}")))?;
    let text = d.to_json();
    match target {
        Some(target) => {
            target.write(text.as_bytes())?;
            let path = target.path();
            Ok(format!(
                "wrote {} ({} moving bodies) to {}\n",
                d.name,
                d.bodies.len(),
                path.display()
            ))
        }
        None => Ok(text),
    }
}
