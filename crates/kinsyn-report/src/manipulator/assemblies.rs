//! `kinsyn analyze FILE --inputs … --all-assemblies`: every assembly of a manipulator at given
//! inputs, from its constraint polynomials in Study parameters solved by homotopy continuation
//! (through their square randomisation when the manipulator is over-constrained).

use super::{Loaded, clean, input_texts, inputs_or_reference, leg_warnings, load_with_body};
use crate::Error;
use crate::solve::{PathOption, solve_with_bar};
use kinsyn::geometry::Chart;
use kinsyn::homotopy::{SolveReport, SolveSettings, satisfying, square_randomisation};
use kinsyn::manipulator::{InputValues, Manipulator, PositionRequest, PositionSystemError};
use kinsyn::mechanism::rotation_log;
use kinsyn::spatial::Displacement;
use serde::Serialize;
use std::path::Path;

/// One real assembly: the platform frame, the largest leg residual, and whether it is
/// certified and the one continued from the reference.
pub struct Assembly {
    /// The platform frame.
    pub pose: Displacement,
    /// The largest residual of the legs' constraints (length unit).
    pub residual: f64,
    /// Whether the solution is certified (Krawczyk).
    pub certified: bool,
    /// Whether it is the assembly reached by continuation from the reference configuration.
    pub current: bool,
}

/// The pose as `--pose` takes it: `x,y,z,rx,ry,rz`, lengths in the file's unit and the rotation
/// vector in its angle unit, each number in full (the shortest text that reads back to the same
/// double): a platform of fewer than six dof meets its constraints only at the exact pose, and
/// six rounded decimals leave it off them by more than the assembly tolerance.
#[must_use]
pub fn pose_text(m: &Manipulator, g: &Displacement) -> String {
    let t = g.translation.vector;
    let r = rotation_log(&g.rotation).map(|a| m.units().angle.from_radians(a));
    [t.x, t.y, t.z, r.x, r.y, r.z]
        .iter()
        .map(|v| format!("{}", clean(*v)))
        .collect::<Vec<_>>()
        .join(",")
}

/// `kinsyn analyze FILE [--inputs …] --all-assemblies`: the manipulator of the file at `path`
/// (its end-effector `body` when given), every assembly at the inputs of `inputs_text` (the
/// others at their reference values) solved with `seed`, and the leg warnings.
///
/// # Errors
/// [`Error::Input`] for a file that is not a description, inputs that do not read, a system past the path limit, or a mechanism whose assemblies cannot be posed as a system.
pub fn all_assemblies(
    path: &Path,
    inputs_text: Option<&str>,
    body: Option<&str>,
    seed: u64,
) -> Result<Loaded<AllAssemblies>, Error> {
    let m = load_with_body(path, body, None, None)?;
    let all = all_assemblies_of(&m, inputs_text, seed)?;
    let warnings = leg_warnings(&m);
    Ok(Loaded {
        manipulator: m,
        result: all,
        warnings,
    })
}

/// Every assembly of a manipulator at given inputs: the solve of its position system and the
/// real assemblies found.
pub struct AllAssemblies {
    /// The inputs, every one, by actuator index and value (radians or length unit; as text
    /// by [`input_texts`]).
    pub inputs: Vec<(usize, f64)>,
    /// The seed of the chart and of the solve.
    pub seed: u64,
    /// The variables, equations and degrees of the position system.
    pub system: kinsyn::poly::System,
    /// The system solved: [`Self::system`] itself when it is square; for an over-constrained
    /// manipulator (more equations than unknowns) its square randomisation
    /// ([`kinsyn::homotopy::square_randomisation`]).
    pub solved: kinsyn::poly::System,
    /// The endpoints of the square randomisation that the original equations refuse (0 for a
    /// square system): they are not in [`Self::report`]'s solutions.
    pub spurious: usize,
    /// What each leg contributes to the position system.
    pub kinds: Vec<&'static str>,
    /// The solve.
    pub report: SolveReport,
    /// The real assemblies.
    pub assemblies: Vec<Assembly>,
    /// How many singular endpoints lie on the null cone.
    pub null_cone: usize,
}

/// Every assembly of `m` at the inputs of `inputs_text` (`--inputs`; the inputs not named at
/// their reference values), by homotopy continuation on the constraint polynomials in the
/// Study parameters of the platform (a random linear chart and the solve seeded by `seed`). A
/// progress bar over the paths is drawn on stderr when it is a terminal.
///
/// # Errors
///
/// [`Error::Input`]: malformed input values, a manipulator without a position system, or
/// a system the solver refuses.
pub fn all_assemblies_of(
    m: &Manipulator,
    inputs_text: Option<&str>,
    seed: u64,
) -> Result<AllAssemblies, Error> {
    let inputs = inputs_or_reference(m, inputs_text)?;
    let chart = Chart::random_linear(seed);
    // More constraints than the platform's six dof (an over-constrained manipulator such as the
    // 4-RUU): the whole system, solved through its square randomisation.
    let ps = match m.position_system(&inputs, &chart) {
        Err(PositionSystemError::Overdetermined(_)) => {
            m.constraint_system(&InputValues::Given(&inputs), &chart)
        }
        other => other,
    }
    .map_err(|e| Error::Input(format!("--all-assemblies: {e}")))?;
    let solved = square_randomisation(ps.system(), seed)
        .map_err(|e| Error::Input(format!("--all-assemblies: {e}")))?;
    let settings = SolveSettings {
        seed,
        ..SolveSettings::default()
    };
    // One run: its report is the only one.
    let mut report = solve_with_bar(
        "--all-assemblies",
        &solved,
        &settings,
        1,
        PathOption::Default,
    )?
    .runs
    .swap_remove(0);
    // Of the randomisation's endpoints, only those that satisfy every original equation.
    let mut spurious = 0;
    if solved.len() < ps.system().len() {
        let keep = satisfying(ps.system(), &report);
        spurious = keep.iter().filter(|ok| !**ok).count();
        let mut keep = keep.into_iter();
        report.solutions.retain(|_| keep.next().unwrap_or(false));
    }
    // The assembly Newton continuation reaches from the reference, to mark it.
    let request = PositionRequest {
        inputs: inputs.clone(),
        ..PositionRequest::default()
    };
    let current = m
        .solve_position(&m.reference(), &request)
        .ok()
        .map(|p| m.platform_frame(&p.q));
    let assemblies: Vec<Assembly> = report
        .solutions
        .iter()
        .filter(|s| s.regular && s.real)
        .filter_map(|s| {
            let x: Vec<f64> = s.x.iter().map(|c| c.re).collect();
            let pose = ps.displacement(&x).ok()?;
            let residual = ps
                .leg_residuals(&pose)
                .iter()
                .map(|r| {
                    r.distance
                        .abs()
                        .max(r.plane.map_or(0.0, f64::abs))
                        .max(r.angle.map_or(0.0, f64::abs))
                })
                .fold(0.0, f64::max);
            let current = current.as_ref().is_some_and(|c| {
                (c.to_homogeneous() - pose.to_homogeneous()).amax()
                    < 1e-6 * (1.0 + c.translation.vector.norm())
            });
            Some(Assembly {
                pose,
                residual,
                certified: s.is_certified(),
                current,
            })
        })
        .collect();
    // Singular endpoints where x0² + x1² + x2² + x3² = 0: the constraints were multiplied by
    // this Δ (or vanish with it), so the null cone solves them without being a displacement.
    let null_cone = report
        .solutions
        .iter()
        .filter(|s| {
            let delta: kinsyn::poly::C64 = s.x[..4].iter().map(|c| c * c).sum();
            let size: f64 = s.x[..4].iter().map(kinsyn::poly::C64::norm_sqr).sum();
            !s.regular && delta.norm() <= 1e-8 * size
        })
        .count();
    let kinds: Vec<&'static str> = ps.legs().iter().map(|l| l.kind.describe()).collect();
    Ok(AllAssemblies {
        inputs,
        seed,
        system: ps.system().clone(),
        solved,
        spurious,
        kinds,
        report,
        assemblies,
        null_cone,
    })
}

impl AllAssemblies {
    /// The report of `kinsyn analyze --all-assemblies --json` for `m`, with the leg `warnings`.
    #[must_use]
    pub fn report(&self, m: &Manipulator, warnings: &[String]) -> AssembliesReport {
        let (report, system, solved) = (&self.report, &self.system, &self.solved);
        AssembliesReport {
            manipulator: m.name().to_string(),
            inputs: input_texts(m, &self.inputs),
            formulation: Formulation {
                variables: system.variables().to_vec(),
                equations: system.len(),
                degrees: system.degrees(),
                bezout_number: solved.bezout_number().to_string(),
                randomised: solved.len() < system.len(),
                legs: self.kinds.clone(),
            },
            spurious: self.spurious,
            summary: report.summary(),
            paths: report.paths(),
            nonsingular: report.nonsingular(),
            real: report.real(),
            singular: report.singular(),
            singular_on_null_cone: self.null_cone,
            at_infinity: report.at_infinity(),
            certified: report.certified(),
            certified_real: report.certified_real(),
            seconds: report.seconds,
            seed: self.seed,
            real_assemblies: self
                .assemblies
                .iter()
                .map(|a| {
                    let t = a.pose.translation.vector;
                    let r = rotation_log(&a.pose.rotation);
                    RealAssembly {
                        pose: pose_text(m, &a.pose),
                        position: [t.x, t.y, t.z],
                        rotation_vector_rad: [r.x, r.y, r.z],
                        largest_leg_residual: a.residual,
                        certified: a.certified,
                        continued_from_reference: a.current,
                    }
                })
                .collect(),
            complex_assemblies: report
                .solutions
                .iter()
                .filter(|s| s.regular && !s.real)
                .map(|s| s.x.iter().map(|c| [c.re, c.im]).collect())
                .collect(),
            warnings: warnings.to_vec(),
        }
    }
}

/// The report of `kinsyn analyze --all-assemblies --json` (and of Python's
/// `Manipulator.all_assemblies`): the position system in the Study parameters of the platform,
/// its solve by homotopy continuation, and the assemblies found. Lengths are in the
/// description's length unit.
///
/// Printed through [`crate::sorted_value`]: its keys come in alphabetical order, as they did
/// when the report was built with `serde_json::json!`, not in the order of these fields.
#[derive(Debug, Clone, Serialize)]
pub struct AssembliesReport {
    /// The manipulator's name (the description's `name`).
    pub manipulator: String,
    /// Every input's value, `LABEL = value` (angles in the description's angle unit, rounded
    /// to 1e-9): those of `--inputs`, the others at their reference values (0).
    pub inputs: Vec<String>,
    /// The position system solved.
    pub formulation: Formulation,
    /// The solve's counts in words.
    pub summary: String,
    /// The paths tracked.
    pub paths: usize,
    /// The non-singular endpoints: the isolated assemblies, real and complex.
    pub nonsingular: usize,
    /// Of those, the real ones.
    pub real: usize,
    /// The singular endpoints.
    pub singular: usize,
    /// Of those, the ones on the null cone `x0² + x1² + x2² + x3² = 0`, which solve the
    /// constraints without being a displacement.
    pub singular_on_null_cone: usize,
    /// The paths that went to infinity.
    pub at_infinity: usize,
    /// The endpoints of the square randomisation of an over-determined system that the original
    /// equations refuse (0 for a square system); they are counted nowhere else.
    pub spurious: usize,
    /// The non-singular endpoints certified (each proved, by the Krawczyk operator in interval
    /// arithmetic, to approximate exactly one root).
    pub certified: usize,
    /// Of those, the ones certified real.
    pub certified_real: usize,
    /// The solve's wall-clock time (seconds).
    pub seconds: f64,
    /// The seed of the random chart and of the solve.
    pub seed: u64,
    /// The real assemblies.
    pub real_assemblies: Vec<RealAssembly>,
    /// The complex (non-real) assemblies: each the position system's variables (the Study
    /// parameters in the chart) as `[re, im]` pairs.
    pub complex_assemblies: Vec<Vec<[f64; 2]>>,
    /// The leg warnings of the description (docs/mechanism-format.md, "Leg checks").
    pub warnings: Vec<String>,
}

/// The position system of `analyze --all-assemblies`: the legs' constraints on the Study
/// parameters `x0…y3` of the platform frame, the Study quadric, and a random linear chart
/// (more equations than unknowns for an over-constrained manipulator).
#[derive(Debug, Clone, Serialize)]
pub struct Formulation {
    /// The unknowns' names.
    pub variables: Vec<String>,
    /// How many equations.
    pub equations: usize,
    /// Each equation's degree.
    pub degrees: Vec<u32>,
    /// The total-degree Bézout number of the system solved (the product of its degrees: of the
    /// square randomisation when [`Self::randomised`]), as decimal text.
    pub bezout_number: String,
    /// Whether the system has more equations than unknowns (an over-constrained manipulator,
    /// e.g. the 4-RUU) and was solved through its square randomisation: the equations of
    /// highest degree, as many as the unknowns, each plus a random real combination of the
    /// others, every endpoint then checked against all the equations.
    pub randomised: bool,
    /// What each leg contributes (`distance`, `R–S: distance and plane`, …), in leg order.
    pub legs: Vec<&'static str>,
}

/// One real assembly: the platform frame where every leg closes.
#[derive(Debug, Clone, Serialize)]
pub struct RealAssembly {
    /// The pose as `--pose` takes it: `x,y,z,rx,ry,rz` (length unit, the rotation vector in
    /// the description's angle unit), each number in full.
    pub pose: String,
    /// The platform frame's origin in the ground frame (length unit).
    pub position: [f64; 3],
    /// The platform frame's orientation as a rotation vector (radians).
    pub rotation_vector_rad: [f64; 3],
    /// The largest residual of the legs' constraints there (their distances and planes missed,
    /// length unit).
    pub largest_leg_residual: f64,
    /// Whether the solution is certified (proved by the Krawczyk operator to approximate
    /// exactly one root).
    pub certified: bool,
    /// Whether it is the assembly reached by continuation from the reference configuration.
    pub continued_from_reference: bool,
}
