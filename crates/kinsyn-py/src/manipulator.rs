//! A parallel manipulator from a description file or built from a leg chain (as `kinsyn
//! build`), and what the command line computes for it: `analyze`, `modes` and
//! `analyze --all-assemblies`.

use crate::error::Error;
use crate::input::read_text;
use crate::report::{Reached, analysis_json};
use kinsyn::homotopy::{self, SolveSettings};
use kinsyn::manipulator::build::{BuildField, BuildSpec, build};
use kinsyn::manipulator::{
    self as m, ContinuationFailure, LegKind, ManipulatorError, PositionError, PositionRequest, file,
};
use kinsyn::mechanism::{SampleSettings, rotation_log};
use kinsyn::poly::geometry::Chart;
use kinsyn::spatial::Displacement;
use pyo3::prelude::*;
use std::path::PathBuf;

/// The most lock subsets `modes` samples unless told otherwise (as `kinsyn modes`).
pub const DEFAULT_MAX_SUBSETS: u32 = 4096;

/// The largest `max_subsets` (as `kinsyn modes --max-subsets`).
pub const MAX_SUBSETS_CEILING: u32 = 1 << 16;

/// The most configurations sampled per motion (as `kinsyn modes --samples`).
const MAX_SAMPLES: usize = 64;

/// A parallel manipulator: its description and the mechanism built from it.
#[pyclass(module = "kinsyn._native", frozen)]
pub struct Manipulator {
    inner: m::Manipulator,
    /// The description as JSON text.
    description: String,
    /// The file it was read from, as the messages name it (`<string>` for text).
    source: String,
}

/// The `kinsyn build` option that sets a [`BuildSpec`] field (the messages name them).
fn build_flag(field: BuildField) -> String {
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

/// The manipulator a description text describes; errors name `source` and the field.
fn parse(text: &str, source: &str) -> Result<m::Manipulator, Error> {
    m::Manipulator::from_json(text).map_err(|e| match &e {
        ManipulatorError::Description(d) if d.is_not_a_description() => {
            Error::Input(format!("{source} is {}", d.message))
        }
        _ => Error::Input(format!("{source}: {e}")),
    })
}

/// A position error in words, with the option that helps when the start is too far.
fn position_error(e: &ManipulatorError) -> String {
    match e {
        ManipulatorError::Position(PositionError::NotReached(
            ContinuationFailure::TooManySteps { .. },
        )) => format!("{e} (analyze --from)"),
        _ => e.to_string(),
    }
}

/// A value without a "-0" for round-off.
fn clean(x: f64) -> f64 {
    if x.abs() < 5e-7 { 0.0 } else { x }
}

impl Manipulator {
    fn leg_warnings(&self) -> Vec<String> {
        self.inner
            .leg_warnings()
            .iter()
            .map(|w| format!("{}: {w}", self.source))
            .collect()
    }

    /// The lock subsets asked for: one (`lock`), or all with at most `max_locks` locked,
    /// refused beyond `max_subsets` as `kinsyn modes` refuses them.
    fn subsets(
        &self,
        max_locks: Option<usize>,
        lock: Option<&str>,
        max_subsets: u32,
    ) -> Result<Vec<Vec<usize>>, Error> {
        let m = &self.inner;
        if let Some(text) = lock {
            let locked = m
                .parse_locks(text)
                .map_err(|e| Error::Input(format!("--lock {text:?}: {e}")))?;
            return Ok(vec![locked]);
        }
        let n = m.actuators().len();
        let k = max_locks.unwrap_or(n);
        let count = m.lock_subset_count(k);
        let limit = u128::from(max_subsets);
        if count <= limit {
            return Ok(m.lock_subsets(k));
        }
        let scope = match max_locks {
            Some(k) => format!("with at most {k} locked"),
            None => format!("(all 2^{n})"),
        };
        let fits = (0..n)
            .take_while(|&k| m.lock_subset_count(k) <= limit)
            .last()
            .unwrap_or(0);
        Err(Error::Input(format!(
            "{}: {n} inputs give {count} lock subsets {scope}, more than --max-subsets {max_subsets} (each is a sampled motion of about 1–5 ms of CPU, docs/limits.md); use --max-locks {fits} ({} subsets) or --lock SET, or raise --max-subsets (at most {MAX_SUBSETS_CEILING})",
            self.source,
            m.lock_subset_count(fits)
        )))
    }

    /// The configuration with the platform frame at `text` (a pose, as `--pose`), every input
    /// free, reached from the reference.
    fn at_pose(&self, text: &str) -> Result<Vec<f64>, Error> {
        let m = &self.inner;
        let request = PositionRequest {
            platform: Some(
                m.parse_pose(text)
                    .map_err(|e| Error::Input(format!("--pose {text:?}: {e}")))?,
            ),
            ..PositionRequest::default()
        };
        m.solve_position(&m.reference(), &request)
            .map(|p| p.q)
            .map_err(|e| Error::Input(format!("--pose {text:?}: {}", position_error(&e))))
    }

    /// `analyze --json` at the configuration of `pose` and `inputs` with `lock` held.
    fn analysis(
        &self,
        pose: Option<&str>,
        inputs: Option<&str>,
        lock: Option<&str>,
        seed: u64,
    ) -> Result<String, Error> {
        let m = &self.inner;
        let locked = match lock {
            Some(text) => m
                .parse_locks(text)
                .map_err(|e| Error::Input(format!("--lock {text:?}: {e}")))?,
            None => Vec::new(),
        };
        let start = m.reference();
        let mut request = PositionRequest {
            held: locked.clone(),
            ..PositionRequest::default()
        };
        if let Some(text) = inputs {
            request.inputs = m
                .parse_inputs(text)
                .map_err(|e| Error::Input(format!("--inputs {text:?}: {e}")))?;
            // Without a pose, inputs not named keep their reference values; with one they are
            // free, and the pose and the named inputs are met together.
            if pose.is_none() {
                request.held.extend(
                    (0..m.actuators().len())
                        .filter(|a| !request.inputs.iter().any(|&(b, _)| b == *a)),
                );
            }
        }
        if let Some(text) = pose {
            request.platform = Some(
                m.parse_pose(text)
                    .map_err(|e| Error::Input(format!("--pose {text:?}: {e}")))?,
            );
        }
        let (q, steps, continuous) = if request.inputs.is_empty() && request.platform.is_none() {
            (start, 0, true)
        } else {
            let asked: Vec<String> = [("--inputs", inputs), ("--pose", pose)]
                .iter()
                .filter_map(|(o, t)| t.map(|t| format!("{o} {t:?}")))
                .collect();
            let p = m.solve_position(&start, &request).map_err(|e| {
                Error::Input(format!("{}: {}", asked.join(" "), position_error(&e)))
            })?;
            (p.q, p.steps, p.continuous)
        };
        let settings = SampleSettings {
            seed,
            ..SampleSettings::default()
        };
        let a = m
            .analyse(&q, &locked, &settings)
            .map_err(|e| Error::Input(e.to_string()))?;
        let reached = Reached {
            start: "the reference configuration".into(),
            steps,
            continuous,
        };
        Ok(analysis_json(m, &a, &reached, &self.leg_warnings()).to_string())
    }

    /// `modes --json` for the lock subsets asked for.
    fn modes_report(
        &self,
        max_locks: Option<usize>,
        lock: Option<&str>,
        pose: Option<&str>,
        max_subsets: u32,
        settings: &SampleSettings,
    ) -> Result<String, Error> {
        let m = &self.inner;
        if max_subsets == 0 || max_subsets > MAX_SUBSETS_CEILING {
            return Err(Error::Input(format!(
                "--max-subsets {max_subsets}: give 1 to {MAX_SUBSETS_CEILING}"
            )));
        }
        if !(2..=MAX_SAMPLES).contains(&settings.samples) {
            return Err(Error::Input(format!(
                "--samples {}: give 2 to {MAX_SAMPLES}",
                settings.samples
            )));
        }
        let subsets = self.subsets(max_locks, lock, max_subsets)?;
        let start = match pose {
            None => m.reference(),
            Some(text) => self.at_pose(text)?,
        };
        let modes = m.modes_from(&start, &subsets, settings, &|| {});
        let mut value = serde_json::to_value(&modes).unwrap_or_default();
        if let Some(object) = value.as_object_mut() {
            object.insert("pose".into(), serde_json::json!(pose));
            object.insert(
                "max_locks".into(),
                serde_json::json!(if lock.is_none() { max_locks } else { None }),
            );
            object.insert(
                "lock".into(),
                serde_json::json!(lock.and(modes.modes.first().map(|m| m.lock_text.clone()))),
            );
            object.insert("warnings".into(), serde_json::json!(self.leg_warnings()));
            object.insert(
                "end_effector".into(),
                serde_json::json!(m.bodies()[m.end_effector()].name),
            );
        }
        Ok(value.to_string())
    }

    /// The inputs of `text`, every input not named at its reference value (0).
    fn inputs_or_reference(&self, text: Option<&str>) -> Result<Vec<(usize, f64)>, Error> {
        let m = &self.inner;
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

    /// `analyze --all-assemblies --json`: every assembly at the inputs, by homotopy
    /// continuation on the constraint polynomials in the Study parameters of the platform.
    fn assemblies_report(&self, inputs_text: Option<&str>, seed: u64) -> Result<String, Error> {
        let m = &self.inner;
        let inputs = self.inputs_or_reference(inputs_text)?;
        let ps = m
            .position_system(&inputs, &Chart::random_linear(seed))
            .map_err(|e| Error::Input(format!("--all-assemblies: {e}")))?;
        let settings = SolveSettings {
            seed,
            ..SolveSettings::default()
        };
        let report =
            homotopy::solve(ps.system(), &settings).map_err(|e| Error::Input(e.to_string()))?;
        let request = PositionRequest {
            inputs: inputs.clone(),
            ..PositionRequest::default()
        };
        let current = m
            .solve_position(&m.reference(), &request)
            .ok()
            .map(|p| m.platform_frame(&p.q));
        let real: Vec<serde_json::Value> = report
            .solutions
            .iter()
            .filter(|s| s.regular && s.real)
            .filter_map(|s| {
                let x: Vec<f64> = s.x.iter().map(|c| c.re).collect();
                let pose = ps.displacement(&x).ok()?;
                let residual = ps
                    .leg_residuals(&pose)
                    .iter()
                    .map(|r| r.distance.abs().max(r.plane.map_or(0.0, f64::abs)))
                    .fold(0.0, f64::max);
                let continued = current.as_ref().is_some_and(|c| {
                    (c.to_homogeneous() - pose.to_homogeneous()).amax()
                        < 1e-6 * (1.0 + c.translation.vector.norm())
                });
                Some(serde_json::json!({
                    "pose": self.pose_text(&pose),
                    "position": pose.translation.vector.as_slice(),
                    "rotation_vector_rad": rotation_log(&pose.rotation).as_slice(),
                    "largest_leg_residual": residual,
                    "certified": s.is_certified(),
                    "continued_from_reference": continued,
                }))
            })
            .collect();
        let null_cone = report
            .solutions
            .iter()
            .filter(|s| {
                let delta: kinsyn::poly::C64 = s.x[..4].iter().map(|c| c * c).sum();
                let size: f64 = s.x[..4].iter().map(kinsyn::poly::C64::norm_sqr).sum();
                !s.regular && delta.norm() <= 1e-8 * size
            })
            .count();
        let kinds: Vec<&str> = ps
            .legs()
            .iter()
            .map(|l| match l.kind {
                LegKind::Distance => "distance",
                LegKind::RevoluteSpherical => "R–S: distance and plane",
                LegKind::SphericalRevolute => "S–R: distance and moving plane",
                LegKind::Coincident => "coincident points",
                LegKind::CoplanarDistance => "U–U: distance and coplanar lines",
            })
            .collect();
        let v = serde_json::json!({
            "manipulator": m.name(),
            "inputs": self.input_texts(&inputs),
            "formulation": {
                "variables": ps.system().variables(),
                "equations": ps.system().len(),
                "degrees": ps.system().degrees(),
                "bezout_number": ps.system().bezout_number().to_string(),
                "legs": kinds,
            },
            "summary": report.summary(),
            "paths": report.paths(),
            "nonsingular": report.nonsingular(),
            "real": report.real(),
            "singular": report.singular(),
            "singular_on_null_cone": null_cone,
            "at_infinity": report.at_infinity(),
            "certified": report.certified(),
            "certified_real": report.certified_real(),
            "seconds": report.seconds,
            "seed": seed,
            "real_assemblies": real,
            "complex_assemblies": report.solutions.iter().filter(|s| s.regular && !s.real).map(|s| {
                s.x.iter().map(|c| [c.re, c.im]).collect::<Vec<_>>()
            }).collect::<Vec<_>>(),
            "warnings": self.leg_warnings(),
        });
        Ok(v.to_string())
    }

    /// The pose as `--pose` takes it: `x,y,z,rx,ry,rz` in the file's units, each number in
    /// full.
    fn pose_text(&self, g: &Displacement) -> String {
        let t = g.translation.vector;
        let r = rotation_log(&g.rotation).map(|a| self.inner.units().angle.from_radians(a));
        [t.x, t.y, t.z, r.x, r.y, r.z]
            .iter()
            .map(|v| format!("{}", clean(*v)))
            .collect::<Vec<_>>()
            .join(",")
    }

    /// `LABEL = value` for each input, angles in the file's unit, rounded to 1e-9.
    fn input_texts(&self, inputs: &[(usize, f64)]) -> Vec<String> {
        let m = &self.inner;
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
}

#[pymethods]
impl Manipulator {
    /// The manipulator described by the file at `path` (a kinsyn description, as `kinsyn
    /// analyze FILE` reads it).
    #[staticmethod]
    #[expect(
        clippy::needless_pass_by_value,
        reason = "PyO3 converts a Python path (str or os.PathLike) to an owned PathBuf"
    )]
    fn from_file(path: PathBuf) -> PyResult<Self> {
        let description = read_text(&path, file::NOT_A_DESCRIPTION)?;
        let source = path.display().to_string();
        let inner = parse(&description, &source)?;
        Ok(Self {
            inner,
            description,
            source,
        })
    }

    /// The manipulator described by the JSON text `text`; messages name it `source`.
    #[staticmethod]
    #[pyo3(signature = (text, source = "<string>"))]
    fn from_json(text: &str, source: &str) -> PyResult<Self> {
        let inner = parse(text, source)?;
        Ok(Self {
            inner,
            description: text.to_string(),
            source: source.to_string(),
        })
    }

    /// A manipulator of `legs` identical legs `chain` (a catalogue id or a chain in notation,
    /// `!` marking inputs) between a base and a platform circle, as `kinsyn build`.
    #[staticmethod]
    #[pyo3(signature = (chain, legs = 3, actuated = None, axes = None, base_radius = 1.0,
        platform_radius = 0.5, height = 1.0, twist = 0.0, alternate = false, name = None))]
    #[expect(
        clippy::too_many_arguments,
        reason = "the options of `kinsyn build`, as Python keyword arguments"
    )]
    fn build(
        chain: String,
        legs: usize,
        actuated: Option<Vec<usize>>,
        axes: Option<String>,
        base_radius: f64,
        platform_radius: f64,
        height: f64,
        twist: f64,
        alternate: bool,
        name: Option<String>,
    ) -> PyResult<Self> {
        let spec = BuildSpec {
            legs,
            chain,
            axes,
            actuated,
            base_radius,
            platform_radius,
            height,
            twist,
            alternate,
            name,
        };
        let description = build(&spec).map_err(|e| Error::Input(e.describe(build_flag)))?;
        let inner = m::Manipulator::new(&description).map_err(|e| {
            Error::Input(format!(
                "--chain {:?} in this geometry makes no usable manipulator: {e}",
                spec.chain.trim()
            ))
        })?;
        if let Some(w) = inner.leg_warnings().first() {
            return Err(Error::Input(format!("--chain {:?}: {w}", spec.chain.trim())).into());
        }
        Ok(Self {
            inner,
            description: description.to_json(),
            source: "<built>".into(),
        })
    }

    /// The manipulator's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name().to_string()
    }

    /// The inputs' labels (`P1.3`: leg 1, primitive joint 3), in order.
    #[getter]
    fn inputs(&self) -> Vec<String> {
        self.inner
            .actuators()
            .iter()
            .map(m::Actuator::label)
            .collect()
    }

    /// The description as JSON text (what `kinsyn build` writes).
    fn to_json(&self) -> String {
        self.description.clone()
    }

    /// `kinsyn analyze FILE [--pose P] [--inputs I] [--lock L] --seed S --json`, as JSON text.
    #[pyo3(signature = (pose = None, inputs = None, lock = None, seed = 2026))]
    fn analyze_json(
        &self,
        py: Python<'_>,
        pose: Option<&str>,
        inputs: Option<&str>,
        lock: Option<&str>,
        seed: u64,
    ) -> PyResult<String> {
        Ok(py.detach(|| self.analysis(pose, inputs, lock, seed))?)
    }

    /// `kinsyn modes FILE [--max-locks K | --lock L] [--pose P] --json`, as JSON text.
    #[pyo3(signature = (max_locks = None, lock = None, pose = None,
        max_subsets = DEFAULT_MAX_SUBSETS, seed = 2026, samples = 3))]
    #[expect(clippy::too_many_arguments, reason = "the options of `kinsyn modes`")]
    fn modes_json(
        &self,
        py: Python<'_>,
        max_locks: Option<usize>,
        lock: Option<&str>,
        pose: Option<&str>,
        max_subsets: u32,
        seed: u64,
        samples: usize,
    ) -> PyResult<String> {
        let settings = SampleSettings {
            seed,
            samples,
            ..SampleSettings::default()
        };
        Ok(py.detach(|| self.modes_report(max_locks, lock, pose, max_subsets, &settings))?)
    }

    /// `kinsyn analyze FILE [--inputs I] --all-assemblies --seed S --json`, as JSON text.
    #[pyo3(signature = (inputs = None, seed = 2026))]
    fn assemblies_json(&self, py: Python<'_>, inputs: Option<&str>, seed: u64) -> PyResult<String> {
        Ok(py.detach(|| self.assemblies_report(inputs, seed))?)
    }

    fn __repr__(&self) -> String {
        format!(
            "Manipulator({:?}, inputs {})",
            self.inner.name(),
            self.inputs().join(" ")
        )
    }
}
