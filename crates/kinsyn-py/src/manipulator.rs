//! A parallel manipulator from a description file or built from a leg chain (as `kinsyn
//! build`), and what the command line computes for it: `analyze`, `modes` and
//! `analyze --all-assemblies`, each by the command's own code (the crate `kinsyn_report`).

use crate::error::{Error, py_err};
use kinsyn::manipulator::build::BuildSpec;
use kinsyn::manipulator::{self as m, file};
use kinsyn::mechanism::SampleSettings;
use kinsyn_report::files::read_text;
use kinsyn_report::manipulator::{
    AnalyzeReport, DEFAULT_MAX_SUBSETS, MAX_SAMPLES, MAX_SUBSETS_CEILING, Placement, Selection,
    all_assemblies_of, analyse_placed, build_checked, modes_report, parse_description,
    parse_description_legs, sample_modes, select_body,
};
use kinsyn_report::sorted_value;
use nalgebra::DMatrix;
use pyo3::prelude::*;
use serde::Serialize;
use std::borrow::Cow;
use std::path::PathBuf;

/// A parallel manipulator: its description and the mechanism built from it.
#[pyclass(module = "kinsyn._native", frozen)]
pub struct Manipulator {
    inner: m::Manipulator,
    /// The description as JSON text.
    description: String,
    /// The file it was read from, as the messages name it (`<string>` for text).
    source: String,
}

/// A matrix as a list of its rows.
fn matrix_rows(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    m.row_iter().map(|r| r.iter().copied().collect()).collect()
}

/// `analyze --json`'s report with the matrices `J_D` and `J_I` themselves, row by row: what
/// Python's `Manipulator.analyze` returns. Handed over as the text of
/// [`kinsyn_report::sorted_value`], its keys in alphabetical order.
#[derive(Serialize)]
struct AnalysisWithMatrices {
    /// The command's report, its fields at the top level.
    #[serde(flatten)]
    report: AnalyzeReport,
    /// `J_D`, row by row (the rows' wrenches `(f; m_P)`).
    jd_matrix: Vec<Vec<f64>>,
    /// `J_I`, row by row (one column per free input).
    ji_matrix: Vec<Vec<f64>>,
}

/// Which bodies and legs a computation takes: the command's `--body`, `--relative-to` and
/// `--legs`.
#[derive(Debug, Default, Clone, Copy)]
struct Bodies<'a> {
    /// `--body`: the moving body analysed instead of the description's end-effector.
    body: Option<&'a str>,
    /// `--relative-to`: the moving body its motion is taken relative to.
    relative_to: Option<&'a str>,
    /// `--legs`: the legs kept (`1-4,29`).
    legs: Option<&'a str>,
}

impl Manipulator {
    /// The leg warnings of `m` (this manipulator or one of its [`Bodies`] selections), each
    /// naming the source (the command's `warning: FILE: …` lines).
    fn leg_warnings(&self, m: &m::Manipulator) -> Vec<String> {
        m.leg_warnings()
            .iter()
            .map(|w| format!("{}: {w}", self.source))
            .collect()
    }

    /// The manipulator as the command loads it with `--body`, `--relative-to` and `--legs`.
    fn selected(&self, bodies: Bodies<'_>) -> Result<Cow<'_, m::Manipulator>, Error> {
        let Bodies {
            body,
            relative_to,
            legs,
        } = bodies;
        if body.is_none() && relative_to.is_none() && legs.is_none() {
            return Ok(Cow::Borrowed(&self.inner));
        }
        let base = match legs {
            Some(list) => parse_description_legs(&self.description, &self.source, list, body)?,
            None => self.inner.clone(),
        };
        Ok(Cow::Owned(select_body(base, body, relative_to)?))
    }

    /// `analyze --json` at the configuration of `pose` and `inputs` with `lock` held, with the
    /// matrices `J_D` and `J_I` themselves (`jd_matrix`, `ji_matrix`, row by row) added.
    fn analysis(
        &self,
        placement: &Placement<'_>,
        lock: Option<&str>,
        seed: u64,
    ) -> Result<String, Error> {
        let selected = self.selected(Bodies {
            body: placement.body,
            relative_to: placement.relative_to,
            legs: None,
        })?;
        let m = selected.as_ref();
        let settings = SampleSettings {
            seed,
            ..SampleSettings::default()
        };
        let analyzed = analyse_placed(m, placement, lock, &settings)?;
        let j = &analyzed.analysis.jacobians;
        let report = AnalysisWithMatrices {
            report: analyzed.report(m, &self.leg_warnings(m)),
            jd_matrix: matrix_rows(&j.jd),
            ji_matrix: matrix_rows(&j.ji),
        };
        Ok(sorted_value(&report).to_string())
    }

    /// `modes --json` for the lock subsets asked for, of the bodies and legs of `bodies`.
    fn modes_report(
        &self,
        bodies: Bodies<'_>,
        max_locks: Option<usize>,
        lock: Option<&str>,
        pose: Option<&str>,
        max_subsets: u32,
        settings: &SampleSettings,
    ) -> Result<String, Error> {
        // The command's clap checks these ranges.
        if max_subsets == 0 || max_subsets > MAX_SUBSETS_CEILING {
            return Err(Error::Input(format!(
                "--max-subsets {max_subsets}: give 1 to {MAX_SUBSETS_CEILING}"
            )));
        }
        if !(2..=usize::from(MAX_SAMPLES)).contains(&settings.samples) {
            return Err(Error::Input(format!(
                "--samples {}: give 2 to {MAX_SAMPLES}",
                settings.samples
            )));
        }
        let selection = match (lock, max_locks) {
            (Some(set), _) => Selection::Lock(set.to_string()),
            (None, Some(k)) => Selection::MaxLocks(k),
            (None, None) => Selection::All,
        };
        let selected = self.selected(bodies)?;
        let m = selected.as_ref();
        let modes = sample_modes(m, &self.source, pose, &selection, max_subsets, settings)?;
        let report = modes_report(m, &modes, pose, &selection, &self.leg_warnings(m));
        Ok(sorted_value(&report).to_string())
    }

    /// `analyze --all-assemblies --json`: every assembly at the inputs, by homotopy
    /// continuation on the constraint polynomials in the Study parameters of the platform.
    fn assemblies_report(&self, inputs: Option<&str>, seed: u64) -> Result<String, Error> {
        let all = all_assemblies_of(&self.inner, inputs, seed)?;
        let report = all.report(&self.inner, &self.leg_warnings(&self.inner));
        Ok(sorted_value(&report).to_string())
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
        let description = read_text(&path, file::NOT_A_DESCRIPTION).map_err(py_err)?;
        let source = path.display().to_string();
        let inner = parse_description(&description, &source).map_err(py_err)?;
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
        let inner = parse_description(text, source).map_err(py_err)?;
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
        let (description, inner) = build_checked(&spec).map_err(py_err)?;
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

    /// `kinsyn analyze FILE [--pose P] [--inputs I] [--lock L] [--body B] [--relative-to R]
    /// [--study S …] --seed S --json`, as JSON text (`study`: one text `x0:…:y3` per moving
    /// body, in series order from the ground).
    #[pyo3(signature = (pose = None, inputs = None, lock = None, seed = 2026, body = None,
        relative_to = None, study = Vec::new()))]
    #[expect(clippy::too_many_arguments, reason = "the options of `kinsyn analyze`")]
    #[expect(
        clippy::needless_pass_by_value,
        reason = "PyO3 converts a Python list of str to an owned Vec"
    )]
    fn analyze_json(
        &self,
        py: Python<'_>,
        pose: Option<&str>,
        inputs: Option<&str>,
        lock: Option<&str>,
        seed: u64,
        body: Option<&str>,
        relative_to: Option<&str>,
        study: Vec<String>,
    ) -> PyResult<String> {
        let placement = Placement {
            pose,
            inputs,
            body,
            relative_to,
            study: &study,
            ..Placement::default()
        };
        py.detach(|| self.analysis(&placement, lock, seed))
            .map_err(py_err)
    }

    /// `kinsyn modes FILE [--max-locks K | --lock L] [--pose P] [--body B] [--relative-to R]
    /// [--legs LIST] --json`, as JSON text.
    #[pyo3(signature = (max_locks = None, lock = None, pose = None,
        max_subsets = DEFAULT_MAX_SUBSETS, seed = 2026, samples = 3, body = None,
        relative_to = None, legs = None))]
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
        body: Option<&str>,
        relative_to: Option<&str>,
        legs: Option<&str>,
    ) -> PyResult<String> {
        let bodies = Bodies {
            body,
            relative_to,
            legs,
        };
        let settings = SampleSettings {
            seed,
            samples,
            ..SampleSettings::default()
        };
        py.detach(|| self.modes_report(bodies, max_locks, lock, pose, max_subsets, &settings))
            .map_err(py_err)
    }

    /// `kinsyn analyze FILE [--inputs I] --all-assemblies --seed S --json`, as JSON text.
    #[pyo3(signature = (inputs = None, seed = 2026))]
    fn assemblies_json(&self, py: Python<'_>, inputs: Option<&str>, seed: u64) -> PyResult<String> {
        py.detach(|| self.assemblies_report(inputs, seed))
            .map_err(py_err)
    }

    /// `kinsyn view FILE [--inputs I] --steps N [--no-assemblies] --seed S`: the 3D page, as
    /// HTML text (docs/view.md).
    #[pyo3(signature = (inputs = None, steps = 16, assemblies = true, components = false,
                        free_inputs = false, max_paths = kinsyn::homotopy::DEFAULT_DECOMPOSE_PATHS,
                        seed = 1))]
    #[expect(
        clippy::too_many_arguments,
        reason = "the options of `kinsyn view`, by keyword"
    )]
    fn view_html(
        &self,
        py: Python<'_>,
        inputs: Option<String>,
        steps: usize,
        assemblies: bool,
        components: bool,
        free_inputs: bool,
        max_paths: u64,
        seed: u64,
    ) -> PyResult<String> {
        let options = kinsyn_report::view::ViewOptions {
            inputs,
            steps,
            assemblies,
            components,
            free_inputs,
            max_paths,
            seed,
        };
        py.detach(|| {
            kinsyn_report::view::view_of(&self.inner, &options).map(|v| kinsyn::view::page(&v))
        })
        .map_err(py_err)
    }

    fn __repr__(&self) -> String {
        format!(
            "Manipulator({:?}, inputs {})",
            self.inner.name(),
            self.inputs().join(" ")
        )
    }
}
